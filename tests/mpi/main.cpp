// SPDX-License-Identifier: MIT
// granulab_mpi_tests: GoogleTest under mpirun (CTest MpiCommunicator.np2 / .np3; tests/CMakeLists.txt).
// MPI is initialised whether or not a launcher started the process (run alone it is rank 0 of 1).
// Only rank 0 prints GoogleTest's report; the other ranks print only their failed assertions,
// prefixed with their rank, and every rank exits with failure when any rank failed.
// `--abort-test=STATUS`: instead of the tests, the last rank calls worldCommunicator().abort(STATUS)
// while the others block in a receive from it (CTest MpiCommunicator.abort: the job must end with
// STATUS instead of hanging).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "core/communicator.hpp"
#include "mpi/mpi_communicator.hpp"

namespace {

/// The report of a rank other than 0: its failed assertions only.
class RankFailurePrinter final : public testing::EmptyTestEventListener {
public:
    explicit RankFailurePrinter(int rank) : m_rank(rank) {}
    // The test's name is kept here: UnitTest::current_test_info() would take the lock that
    // GoogleTest holds while it reports a result (a deadlock in OnTestPartResult).
    void OnTestStart(const testing::TestInfo& test) override {
        m_test = std::string(test.test_suite_name()) + "." + test.name();
    }
    void OnTestPartResult(const testing::TestPartResult& result) override {
        if (!result.failed()) return;
        std::cerr << "[rank " << m_rank << "] " << m_test << ": "
                  << (result.file_name() ? result.file_name() : "?") << ':' << result.line_number() << ": "
                  << result.message() << std::endl;
    }

private:
    int m_rank;
    std::string m_test;
};

[[noreturn]] void abortTest(int status) {
    granulab::Communicator& comm = granulab::worldCommunicator();
    const int last = comm.size() - 1;
    comm.barrier();
    if (comm.rank() == last) {
        std::cout << "rank " << last << " calls abort(" << status << ")\n";  // flushed by abort
        comm.abort(status);
    }
    comm.receive(last, 999);  // never sent: only the abort ends this rank
    std::cerr << "rank " << comm.rank() << ": the receive returned\n";
    std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
    granulab::mpi::MpiEnvironment environment(argc, argv);
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--abort-test=", 13) == 0) abortTest(std::atoi(argv[i] + 13));
    }
    testing::InitGoogleTest(&argc, argv);
    const granulab::Communicator& comm = granulab::worldCommunicator();
    if (!comm.root()) {
        auto& listeners = testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
        listeners.Append(new RankFailurePrinter(comm.rank()));
    }
    int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (failed && comm.root())
        std::printf("granulab_mpi_tests: a test failed on some of the %d ranks\n", comm.size());
    return failed;
}
