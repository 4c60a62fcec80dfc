#!/usr/bin/env bash
# Configures and builds tmop (Release) in build/ with warnings as errors.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTMOP_WERROR=ON >/dev/null
cmake --build build -j"$(nproc)"
