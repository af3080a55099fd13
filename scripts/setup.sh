#!/usr/bin/env bash
# Installs the Debian packages granulab needs (only when some are missing; apt-get update once),
# then configures and builds into build/ (Release). Idempotent and quiet when all is present.
# python3-matplotlib and python3-numpy are for scripts/plot_series.py and plot_analysis.py; openfoam
# (the CFD program) for examples/levitation and examples/channel and their integration test.
# libopenmpi-dev and openmpi-bin (mpirun) for the mpi layer and its tests (MpiCommunicator.np2/np3);
# without them the build is serial (CMake option GRANULAB_MPI).
# Environment: GRANULAB_WERROR=1 treats warnings as errors (CI); BUILD_DIR overrides build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config git libgtest-dev libgmock-dev libbenchmark-dev
          libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev libcairo2-dev libvtk9-dev zlib1g-dev clang-format
          python3-matplotlib python3-numpy openfoam libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

build_dir="${BUILD_DIR:-build}"
werror=OFF
if [ "${GRANULAB_WERROR:-0}" = "1" ]; then werror=ON; fi
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRANULAB_WERROR="$werror" >/dev/null
cmake --build "$build_dir" -- --quiet
