#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds everything with warnings as errors and runs the
# whole test suite with CTest; then the same suite under AddressSanitizer + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)

cmake -S . -B build/test -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGEM_WERROR=ON >/dev/null
cmake --build build/test -j "$jobs"
# The VM test's short variant (label vm-short) is left out: the full one (label vm) covers it.
ctest --test-dir build/test --output-on-failure -j "$jobs" -LE vm-short

if [ "${GEM_SKIP_SANITIZERS:-0}" != 1 ]; then
  cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DGEM_WERROR=ON -DGEM_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS="-O1" >/dev/null
  cmake --build build/asan -j "$jobs" --target gem_unit_test_targets
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build/asan --output-on-failure -j "$jobs" -L unit
fi
