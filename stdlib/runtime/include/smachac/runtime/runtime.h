// The whole runtime in one include, for generated programs: `namespace rt = smachac::runtime;`.
#pragma once

#include "smachac/runtime/concurrence.h"
#include "smachac/runtime/container.h"
#include "smachac/runtime/core_states.h"
#include "smachac/runtime/errors.h"
#include "smachac/runtime/expression_ops.h"
#include "smachac/runtime/file_states.h"
#include "smachac/runtime/lambda_state.h"
#include "smachac/runtime/run.h"
#include "smachac/runtime/state.h"
#include "smachac/runtime/state_machine.h"
#include "smachac/runtime/thread_observer.h"
#include "smachac/runtime/trace.h"
#include "smachac/runtime/userdata.h"
#include "smachac/runtime/value.h"
