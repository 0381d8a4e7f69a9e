#!/usr/bin/env bash
# Installs what is missing (Debian 12 packages), then configures and builds rollnoise in
# build/ (Release with assertions on). Used by tools/demo.sh and tools/test.sh.
#   bash tools/setup.sh [TARGET ...]   only these targets (the demo: rollnoise), else all
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  g++ cmake ninja-build pkg-config
  clang libclang-rt-14-dev
  libeigen3-dev libfftw3-dev libsundials-dev libsndfile1-dev libsamplerate0-dev libhdf5-dev
  libopenblas-dev
  libceres-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  gnuplot-nox fonts-dejavu-core
  pybind11-dev python3-dev python3-numpy python3-pytest
  python3-nbclient python3-nbformat python3-ipykernel python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DROLLNOISE_ASSERTIONS=ON -DROLLNOISE_WERROR=ON
targets=()
if (($#)); then targets=(--target "$@"); fi
cmake --build build -j "$jobs" "${targets[@]}"
