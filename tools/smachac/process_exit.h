// How smachac's process ends once its command has run. Rule: every stream is flushed before
// the process goes; files the command wrote are already closed (output.h).
#pragma once

namespace smachac::driver {

/// For a command whose process ends as soon as its output is written: the template engines it
/// makes leave their memory to the end of the process (tmpl::Environment::leaveToProcessExit)
/// instead of freeing it piece by piece. Nothing in sanitizer builds (leak checks).
void leaveMemoryToProcessExit();

/// Flushes every stream and ends the process with `code` at once, leaving what is still
/// allocated (thread-local pools, static tables, iostreams) to the operating system instead
/// of running the exit handlers. Sanitizer builds (SMACHAC_SANITIZED) return `code` for an
/// ordinary exit, so that leak checks still run.
int finishProcess(int code);

}  // namespace smachac::driver
