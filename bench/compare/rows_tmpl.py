"""Row: template rendering, smachac's engine vs python3-jinja2, on the existing workload.

The workload is bench/README.md's `BM_TmplSmachaWorkload1000` (1,000 leaf states rendered
block by block like SMACHA's generator, then the base template): smachac's side is the
bench_tmpl binary of the build tree run with --benchmark_filter (its CPU time per workload,
Google Benchmark's mean over its iterations), the anchor's side is bench/tmpl_bench_jinja.py
imported here (its Templater configured like SMACHA, warm caches; CPU time of one workload).
They run alternately, config.REPEATS times.
"""
import json
import sys
import time

import anchors
import config
import measure
import table
from context import ROOT

GROUP = "templates"
WHAT = "SMACHA-shaped workload, 1,000 states rendered block by block (CPU, warm)"
BENCHMARK = "BM_TmplSmachaWorkload1000"


def rows(ctx):
    why = anchors.jinja_why_not()
    if not ctx.bench_tmpl.exists():
        return [table.Row(GROUP, WHAT, "skipped: no %s" % ctx.bench_tmpl, "python3-jinja2")]

    def ours():
        return smachac_sample(ctx)

    if why:
        result = measure.pair(config.REPEATS, ours, None, anchor_repeats=0)
        return [table.skipped(GROUP, WHAT, table.seconds(result.median("ours", "cpu")),
                              "python3-jinja2", why)]
    sys.path.insert(0, str(ROOT / "bench"))
    import jinja2
    import tmpl_bench_jinja  # the reference workload of bench_tmpl (and its Jinja2 setup)
    ctx.say("templates: warming python3-jinja2")
    templater = tmpl_bench_jinja.Templater()
    tmpl_bench_jinja.workload(templater, tmpl_bench_jinja.COUNT)

    def anchor():
        start = time.process_time()
        tmpl_bench_jinja.workload(templater, tmpl_bench_jinja.COUNT)
        cpu = time.process_time() - start
        return measure.Sample(cpu, cpu, 0.0)

    ctx.say("templates: %d runs each" % config.REPEATS)
    result = measure.pair(config.REPEATS, ours, anchor)
    return [table.Row(GROUP, WHAT, table.seconds(result.median("ours", "cpu")),
                      "python3-jinja2 %s" % jinja2.__version__,
                      table.seconds(result.median("anchor", "cpu")), result.ratio("cpu"),
                      "bench_tmpl `%s` vs bench/tmpl_bench_jinja.py; median of %d runs"
                      % (BENCHMARK, config.REPEATS))]


def smachac_sample(ctx):
    """One run of bench_tmpl for the workload: a Sample of its CPU seconds per workload."""
    sample = measure.run([ctx.bench_tmpl, "--benchmark_filter=^%s$" % BENCHMARK,
                          "--benchmark_format=json"], keep_stdout=True)
    bench = next(b for b in json.loads(sample.stdout)["benchmarks"] if b["name"] == BENCHMARK)
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[bench["time_unit"]]
    cpu = bench["cpu_time"] * scale
    return measure.Sample(bench["real_time"] * scale, cpu, sample.rss_mb)
