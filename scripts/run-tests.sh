#!/usr/bin/env bash
# The whole test suite on a fresh Debian bookworm machine (as root):
# install what is missing, build with tests, run them all with CTest; then
# build again with AddressSanitizer + UndefinedBehaviorSanitizer (preset
# "asan": everything but the viewer's window, left out to keep CI under 30
# minutes; its test runs in the release build, its live decimation's
# under the sanitizers too) and run every test again under them. The
# sanitizer build compiles at -O1 -g1 (the level AddressSanitizer's docs
# suggest): half the compile time of -O2 -g, with file and line in every
# report. Each phase prints its wall time, so a slow CI run says where.
set -euo pipefail
cd "$(dirname "$0")/.."

phase() { echo "== run-tests: $1 done at ${SECONDS} s"; }

bash scripts/install-deps.sh test
phase "install"
cmake --preset release >/dev/null
cmake --build --preset release
phase "release build"
ctest --preset release --parallel 2
phase "release tests"

cmake --preset asan >/dev/null
cmake --build --preset asan
phase "sanitizer build"
ctest --preset asan --parallel 2
phase "sanitizer tests"
