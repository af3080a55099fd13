// SPDX-License-Identifier: MIT
// core/interrupt: the first SIGINT/SIGTERM only sets the flag the engines poll; a second one
// ends the process at once with the signal's default action (run in a forked death-test child).
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>

#include "core/interrupt.hpp"

using namespace granulab;

TEST(Interrupt, NothingIsRequestedWithoutASignal) {
    EXPECT_FALSE(interruptRequested());
    EXPECT_EQ(interruptSignal(), 0);
    EXPECT_STREQ(signalName(SIGINT), "SIGINT");
    EXPECT_STREQ(signalName(SIGTERM), "SIGTERM");
}

TEST(Interrupt, FirstSignalSetsTheFlagSecondAbortsAtOnce) {
    for (const int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(sig);
        EXPECT_EXIT(
            {
                installInterruptHandlers();
                std::raise(sig);
                if (!interruptRequested() || interruptSignal() != sig) std::_Exit(1);
                std::raise(sig);  // the default action: the process ends here
                std::_Exit(2);
            },
            testing::KilledBySignal(sig), "");
    }
}
