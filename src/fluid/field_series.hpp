// SPDX-License-Identifier: MIT
// A time series of flow fields (cfddem spec 5.5 "Time series"): which field applies at time t,
// loaded lazily (at most the two neighbouring fields are in memory), optionally blended linearly
// in time. Times are either the seed's rule (n files spread evenly over the run, Eq. 4.2: file k
// applies once t > k t_end / n) or the times the files carry (field k from t >= t_k on). Before the
// first time the first field applies, after the last the last one.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "fluid/field_interpolator.hpp"

namespace granulab::fluid {

/// Where the fields of a run come from (built by the app from io's field files).
struct FieldSource {
    std::vector<Real> times;  ///< [s] ascending: when each field starts to apply
    bool afterTime = false;   ///< the seed's rule: field k applies once t > times[k] (else t >= times[k])
    bool interpolateInTime = false;
    /// Loads field k (may throw std::exception with a message naming the file). Empty: a uniform
    /// field of `uniformVelocity`.
    std::function<FlowField(std::size_t)> load;
    Vec2 uniformVelocity;  ///< [m/s]
    InterpolatorOptions options;
    std::size_t count() const noexcept { return load ? times.size() : 1; }
};

class FieldSeries {
public:
    explicit FieldSeries(FieldSource source);

    /// Makes the field(s) of time t current, loading what is missing; throws what the loader throws
    /// (the interpolator's std::invalid_argument is rethrown as std::runtime_error naming the file).
    void update(Real t);

    /// True once a field is current (after the first update).
    bool ready() const noexcept { return m_a != nullptr; }
    /// The current field (after update).
    const FieldInterpolator& first() const noexcept { return *m_a; }
    /// The next field when blending in time (nullptr otherwise), and its weight in [0, 1].
    const FieldInterpolator* second() const noexcept { return m_weight > 0 ? m_b.get() : nullptr; }
    Real weight() const noexcept { return m_weight; }
    /// Velocity and pressure at pos, blended in time when so configured.
    FluidSample sample(Vec2 pos) const noexcept;
    Vec2 pressureGradient(Vec2 pos) const noexcept;

    std::size_t currentIndex() const noexcept { return m_index; }
    /// Changes whenever the current field (first()) is replaced: caches of its cells are stale then.
    std::uint64_t generation() const noexcept { return m_generation; }
    std::size_t count() const noexcept { return m_source.count(); }
    std::size_t loads() const noexcept { return m_loads; }  ///< files read since construction
    const FieldSource& source() const noexcept { return m_source; }
    std::size_t memoryBytes() const noexcept;

    /// Index of the field that applies at t.
    std::size_t indexAt(Real t) const noexcept;

private:
    std::unique_ptr<FieldInterpolator> loadField(std::size_t k);

    FieldSource m_source;
    std::unique_ptr<FieldInterpolator> m_a, m_b;
    std::size_t m_index = static_cast<std::size_t>(-1);  ///< field held in m_a
    std::size_t m_indexB = static_cast<std::size_t>(-1);
    Real m_weight = 0;
    std::size_t m_loads = 0;
    std::uint64_t m_generation = 0;
};

}  // namespace granulab::fluid
