#!/usr/bin/env bash
# Set up, build (Release with assertions on) and run the whole test suite with ctest; then the
# sanitizers on their named subset: every reader of outside data replayed over its whole corpus
# under ASan + UBSan (tools/sanitize.sh --readers; the whole suite under the sanitizers takes too
# long for CI's 90 minutes: docs/reliability.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900 --no-tests=error
bash tools/sanitize.sh --readers
