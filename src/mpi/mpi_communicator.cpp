// SPDX-License-Identifier: MIT
// MpiCommunicator and MpiEnvironment (mpi_communicator.hpp).
#include "mpi/mpi_communicator.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace granulab::mpi {

MpiCommunicator::MpiCommunicator() {
    // A duplicate: our tags never match messages of another library that uses MPI_COMM_WORLD.
    // It inherits MPI_COMM_WORLD's error handler, MPI_ERRORS_ARE_FATAL.
    MPI_Comm_dup(MPI_COMM_WORLD, &m_comm);
    MPI_Comm_rank(m_comm, &m_rank);
    MPI_Comm_size(m_comm, &m_size);
}

MpiCommunicator::~MpiCommunicator() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (finalized) return;
    // A nonblocking collective may not be freed, only completed.
    if (m_minInFlight) MPI_Wait(&m_minRequest, MPI_STATUS_IGNORE);
    flushSends();
    if (m_comm != MPI_COMM_NULL) MPI_Comm_free(&m_comm);
}

int MpiCommunicator::mpiCount(std::size_t n, const char* what) {
    if (n > static_cast<std::size_t>(INT_MAX)) {
        std::cerr << "granulab: rank " << m_rank << ": " << what << " of " << n
                  << " bytes or values exceeds MPI's count limit of 2^31 - 1\n";
        abort(1);
    }
    return static_cast<int>(n);
}

void MpiCommunicator::releaseCompletedSends() {
    if (m_sendRequests.empty()) return;
    m_completed.resize(m_sendRequests.size());
    int completed = 0;
    MPI_Testsome(static_cast<int>(m_sendRequests.size()), m_sendRequests.data(), &completed,
                 m_completed.data(), MPI_STATUSES_IGNORE);
    if (completed == MPI_UNDEFINED || completed == 0) return;
    // MPI_Testsome sets the completed requests to MPI_REQUEST_NULL: keep the others, in order.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < m_sendRequests.size(); ++i) {
        if (m_sendRequests[i] == MPI_REQUEST_NULL) continue;
        if (kept != i) {
            m_sendRequests[kept] = m_sendRequests[i];
            m_sendBuffers[kept] = std::move(m_sendBuffers[i]);  // moves the pointer, not the bytes
        }
        ++kept;
    }
    m_sendRequests.resize(kept);
    m_sendBuffers.resize(kept);
}

void MpiCommunicator::send(int destination, int tag, ByteBuffer data) {
    releaseCompletedSends();
    const int n = mpiCount(data.size(), "a message");
    // Store first, then start the send from the stored buffer: a later move of the vector keeps
    // its heap block, so the address MPI reads from stays valid until the send completes.
    m_sendBuffers.push_back(std::move(data));
    try {
        m_sendRequests.push_back(MPI_REQUEST_NULL);
    } catch (...) {
        m_sendBuffers.pop_back();
        throw;
    }
    MPI_Isend(m_sendBuffers.back().data(), n, MPI_BYTE, destination, tag, m_comm, &m_sendRequests.back());
}

ByteBuffer MpiCommunicator::receive(int source, int tag) {
    releaseCompletedSends();
    MPI_Status status;
    MPI_Probe(source, tag, m_comm, &status);
    int n = 0;
    MPI_Get_count(&status, MPI_BYTE, &n);
    ByteBuffer data(static_cast<std::size_t>(n));
    // One thread and the probed message's own source and tag: this receives the message just
    // probed (also if a caller passed MPI_ANY_SOURCE or MPI_ANY_TAG).
    MPI_Recv(data.data(), n, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, m_comm, MPI_STATUS_IGNORE);
    return data;
}

bool MpiCommunicator::probe(int source, int tag) {
    releaseCompletedSends();
    int flag = 0;
    MPI_Iprobe(source, tag, m_comm, &flag, MPI_STATUS_IGNORE);
    return flag != 0;
}

void MpiCommunicator::flushSends() {
    if (m_sendRequests.empty()) return;
    MPI_Waitall(static_cast<int>(m_sendRequests.size()), m_sendRequests.data(), MPI_STATUSES_IGNORE);
    m_sendRequests.clear();
    m_sendBuffers.clear();
}

void MpiCommunicator::barrier() {
    releaseCompletedSends();
    MPI_Barrier(m_comm);
}

void MpiCommunicator::reduceInPlace(void* values, std::size_t n, MPI_Datatype type, MPI_Op op) {
    releaseCompletedSends();
    MPI_Allreduce(MPI_IN_PLACE, values, mpiCount(n, "a reduction"), type, op, m_comm);
}

void MpiCommunicator::allMin(std::span<double> values) {
    reduceInPlace(values.data(), values.size(), MPI_DOUBLE, MPI_MIN);
}
void MpiCommunicator::allMax(std::span<double> values) {
    reduceInPlace(values.data(), values.size(), MPI_DOUBLE, MPI_MAX);
}
void MpiCommunicator::allSum(std::span<double> values) {
    reduceInPlace(values.data(), values.size(), MPI_DOUBLE, MPI_SUM);
}
void MpiCommunicator::allSum(std::span<std::uint64_t> values) {
    reduceInPlace(values.data(), values.size(), MPI_UINT64_T, MPI_SUM);
}

std::vector<double> MpiCommunicator::allGather(std::span<const double> mine) {
    releaseCompletedSends();
    const int n = mpiCount(mine.size(), "allGather");
    std::vector<double> all(mine.size() * static_cast<std::size_t>(m_size));
    mpiCount(all.size(), "allGather (all ranks)");
    MPI_Allgather(mine.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, m_comm);
    return all;
}

std::vector<ByteBuffer> MpiCommunicator::gather(ByteBuffer mine) {
    releaseCompletedSends();
    const bool isRoot = m_rank == 0;
    const int mySize = mpiCount(mine.size(), "gather");
    std::vector<int> sizes(isRoot ? static_cast<std::size_t>(m_size) : 0);
    MPI_Gather(&mySize, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, m_comm);

    std::vector<int> offsets(sizes.size());
    std::size_t total = 0;
    for (std::size_t r = 0; r < sizes.size(); ++r) {
        offsets[r] = mpiCount(total, "gather (offset)");
        total += static_cast<std::size_t>(sizes[r]);
    }
    ByteBuffer all(total);
    MPI_Gatherv(mine.data(), mySize, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0, m_comm);

    std::vector<ByteBuffer> result;
    if (!isRoot) return result;
    result.reserve(sizes.size());
    for (std::size_t r = 0; r < sizes.size(); ++r) {
        const auto first = all.begin() + offsets[r];
        result.emplace_back(first, first + sizes[r]);
    }
    return result;
}

ByteBuffer MpiCommunicator::broadcast(ByteBuffer data) {
    releaseCompletedSends();
    std::uint64_t n = m_rank == 0 ? data.size() : 0;
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, m_comm);
    if (m_rank != 0) {
        data.clear();
        data.resize(static_cast<std::size_t>(n));
    }
    MPI_Bcast(data.data(), mpiCount(static_cast<std::size_t>(n), "broadcast"), MPI_BYTE, 0, m_comm);
    return data;
}

std::vector<ByteBuffer> MpiCommunicator::allToAll(std::vector<ByteBuffer> outgoing) {
    if (outgoing.size() != static_cast<std::size_t>(m_size)) {
        throw std::invalid_argument("MpiCommunicator::allToAll: " + std::to_string(outgoing.size()) +
                                    " outgoing buffers for " + std::to_string(m_size) + " ranks");
    }
    releaseCompletedSends();
    const auto ranks = static_cast<std::size_t>(m_size);
    std::vector<int> sendCounts(ranks), sendOffsets(ranks), recvCounts(ranks), recvOffsets(ranks);
    std::size_t sendTotal = 0;
    for (std::size_t r = 0; r < ranks; ++r) {
        sendCounts[r] = mpiCount(outgoing[r].size(), "allToAll");
        sendOffsets[r] = mpiCount(sendTotal, "allToAll (offset)");
        sendTotal += outgoing[r].size();
    }
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, m_comm);
    std::size_t recvTotal = 0;
    for (std::size_t r = 0; r < ranks; ++r) {
        recvOffsets[r] = mpiCount(recvTotal, "allToAll (offset)");
        recvTotal += static_cast<std::size_t>(recvCounts[r]);
    }

    ByteBuffer packed(sendTotal);
    for (std::size_t r = 0; r < ranks; ++r) {
        std::copy(outgoing[r].begin(), outgoing[r].end(), packed.begin() + sendOffsets[r]);
        ByteBuffer().swap(outgoing[r]);  // release as we go: peak memory about twice the payload
    }
    ByteBuffer received(recvTotal);
    MPI_Alltoallv(packed.data(), sendCounts.data(), sendOffsets.data(), MPI_BYTE, received.data(),
                  recvCounts.data(), recvOffsets.data(), MPI_BYTE, m_comm);

    std::vector<ByteBuffer> incoming;
    incoming.reserve(ranks);
    for (std::size_t r = 0; r < ranks; ++r) {
        const auto first = received.begin() + recvOffsets[r];
        incoming.emplace_back(first, first + recvCounts[r]);
    }
    return incoming;
}

void MpiCommunicator::startMin(std::span<const double> values) {
    if (m_minInFlight)
        throw std::logic_error("MpiCommunicator::startMin: the previous startMin was not waited for");
    releaseCompletedSends();
    m_minValues.assign(values.begin(), values.end());
    MPI_Iallreduce(MPI_IN_PLACE, m_minValues.data(), mpiCount(m_minValues.size(), "startMin"), MPI_DOUBLE,
                   MPI_MIN, m_comm, &m_minRequest);
    m_minInFlight = true;
}

std::vector<double> MpiCommunicator::waitMin() {
    if (!m_minInFlight) throw std::logic_error("MpiCommunicator::waitMin: no startMin in flight");
    MPI_Wait(&m_minRequest, MPI_STATUS_IGNORE);
    m_minInFlight = false;
    std::vector<double> minima = std::move(m_minValues);
    m_minValues.clear();
    return minima;
}

void MpiCommunicator::abort(int status) {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status);  // MPI_Abort does not return; this keeps [[noreturn]] true if it did
}

bool MpiEnvironment::launchedByMpirun() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(name) != nullptr) return true;
    }
    return false;
}

MpiEnvironment::MpiEnvironment(int& argc, char**& argv) {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
        // FUNNELED: the process may have threads (parallelFor), only the main thread calls MPI.
        int provided = 0;
        MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    }
    setWorldCommunicator(std::make_unique<MpiCommunicator>());
}

MpiEnvironment::~MpiEnvironment() {
    setWorldCommunicator(nullptr);  // destroys the MpiCommunicator while MPI is still up
    int initialized = 0;
    int finalized = 0;
    MPI_Initialized(&initialized);
    MPI_Finalized(&finalized);
    if (initialized && !finalized) MPI_Finalize();
}

}  // namespace granulab::mpi
