// The synthetic SMACHA-shaped workload of the template benchmarks: N leaf states rendered
// block by block into code buffers (renderBlock of every block of WorkState.tpl.py), then the
// module layout rendered from the joined buffers (Base.tpl.py). tmpl_bench_jinja.py runs the
// same workload with python3-jinja2.
#pragma once

#include <string>
#include <vector>

#include "backends/tmpl/environment.h"

namespace smachac::bench {

/// The context of leaf state `i` (defined_headers is shared by all states, as in SMACHA).
tmpl::Value stateContext(int i, int count, const tmpl::Value& definedHeaders);

/// Runs the workload for `count` states; returns the size of the generated module.
size_t runSmachaWorkload(tmpl::Environment& env, int count);

}  // namespace smachac::bench
