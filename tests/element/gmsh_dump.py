# Prints what gmsh itself says about its element types, for tests/element/gmsh_agreement_test.cc:
#   ref TYPE NUM_NODES x y z x y z ...      reference nodes (getElementProperties), padded to 3D
#   elem TYPE NUM_NODES x y z x y z ...     nodes of elements of straight-sided second-order
#                                           meshes of the unit square / cube (a few per type)
# Run with /usr/bin/python3 (the interpreter that has the gmsh module).
import gmsh


def pad(c, dim):
    out = []
    for i in range(len(c) // dim if dim else 1):
        p = list(c[i * dim:(i + 1) * dim]) if dim else []
        out += p + [0.0] * (3 - len(p))
    return out


def dump_elements(limit=6):
    coords = {}
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    for i, t in enumerate(tags):
        coords[int(t)] = xyz[3 * i:3 * i + 3]
    types, _, nodes = gmsh.model.mesh.getElements()
    for t, ns in zip(types, nodes):
        _, _, _, nn, _, _ = gmsh.model.mesh.getElementProperties(t)
        if t not in (9, 10, 11, 12, 6, 7, 5, 3, 4, 2, 13, 16, 17, 18, 19, 14):
            continue
        for e in range(min(limit, len(ns) // nn)):
            xs = []
            for n in ns[e * nn:(e + 1) * nn]:
                xs += list(coords[int(n)])
            print("elem", t, nn, " ".join(repr(float(x)) for x in xs))


def dump_both_second_orders():
    """Dumps the current linear mesh at order 2, complete then incomplete, and leaves it linear."""
    for incomplete in (0, 1):
        gmsh.option.setNumber("Mesh.SecondOrderIncomplete", incomplete)
        gmsh.model.mesh.setOrder(2)
        dump_elements()
        gmsh.model.mesh.setOrder(1)
    gmsh.option.setNumber("Mesh.SecondOrderIncomplete", 0)


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
for t in [15, 1, 8, 2, 3, 4, 5, 6, 7, 9, 10, 11, 12, 16, 17, 18, 13, 19, 14]:
    _, dim, _, nn, c, _ = gmsh.model.mesh.getElementProperties(t)
    print("ref", t, nn, " ".join(repr(float(x)) for x in pad(c, dim)))

gmsh.option.setNumber("Mesh.SecondOrderIncomplete", 0)
# tri6 and quad9 on a square (quads by recombination).
for recombine in (False, True):
    gmsh.model.add("sq")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.4)
    if recombine:
        gmsh.model.mesh.setRecombine(2, 1)
    gmsh.model.mesh.generate(2)
    gmsh.model.mesh.setOrder(2)
    dump_elements()
    gmsh.model.remove()
# tet10 on a cube, hex27 on a transfinite recombined cube.
for hexes in (False, True):
    gmsh.model.add("cube")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1.5, 2)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.8)
    if hexes:
        for c in gmsh.model.getEntities(1):
            gmsh.model.mesh.setTransfiniteCurve(c[1], 3)
        for s in gmsh.model.getEntities(2):
            gmsh.model.mesh.setTransfiniteSurface(s[1])
            gmsh.model.mesh.setRecombine(2, s[1])
        gmsh.model.mesh.setTransfiniteVolume(1)
        gmsh.model.mesh.setRecombine(3, 1)
    gmsh.model.mesh.generate(3)
    gmsh.model.mesh.setOrder(2)
    dump_elements()
    gmsh.model.remove()
# Linear wedges (extruded triangles) and pyramids (hex/tet transition) for orientation checks.
gmsh.model.add("wedge")
gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
gmsh.model.occ.synchronize()
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
gmsh.model.occ.extrude([(2, 1)], 0, 0, 0.5, [2], recombine=True)
gmsh.model.occ.synchronize()
gmsh.model.mesh.generate(3)
dump_elements()
# The same wedges at order 2: complete (wedge18, what `gmsh -order 2` writes) and incomplete
# (wedge15).
dump_both_second_orders()
gmsh.model.remove()
# Serendipity quad8 / hex20: second order, incomplete, on a recombined square / transfinite cube.
gmsh.option.setNumber("Mesh.SecondOrderIncomplete", 1)
gmsh.model.add("serendipity")
gmsh.model.occ.addBox(0, 0, 0, 1, 1.5, 2)
gmsh.model.occ.synchronize()
for c in gmsh.model.getEntities(1):
    gmsh.model.mesh.setTransfiniteCurve(c[1], 3)
for s in gmsh.model.getEntities(2):
    gmsh.model.mesh.setTransfiniteSurface(s[1])
    gmsh.model.mesh.setRecombine(2, s[1])
gmsh.model.mesh.setTransfiniteVolume(1)
gmsh.model.mesh.setRecombine(3, 1)
gmsh.model.mesh.generate(3)
gmsh.model.mesh.setOrder(2)
dump_elements()
gmsh.model.remove()
gmsh.option.setNumber("Mesh.SecondOrderIncomplete", 0)
# A hex box glued to a tet box: gmsh puts pyramids on the shared quad face.
gmsh.model.add("pyramids")
gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
gmsh.model.occ.addBox(1, 0, 0, 1, 1, 1)
gmsh.model.occ.fragment([(3, 1)], [(3, 2)])
gmsh.model.occ.synchronize()
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
hex_box = gmsh.model.getEntitiesInBoundingBox(-0.1, -0.1, -0.1, 1.1, 1.1, 1.1, 3)[0][1]
for c in gmsh.model.getBoundary([(3, hex_box)], combined=False, recursive=True):
    if c[0] == 1:
        gmsh.model.mesh.setTransfiniteCurve(c[1], 3)
for s in gmsh.model.getBoundary([(3, hex_box)], combined=False):
    gmsh.model.mesh.setTransfiniteSurface(abs(s[1]))
    gmsh.model.mesh.setRecombine(2, abs(s[1]))
gmsh.model.mesh.setTransfiniteVolume(hex_box)
gmsh.model.mesh.setRecombine(3, hex_box)
gmsh.model.mesh.generate(3)
dump_elements()
# The same pyramids at order 2: complete (pyramid14) and incomplete (pyramid13).
dump_both_second_orders()
gmsh.model.remove()
# gmsh's own basis functions of the pyramids at a few interior points:
#   basis TYPE NUM_NODES x y z N_0 .. N_{n-1}
for t in (7, 19, 14):
    _, _, _, nn, _, _ = gmsh.model.mesh.getElementProperties(t)
    pts = []
    for k in range(12):
        z = 0.07 * k
        pts += [(0.83 * ((k * 7) % 11) / 10.0 - 0.4) * (1 - z),
                (0.61 * ((k * 5) % 13) / 12.0 - 0.3) * (1 - z), z]
    _, values, _ = gmsh.model.mesh.getBasisFunctions(t, pts, "Lagrange")
    for k in range(12):
        print("basis", t, nn, " ".join(repr(float(v)) for v in
                                      pts[3 * k:3 * k + 3] + list(values[nn * k:nn * (k + 1)])))
gmsh.finalize()
