// SPDX-License-Identifier: MIT
// The MPI implementation of core's Communicator (OpenMPI; built when CMake finds MPI, option
// GRANULAB_MPI) and the RAII environment that initialises MPI and installs it as the world
// communicator. Only the app (main) and the MPI tests include this layer; engines see
// core/communicator.hpp only.
// Errors: MPI's default handler MPI_ERRORS_ARE_FATAL stays on (a failing call ends the job); a
// message of more than 2^31 - 1 bytes (MPI's int counts) ends the job with MPI_Abort too.
#pragma once
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/communicator.hpp"

namespace granulab::mpi {

/// A Communicator over a duplicate of MPI_COMM_WORLD (its messages never match another
/// library's). Sends are non-blocking (MPI_Isend): the buffers and requests are kept until the
/// sends complete; completed ones are released on every call, flushSends() waits for all.
/// Receives probe for the size first (MPI_Probe, MPI_Get_count), then MPI_Recv of MPI_BYTE.
/// Thread use: MPI_THREAD_FUNNELED, so only the thread that initialised MPI calls it.
class MpiCommunicator final : public Communicator {
public:
    /// Needs MPI initialised (MpiEnvironment does it).
    MpiCommunicator();
    /// Completes the pending sends (a send that no rank ever receives may block here, as it would
    /// in MPI_Finalize) and frees the duplicated communicator; does nothing after MPI_Finalize.
    ~MpiCommunicator() override;
    MpiCommunicator(const MpiCommunicator&) = delete;
    MpiCommunicator& operator=(const MpiCommunicator&) = delete;

    int rank() const noexcept override { return m_rank; }
    int size() const noexcept override { return m_size; }

    void send(int destination, int tag, ByteBuffer data) override;
    ByteBuffer receive(int source, int tag) override;
    bool probe(int source, int tag) override;
    void flushSends() override;

    void barrier() override;
    void allMin(std::span<double> values) override;
    void allMax(std::span<double> values) override;
    void allSum(std::span<double> values) override;
    void allSum(std::span<std::uint64_t> values) override;
    std::vector<double> allGather(std::span<const double> mine) override;
    std::vector<ByteBuffer> gather(ByteBuffer mine) override;
    ByteBuffer broadcast(ByteBuffer data) override;
    std::vector<ByteBuffer> allToAll(std::vector<ByteBuffer> outgoing) override;

    void startMin(std::span<const double> values) override;
    std::vector<double> waitMin() override;

    [[noreturn]] void abort(int status) override;

    /// Sends started and not yet known to be complete (for tests and diagnostics).
    std::size_t pendingSends() const noexcept { return m_sendRequests.size(); }
    MPI_Comm handle() const noexcept { return m_comm; }

private:
    /// Releases the buffers of the sends that have completed (MPI_Testsome; also drives MPI's
    /// progress). Cheap when nothing is pending.
    void releaseCompletedSends();
    void reduceInPlace(void* values, std::size_t count, MPI_Datatype type, MPI_Op op);
    /// `n` as an MPI count, or the job ends (MPI_Abort) when it exceeds INT_MAX.
    int mpiCount(std::size_t n, const char* what);

    MPI_Comm m_comm = MPI_COMM_NULL;
    int m_rank = 0;
    int m_size = 1;
    // Parallel arrays: request i sends buffer i (contiguous requests for MPI_Testsome/Waitall).
    std::vector<MPI_Request> m_sendRequests;
    std::vector<ByteBuffer> m_sendBuffers;
    std::vector<int> m_completed;  // scratch of releaseCompletedSends
    // The overlapped minimum of startMin/waitMin.
    std::vector<double> m_minValues;
    MPI_Request m_minRequest = MPI_REQUEST_NULL;
    bool m_minInFlight = false;
};

/// MPI for the lifetime of the object: MPI_Init_thread(MPI_THREAD_FUNNELED) (unless MPI is
/// already initialised) and an MpiCommunicator installed as the world communicator; the
/// destructor installs a SingleProcessCommunicator again and calls MPI_Finalize (when MPI is
/// initialised and not yet finalised). One per process, in main's scope.
class MpiEnvironment {
public:
    /// True when an MPI launcher started this process: Open MPI's mpirun (OMPI_COMM_WORLD_SIZE),
    /// a PMI launcher such as MPICH's hydra (PMI_SIZE) or a PMIx one such as srun (PMIX_RANK).
    static bool launchedByMpirun();

    MpiEnvironment(int& argc, char**& argv);
    ~MpiEnvironment();
    MpiEnvironment(const MpiEnvironment&) = delete;
    MpiEnvironment& operator=(const MpiEnvironment&) = delete;
};

}  // namespace granulab::mpi
