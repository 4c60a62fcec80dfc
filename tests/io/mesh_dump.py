#!/usr/bin/python3
"""Independent readers / writers for tmop's io tests (run with /usr/bin/python3).

  mesh_dump.py gmsh FILE...       dump each FILE as read by the Gmsh API (gmsh.open) into
                                  FILE.gmsh.dump
  mesh_dump.py meshio FILE...     dump each FILE as read by meshio into FILE.meshio.dump
  mesh_dump.py meshio-write-ugrid DIR
                                  write one UGRID mesh per encoding (ASCII, b8, lb8, r8, lr8)
                                  with meshio into DIR, each with a NAME.expected dump
  mesh_dump.py meshio-write-exodus DIR
                                  write a.exo with meshio (every type both know) into DIR,
                                  with a.exo.expected
  mesh_dump.py meshio-write-su2 DIR
                                  write a2.su2 (2D: triangles, quads, boundary lines) and a3.su2
                                  (3D: every linear volume type, boundary triangles and quads)
                                  with meshio into DIR, each with NAME.expected
  mesh_dump.py cgns-h5 FILE...    dump each CGNS/HDF5 FILE as read node by node with h5py (the
                                  SIDS layout: first base, first zone, its Elements_t nodes)
                                  into FILE.cgns-h5.dump
  mesh_dump.py meshio-write DIR   write test meshes with meshio in every format into DIR, each
                                  with a NAME.expected dump of what was written

The canonical dump (parsed by io_test_util.cc):
  order gmsh|meshio|vtk node order of the cells below (meshio's own order is VTK's except for
                        wedges, which it keeps in Gmsh order; SU2 files hold VTK's order for
                        every type, and meshio passes it through: "vtk")
  points N              then N lines "x y z" (repr: shortest exact form)
  cells M               then M lines "TYPE REGION n0 n1 ..." (tmop type names, 0-based nodes)
REGION is the Gmsh physical tag (first physical group of the element's entity) or, for meshio,
the cell data "gmsh:physical" / "medit:ref"; 0 when there is none.
"""
import sys

GMSH_TYPES = {15: "vertex", 1: "line2", 8: "line3", 2: "tri3", 3: "quad4", 4: "tet4",
              5: "hex8", 6: "wedge6", 7: "pyramid5", 9: "tri6", 10: "quad9", 11: "tet10",
              12: "hex27", 16: "quad8", 17: "hex20", 18: "wedge15", 13: "wedge18",
              19: "pyramid13", 14: "pyramid14"}
MESHIO_TYPES = {"vertex": "vertex", "line": "line2", "line3": "line3", "triangle": "tri3",
                "quad": "quad4", "tetra": "tet4", "hexahedron": "hex8", "wedge": "wedge6",
                "pyramid": "pyramid5", "triangle6": "tri6", "quad9": "quad9",
                "tetra10": "tet10", "hexahedron27": "hex27", "quad8": "quad8",
                "hexahedron20": "hex20", "wedge15": "wedge15", "wedge18": "wedge18",
                "pyramid13": "pyramid13", "pyramid14": "pyramid14"}
# meshio keeps wedge15 / wedge18 from a .msh file in its own orders (its gmsh permutation for
# wedge15, none for wedge18) but from VTK files in VTK's: the dump normalises both to VTK's, so
# "order meshio" means VTK's order for every type but wedge6. Index k of a row = the meshio
# node of VTK node k.
MESHIO_MSH_TO_VTK = {"wedge15": [0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13],
                     "wedge18": [0, 2, 1, 3, 5, 4, 7, 9, 6, 13, 14, 12, 8, 11, 10, 16, 17, 15]}


def emit(order, points, cells, path):
    out = ["order " + order, "points %d" % len(points)]
    for p in points:
        xyz = [float(x) for x in p] + [0.0] * (3 - len(p))
        out.append(" ".join(repr(x) for x in xyz))
    out.append("cells %d" % len(cells))
    for name, region, nodes in cells:
        out.append("%s %d %s" % (name, region, " ".join(str(int(n)) for n in nodes)))
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def dump_gmsh(path):
    import gmsh
    gmsh.clear()
    gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    order = sorted(range(len(tags)), key=lambda i: tags[i])
    index = {int(tags[i]): k for k, i in enumerate(order)}
    points = [coords[3 * i:3 * i + 3] for i in order]
    elems = []
    for dim, tag in gmsh.model.getEntities():
        phys = gmsh.model.getPhysicalGroupsForEntity(dim, tag)
        region = int(phys[0]) if len(phys) else 0
        types, etags, enodes = gmsh.model.mesh.getElements(dim, tag)
        for t, et, en in zip(types, etags, enodes):
            n = len(en) // len(et)
            for k, e in enumerate(et):
                elems.append((int(e), GMSH_TYPES[int(t)], region,
                              [index[int(x)] for x in en[k * n:(k + 1) * n]]))
    elems.sort(key=lambda e: e[0])
    emit("gmsh", points, [e[1:] for e in elems], path + ".gmsh.dump")


def meshio_cells(mesh, from_msh=False):
    cells = []
    for i, block in enumerate(mesh.cells):
        region = None
        for key in ("gmsh:physical", "medit:ref", "ugrid:ref", "CellEntityIds", "su2:tag"):
            if key in mesh.cell_data:
                region = mesh.cell_data[key][i]
                break
        perm = MESHIO_MSH_TO_VTK.get(block.type) if from_msh else None
        for k, nodes in enumerate(block.data):
            if perm is not None:
                nodes = [nodes[p] for p in perm]
            cells.append((MESHIO_TYPES[block.type], int(region[k]) if region is not None else 0,
                          nodes))
    return cells


def dump_meshio(path):
    import meshio
    # meshio 5.0 reads and writes wedge15, pyramid13 and pyramid14 but its topological_dimension
    # table lacks the names (KeyError on every file holding one); the entry is all that is missing.
    for name in ("wedge15", "pyramid13", "pyramid14"):
        meshio._mesh.topological_dimension.setdefault(name, 3)
    mesh = meshio.read(path)
    emit("vtk" if path.endswith(".su2") else "meshio", mesh.points,
         meshio_cells(mesh, path.endswith(".msh")), path + ".meshio.dump")


def sample(types, with_quadratic):
    """Points with awkward doubles and one or two cells of each meshio type, tagged per block."""
    import math
    import numpy as np
    points = np.array([[math.sin(1.0 + v) * 1e3 / 7.0, math.cos(0.5 * v) / 3.0,
                        math.sqrt(2.0 + v) * 1e-5] for v in range(60)])
    sizes = {"line": 2, "line3": 3, "triangle": 3, "quad": 4, "tetra": 4, "hexahedron": 8,
             "wedge": 6, "pyramid": 5, "triangle6": 6, "quad9": 9, "tetra10": 10,
             "hexahedron27": 27}
    cells, phys, geom = [], [], []
    nxt = 0
    for b, t in enumerate(types):
        rows = []
        for r in range(2):
            rows.append([(nxt + 7 * k) % 60 for k in range(sizes[t])])
            nxt += 5
        cells.append((t, np.array(rows)))
        phys.append(np.array([10 + b, 10 + b], dtype=int))
        geom.append(np.array([100 + b, 100 + b], dtype=int))
    return points, cells, phys, geom


def meshio_write(outdir):
    import os
    import meshio
    import numpy as np
    volume = ["tetra", "hexahedron", "wedge", "pyramid", "triangle", "quad", "line",
              "tetra10", "hexahedron27", "triangle6", "quad9", "line3"]
    points, cells, phys, geom = sample(volume, True)
    full = meshio.Mesh(points, cells, cell_data={"gmsh:physical": phys, "gmsh:geometrical": geom})
    # meshio's 4.1 writer needs the entity of every node; put them all on volume 100.
    full41 = meshio.Mesh(points, cells, cell_data={"gmsh:physical": phys, "gmsh:geometrical": geom},
                         point_data={"gmsh:dim_tags": np.array([[3, 100]] * len(points))})
    jobs = [
        ("ascii.vtu", lambda p: meshio.vtu.write(p, full, binary=False)),
        ("zlib.vtu", lambda p: meshio.vtu.write(p, full, binary=True, compression="zlib")),
        ("raw.vtu", lambda p: meshio.vtu.write(p, full, binary=True, compression=None)),
        ("ascii.vtk", lambda p: meshio.vtk.write(p, full, binary=False)),
        ("binary.vtk", lambda p: meshio.vtk.write(p, full, binary=True)),
        ("ascii42.vtk", lambda p: meshio.vtk.write(p, full, binary=False, fmt_version="4.2")),
        ("binary42.vtk", lambda p: meshio.vtk.write(p, full, binary=True, fmt_version="4.2")),
        ("ascii22.msh", lambda p: meshio.gmsh.write(p, full, fmt_version="2.2", binary=False)),
        ("binary22.msh", lambda p: meshio.gmsh.write(p, full, fmt_version="2.2", binary=True)),
        ("ascii41.msh", lambda p: meshio.gmsh.write(p, full41, fmt_version="4.1", binary=False)),
        ("binary41.msh", lambda p: meshio.gmsh.write(p, full41, fmt_version="4.1", binary=True)),
    ]
    medit_types = ["tetra", "hexahedron", "wedge", "pyramid", "triangle", "quad", "line"]
    mp, mc, mphys, _ = sample(medit_types, False)
    medit = meshio.Mesh(mp, mc, cell_data={"medit:ref": mphys})
    jobs.append(("medit.mesh", lambda p: meshio.medit.write(p, medit)))
    for name, write in jobs:
        path = outdir + "/" + name
        try:
            write(path)
        except Exception as e:  # report, keep going: the C++ test names the missing file
            sys.stderr.write("meshio could not write %s: %s\n" % (name, e))
            if os.path.exists(path):
                os.remove(path)
            continue
        mesh = medit if name.endswith(".mesh") else full
        emit("meshio", mesh.points, meshio_cells(mesh), path + ".expected")


def meshio_write_ugrid(outdir):
    import meshio
    import numpy as np
    types = ["triangle", "quad", "tetra", "pyramid", "wedge", "hexahedron"]
    points, cells, _, _ = sample(types, False)
    # meshio 5's UGRID writer fails on per-block cell data and writes surface ID 1 on every
    # face without it; UGRID has no volume IDs (0 on reading).
    mesh = meshio.Mesh(points, cells)
    refs = [np.ones(2, dtype=int) if t in ("triangle", "quad") else np.zeros(2, dtype=int)
            for t in types]
    tagged = meshio.Mesh(points, cells, cell_data={"ugrid:ref": refs})
    for name in ("a.ugrid", "a.b8.ugrid", "a.lb8.ugrid", "a.r8.ugrid", "a.lr8.ugrid"):
        path = outdir + "/" + name
        meshio.ugrid.write(path, mesh)
        emit("meshio", mesh.points, meshio_cells(tagged), path + ".expected")


def meshio_write_exodus(outdir):
    import meshio
    types = ["line", "triangle", "quad", "tetra", "pyramid", "wedge", "hexahedron",
             "triangle6", "quad9", "tetra10"]
    points, cells, _, _ = sample(types, True)
    mesh = meshio.Mesh(points, cells)
    path = outdir + "/a.exo"
    meshio.exodus.write(path, mesh)
    emit("meshio", mesh.points, meshio_cells(mesh), path + ".expected")


def meshio_write_su2(outdir):
    import meshio
    import numpy as np
    # meshio 5.0's SU2 writer unpacks cell blocks as (type, data) pairs when it writes markers,
    # which its CellBlock does not support (TypeError): give it that form.
    if not hasattr(meshio.CellBlock, "__iter__"):
        meshio.CellBlock.__iter__ = lambda self: iter((self.type, self.data))
    for name, types, boundary, dim in (
            ("a2.su2", ["triangle", "quad", "line"], ("line",), 2),
            ("a3.su2", ["tetra", "hexahedron", "wedge", "pyramid", "triangle", "quad"],
             ("triangle", "quad"), 3)):
        points, cells, phys, _ = sample(types, False)
        points = points[:, :dim]
        # SU2 tags boundary cells only (MARKER_TAG= the number); element cells read back as 0.
        tags = [p if t in boundary else np.zeros(2, dtype=int) for t, p in zip(types, phys)]
        mesh = meshio.Mesh(points, cells, cell_data={"su2:tag": tags})
        path = outdir + "/" + name
        meshio.su2.write(path, mesh)
        emit("vtk", mesh.points, meshio_cells(mesh), path + ".expected")


CGNS_TYPES = {2: "vertex", 3: "line2", 4: "line3", 5: "tri3", 6: "tri6", 7: "quad4", 9: "quad9",
              10: "tet4", 11: "tet10", 12: "pyramid5", 14: "wedge6", 17: "hex8"}


def dump_cgns_h5(path):
    """Reads the HDF5 nodes directly (no libcgns): CGNS SIDS node order is VTK's for tet10 and
    Gmsh's for the wedge, i.e. the dump's "meshio" order."""
    import h5py
    with h5py.File(path, "r") as f:
        base = [f[k] for k in f if f[k].attrs.get("label", b"") == b"CGNSBase_t"][0]
        zone = [base[k] for k in base if base[k].attrs.get("label", b"") == b"Zone_t"][0]
        grid = zone["GridCoordinates"]
        xyz = [grid[c][" data"][()] for c in ("CoordinateX", "CoordinateY", "CoordinateZ")]
        points = list(zip(*xyz))
        sections = [zone[k] for k in zone if zone[k].attrs.get("label", b"") == b"Elements_t"]
        sections.sort(key=lambda e: int(e["ElementRange"][" data"][0]))
        cells = []
        for sec in sections:
            name = CGNS_TYPES[int(sec[" data"][0])]
            region = int(sec.name.split("/")[-1].split("_")[1])
            conn = sec["ElementConnectivity"][" data"][()]
            n = len(conn) // (int(sec["ElementRange"][" data"][1]) -
                              int(sec["ElementRange"][" data"][0]) + 1)
            for k in range(0, len(conn), n):
                cells.append((name, region, [int(v) - 1 for v in conn[k:k + n]]))
    emit("meshio", points, cells, path + ".cgns-h5.dump")


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("gmsh", "meshio", "meshio-write",
                                                "meshio-write-ugrid", "meshio-write-exodus",
                                                "meshio-write-su2",
                                                "cgns-h5"):
        sys.exit(__doc__)
    if sys.argv[1] == "cgns-h5":
        for f in sys.argv[2:]:
            dump_cgns_h5(f)
    elif sys.argv[1] == "meshio-write-exodus":
        meshio_write_exodus(sys.argv[2])
    elif sys.argv[1] == "meshio-write-su2":
        meshio_write_su2(sys.argv[2])
    elif sys.argv[1] == "meshio-write-ugrid":
        meshio_write_ugrid(sys.argv[2])
    elif sys.argv[1] == "meshio-write":
        meshio_write(sys.argv[2])
    elif sys.argv[1] == "meshio":
        for f in sys.argv[2:]:
            dump_meshio(f)
    else:
        import gmsh
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        for f in sys.argv[2:]:
            dump_gmsh(f)
        gmsh.finalize()
