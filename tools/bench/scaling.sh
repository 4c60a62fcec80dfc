#!/usr/bin/env bash
# tools/bench/scaling.sh OUT.json MESH... [-- TMOP_BENCH_FLAGS...]
# The scaling report of docs/benchmarks.md: tmop_bench --task=shape on each mesh (one process
# per mesh, so each peak RSS is its own), all records in OUT.json (a JSON array), and a Markdown
# table on stdout: time per element and iteration (Ceres's minimizer time / (elements x
# iterations)), per element and Jacobian evaluation, per element and CGNR inner iteration, and
# memory per element (peak RSS / elements, and the marginal bytes per element against the
# smallest mesh, which removes the process's fixed footprint).
# TMOP_BENCH (default: build-bench/tools/tmop_bench, else build/tools/tmop_bench) is the binary.
# Needs python3 for the table.
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 OUT.json MESH... [-- TMOP_BENCH_FLAGS...]" >&2
  exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$(dirname "$here")")"
out="$1"
shift
meshes=()
while [[ $# -gt 0 && "$1" != "--" ]]; do
  meshes+=("$1")
  shift
done
[[ $# -gt 0 ]] && shift
flags=("$@")
[[ ${#meshes[@]} -gt 0 ]] || { echo "$0: no mesh given" >&2; exit 2; }
bench="${TMOP_BENCH:-}"
if [[ -z "$bench" ]]; then
  bench="$root/build-bench/tools/tmop_bench"
  [[ -x "$bench" ]] || bench="$root/build/tools/tmop_bench"
fi
[[ -x "$bench" ]] || { echo "$0: $bench not found (build target tmop_bench)" >&2; exit 2; }
command -v python3 >/dev/null || { echo "$0: python3 is needed for the table" >&2; exit 2; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp" "$out.tmp"' EXIT
i=0
for m in "${meshes[@]}"; do
  i=$((i + 1))
  echo "  $(basename "$m") ..." >&2
  # A mesh that fails (unreadable, or a recipe failure) gets a row saying so; the others go on.
  if ! "$bench" --input="$m" --task=shape --json="$tmp/$i.json" "${flags[@]}" >/dev/null \
    2>"$tmp/$i.err"; then
    [[ -s "$tmp/$i.json" ]] || python3 -c '
import json, sys
lines = open(sys.argv[2]).read().strip().splitlines()
print(json.dumps({"ok": False, "mesh": {"path": sys.argv[1]},
                  "message": lines[-1] if lines else "tmop_bench failed"}))' "$m" "$tmp/$i.err" \
      >"$tmp/$i.json"
  fi
done

python3 - "$tmp" "$i" "$out.tmp" <<'PY'
import json, os, sys
tmp, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
recs = [json.load(open(os.path.join(tmp, f"{k}.json"))) for k in range(1, n + 1)]
with open(out, "w") as f:
    json.dump(recs, f, indent=1)
    f.write("\n")
os.replace(out, out[:-len(".tmp")])  # the records are in place before the table is made
good = [r for r in recs if r.get("ok") and r.get("stages")]
if not good:
    sys.exit("no mesh ran")
base = min(good, key=lambda r: r["mesh"]["elements"])
print("| mesh | elements | free vertices | iterations | wall s | setup s | Ceres minimizer s "
      "| us / element / iteration | us / element / evaluation | CG iterations (recorded steps) "
      "| us / element / CG iteration | peak RSS MB | bytes / element | marginal bytes / element "
      "| final objective | min quality |")
print("|" + "---|" * 16)
per_it = []
for r in recs:
    if r not in good:
        print("| %s | failed: %s |" % (os.path.basename(r["mesh"]["path"]), r.get("message", "")))
        continue
    st = r["stages"][0]  # the shape stage (a guard round, when one ran, is not counted here)
    t = st["times"]
    e = r["mesh"]["elements"]
    if st["us_per_element_iteration"] > 0:
        per_it.append(st["us_per_element_iteration"])
    marginal = ""
    if e > base["mesh"]["elements"]:
        marginal = "%.0f" % ((r["peak_rss_mb"] - base["peak_rss_mb"]) * 1048576.0 /
                             (e - base["mesh"]["elements"]))
    print("| %s | %d | %d | %d | %.2f | %.3f | %.2f | %.2f | %.3f | %d | %.3f | %.0f | %.0f | %s | %.6f | %.4f |" % (
        os.path.basename(r["mesh"]["path"]), e, st["free_vertices"], st["iterations"],
        r["wall_seconds"], t["setup"] + t["preprocessor"], t["minimizer"],
        st["us_per_element_iteration"], st["us_per_element_evaluation"],
        t["linear_iterations"], st["us_per_element_linear_iteration"], r["peak_rss_mb"],
        r["peak_rss_bytes_per_element"], marginal, r["final_objective"],
        r["min_quality_after"]))
print()
if per_it:
    print("us / element / iteration: max / min = %.2f" % (max(per_it) / min(per_it)))
r0 = good[0]
print("machine: %s, %d cores; commit %s; %s" % (r0["machine"]["cpu"], r0["machine"]["nproc"],
                                              r0["commit"], r0["date"]))
PY
