# VTK 9.1's readers and tmop's boundary sets (python3-vtk9): vtkExodusIIReader builds the cells of
# each Exodus side set from (element, side) with its own side table, vtkCGNSReader (LoadBndPatch
# on) builds a patch from each BC_t. Both are compared with the boundary cells of the same name
# in the .exo's element blocks (tmop writes a region's cells as blocks named by its physical
# name, which VTK reads independently of either table):
#   vtk_boundary_sets_check.py EXO CGNS
# Cells are matched by their point sets (coordinates rounded to 1e-6), not their VTK types (VTK
# 9.1 gives the 3-node side of a 2D quadratic element type 5, a triangle, with the line3's
# points); the corners of each side set cell must be the block cell's corners in the same cyclic
# order (the same outward normal).
# Prints "sideset NAME N" and "patch NAME N" per agreeing set, exits 1 on the first disagreement.
import sys

import vtk

E = vtk.vtkExodusIIReader
# VTK boundary cell types -> corner count: line, tri, quad and line3, tri6, quad8, quad9.
CORNERS = {3: 2, 5: 3, 9: 4, 21: 2, 22: 3, 23: 4, 28: 4}


def cells(ug):
    out = []
    for c in range(ug.GetNumberOfCells()):
        ids = ug.GetCell(c).GetPointIds()
        pts = [tuple(round(x, 6) for x in ug.GetPoint(ids.GetId(i)))
               for i in range(ids.GetNumberOfIds())]
        out.append((ug.GetCellType(c), pts))
    return out


def children(mb):
    for i in range(mb.GetNumberOfBlocks()):
        yield mb.GetMetaData(i).Get(vtk.vtkCompositeDataSet.NAME()), mb.GetBlock(i)


def key(cell):
    return tuple(sorted(cell[1]))


def same_cycle(a, b, n):
    a, b = a[:n], b[:n]
    return any(a[k:] + a[:k] == b for k in range(n))


def compare(kind, name, got, want):
    if sorted(key(c) for c in got) != sorted(key(c) for c in want):
        print("%s %s: VTK gives %d cells, the blocks %d, or other point sets" %
              (kind, name, len(got), len(want)))
        sys.exit(1)
    by_key = {key(c): c for c in want}
    for c in got:
        w = by_key[key(c)]
        if not same_cycle(c[1], w[1], CORNERS[w[0]]):
            print("%s %s: cell %s is %s in the blocks (orientation)" % (kind, name, c[1], w[1]))
            sys.exit(1)
    print(kind, name, len(got))


def main():
    exo, cgns = sys.argv[1:3]
    r = E()
    r.SetFileName(exo)
    r.UpdateInformation()
    for i in range(r.GetNumberOfObjects(E.SIDE_SET)):
        r.SetObjectStatus(E.SIDE_SET, i, 1)
    r.Update()
    blocks, sides = {}, {}
    for top_name, top in children(r.GetOutput()):
        target = {"Element Blocks": blocks, "Side Sets": sides}.get(top_name)
        if target is None or top is None:
            continue
        for name, g in children(top):
            if g is not None:
                target.setdefault(name, []).extend(cells(g))
    for name in sorted(sides):
        compare("sideset", name, sides[name], blocks.get(name, []))
    c = vtk.vtkCGNSReader()
    c.SetFileName(cgns)
    c.UpdateInformation()
    c.EnableAllBases()
    c.LoadBndPatchOn()
    c.Update()
    for _, base in children(c.GetOutput()):
        for _, zone in children(base):
            for part, sub in children(zone):
                if part != "Patches":
                    continue
                for name, g in children(sub):
                    compare("patch", name, cells(g), blocks.get(name, []))


main()
