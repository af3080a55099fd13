// SPDX-License-Identifier: MIT
// A trigger walks one Schedule (app/simulation.hpp): its next point in time or count, whether
// the run has reached it, and stepping past it. Re-derived from the scene on --resume.
#pragma once
#include <cstdint>
#include <limits>

#include "app/simulation.hpp"

namespace granulab::app {

class Trigger {
public:
    explicit Trigger(Schedule schedule) : m_schedule(std::move(schedule)) {}

    /// Positions the trigger at its first point strictly after the run's (time, count).
    void seek(double time, std::uint64_t count) {
        m_k = 0;
        m_next = 0;
        step();
        while (reached(time, count)) step();
    }
    bool reached(double time, std::uint64_t count) const { return position(time, count) >= m_next; }
    /// Steps past every point the run has reached.
    void pass(double time, std::uint64_t count) {
        while (reached(time, count)) step();
    }
    /// Narrows `stop` to this trigger's next point if the schedule is exact.
    void limit(Stop& stop) const {
        if (!m_schedule.exact || !(m_next < std::numeric_limits<double>::infinity())) return;
        if (m_schedule.unit == Schedule::Unit::Time) {
            if (m_next < stop.time) stop.time = m_next;
        } else {
            const auto c = static_cast<std::uint64_t>(m_next);
            if (c < stop.count) stop.count = c;
        }
    }
    double next() const { return m_next; }

private:
    double position(double time, std::uint64_t count) const {
        return m_schedule.unit == Schedule::Unit::Time ? time : static_cast<double>(count);
    }
    /// The next point; a point not later than the previous one ends the schedule (rows clamped
    /// to the end of the run, an `every` too small to advance the sum).
    void step() {
        ++m_k;
        const double previous = m_next;
        if (m_schedule.point)
            m_next = m_schedule.point(m_k);
        else
            m_next =
                m_schedule.every > 0 ? m_next + m_schedule.every : std::numeric_limits<double>::infinity();
        if (m_k > 1 && !(m_next > previous)) m_next = std::numeric_limits<double>::infinity();
    }

    Schedule m_schedule;
    std::int64_t m_k = 0;
    double m_next = 0;
};

}  // namespace granulab::app
