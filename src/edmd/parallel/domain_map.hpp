// SPDX-License-Identifier: MIT
// Map from Morton cell numbers to ranks for the parallel event-driven engine (edmd spec sections
// 3.1 and 3.2): every rank owns one aligned block of 2^n consecutive Morton numbers (a box of
// cells, morton.hpp), n per rank; the blocks are the leaves of a binary tree over the Morton bits,
// so any number of ranks is possible. Dynamic load balancing uses the spec's elementary
// three-rank move: two lightly loaded ranks whose blocks are Morton siblings merge them into
// their parent block, and the freed rank takes the second half of a heavily loaded rank's block.
// Everything here is deterministic: every rank computes the same map from the same input.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace granulab::edmd {

/// One rank's block of Morton numbers [start, start + 2^log2Size); aligned: start % 2^log2Size == 0.
struct DomainBlock {
    std::uint64_t start = 0;
    int log2Size = 0;
    int rank = 0;
    friend bool operator==(const DomainBlock&, const DomainBlock&) = default;
};

/// One of the spec's three-rank moves (edmd 3.2): siblings `freed` and `keeper` merge into their
/// parent block (owned by keeper); `freed` takes the second half of `heavy`'s block, `heavy` keeps
/// the first half.
struct BalanceMove {
    int heavy = -1, keeper = -1, freed = -1;
    friend bool operator==(const BalanceMove&, const BalanceMove&) = default;
};

class DomainMap {
public:
    /// P = ranks over 2^totalBits cells: starting from the whole range, repeatedly halve a block
    /// until there are P blocks; rank r gets the r-th block in Morton order. The block halved is
    /// the one with the largest weight (ties: the lower start) among, in order of preference,
    /// (1) blocks whose two halves both have weight > 0, (2) blocks with weight > 0, (3) any
    /// block of size > 1; so no block ends with weight 0 while that can be avoided by this rule.
    /// weight(start, log2Size) is typically MortonGrid::realCellsIn (weight of an aligned block,
    /// >= 0). Throws std::invalid_argument when ranks < 1, totalBits is not in [0, 62] or
    /// ranks > 2^totalBits.
    static DomainMap initial(int ranks, int totalBits,
                             const std::function<double(std::uint64_t, int)>& weight);

    /// From explicit blocks, in any order (validated: log2Size in [0, totalBits], aligned,
    /// disjoint, covering [0, 2^totalBits), exactly one per rank 0..P-1; throws
    /// std::invalid_argument otherwise).
    DomainMap(int totalBits, std::vector<DomainBlock> blocks);

    int ranks() const noexcept { return static_cast<int>(m_blocks.size()); }
    int totalBits() const noexcept { return m_totalBits; }
    /// Rank owning Morton number morton < 2^totalBits. O(log P): binary search on the starts.
    int owner(std::uint64_t morton) const noexcept;
    /// Block of rank 0 <= rank < ranks().
    const DomainBlock& blockOf(int rank) const noexcept { return m_blocks[m_indexOfRank[rank]]; }
    /// All blocks, sorted by start.
    const std::vector<DomainBlock>& blocks() const noexcept { return m_blocks; }

    /// The spec's dynamic load balancing at a synchronisation point (edmd 3.2). halfLoads[r] =
    /// the measured load (e.g. collisions per second [1/s]) of the first and the second half of
    /// rank r's block (the second is ignored for a block of one cell). Moves are planned
    /// greedily, repeatedly:
    ///  * H = the heaviest rank (largest total load; ties: lower rank) not yet moved in this call
    ///    whose block can be split (more than one cell);
    ///  * among the sibling pairs (two ranks whose blocks are the two halves of one aligned
    ///    parent block), neither being H nor already moved in this call, the pair with the
    ///    smallest combined load (ties: the lower start);
    ///  * the move is planned when the largest of the three new loads (estimated: merged = sum
    ///    of both, H = its first half, freed = H's second half) is below `threshold` times H's
    ///    load; otherwise planning stops. The loads are updated after each planned move.
    /// The planned moves are made only if the largest load after all of them (other ranks
    /// unchanged) is below `threshold` times the largest load before; so for a single move this
    /// is "the largest load after it is below threshold times the largest before", and several
    /// equally heavy ranks (which no single move can relieve) are split in one call.
    /// The sibling with the larger load keeps the merged block (fewer particles move); on equal
    /// loads the one with the higher start. Moves involve disjoint ranks. Returns the moves made
    /// in order (empty: map unchanged). Deterministic: every rank computes the same result from
    /// the same input. Throws std::invalid_argument (map unchanged) if halfLoads.size() !=
    /// ranks(), a load is negative or not finite, or threshold is not > 0 and finite.
    std::vector<BalanceMove> rebalance(std::span<const std::array<double, 2>> halfLoads, double threshold);

    /// Serialisation for checkpoints: totalBits, then per block (sorted by start) start,
    /// log2Size, rank, as plain numbers (1 + 3 P values).
    std::vector<std::uint64_t> encode() const;
    /// Inverse of encode(); validated like the constructor (throws std::invalid_argument).
    static DomainMap decode(std::span<const std::uint64_t> data);

private:
    void index();

    int m_totalBits = 0;
    std::vector<DomainBlock> m_blocks;  ///< sorted by start
    std::vector<int> m_indexOfRank;     ///< rank -> position in m_blocks
};

}  // namespace granulab::edmd
