// SPDX-License-Identifier: MIT
// SIGINT / SIGTERM as a request to stop cleanly (issue 11 item 14): the handler only records the
// signal; the engines poll interruptRequested() between steps or events and the run loop ends
// at a consistent state (checkpoint, series row, summary.json, exit 128 + signal). A second
// signal while the first is pending restores the default action and re-raises it: abort at once.
#pragma once

namespace granulab {

/// Installs the SIGINT and SIGTERM handlers (sigaction, SA_RESTART). Call once, before the run
/// loop; commands that never poll leave the default action (stop at once) in place.
void installInterruptHandlers() noexcept;

/// True once SIGINT or SIGTERM has arrived after installInterruptHandlers(). Async-signal-safe
/// read of one volatile sig_atomic_t: cheap enough for once per step (dem) or per batch of
/// events (edmd).
bool interruptRequested() noexcept;

/// The signal that requested the stop (SIGINT, SIGTERM), 0 when none.
int interruptSignal() noexcept;

/// "SIGINT", "SIGTERM" or "a signal".
const char* signalName(int signal) noexcept;

}  // namespace granulab
