#pragma once
/// @file Interrupt.hpp
/// Ctrl-C (SIGINT) and SIGTERM as a request to stop cleanly: a long dynamic run ends at the next step,
/// like a run that fails midway, and the caller writes every result computed so far (clash report
/// included) instead of losing them to the default signal action.

namespace tangle::core {

/// Installs the handler for SIGINT and SIGTERM (the CLI calls it once). A second Ctrl-C while a stop is
/// pending restores the default action, so an impatient user can still kill the program.
void installInterruptHandler();

/// True once SIGINT or SIGTERM has arrived (async-signal-safe flag).
bool interruptRequested();

}  // namespace tangle::core
