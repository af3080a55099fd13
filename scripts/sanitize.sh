#!/usr/bin/env bash
# Sanitizer job (issue 11; run by .ci/run after the test suite): AddressSanitizer +
# UndefinedBehaviorSanitizer build in build-asan/ (Debug, so GL_ASSERT is on; -O1 -g from
# GRANULAB_SANITIZE), then the unit tests, the fuzz corpus and the fuzz smoke run under the
# sanitizers: ctest -L 'unit|fuzz' -LE slow, and the MPI tests on 2 and 3 ranks where MPI was
# found. The physics and cli tests are left out: they run
# whole simulations and would not fit the CI budget at sanitizer speed (docs/architecture.md
# "Tests"). Any sanitizer report fails its test.
# Environment: GRANULAB_WERROR=1 treats warnings as errors (CI); ASAN_BUILD_DIR overrides build-asan/.
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir="${ASAN_BUILD_DIR:-build-asan}"
werror=OFF
if [ "${GRANULAB_WERROR:-0}" = "1" ]; then werror=ON; fi
# detect_leaks: LeakSanitizer runs at exit and stops with "LeakSanitizer does not work under
# ptrace" where the process is traced (strace, gdb, some container sandboxes); set
# ASAN_OPTIONS=detect_leaks=0 there. abort_on_error=0: a report ends the process with exit 1
# (the fuzz harness saves the input from the sanitizer's death callback).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}:halt_on_error=1:abort_on_error=0:strict_string_checks=1"
# UBSan reports go to stderr with a stack; the fuzz harness cannot save the input of a UBSan
# error (the runtime restores the default SIGABRT action): rerun the mutant from its seed.
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

t0=$(date +%s)
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DGRANULAB_SANITIZE=ON -DGRANULAB_BUILD_BENCH=OFF \
      -DGRANULAB_WERROR="$werror" >/dev/null
cmake --build "$build_dir" --target granulab granulab_tests granulab_fuzz -- --quiet
t1=$(date +%s)
status=0
ctest --test-dir "$build_dir" --output-on-failure -j2 -L '^(unit|fuzz)$' -LE slow || status=$?
# The MPI tests (granulab_mpi_tests under mpirun on 2 and 3 ranks), where CMake found MPI: the
# parallel engine's domain mode (halo, migrations, slot reuse, rollback copies) runs only there.
# Leak detection off for them: Open MPI's MPI_Init never frees ~120 kB.
if cmake --build "$build_dir" --target help | grep -q '^granulab_mpi_tests:'; then
    cmake --build "$build_dir" --target granulab_mpi_tests -- --quiet
    ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
        ctest --test-dir "$build_dir" --output-on-failure -R '^MpiCommunicator\.np[23]$' || status=$?
fi
t2=$(date +%s)
echo "sanitize: build $((t1 - t0)) s, tests $((t2 - t1)) s (ASan + UBSan, $build_dir)"
exit "$status"
