#!/usr/bin/env bash
# Install what is missing, build everything (core, CLI, GUI, tutorials, docs) and run the
# whole test suite. Warnings in the docs fail the build.
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
