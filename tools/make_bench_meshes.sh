#!/usr/bin/env bash
# make_bench_meshes.sh OUTDIR [TMOP_BENCH]
# Generates the benchmark meshes of docs/benchmarks.md reproducibly (fixed sizes, fixed seeds,
# single-threaded gmsh) as binary Gmsh 4.1 files in OUTDIR (keep them out of the repository):
#   part_10k.msh part_100k.msh part_1m.msh   data/part.geo tets, interior nodes moved by 0.3 x
#                                            the shortest incident edge, every tet kept valid
#   part_30k.msh part_300k.msh               the same, for the scaling sweep (tools/bench/scaling.sh)
#   plate_200k.msh                           ~200k triangles, perturbed the same way
#   tangle_05.msh tangle_30.msh tangle_40.msh  ~16k tets perturbed without a validity check
#                                            (~5 / ~30 / ~40 % inverted elements)
#   *_raw.msh                                the unperturbed gmsh output
# TMOP_BENCH (default: build-bench/tools/tmop_bench next to this script) does the perturbation
# (tmop_bench --task=perturb), which is C++ because the Python version takes minutes at 1M tets.
# Set SKIP_1M=1 to skip the 1M-tet mesh (gmsh's HXT algorithm, ~10 s on one core).
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 OUTDIR [TMOP_BENCH]" >&2
  exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
out="$1"
bench="${2:-$root/build-bench/tools/tmop_bench}"
mkdir -p "$out"
[[ -x "$bench" ]] || { echo "$0: $bench not found (build target tmop_bench)" >&2; exit 2; }

# data/part.geo with the size as a parameter (the file sets its own CharacteristicLengthMax).
cat > "$out/part_cl.geo" <<GEO
Include "$root/data/part.geo";
Mesh.CharacteristicLengthMax = cl;
GEO
# A 2 x 1 plate with two holes.
cat > "$out/plate_cl.geo" <<'GEO'
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Disk(2) = {0.6, 0.5, 0, 0.25};
Disk(3) = {1.45, 0.5, 0, 0.2};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Surface{3}; Delete; }
Mesh.CharacteristicLengthMax = cl;
Physical Surface("plate", 1) = {1};
GEO

# gmsh_mesh GEO DIM CL OUT [gmsh flags]: single-threaded, so the output is reproducible.
gmsh_mesh() {
  local t0=$SECONDS
  gmsh "$1" -setnumber cl "$3" -"$2" -nt 1 -format msh41 -bin -v 1 -o "$4" "${@:5}"
  echo "  $(basename "$4"): gmsh $((SECONDS - t0)) s"
}

# perturb IN OUT AMOUNT SEED [extra flags]
perturb() {
  local in="$1" o="$2" amount="$3" seed="$4"
  shift 4
  "$bench" --task=perturb --input="$in" --output="$o" --amount="$amount" --seed="$seed" "$@"
}

echo "tets of data/part.geo"
gmsh_mesh "$out/part_cl.geo" 3 0.096 "$out/part_10k_raw.msh"
gmsh_mesh "$out/part_cl.geo" 3 0.0437 "$out/part_100k_raw.msh"
gmsh_mesh "$out/part_cl.geo" 3 0.083 "$out/part_16k_raw.msh"
gmsh_mesh "$out/part_cl.geo" 3 0.068 "$out/part_30k_raw.msh"
gmsh_mesh "$out/part_cl.geo" 3 0.030 "$out/part_300k_raw.msh"
if [[ "${SKIP_1M:-0}" != 1 ]]; then
  # HXT: ~10 s where the default Delaunay takes ~5 min at this size.
  gmsh_mesh "$out/part_cl.geo" 3 0.0192 "$out/part_1m_raw.msh" -algo hxt
fi
echo "triangles"
gmsh_mesh "$out/plate_cl.geo" 2 0.0045 "$out/plate_200k_raw.msh"

echo "perturbation (0.3 x shortest incident edge, valid)"
perturb "$out/part_10k_raw.msh" "$out/part_10k.msh" 0.3 1
perturb "$out/part_100k_raw.msh" "$out/part_100k.msh" 0.3 2
perturb "$out/part_30k_raw.msh" "$out/part_30k.msh" 0.3 11
perturb "$out/part_300k_raw.msh" "$out/part_300k.msh" 0.3 12
[[ -f "$out/part_1m_raw.msh" ]] && perturb "$out/part_1m_raw.msh" "$out/part_1m.msh" 0.3 3
perturb "$out/plate_200k_raw.msh" "$out/plate_200k.msh" 0.3 4
echo "tangled (no validity check)"
perturb "$out/part_16k_raw.msh" "$out/tangle_05.msh" "${TANGLE_05:-0.57}" 5 --keep_valid=false
perturb "$out/part_16k_raw.msh" "$out/tangle_30.msh" "${TANGLE_30:-1.45}" 6 --keep_valid=false
perturb "$out/part_16k_raw.msh" "$out/tangle_40.msh" "${TANGLE_40:-2.35}" 7 --keep_valid=false
