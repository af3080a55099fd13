// SPDX-License-Identifier: MIT
// Map from Morton cell numbers to ranks and the three-rank load balancing move (edmd spec
// sections 3.1 and 3.2); see domain_map.hpp.
#include "edmd/parallel/domain_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

namespace granulab::edmd {

namespace {

constexpr int kMaxBits = 62;

std::uint64_t sizeOf(int log2Size) noexcept {
    return std::uint64_t{1} << log2Size;
}

void checkTotalBits(int totalBits, const char* where) {
    if (totalBits < 0 || totalBits > kMaxBits)
        throw std::invalid_argument(std::string(where) + ": totalBits " + std::to_string(totalBits) +
                                    " (must be 0 to 62)");
}

}  // namespace

DomainMap DomainMap::initial(int ranks, int totalBits,
                             const std::function<double(std::uint64_t, int)>& weight) {
    checkTotalBits(totalBits, "DomainMap::initial");
    if (ranks < 1) throw std::invalid_argument("DomainMap::initial: " + std::to_string(ranks) + " ranks");
    if (totalBits < 31 && static_cast<std::uint64_t>(ranks) > sizeOf(totalBits))
        throw std::invalid_argument("DomainMap::initial: " + std::to_string(ranks) + " ranks for " +
                                    std::to_string(sizeOf(totalBits)) + " cells");
    auto weightOf = [&](std::uint64_t start, int log2Size) {
        const double w = weight(start, log2Size);
        if (!(w >= 0) || !std::isfinite(w))
            throw std::invalid_argument("DomainMap::initial: weight " + std::to_string(w) + " of block " +
                                        std::to_string(start) + " (must be >= 0)");
        return w;
    };
    // Candidates ordered by (preference class, weight descending, start ascending); the first
    // one is halved next. Class 0: both halves have weight > 0; 1: weight > 0; 2: weight 0.
    // Blocks of one cell are kept aside (they cannot be split).
    using Key = std::tuple<int, double, std::uint64_t, int>;  // class, -weight, start, log2Size
    std::set<Key> splittable;
    std::vector<DomainBlock> done;
    auto add = [&](std::uint64_t start, int log2Size) {
        if (log2Size == 0) {
            done.push_back({start, 0, 0});
            return;
        }
        const double w = weightOf(start, log2Size);
        const double w0 = weightOf(start, log2Size - 1);
        const double w1 = weightOf(start + sizeOf(log2Size - 1), log2Size - 1);
        const int cls = (w0 > 0 && w1 > 0) ? 0 : (w > 0 ? 1 : 2);
        splittable.insert({cls, -w, start, log2Size});
    };
    add(0, totalBits);
    while (static_cast<int>(splittable.size() + done.size()) < ranks) {
        // Not empty: ranks <= 2^totalBits and each split adds one block.
        const auto [cls, negW, start, log2Size] = *splittable.begin();
        splittable.erase(splittable.begin());
        add(start, log2Size - 1);
        add(start + sizeOf(log2Size - 1), log2Size - 1);
    }
    std::vector<DomainBlock> blocks = std::move(done);
    for (const auto& [cls, negW, start, log2Size] : splittable) blocks.push_back({start, log2Size, 0});
    std::sort(blocks.begin(), blocks.end(),
              [](const DomainBlock& a, const DomainBlock& b) { return a.start < b.start; });
    for (int r = 0; r < ranks; ++r) blocks[r].rank = r;
    return DomainMap(totalBits, std::move(blocks));
}

DomainMap::DomainMap(int totalBits, std::vector<DomainBlock> blocks)
    : m_totalBits(totalBits), m_blocks(std::move(blocks)) {
    checkTotalBits(totalBits, "DomainMap");
    if (m_blocks.empty()) throw std::invalid_argument("DomainMap: no blocks");
    if (m_blocks.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::invalid_argument("DomainMap: too many blocks");
    std::sort(m_blocks.begin(), m_blocks.end(),
              [](const DomainBlock& a, const DomainBlock& b) { return a.start < b.start; });
    const int n = static_cast<int>(m_blocks.size());
    std::vector<char> seen(static_cast<std::size_t>(n), 0);
    std::uint64_t next = 0;  // first number not yet covered
    for (const DomainBlock& b : m_blocks) {
        const std::string which = "DomainMap: block of rank " + std::to_string(b.rank) + " at " +
                                  std::to_string(b.start) + " (2^" + std::to_string(b.log2Size) + ")";
        if (b.log2Size < 0 || b.log2Size > totalBits)
            throw std::invalid_argument(which + ": size out of range");
        if (b.start % sizeOf(b.log2Size) != 0) throw std::invalid_argument(which + ": not aligned");
        if (b.start != next)
            throw std::invalid_argument(which + (b.start < next ? ": overlaps" : ": leaves a gap before it"));
        if (b.rank < 0 || b.rank >= n) throw std::invalid_argument(which + ": rank out of range");
        if (seen[b.rank]) throw std::invalid_argument(which + ": rank has two blocks");
        seen[b.rank] = 1;
        next = b.start + sizeOf(b.log2Size);
    }
    if (next != sizeOf(totalBits))
        throw std::invalid_argument("DomainMap: blocks end at " + std::to_string(next) + ", not at " +
                                    std::to_string(sizeOf(totalBits)));
    index();
}

void DomainMap::index() {
    m_indexOfRank.assign(m_blocks.size(), 0);
    for (std::size_t i = 0; i < m_blocks.size(); ++i) m_indexOfRank[m_blocks[i].rank] = static_cast<int>(i);
}

int DomainMap::owner(std::uint64_t morton) const noexcept {
    const auto it = std::upper_bound(m_blocks.begin(), m_blocks.end(), morton,
                                     [](std::uint64_t m, const DomainBlock& b) { return m < b.start; });
    return std::prev(it)->rank;
}

std::vector<BalanceMove> DomainMap::rebalance(std::span<const std::array<double, 2>> halfLoads,
                                              double threshold) {
    const int n = ranks();
    if (static_cast<int>(halfLoads.size()) != n)
        throw std::invalid_argument("DomainMap::rebalance: " + std::to_string(halfLoads.size()) +
                                    " loads for " + std::to_string(n) + " ranks");
    if (!(threshold > 0) || !std::isfinite(threshold))
        throw std::invalid_argument("DomainMap::rebalance: threshold " + std::to_string(threshold));
    std::vector<std::array<double, 2>> half(halfLoads.begin(), halfLoads.end());
    std::vector<double> load(static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r) {
        for (double h : half[r])
            if (!(h >= 0) || !std::isfinite(h))
                throw std::invalid_argument("DomainMap::rebalance: load " + std::to_string(h) + " of rank " +
                                            std::to_string(r));
        // A block of one cell has no second half.
        if (blockOf(r).log2Size == 0) half[r][1] = 0;
        load[r] = half[r][0] + half[r][1];
    }
    const double maxBefore = *std::max_element(load.begin(), load.end());

    // Moves are planned on a copy and committed only if the batch as a whole qualifies.
    std::vector<DomainBlock> blocks = m_blocks;  // sorted by start
    std::vector<int> at = m_indexOfRank;         // rank -> position in blocks
    std::vector<char> moved(static_cast<std::size_t>(n), 0);
    std::vector<BalanceMove> moves;
    for (;;) {
        int heavy = -1;
        for (int r = 0; r < n; ++r)
            if (!moved[r] && blocks[at[r]].log2Size > 0 && (heavy < 0 || load[r] > load[heavy])) heavy = r;
        if (heavy < 0) break;
        // Sibling pairs are neighbours in start order with equal size, the first aligned to the
        // parent size.
        int pair = -1;  // position of the first sibling in blocks
        double pairLoad = 0;
        for (int i = 0; i + 1 < n; ++i) {
            const DomainBlock& a = blocks[i];
            const DomainBlock& b = blocks[i + 1];
            if (a.log2Size != b.log2Size || a.start % sizeOf(a.log2Size + 1) != 0) continue;
            if (a.rank == heavy || b.rank == heavy || moved[a.rank] || moved[b.rank]) continue;
            const double l = load[a.rank] + load[b.rank];
            if (pair < 0 || l < pairLoad) {
                pair = i;
                pairLoad = l;
            }
        }
        if (pair < 0) break;
        // The three ranks involved must all end clearly below the heavy rank's load.
        if (!(std::max({pairLoad, half[heavy][0], half[heavy][1]}) < threshold * load[heavy])) break;

        const int first = blocks[pair].rank;
        const int second = blocks[pair + 1].rank;
        const bool secondKeeps = load[second] >= load[first];
        const int keeper = secondKeeps ? second : first;
        const int freed = secondKeeps ? first : second;
        const std::uint64_t parentStart = blocks[pair].start;
        const int parentLog2 = blocks[pair].log2Size + 1;
        DomainBlock& h = blocks[at[heavy]];
        const int halfLog2 = h.log2Size - 1;
        const std::uint64_t secondHalf = h.start + sizeOf(halfLog2);
        h.log2Size = halfLog2;
        blocks[at[keeper]] = {parentStart, parentLog2, keeper};
        blocks[at[freed]] = {secondHalf, halfLog2, freed};
        std::sort(blocks.begin(), blocks.end(),
                  [](const DomainBlock& a, const DomainBlock& b) { return a.start < b.start; });
        for (int i = 0; i < n; ++i) at[blocks[i].rank] = i;

        // Estimated loads after the move; the three ranks are not considered again in this call.
        load[keeper] = pairLoad;
        load[freed] = half[heavy][1];
        load[heavy] = half[heavy][0];
        moved[heavy] = moved[keeper] = moved[freed] = 1;
        moves.push_back({heavy, keeper, freed});
    }
    if (moves.empty()) return moves;
    const double maxAfter = *std::max_element(load.begin(), load.end());
    if (!(maxAfter < threshold * maxBefore)) return {};
    m_blocks = std::move(blocks);
    m_indexOfRank = std::move(at);
    return moves;
}

std::vector<std::uint64_t> DomainMap::encode() const {
    std::vector<std::uint64_t> out;
    out.reserve(1 + 3 * m_blocks.size());
    out.push_back(static_cast<std::uint64_t>(m_totalBits));
    for (const DomainBlock& b : m_blocks) {
        out.push_back(b.start);
        out.push_back(static_cast<std::uint64_t>(b.log2Size));
        out.push_back(static_cast<std::uint64_t>(b.rank));
    }
    return out;
}

DomainMap DomainMap::decode(std::span<const std::uint64_t> data) {
    if (data.size() < 4 || (data.size() - 1) % 3 != 0)
        throw std::invalid_argument("DomainMap::decode: " + std::to_string(data.size()) +
                                    " values (expected 1 + 3 P)");
    if (data[0] > kMaxBits)
        throw std::invalid_argument("DomainMap::decode: totalBits " + std::to_string(data[0]));
    std::vector<DomainBlock> blocks;
    blocks.reserve((data.size() - 1) / 3);
    for (std::size_t i = 1; i < data.size(); i += 3) {
        if (data[i + 1] > kMaxBits ||
            data[i + 2] > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
            throw std::invalid_argument("DomainMap::decode: block " + std::to_string(i / 3) +
                                        " out of range");
        blocks.push_back({data[i], static_cast<int>(data[i + 1]), static_cast<int>(data[i + 2])});
    }
    return DomainMap(static_cast<int>(data[0]), std::move(blocks));
}

}  // namespace granulab::edmd
