#!/usr/bin/env bash
# make_never_worse_meshes.sh OUTDIR [TMOP_BENCH]
# Builds the "never worse" collection of issue 18 (tools/bench/never_worse.py measures it) as
# Gmsh 4.1 files in OUTDIR (keep them out of the repository). Single-threaded gmsh, fixed seeds:
#   tut_tN_3d.msh        every Gmsh tutorial tN.geo (gmsh-doc) meshed with -3 (a 2D-only
#                        tutorial gives its 2D mesh); tut_tN_2d.msh: t1..t6 with -2 (for the 3D
#                        tutorials that is their surface mesh: triangles / quads in 3D)
#   tut_t1_o2.msh        t1 at -order 2 (tri6), tut_t5_o2.msh: t5 at -order 2 (tet10)
#   tut_t6_2d.msh        t6's quads (the -2 mesh above)
#   demo_pripyrtet.msh   demos/simple_geo/pripyrtet.geo (tet + wedge6 + pyramid5)
#   demo_sg_transfinite.msh  demos/simple_geo/transfinite.geo (hex, transfinite)
#   gen_bl.msh           tests/data/geo/boundary_layer_slivers.geo: 10-layer boundary-layer tets
#   gen_hex_perturbed.msh  28 x 24 x 16 = 10,752 hex of a box, interior vertices moved by
#                        0.2 x their shortest incident edge, kept valid (tmop_bench --task=perturb)
#   gen_hex_sector_perturbed.msh  unstructured hex (a recombined sector with a hole, extruded in
#                        5 layers), perturbed the same way
#   gen_paved_quads.msh  unit square, point attractor (size 0.014 -> 0.12), Frontal-Delaunay +
#                        blossom full-quad recombination (the equal_edge fixture's mesh)
#   gen_sphere_quads.msh radius-5 sphere, 150 quads (equiangular cube sphere, python3-meshio)
# gmsh runs with -save_all: elements outside physical groups (t2's extruded wedges and hexes) are
# kept, with region 0. A mesh that gmsh fails to make (or takes > 120 s) is skipped with a note
# on stderr.
# TMOP_BENCH defaults to build/tools/tmop_bench of this work tree (target tmop_bench).
set -uo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 OUTDIR [TMOP_BENCH]" >&2
  exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$(dirname "$here")")"
out="$(mkdir -p "$1" && cd "$1" && pwd)"
bench="${2:-$root/build/tools/tmop_bench}"
doc=/usr/share/doc/gmsh-doc/doc/gmsh
src="$out/src"
mkdir -p "$src"

# The tutorials read their data files (t13_data.stl, t7_bgmesh.pos, ...) from their own folder.
cp "$doc"/tutorial/*.* "$src"/
cp "$doc"/demos/simple_geo/pripyrtet.geo "$src"/
[[ -f "$doc/demos/simple_geo/transfinite.geo" ]] && cp "$doc/demos/simple_geo/transfinite.geo" "$src/sg_transfinite.geo"
gunzip -f "$src"/*.gz 2>/dev/null

# mesh GEO OUT FLAGS...: single-threaded gmsh, 120 s at most.
mesh() {
  local geo="$1" o="$2"
  shift 2
  if (cd "$(dirname "$geo")" && timeout 120 gmsh "$geo" -nt 1 -save_all -format msh41 -v 1 -o "$o" "$@" \
        > "$o.log" 2>&1) && [[ -s "$o" ]]; then
    rm -f "$o.log"
    echo "  $(basename "$o")"
  else
    echo "  $(basename "$o"): gmsh failed, skipped (see $o.log)" >&2
    rm -f "$o"
  fi
}

echo "Gmsh tutorials"
for geo in "$src"/t[0-9]*.geo; do
  t="$(basename "$geo" .geo)"
  mesh "$geo" "$out/tut_${t}_3d.msh" -3
  case "$t" in
    t1 | t2 | t3 | t4 | t5 | t6) mesh "$geo" "$out/tut_${t}_2d.msh" -2 ;;
  esac
done
mesh "$src/t1.geo" "$out/tut_t1_o2.msh" -2 -order 2
mesh "$src/t5.geo" "$out/tut_t5_o2.msh" -3 -order 2

echo "Gmsh demos"
mesh "$src/pripyrtet.geo" "$out/demo_pripyrtet.msh" -3
[[ -f "$src/sg_transfinite.geo" ]] && mesh "$src/sg_transfinite.geo" "$out/demo_sg_transfinite.msh" -3

echo "Generated"
mesh "$root/tests/data/geo/boundary_layer_slivers.geo" "$out/gen_bl.msh" -3

cat > "$src/hexbox.geo" <<'GEO'
// 28 x 24 x 16 hexahedra of the box [0,1.4] x [0,1.2] x [0,0.8] (10,752 hex).
Point(1) = {0, 0, 0}; Point(2) = {1.4, 0, 0}; Point(3) = {1.4, 1.2, 0}; Point(4) = {0, 1.2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 29;
Transfinite Curve{2, 4} = 25;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude{0, 0, 0.8}{ Surface{1}; Layers{16}; Recombine; };
Physical Volume(1) = {out[1]};
GEO
mesh "$src/hexbox.geo" "$src/hexbox_raw.msh" -3
if [[ -x "$bench" && -s "$src/hexbox_raw.msh" ]]; then
  "$bench" --task=perturb --input="$src/hexbox_raw.msh" --output="$out/gen_hex_perturbed.msh" \
    --amount=0.2 --seed=18 --keep_valid=true > "$src/perturb.json" &&
    echo "  gen_hex_perturbed.msh"
else
  echo "  gen_hex_perturbed.msh: $bench not found (build target tmop_bench), skipped" >&2
fi

# Unstructured hexes: a recombined (blossom full-quad) sector with a hole, extruded in 5 layers,
# perturbed the same way (the structured box above relaxes back to its grid).
cat > "$src/hexsector.geo" <<'GEO'
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1, 0.7};
Disk(2) = {0.2, 0, 0, 0.3, 0.3};
BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Mesh.CharacteristicLengthMax = 0.035;
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 3;
Recombine Surface{1};
Extrude {0, 0, 0.6} { Surface{1}; Layers{5}; Recombine; }
GEO
mesh "$src/hexsector.geo" "$src/hexsector_raw.msh" -3
if [[ -x "$bench" && -s "$src/hexsector_raw.msh" ]]; then
  "$bench" --task=perturb --input="$src/hexsector_raw.msh" \
    --output="$out/gen_hex_sector_perturbed.msh" --amount=0.2 --seed=18 --keep_valid=true \
    > "$src/perturb_sector.json" && echo "  gen_hex_sector_perturbed.msh"
fi

cat > "$src/paved.geo" <<'GEO'
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point(10) = {0.5, 0.5, 0};
Field[1] = Distance; Field[1].PointsList = {10};
Field[2] = Threshold; Field[2].InField = 1;
Field[2].SizeMin = 0.014; Field[2].SizeMax = 0.12;
Field[2].DistMin = 0.02; Field[2].DistMax = 0.35;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 3;
GEO
mesh "$src/paved.geo" "$out/gen_paved_quads.msh" -2

# Gmsh cannot full-quad-recombine a sphere (periodic surface): an equiangular cube sphere
# instead, 6 x 5 x 5 = 150 quads, every vertex on the sphere (to rounding), outward normals.
/usr/bin/python3 - "$out/gen_sphere_quads.msh" <<'PY' && echo "  gen_sphere_quads.msh"
import sys, numpy as np, meshio
n, r = 5, 5.0
pts, index, quads = [], {}, []
def vid(p):
    key = tuple(np.round(p, 9))
    if key not in index:
        index[key] = len(pts)
        pts.append(p)
    return index[key]
t = np.tan(np.linspace(-np.pi / 4, np.pi / 4, n + 1))
for axis in range(3):
    for sign in (1.0, -1.0):
        def point(i, j):
            q = np.empty(3)
            q[axis] = sign
            q[(axis + 1) % 3], q[(axis + 2) % 3] = t[i], t[j]
            return r * q / np.linalg.norm(q)
        for i in range(n):
            for j in range(n):
                c = [vid(point(i, j)), vid(point(i + 1, j)), vid(point(i + 1, j + 1)),
                     vid(point(i, j + 1))]
                if sign < 0:
                    c = c[::-1]
                quads.append(c)
meshio.write(sys.argv[1], meshio.Mesh(np.array(pts), [("quad", np.array(quads))]),
             file_format="gmsh22", binary=False)
PY
echo "$(ls "$out"/*.msh | wc -l) meshes in $out"
