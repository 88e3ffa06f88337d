#!/usr/bin/env bash
# The whole test suite on a fresh Debian bookworm machine (as root):
# install what is missing, build with tests, run them all with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh test
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release --parallel 2
