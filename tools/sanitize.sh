#!/usr/bin/env bash
# Builds rollnoise with AddressSanitizer and UndefinedBehaviorSanitizer (clang from Debian's
# packages, gcc if clang is missing) in build-sanitize/ and runs the test suite under them.
#   bash tools/sanitize.sh            the whole suite (see docs/reliability.md for how long)
#   bash tools/sanitize.sh REGEX      only the tests whose names match REGEX (ctest -R)
#   bash tools/sanitize.sh --readers  CI's subset: builds only the replay drivers of the fuzz
#                                     targets and runs them over every corpus (every reader of
#                                     outside data on every seed and every regression input)
# Any sanitizer report aborts the process (-fno-sanitize-recover=all, halt_on_error), so the test
# that ran into it fails and ctest's exit status says so.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh >/dev/null

if command -v clang++ >/dev/null; then
  compilers=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
else
  compilers=(-DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++)
fi
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build-sanitize -G Ninja "${compilers[@]}" "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROLLNOISE_ASSERTIONS=ON -DROLLNOISE_SANITIZE=ON \
  -DROLLNOISE_BUILD_BENCHMARKS=OFF
filter=()
targets=()
if [[ ${1:-} == --readers ]]; then
  filter=(-R '^fuzz_replay\.')
  targets=(fuzz_replays)  # every fuzz_replay_<target> of fuzz/CMakeLists.txt
elif (($# > 0)); then
  filter=(-R "$1")
fi
if ((${#targets[@]})); then
  cmake --build build-sanitize -j "$jobs" --target "${targets[@]}"
else
  cmake --build build-sanitize -j "$jobs"
fi

# Leaks are reported too (detect_leaks); the suppressions name the libraries outside rollnoise
# whose one-off allocations at exit are not ours to free.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:suppressions=$PWD/tools/sanitize_asan.supp${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$PWD/tools/sanitize_lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$PWD/tools/sanitize_ubsan.supp${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"

ctest --test-dir build-sanitize --output-on-failure -j "$jobs" --timeout 3600 --no-tests=error "${filter[@]}"
