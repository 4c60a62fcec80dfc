#!/usr/bin/python3
"""never_worse.py: the outside check of issue 18 ("never worse, on every kind of mesh").

For each mesh: runs tmop_optimize (the default, or --recipe=NAME) to OUTDIR/NAME.out.EXT, measures
input and output with tmop_quality --output=Q.vtu (per-cell fields), and reports per cell type
(and per type and region, "gmsh:physical") the worst and mean of the type's headline measure:

  tri3, tet4                      mean_ratio (tmop's field)
  quad4, hex8, wedge6, pyramid5,  scaled_jacobian (tmop's field; quadratic: of the corners)
  quad9, hex27
  tri6, tet10                     corner_mean_ratio (the corner simplex's mean ratio, computed
                                  here from the node coordinates: 4 sqrt3 A / sum l^2 and
                                  12 (3V)^(2/3) / sum l^2, signed) and mean_ratio (tmop's curved
                                  mean ratio, minimum over its sample points)
  tets (tet4, tet10)              also min / max dihedral and slivers (max dihedral > 150 deg and
                                  min < 10 deg, from tmop's dihedral fields of the corner tet)

A run is flagged WORSE when it exits 0 and any of these got worse by more than --tol (1e-6):
a per-type worst or mean of a headline measure, a per-(type, region) worst, the number of
slivers, the number of inverted cells; for tet10 also the min / max dihedral (they count for the
corner cell, issue 18). Linear tets' dihedral changes are reported, not flagged. An input with
inverted cells is untangled: there only more inverted cells are flagged (docs/quality.md). A run that exits
0 with the output identical to the input is marked "unchanged". Writes a JSON file (--json) and
prints a table (--markdown also writes it as Markdown).

usage: never_worse.py [--recipe=NAME] [--tools=DIR] [--outdir=DIR] [--timeout=S] [--json=F]
                      [--markdown=F] [--extra="--flag=value ..."] MESH...
"""
import argparse
import json
import math
import os
import shlex
import subprocess
import sys
import time

import meshio

# meshio 5.0 reads wedge15, pyramid13 and pyramid14 but lacks their topological dimension.
for _name in ("wedge15", "pyramid13", "pyramid14"):
    meshio._mesh.topological_dimension.setdefault(_name, 3)
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TOOLS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "build", "tools")

# meshio cell type -> (tmop name, dimension)
TYPES = {
    "triangle": ("tri3", 2), "quad": ("quad4", 2), "tetra": ("tet4", 3),
    "hexahedron": ("hex8", 3), "wedge": ("wedge6", 3), "pyramid": ("pyramid5", 3),
    "triangle6": ("tri6", 2), "quad9": ("quad9", 2), "tetra10": ("tet10", 3),
    "hexahedron27": ("hex27", 3),
}
SIMPLEX = {"tri3", "tet4"}
QUADRATIC_SIMPLEX = {"tri6", "tet10"}
TETS = {"tet4", "tet10"}
SLIVER_MAX, SLIVER_MIN = 150.0, 10.0


def corner_mean_ratio(name, pts, conn, planar):
    """Signed mean ratio of the corner simplex of each cell (independent of tmop)."""
    if name in ("tri3", "tri6"):
        a, b, c = (pts[conn[:, i]] for i in range(3))
        cr = np.cross(b - a, c - a)
        if planar:
            area = 0.5 * cr[:, 2]
        else:  # surface: oriented by its own normal, so never negative here
            area = 0.5 * np.linalg.norm(cr, axis=1)
        l2 = (np.sum((b - a) ** 2, 1) + np.sum((c - b) ** 2, 1) + np.sum((a - c) ** 2, 1))
        return 4 * math.sqrt(3) * area / l2
    a, b, c, d = (pts[conn[:, i]] for i in range(4))
    vol = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6
    l2 = sum(np.sum((p - q) ** 2, 1) for p, q in ((a, b), (a, c), (a, d), (b, c), (b, d), (c, d)))
    return np.sign(vol) * 12 * np.cbrt(3 * np.abs(vol)) ** 2 / l2


def measure(tools, path, workdir, tag):
    """Runs tmop_quality on path; returns per-type per-cell arrays and the raw points."""
    q = os.path.join(workdir, tag + ".quality.vtu")
    r = subprocess.run([os.path.join(tools, "tmop_quality"), "--input=" + path, "--output=" + q],
                       capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(q):
        return {"error": (r.stderr or r.stdout).strip().splitlines()[-1:] or ["tmop_quality failed"]}
    m = meshio.read(q)
    pts = np.asarray(m.points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.c_[pts, np.zeros(len(pts))]
    planar = bool(np.ptp(pts[:, 2]) == 0)
    dim = max(TYPES[b.type][1] for b in m.cells if b.type in TYPES)
    per_type = {}
    for k, block in enumerate(m.cells):
        if block.type not in TYPES or TYPES[block.type][1] != dim:
            continue
        name = TYPES[block.type][0]
        n = len(block.data)  # quadratic blocks come back as (n, 1) arrays
        f = {key: np.asarray(arrs[k], dtype=float).reshape(n, -1)[:, 0]
             for key, arrs in m.cell_data.items()}
        region = f.get("gmsh:physical", np.zeros(n)).astype(int)
        cols = {"region": region, "inverted": f["inverted"]}
        if name in SIMPLEX:
            cols["mean_ratio"] = f["mean_ratio"]
        elif name in QUADRATIC_SIMPLEX:
            cols["corner_mean_ratio"] = corner_mean_ratio(name, pts, block.data, planar)
            cols["mean_ratio"] = f["mean_ratio"]
        else:
            cols["scaled_jacobian"] = f["scaled_jacobian"]
        if name in TETS:
            cols["min_dihedral"] = f["min_dihedral_deg"]
            cols["max_dihedral"] = f["max_dihedral_deg"]
        prev = per_type.get(name)
        if prev:
            for key in cols:
                prev[key] = np.concatenate([prev[key], cols[key]])
        else:
            per_type[name] = cols
    return {"types": per_type, "points": pts}


def stats(a):
    a = a[np.isfinite(a)]
    if len(a) == 0:
        return None
    return {"min": float(a.min()), "mean": float(a.mean()), "max": float(a.max()), "count": len(a)}


def summarize(meas):
    out = {}
    for name, cols in meas["types"].items():
        t = {"cells": int(len(cols["region"])), "inverted": int(np.sum(cols["inverted"] > 0))}
        for key in ("mean_ratio", "corner_mean_ratio", "scaled_jacobian"):
            if key in cols:
                t[key] = stats(cols[key])
                t[key + "_by_region"] = {
                    str(r): stats(cols[key][cols["region"] == r])["min"]
                    for r in np.unique(cols["region"])
                    if stats(cols[key][cols["region"] == r])}
        if "min_dihedral" in cols:
            t["min_dihedral"] = stats(cols["min_dihedral"])["min"]
            t["max_dihedral"] = stats(cols["max_dihedral"])["max"]
            t["slivers"] = int(np.sum((cols["max_dihedral"] > SLIVER_MAX) &
                                      (cols["min_dihedral"] < SLIVER_MIN)))
        out[name] = t
    return out


def headline_keys(name):
    if name in SIMPLEX:
        return ["mean_ratio"]
    if name in QUADRATIC_SIMPLEX:
        return ["corner_mean_ratio", "mean_ratio"]
    return ["scaled_jacobian"]


def compare(before, after, tol):
    """Everything that got worse: list of (flagged, text)."""
    found = []
    # A tangled input is untangled: valid cells may pay for it (docs/quality.md), so only more
    # inverted cells count there; the rest is reported, not flagged.
    tangled = any(b["inverted"] > 0 for b in before.values())
    for name, b in before.items():
        a = after.get(name)
        if a is None:
            found.append((True, f"{name}: missing in the output"))
            continue
        if a["inverted"] > b["inverted"]:
            found.append((True, f"{name} inverted {b['inverted']} -> {a['inverted']}"))
        for key in headline_keys(name):
            if not b.get(key) or not a.get(key):
                continue
            for s in ("min", "mean"):
                if a[key][s] < b[key][s] - tol:
                    found.append((not tangled, f"{name} {key} {'worst' if s == 'min' else s} "
                                        f"{b[key][s]:.4g} -> {a[key][s]:.4g}"))
            if len(b[key + "_by_region"]) > 1:
                for r, wb in b[key + "_by_region"].items():
                    wa = a[key + "_by_region"].get(r)
                    if wa is not None and wa < wb - tol:
                        found.append((not tangled, f"{name} region {r} {key} worst {wb:.4g} -> {wa:.4g}"))
        if "slivers" in b:
            if a["slivers"] > b["slivers"]:
                found.append((not tangled, f"{name} slivers {b['slivers']} -> {a['slivers']}"))
            flag = name == "tet10" and not tangled
            if a["min_dihedral"] < b["min_dihedral"] - tol:
                found.append((flag, f"{name} min dihedral {b['min_dihedral']:.2f} -> "
                                    f"{a['min_dihedral']:.2f}"))
            if a["max_dihedral"] > b["max_dihedral"] + tol:
                found.append((flag, f"{name} max dihedral {b['max_dihedral']:.2f} -> "
                                    f"{a['max_dihedral']:.2f}"))
    return found


def run_one(args, path):
    base = os.path.basename(path)
    stem, ext = os.path.splitext(base)
    work = os.path.join(args.outdir, stem + ("." + args.recipe if args.recipe else ""))
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, stem + ".out" + ext)
    if os.path.exists(out):
        os.remove(out)
    rec = {"mesh": path, "name": stem, "recipe": args.recipe or "auto (default)"}
    mb = measure(args.tools, path, work, "before")
    if "error" in mb:
        rec.update(status="unreadable", error=mb["error"])
        return rec
    rec["before"] = summarize(mb)
    cmd = [os.path.join(args.tools, "tmop_optimize"), "--input=" + path, "--output=" + out]
    if args.recipe:
        cmd.append("--recipe=" + args.recipe)
    cmd += shlex.split(args.extra)
    rec["command"] = " ".join(cmd)
    t0 = time.time()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        rec["exit"] = r.returncode
        lines = (r.stdout + r.stderr).strip().splitlines()
        rec["last_line"] = lines[-1] if lines else ""
        with open(os.path.join(work, "tmop_optimize.log"), "w") as f:
            f.write(r.stdout + r.stderr)
    except subprocess.TimeoutExpired:
        rec["exit"] = "timeout"
    rec["seconds"] = round(time.time() - t0, 2)
    if rec["exit"] != 0 or not os.path.exists(out):
        rec["status"] = "failed" if rec["exit"] != 0 else "no output"
        return rec
    ma = measure(args.tools, out, work, "after")
    if "error" in ma:
        rec.update(status="output unreadable", error=ma["error"])
        return rec
    rec["after"] = summarize(ma)
    pb, pa = mb["points"], ma["points"]
    rec["max_vertex_move"] = float(np.max(np.abs(pa - pb))) if pa.shape == pb.shape else None
    found = compare(rec["before"], rec["after"], args.tol)
    rec["worse"] = [t for flagged, t in found if flagged]
    rec["notes"] = [t for flagged, t in found if not flagged]
    if rec["worse"]:
        rec["status"] = "WORSE"
    elif rec["max_vertex_move"] == 0:
        rec["status"] = "unchanged"
    else:
        rec["status"] = "ok"
    return rec


def fmt(s, key="min"):
    return "-" if not s else f"{s[key]:.3f}"


def table_rows(rec):
    """One row per cell type: type, cells, measure, worst b->a, mean b->a, tets extras."""
    rows = []
    b, a = rec.get("before", {}), rec.get("after", {})
    for name in b:
        for key in headline_keys(name):
            sb, sa = b[name].get(key), a.get(name, {}).get(key)
            extra = ""
            if "slivers" in b[name]:
                an = a.get(name, {})
                extra = (f"dihedral {b[name]['min_dihedral']:.1f}..{b[name]['max_dihedral']:.1f}"
                         + (f" -> {an['min_dihedral']:.1f}..{an['max_dihedral']:.1f}" if an else "")
                         + f", slivers {b[name]['slivers']}"
                         + (f" -> {an['slivers']}" if an else ""))
            rows.append([name, str(b[name]["cells"]), key,
                         f"{fmt(sb)} -> {fmt(sa)}", f"{fmt(sb, 'mean')} -> {fmt(sa, 'mean')}",
                         extra if key == headline_keys(name)[0] else ""])
    return rows


def report(records, markdown):
    lines = []
    if markdown:
        lines.append("| mesh | exit | s | status | type | cells | measure | worst before -> after "
                     "| mean before -> after | tets |")
        lines.append("|---|---|---|---|---|---|---|---|---|---|")
    for rec in records:
        rows = table_rows(rec) or [["-", "-", "-", "-", "-", ""]]
        for i, row in enumerate(rows):
            head = ([rec["name"], str(rec.get("exit", "-")), str(rec.get("seconds", "-")),
                     rec["status"]] if i == 0 else ["", "", "", ""])
            cells = head + row
            lines.append("| " + " | ".join(cells) + " |" if markdown else "  ".join(
                f"{c:<{w}}" for c, w in zip(cells, (24, 7, 6, 10, 9, 7, 18, 17, 17, 0))))
        for t in rec.get("worse", []):
            lines.append(("| | | | | | | WORSE: " + t + " | | | |") if markdown else "    WORSE: " + t)
        if rec.get("status") in ("failed", "no output", "unreadable"):
            msg = rec.get("last_line") or " ".join(rec.get("error", []))
            lines.append(("| | | | | | | " + msg.replace("|", "/") + " | | | |") if markdown
                         else "    " + msg)
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("meshes", nargs="+")
    p.add_argument("--recipe", default="")
    p.add_argument("--tools", default=DEFAULT_TOOLS)
    p.add_argument("--outdir", default="/tmp/never_worse")
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("--tol", type=float, default=1e-6)
    p.add_argument("--json", default="")
    p.add_argument("--markdown", default="")
    p.add_argument("--extra", default="", help="more tmop_optimize flags")
    args = p.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    records = []
    for path in args.meshes:
        rec = run_one(args, path)
        records.append(rec)
        print(report([rec], False), flush=True)
        if args.json:  # rewritten after every mesh, so a long run can be read as it goes
            with open(args.json, "w") as f:
                json.dump(records, f, indent=1)
    worse = [r["name"] for r in records if r["status"] == "WORSE"]
    print(f"\n{len(worse)} of {len(records)} meshes WORSE with exit 0: {', '.join(worse)}")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(report(records, True) + "\n")
    return 1 if worse else 0


if __name__ == "__main__":
    sys.exit(main())
