#!/usr/bin/env bash
# Set up, build (Release with assertions on) and run the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900 --no-tests=error
