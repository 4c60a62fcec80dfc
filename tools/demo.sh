#!/usr/bin/env bash
# The main job: install what is missing, build, and optimize the bundled demo mesh, printing the
# quality before and after and writing part_optimized.vtu (open it in ParaView) and a JSON report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
./build/tools/tmop_optimize --input=data/part_perturbed.msh --output=part_optimized.vtu \
  --report=part_optimized.json
