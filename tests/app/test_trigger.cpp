// SPDX-License-Identifier: MIT
// The run loop's schedules (app/trigger.hpp): periodic points are the running sum a loop adds,
// count schedules stop exactly on their points, a schedule clamped at the end of the run ends
// there, and seeking (on --resume) lands on the first point strictly after the run's position.
#include <gtest/gtest.h>

#include <cmath>

#include "app/trigger.hpp"

using namespace granulab;
using app::Schedule;
using app::Trigger;

TEST(Trigger, PeriodicTimePointsAreTheRunningSum) {
    Trigger t(Schedule::periodic(Schedule::Unit::Time, 0.1));
    t.seek(0, 0);
    double sum = 0;
    for (int k = 0; k < 25; ++k) {
        sum += 0.1;
        EXPECT_EQ(t.next(), sum);  // bit for bit the sum, not k * 0.1
        app::Stop stop;
        t.limit(stop);
        EXPECT_EQ(stop.time, sum);
        t.pass(sum, 0);
    }
    t.seek(1.05, 0);  // resume between points
    double expected = 0;
    while (expected <= 1.05) expected += 0.1;
    EXPECT_EQ(t.next(), expected);
}

TEST(Trigger, CountSchedulesStopOnTheirPointsAndClampedSchedulesEnd) {
    Trigger steps(Schedule::periodic(Schedule::Unit::Count, 40));
    steps.seek(0, 100);  // resumed at step 100
    EXPECT_EQ(steps.next(), 120);
    app::Stop stop;
    steps.limit(stop);
    EXPECT_EQ(stop.count, 120u);
    EXPECT_TRUE(std::isinf(stop.time));
    // Rows clamped to the end of the run (t = 1): the schedule ends after its last point.
    Trigger rows({Schedule::Unit::Time, true,
                  [](std::int64_t k) { return std::min(0.3 * static_cast<double>(k), 1.0); }, 0});
    rows.seek(0, 0);
    for (const double t : {0.3, 0.6, 0.8999999999999999, 1.0}) {
        EXPECT_DOUBLE_EQ(rows.next(), t);
        rows.pass(rows.next(), 0);
    }
    EXPECT_TRUE(std::isinf(rows.next()));
    // Polled schedules never narrow a stop.
    Trigger polled(Schedule::periodic(Schedule::Unit::Time, 0.5, false));
    polled.seek(0, 0);
    app::Stop open;
    polled.limit(open);
    EXPECT_TRUE(std::isinf(open.time));
    EXPECT_TRUE(polled.reached(0.7, 0));
}
