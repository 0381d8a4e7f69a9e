#!/usr/bin/env bash
# Coverage-guided fuzzing of every reader of outside data (fuzz/<target>.cpp, docs/reliability.md)
# with libFuzzer (clang from Debian's packages), each target for SECONDS (default 60).
#   bash tools/fuzz.sh [SECONDS] [TARGET...]
# Builds build-fuzz/ (clang, -DROLLNOISE_FUZZ=ON: libFuzzer's coverage, ASan and UBSan), then
# runs each target from its seeds in tests/corpus/<target>/ (read only: the corpus that grows
# is build-fuzz/corpus/<target>/, kept between runs). A crash, a sanitizer report, a leak, an
# input slower than 10 s or over 2 GB of memory is saved as build-fuzz/artifacts/<target>/...;
# fix it, then copy the input into tests/corpus/<target>/ (named bad_fuzz_* or ok_fuzz_*), where
# ctest replays it (fuzz_replay.<target>). The last status line of each target (executions,
# cov: and ft: coverage, corpus size) is collected in build-fuzz/fuzz-summary.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
all=(case_file model_file csv profile_csv laser line_laser height_map_hdf5 frf_csv uff wav modal_table_hdf5 study_file)
targets=("$@")
if ((${#targets[@]} == 0)); then targets=("${all[@]}"); fi

if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ is missing (Debian: apt-get install clang); tools/setup.sh installs it" >&2
  exit 1
fi
bash tools/setup.sh >/dev/null
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-fuzz -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROLLNOISE_ASSERTIONS=ON -DROLLNOISE_FUZZ=ON \
  -DROLLNOISE_BUILD_TESTS=OFF -DROLLNOISE_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc 2>/dev/null || echo 2)" --target "${targets[@]/#/fuzz_}"

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
summary=build-fuzz/fuzz-summary.txt
: >"$summary"
failed=()
for target in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$target
  artifacts=build-fuzz/artifacts/$target/
  mkdir -p "$corpus" "$artifacts"
  log=build-fuzz/fuzz-$target.log
  echo "fuzz: $target for $seconds s (log: $log)"
  status=0
  build-fuzz/fuzz/fuzz_"$target" "$corpus" "tests/corpus/$target" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" \
    >"$log" 2>&1 || status=$?
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' || true)
  echo "$target: seconds $seconds, executions ${execs:-?}, last status: ${last:-none}, exit $status" | tee -a "$summary"
  if ((status != 0)); then
    failed+=("$target")
    grep -E 'ERROR|SUMMARY|Test unit written|fuzz:' "$log" | head -5 >&2 || true
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: findings in: ${failed[*]} (inputs in build-fuzz/artifacts/)" >&2
  exit 1
fi
echo "fuzz: no crash, hang or leak in ${#targets[@]} targets"
