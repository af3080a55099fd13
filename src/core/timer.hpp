// SPDX-License-Identifier: MIT
// Wall-clock timing of pipeline stages (DESIGN.md "each stage timed").
#pragma once
#include <array>
#include <chrono>
#include <string_view>

namespace granulab {

inline double wallSeconds() noexcept {
    using Clock = std::chrono::steady_clock;
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

/// Accumulated seconds per stage; `Stage` is an enum with a `Count` last member.
template <class Stage>
class StageTimers {
public:
    static constexpr std::size_t kCount = static_cast<std::size_t>(Stage::Count);
    void add(Stage s, double seconds) noexcept { m_seconds[static_cast<std::size_t>(s)] += seconds; }
    double seconds(Stage s) const noexcept { return m_seconds[static_cast<std::size_t>(s)]; }
    double total() const noexcept {
        double t = 0;
        for (double s : m_seconds) t += s;
        return t;
    }
    void reset() noexcept { m_seconds.fill(0.0); }

private:
    std::array<double, kCount> m_seconds{};
};

/// Adds the lifetime of the scope to one stage timer.
template <class Stage>
class ScopedStage {
public:
    ScopedStage(StageTimers<Stage>& timers, Stage stage) noexcept
        : m_timers(timers), m_stage(stage), m_start(wallSeconds()) {}
    ~ScopedStage() { m_timers.add(m_stage, wallSeconds() - m_start); }
    ScopedStage(const ScopedStage&) = delete;
    ScopedStage& operator=(const ScopedStage&) = delete;

private:
    StageTimers<Stage>& m_timers;
    Stage m_stage;
    double m_start;
};

}  // namespace granulab
