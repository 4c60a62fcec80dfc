# Checks the node order of quadratic cells in an Exodus II (.exo, read with netCDF4) or CGNS
# (.cgns, read with h5py) file written by tmop, without libexodus, libcgns or tmop's tables: for
# straight-sided cells, each mid-edge (and face) node must be the midpoint of the corners of the edge that the
# format documents (Exodus II / CGNS SIDS, PATRAN's numbering) place at that position.
#   patran_order_check.py exodus|cgns FILE
# Prints one line per checked cell type ("checked TYPE N") and exits 1 on the first mismatch.
import sys

import numpy as np

# 0-based corner pairs of the mid-edge nodes, in the file's order, after the corners.
EDGES = {
    "tri6": [(0, 1), (1, 2), (2, 0)],
    "quad8": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "quad9": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "tet10": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
    "hex20": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 5), (2, 6), (3, 7),
              (4, 5), (5, 6), (6, 7), (7, 4)],
    "wedge15": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 4), (2, 5), (3, 4), (4, 5), (5, 3)],
    "pyramid13": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 4), (2, 4), (3, 4)],
    "pyramid14": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 4), (2, 4), (3, 4)],
}
# Face nodes after the edges: (position, corners) - pyramid14's base centre.
FACES = {"pyramid14": [(13, (0, 1, 2, 3))]}
CORNERS = {"tri6": 3, "quad8": 4, "quad9": 4, "tet10": 4, "hex20": 8, "wedge15": 6,
           "pyramid13": 5, "pyramid14": 5}
EXODUS = {("TRI6", 6): "tri6", ("QUAD8", 8): "quad8", ("QUAD9", 9): "quad9",
          ("TETRA10", 10): "tet10", ("HEX20", 20): "hex20", ("WEDGE15", 15): "wedge15",
          ("PYRAMID13", 13): "pyramid13", ("PYRAMID14", 14): "pyramid14"}
CGNS = {6: "tri6", 8: "quad8", 9: "quad9", 11: "tet10", 15: "wedge15", 18: "hex20",
        21: "pyramid13", 13: "pyramid14"}


def exodus_blocks(path):
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        if "coord" in nc.variables:
            xyz = np.array(nc.variables["coord"][:]).T
        else:
            xyz = np.array([nc.variables[c][:] for c in ("coordx", "coordy", "coordz")]).T
        b = 1
        while "connect%d" % b in nc.variables:
            v = nc.variables["connect%d" % b]
            conn = np.array(v[:]) - 1
            yield EXODUS.get((v.elem_type.upper(), conn.shape[1])), xyz, conn
            b += 1


def cgns_blocks(path):
    import h5py
    with h5py.File(path, "r") as f:
        base = [f[k] for k in f if f[k].attrs.get("label", b"") == b"CGNSBase_t"][0]
        zone = [base[k] for k in base if base[k].attrs.get("label", b"") == b"Zone_t"][0]
        grid = zone["GridCoordinates"]
        xyz = np.array([grid[c][" data"][()] for c in ("CoordinateX", "CoordinateY",
                                                        "CoordinateZ")]).T
        for k in zone:
            sec = zone[k]
            if sec.attrs.get("label", b"") != b"Elements_t":
                continue
            r = sec["ElementRange"][" data"][()]
            conn = np.array(sec["ElementConnectivity"][" data"][()]) - 1
            yield CGNS.get(int(sec[" data"][0])), xyz, conn.reshape(int(r[1] - r[0] + 1), -1)


def main():
    kind, path = sys.argv[1], sys.argv[2]
    blocks = exodus_blocks(path) if kind == "exodus" else cgns_blocks(path)
    for name, xyz, conn in blocks:
        if name is None:
            continue
        nc = CORNERS[name]
        for cell in conn:
            for k, (a, b) in enumerate(EDGES[name]):
                mid = 0.5 * (xyz[cell[a]] + xyz[cell[b]])
                if np.abs(xyz[cell[nc + k]] - mid).max() > 1e-12 * (1 + np.abs(mid).max()):
                    print("%s: %s node %d is not the midpoint of corners %d-%d" %
                          (path, name, nc + k, a, b))
                    sys.exit(1)
            for pos, corners in FACES.get(name, []):
                centre = np.mean([xyz[cell[c]] for c in corners], axis=0)
                if np.abs(xyz[cell[pos]] - centre).max() > 1e-12 * (1 + np.abs(centre).max()):
                    print("%s: %s node %d is not the centre of its face" % (path, name, pos))
                    sys.exit(1)
        print("checked", name, len(conn))


main()
