# Sourced by the bench scripts from the repository's root: sets `exe` to the program they time,
# $ROLLNOISE_EXE when given, else the Release build without assertions in build-bench/ (built
# here when needed).
if [[ -z ${ROLLNOISE_EXE:-} ]]; then
  bash tools/setup.sh >/dev/null
  cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DROLLNOISE_ASSERTIONS=OFF -DROLLNOISE_BUILD_TESTS=OFF -DROLLNOISE_PYTHON=OFF >/dev/null
  cmake --build build-bench -j "$(nproc)" --target rollnoise >/dev/null
fi
exe=${ROLLNOISE_EXE:-build-bench/tools/rollnoise/rollnoise}
