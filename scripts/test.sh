#!/usr/bin/env bash
# Install what is missing, build everything (core, CLI, GUI, tutorials, docs) and run the
# whole test suite. Warnings in the docs fail the build. Then the core suite again under
# AddressSanitizer and UBSan (preset asan), and a bounded fuzz run (RAYCACHE_FUZZ_SECONDS,
# default 60; scripts/fuzz.sh runs longer).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
cmake --preset default >/dev/null
cmake --build --preset default -j "$jobs"
if cmake --build --preset default --target help | grep -q '^docs:'; then
  cmake --build --preset default --target docs
fi
ctest --preset default -j "$jobs"

# The core library, the CLI and raycache_tests under AddressSanitizer and UBSan
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs"

# libFuzzer on the NFF reader and on rendering what it accepts, bounded
bash scripts/fuzz.sh "${RAYCACHE_FUZZ_SECONDS:-60}"
