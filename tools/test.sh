#!/usr/bin/env bash
# Install what is missing, build with warnings as errors, run the whole test suite with ctest,
# then the I/O, mesh, element and quality tests again under AddressSanitizer + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 900
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTMOP_WERROR=ON -DTMOP_SANITIZE=ON \
  -DTMOP_BUILD_TOOLS=OFF >/dev/null
cmake --build build-asan -j"$(nproc)" --target tmop_io_tests tmop_mesh_tests tmop_element_tests \
  tmop_quality_tests
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -L 'io|mesh|element|quality' \
  --timeout 900
# libFuzzer targets of the mesh readers (docs/fuzzing.md): a short timed run per family and the
# replay of every recorded finding.
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTMOP_WERROR=ON \
  -DTMOP_FUZZ=ON -DTMOP_BUILD_TOOLS=OFF -DTMOP_BUILD_TESTS=OFF -DTMOP_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target tmop_fuzz_read
ctest --test-dir build-fuzz --output-on-failure -j"$(nproc)" -L fuzz --timeout 900
