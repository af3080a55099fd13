// SPDX-License-Identifier: MIT
// Lazy loading and time selection of flow fields (fluid/field_series.hpp; cfddem Eq. 4.2).
#include "fluid/field_series.hpp"

#include <algorithm>
#include <stdexcept>

namespace granulab::fluid {

FieldSeries::FieldSeries(FieldSource source) : m_source(std::move(source)) {
    if (!m_source.load) {
        m_a = std::make_unique<FieldInterpolator>(m_source.uniformVelocity);
        m_index = 0;
    }
}

std::size_t FieldSeries::indexAt(Real t) const noexcept {
    const auto& ts = m_source.times;
    if (ts.empty()) return 0;
    // The last k whose time has come (t > t_k for the seed's rule, t >= t_k otherwise); 0 before.
    const auto it = m_source.afterTime ? std::lower_bound(ts.begin(), ts.end(), t)
                                       : std::upper_bound(ts.begin(), ts.end(), t);
    const std::size_t passed = static_cast<std::size_t>(it - ts.begin());
    return passed == 0 ? 0 : passed - 1;
}

std::unique_ptr<FieldInterpolator> FieldSeries::loadField(std::size_t k) {
    FlowField f = m_source.load(k);
    ++m_loads;
    const std::string name = f.source;
    try {
        return std::make_unique<FieldInterpolator>(std::move(f), m_source.options);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
}

void FieldSeries::update(Real t) {
    if (!m_source.load) return;
    const std::size_t k = indexAt(t);
    if (k != m_index) {
        if (k == m_indexB && m_b) {  // moving on by one field: the next one is already loaded
            m_a = std::move(m_b);
            m_indexB = static_cast<std::size_t>(-1);
        } else {
            m_a = loadField(k);
        }
        m_index = k;
        ++m_generation;
    }
    m_weight = 0;
    const auto& ts = m_source.times;
    if (!m_source.interpolateInTime || k + 1 >= ts.size() || t <= ts[k]) return;
    if (m_indexB != k + 1) {
        m_b = loadField(k + 1);
        m_indexB = k + 1;
    }
    m_weight = std::clamp((t - ts[k]) / (ts[k + 1] - ts[k]), Real{0}, Real{1});
}

FluidSample FieldSeries::sample(Vec2 pos) const noexcept {
    FluidSample s = m_a->sample(pos);
    if (const FieldInterpolator* b = second()) {
        const FluidSample s2 = b->sample(pos);
        s.u = s.u * (1 - m_weight) + s2.u * m_weight;
        s.p = s.p * (1 - m_weight) + s2.p * m_weight;
        s.inside = s.inside && s2.inside;
    }
    return s;
}

Vec2 FieldSeries::pressureGradient(Vec2 pos) const noexcept {
    Vec2 g = m_a->pressureGradient(pos);
    if (const FieldInterpolator* b = second()) g = g * (1 - m_weight) + b->pressureGradient(pos) * m_weight;
    return g;
}

std::size_t FieldSeries::memoryBytes() const noexcept {
    return (m_a ? m_a->memoryBytes() : 0) + (m_b ? m_b->memoryBytes() : 0);
}

}  // namespace granulab::fluid
