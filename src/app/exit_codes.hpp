// SPDX-License-Identifier: MIT
// Exit statuses of the command line (README "Command line").
#pragma once

namespace granulab::app {

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitUnstable = 3 };

/// A run stopped cleanly by a signal exits as a shell reports a process that the signal ended:
/// 128 + signal number (130 for SIGINT, 143 for SIGTERM).
constexpr int exitStatusOfSignal(int signal) noexcept {
    return 128 + signal;
}

}  // namespace granulab::app
