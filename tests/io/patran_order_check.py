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
EDGES["hex27"] = EDGES["hex20"]
EDGES["wedge18"] = EDGES["wedge15"]
# Face and centre nodes after the edges: (position, corners whose mean it is). hex27 differs:
# Exodus (IOSS's Hex27 face table) puts the centre at 20, then faces z- z+ x- x+ y- y+; CGNS
# (SIDS HEXA_27) faces z- y- x+ y+ x- z+ at 20..25 and the centre at 26. wedge18 (IOSS Wedge18,
# SIDS PENTA_18) has its quad faces 0-1-4-3, 1-2-5-4, 2-0-3-5 at 15..17 in both.
HEX_CENTRE = tuple(range(8))
WEDGE18_FACES = [(15, (0, 1, 4, 3)), (16, (1, 2, 5, 4)), (17, (2, 0, 3, 5))]
FACES = {
    "exodus": {"pyramid14": [(13, (0, 1, 2, 3))], "wedge18": WEDGE18_FACES,
               "hex27": [(20, HEX_CENTRE), (21, (0, 1, 2, 3)), (22, (4, 5, 6, 7)),
                         (23, (0, 3, 7, 4)), (24, (1, 2, 6, 5)), (25, (0, 1, 5, 4)),
                         (26, (2, 3, 7, 6))]},
    "cgns": {"pyramid14": [(13, (0, 1, 2, 3))], "wedge18": WEDGE18_FACES,
             "hex27": [(20, (0, 1, 2, 3)), (21, (0, 1, 5, 4)), (22, (1, 2, 6, 5)),
                       (23, (2, 3, 7, 6)), (24, (0, 3, 7, 4)), (25, (4, 5, 6, 7)),
                       (26, HEX_CENTRE)]},
}
CORNERS = {"tri6": 3, "quad8": 4, "quad9": 4, "tet10": 4, "hex20": 8, "wedge15": 6,
           "pyramid13": 5, "pyramid14": 5, "hex27": 8, "wedge18": 6}
EXODUS = {("TRI6", 6): "tri6", ("QUAD8", 8): "quad8", ("QUAD9", 9): "quad9",
          ("TETRA10", 10): "tet10", ("HEX20", 20): "hex20", ("WEDGE15", 15): "wedge15",
          ("PYRAMID13", 13): "pyramid13", ("PYRAMID14", 14): "pyramid14",
          ("HEX27", 27): "hex27", ("WEDGE18", 18): "wedge18"}
# CGNS ElementType_t values (cgnslib.h).
CGNS = {6: "tri6", 8: "quad8", 9: "quad9", 11: "tet10", 15: "wedge15", 18: "hex20",
        21: "pyramid13", 13: "pyramid14", 19: "hex27", 16: "wedge18"}


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
            for pos, corners in FACES[kind].get(name, []):
                centre = np.mean([xyz[cell[c]] for c in corners], axis=0)
                if np.abs(xyz[cell[pos]] - centre).max() > 1e-12 * (1 + np.abs(centre).max()):
                    print("%s: %s node %d is not the centre of corners %s" % (path, name, pos, corners))
                    sys.exit(1)
        print("checked", name, len(conn))


main()
