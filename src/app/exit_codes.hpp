// SPDX-License-Identifier: MIT
// Exit statuses of the command line (README "Command line").
#pragma once

namespace granulab::app {

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitUnstable = 3 };

}  // namespace granulab::app
