#!/usr/bin/env bash
# The whole test suite on a fresh Debian bookworm machine (as root):
# install what is missing, build with tests, run them all with CTest; then
# build again with AddressSanitizer + UndefinedBehaviorSanitizer (preset
# "asan": everything but the viewer's window, left out to keep CI under 30
# minutes; its test runs in the release build, its live decimation's
# under the sanitizers too) and run every test again under them.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh test
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release --parallel 2

cmake --preset asan >/dev/null
cmake --build --preset asan
ctest --preset asan --parallel 2
