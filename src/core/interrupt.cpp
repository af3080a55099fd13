// SPDX-License-Identifier: MIT
// Interrupt flag and handlers (core/interrupt.hpp). The handler does only async-signal-safe
// work: it stores the signal number, or on a second signal restores the default action and
// re-raises it (the process then ends as the signal dictates, e.g. exit status 130 in a shell).
#include "core/interrupt.hpp"

#include <csignal>

namespace granulab {

namespace {

volatile std::sig_atomic_t g_signal = 0;  ///< the first SIGINT/SIGTERM received, 0 before

void onInterrupt(int sig) {
    if (g_signal != 0) {  // second signal: stop at once
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return;
    }
    g_signal = sig;
}

}  // namespace

void installInterruptHandlers() noexcept {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a write interrupted by the first signal goes on
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

bool interruptRequested() noexcept {
    return g_signal != 0;
}

int interruptSignal() noexcept {
    return static_cast<int>(g_signal);
}

const char* signalName(int signal) noexcept {
    if (signal == SIGINT) return "SIGINT";
    if (signal == SIGTERM) return "SIGTERM";
    return "a signal";
}

}  // namespace granulab
