// SPDX-License-Identifier: MIT
// The one interface through which the parallel engines talk to other processes (DESIGN.md:
// "MPI and threads each behind one interface"; edmd spec section 3.6: non-blocking messages,
// global reductions at synchronisation points). Engines see only this class; the MPI
// implementation lives in the `mpi` layer (src/mpi/, built when OpenMPI is found) and is made
// by the app once per process. A serial build, or a run without mpirun, uses
// SingleProcessCommunicator: rank 0 of 1, every collective the identity.
// Virtual calls: a few per communication phase (hundreds of events), never per event.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace granulab {

/// A message payload: plain bytes (the sender packs POD records, the receiver unpacks them).
using ByteBuffer = std::vector<std::byte>;

/// The bytes of plain values (records, keys) for a message.
template <class T>
ByteBuffer packPod(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>, "packPod: plain values only");
    ByteBuffer b(values.size_bytes());
    if (!b.empty()) std::memcpy(b.data(), values.data(), b.size());
    return b;
}

/// Appends the values held in `bytes` from byte `from` on to `out`; throws std::runtime_error
/// when the bytes are not a whole number of values.
template <class T>
void unpackPod(const ByteBuffer& bytes, std::vector<T>& out, std::size_t from = 0) {
    static_assert(std::is_trivially_copyable_v<T>, "unpackPod: plain values only");
    const std::size_t size = bytes.size() - std::min(from, bytes.size());
    if (size % sizeof(T) != 0) throw std::runtime_error("a message that is not a whole number of records");
    const std::size_t at = out.size();
    out.resize(at + size / sizeof(T));
    if (size) std::memcpy(out.data() + at, bytes.data() + from, size);
}

class Communicator {
public:
    virtual ~Communicator() = default;

    virtual int rank() const noexcept = 0;
    virtual int size() const noexcept = 0;
    bool root() const noexcept { return rank() == 0; }

    // ---- point to point (ordered per (source, destination, tag), like MPI) ----
    /// Starts sending `data` to `destination` with `tag` and returns at once (the communicator
    /// keeps the buffer until the send completes). Sending to oneself is allowed.
    virtual void send(int destination, int tag, ByteBuffer data) = 0;
    /// Blocks until a message from `source` with `tag` has arrived and returns its payload.
    virtual ByteBuffer receive(int source, int tag) = 0;
    /// True when a message from `source` with `tag` is waiting (receive() would not block).
    virtual bool probe(int source, int tag) = 0;
    /// Completes every pending send of this process (call before reusing or freeing state that
    /// the receivers may still need; cheap when all have completed).
    virtual void flushSends() = 0;

    // ---- collectives (every rank calls them in the same order) ----
    virtual void barrier() = 0;
    /// Element-wise global minimum / maximum / sum, result on every rank.
    virtual void allMin(std::span<double> values) = 0;
    virtual void allMax(std::span<double> values) = 0;
    virtual void allSum(std::span<double> values) = 0;
    virtual void allSum(std::span<std::uint64_t> values) = 0;
    /// Every rank's `mine` (the same size on every rank), concatenated in rank order, on every rank.
    virtual std::vector<double> allGather(std::span<const double> mine) = 0;
    /// Variable-size gather: on the root, every rank's bytes in rank order (entry r from rank r);
    /// elsewhere an empty vector.
    virtual std::vector<ByteBuffer> gather(ByteBuffer mine) = 0;
    /// The root's `data` on every rank (the argument is ignored elsewhere).
    virtual ByteBuffer broadcast(ByteBuffer data) = 0;
    /// Every rank sends outgoing[r] to rank r (outgoing has size() entries) and receives what
    /// every rank sent to it, in rank order.
    virtual std::vector<ByteBuffer> allToAll(std::vector<ByteBuffer> outgoing) = 0;

    // ---- overlapped reduction of a small vector (one in flight at a time) ----
    /// Starts an element-wise global minimum of `values` (copied); finish with waitMin().
    virtual void startMin(std::span<const double> values) = 0;
    /// Completes the reduction started by startMin and returns the minima.
    virtual std::vector<double> waitMin() = 0;

    /// Ends every process of the run with `status` (after a fatal error on one rank).
    [[noreturn]] virtual void abort(int status) = 0;
};

/// Every rank's `mine` (any size per rank), concatenated in rank order, on every rank: one
/// all-to-all that sends the same bytes to each rank.
template <class T>
std::vector<T> allGatherPod(Communicator& comm, std::span<const T> mine) {
    const ByteBuffer bytes = packPod(mine);
    std::vector<ByteBuffer> out(static_cast<std::size_t>(comm.size()), bytes);
    std::vector<T> all;
    for (const ByteBuffer& b : comm.allToAll(std::move(out))) unpackPod(b, all);
    return all;
}

/// Rank 0 of 1: messages to oneself are queued in order per tag; collectives return their input.
/// receive() of a tag with nothing queued throws std::logic_error (nobody could ever send it);
/// a rank other than 0 in send/receive/probe throws std::logic_error too.
class SingleProcessCommunicator final : public Communicator {
public:
    int rank() const noexcept override { return 0; }
    int size() const noexcept override { return 1; }
    void send(int destination, int tag, ByteBuffer data) override;
    ByteBuffer receive(int source, int tag) override;
    bool probe(int source, int tag) override;
    void flushSends() override {}
    void barrier() override {}
    void allMin(std::span<double>) override {}
    void allMax(std::span<double>) override {}
    void allSum(std::span<double>) override {}
    void allSum(std::span<std::uint64_t>) override {}
    std::vector<double> allGather(std::span<const double> mine) override {
        return {mine.begin(), mine.end()};
    }
    std::vector<ByteBuffer> gather(ByteBuffer mine) override;
    ByteBuffer broadcast(ByteBuffer data) override { return data; }
    std::vector<ByteBuffer> allToAll(std::vector<ByteBuffer> outgoing) override { return outgoing; }
    void startMin(std::span<const double> values) override { m_pending.assign(values.begin(), values.end()); }
    std::vector<double> waitMin() override { return std::move(m_pending); }
    [[noreturn]] void abort(int status) override;

private:
    struct Message {
        int tag;
        ByteBuffer data;
    };
    std::vector<Message> m_queue;
    std::vector<double> m_pending;
};

/// The process's communicator: the one set by setWorldCommunicator (the app does this when it
/// runs under mpirun), else a SingleProcessCommunicator.
Communicator& worldCommunicator();
/// Installs `communicator` (nullptr: a new SingleProcessCommunicator) and destroys the previous
/// one: references obtained from worldCommunicator() before the call dangle after it.
void setWorldCommunicator(std::unique_ptr<Communicator> communicator);

}  // namespace granulab
