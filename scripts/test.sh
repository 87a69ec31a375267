#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds everything with warnings as errors and runs the
# whole test suite with CTest; then the same suite under AddressSanitizer + UBSan. The second
# pass runs even when the first fails (one failure must not hide another); the script exits
# non-zero at the end if either did.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)

# Each pass is one && chain: errexit does not apply inside a function called before ||.
suite() {
  cmake -S . -B build/test -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGEM_WERROR=ON >/dev/null &&
    cmake --build build/test -j "$jobs" &&
    # The VM test's short variant (label vm-short) is left out: the full one (label vm) covers it.
    ctest --test-dir build/test --output-on-failure -j "$jobs" -LE vm-short
}

sanitizers() {
  cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DGEM_WERROR=ON -DGEM_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS="-O1" >/dev/null &&
    cmake --build build/asan -j "$jobs" --target gem_unit_test_targets &&
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
      ctest --test-dir build/asan --output-on-failure -j "$jobs" -L unit
}

failed=()
suite || failed+=("the test suite (build/test)")
if [ "${GEM_SKIP_SANITIZERS:-0}" != 1 ]; then
  sanitizers || failed+=("the sanitizer pass (build/asan)")
fi
if [ ${#failed[@]} -gt 0 ]; then
  printf 'test.sh: FAILED: %s\n' "${failed[@]}" >&2
  exit 1
fi
echo "test.sh: passed" >&2
