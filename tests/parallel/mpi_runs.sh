#!/usr/bin/env bash
# mpi_runs.sh BUILD SOURCE MPIEXEC NP: tmop_optimize under `mpirun -np NP` (tmop/parallel/) must
# give the single-process result for the same partitions, byte for byte, for a volume and a
# planar mesh and the default recipe; rank 0 alone prints and writes (one "wrote" line, one
# report); a bad input fails with exit 2 and one line on stderr.
set -euo pipefail
build=$1 src=$2 mpiexec=$3 np=$4
tool=$build/tools/tmop_optimize
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# CI runs as root on 2 cores: both flags are needed there and harmless elsewhere.
# -q: without it mpirun adds its own multi-line banner to a failed run's one line.
mpi=("$mpiexec" -q --oversubscribe --allow-run-as-root -np "$np")
fail() { echo "FAIL: $*"; exit 1; }

gmsh -3 -nt 1 "$src/tests/data/geo/box.geo" -clmax 0.06 -o "$tmp/box.msh" >/dev/null
cat >"$tmp/square.geo" <<'GEO'
lc = 0.03;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
GEO
gmsh -2 -nt 1 "$tmp/square.geo" -o "$tmp/square.msh" >/dev/null
for mesh in box square; do
  for recipe in shape auto; do
    args=(--input="$tmp/$mesh.msh" --partitions=8 --threads=1 --recipe=$recipe)
    "$tool" "${args[@]}" --output="$tmp/one.msh" --report="$tmp/one.json" >"$tmp/one.log" 2>&1 ||
      fail "$mesh $recipe: one process: $(tail -1 "$tmp/one.log")"
    grep -q "partitioned" "$tmp/one.log" || fail "$mesh $recipe: the stage was not partitioned"
    timeout 300 "${mpi[@]}" "$tool" "${args[@]}" --output="$tmp/many.msh" --report="$tmp/many.json" \
      >"$tmp/many.log" 2>&1 || fail "$mesh $recipe: mpirun -np $np: $(tail -3 "$tmp/many.log")"
    cmp -s "$tmp/one.msh" "$tmp/many.msh" ||
      fail "$mesh $recipe: mpirun -np $np differs from one process"
    [ "$(grep -c '^wrote ' "$tmp/many.log")" = 1 ] || fail "$mesh $recipe: not one 'wrote' line"
    [ -s "$tmp/many.json" ] || fail "$mesh $recipe: no report"
    echo "ok: $mesh $recipe, mpirun -np $np = one process ($(grep '^stage' "$tmp/many.log" | head -1 | cut -c1-60)...)"
  done
done

# A .pvtu output: one piece per rank and the index; VTK's parallel reader finds the cells of the
# single-process .vtu (tests/io/pvtu_check.py).
args=(--input="$tmp/box.msh" --partitions=8 --threads=1 --recipe=shape)
"$tool" "${args[@]}" --output="$tmp/one.vtu" >/dev/null 2>&1 || fail "box: one process .vtu"
timeout 300 "${mpi[@]}" "$tool" "${args[@]}" --output="$tmp/many.pvtu" >"$tmp/pvtu.log" 2>&1 ||
  fail "box: mpirun .pvtu: $(tail -3 "$tmp/pvtu.log")"
for ((k = 0; k < np; ++k)); do [ -s "$tmp/many_$k.vtu" ] || fail "no piece $k"; done
[ ! -e "$tmp/many_$np.vtu" ] || fail "a piece too many"
if python3 -c "import vtk" 2>/dev/null; then
  python3 "$src/tests/io/pvtu_check.py" "$tmp/one.vtu" "$tmp/many.pvtu" "$np" ||
    fail "the .pvtu pieces differ from the .vtu"
fi
echo "ok: .pvtu output, $np pieces"

set +e
"${mpi[@]}" "$tool" --input="$tmp/missing.msh" --output="$tmp/x.msh" >"$tmp/bad.out" 2>"$tmp/bad.err"
rc=$?
set -e
[ "$rc" = 2 ] || fail "a missing input under mpirun: exit $rc, not 2"
[ "$(grep -c . "$tmp/bad.err")" = 1 ] || fail "a missing input: not one line: $(cat "$tmp/bad.err")"
grep -q "missing.msh" "$tmp/bad.err" || fail "the message does not name the file"
[ ! -e "$tmp/x.msh" ] || fail "a failed run wrote its output"
echo "ok: a missing input under mpirun: exit 2, one line"
