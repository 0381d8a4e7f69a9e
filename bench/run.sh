#!/usr/bin/env bash
# Builds the benchmarks without assertions (build-bench/) and runs them; JSON results go to
# build-bench/bench_contact.json and build-bench/bench_radiation.json. Performance targets live here,
# not in the test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh >/dev/null
cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DROLLNOISE_ASSERTIONS=OFF -DROLLNOISE_BUILD_TESTS=OFF -DROLLNOISE_PYTHON=OFF >/dev/null
cmake --build build-bench -j "$(nproc)" --target bench_contact bench_radiation
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
build-bench/bench/bench_contact --benchmark_out=build-bench/bench_contact.json --benchmark_out_format=json "$@"
build-bench/bench/bench_radiation --benchmark_out=build-bench/bench_radiation.json --benchmark_out_format=json "$@"
