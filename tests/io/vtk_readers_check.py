# VTK's own Exodus II and CGNS readers (python3-vtk9: vtkExodusIIReader, vtkCGNSReader) convert
# each cell to VTK's node order with tables of their own; this compares every cell they return,
# point by point, with the same cells in tmop's .vtu (read with vtkXMLUnstructuredGridReader).
#   vtk_readers_check.py VTU EXO CGNS
# Prints "agree exodus|cgns VTK_TYPE N" per cell type and exits 1 on the first disagreement.
# Cells are matched by their VTK type and centroid; vtkExodusIIReader stores points as float32, so
# points agree to 1e-6 of the mesh size.
# Wedges: Exodus II and CGNS (PATRAN's convention, shared by Gmsh, Abaqus, Nastran) put the first
# triangle's normal towards the second; VTK's wedge is the mirror image (its cell validator and
# cell-size filter call the PATRAN orientation inverted). VTK 9.1's Exodus and CGNS readers pass
# wedge connectivity through unchanged, so the reader's wedge k-th node is the .vtu's MIRROR[k]-th
# node: this checks that, i.e. that the file holds the PATRAN order.
import sys

import numpy as np
import vtk


# VTK's 3D cell types (vtkCellType.h): tet, hex, wedge, pyramid and their quadratic forms.
VOLUME_TYPES = {10, 12, 13, 14, 24, 25, 26, 27, 29, 32}
# VTK 9.1's vtkCGNSReader has no PYRA_13: it returns such cells as empty cells (type 0).
READER_GAPS = {"cgns": {27}}
MIRROR = {13: [0, 2, 1, 3, 5, 4],
          26: [0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13],
          32: [0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13, 17, 16, 15]}


def cells_of(ug, out):
    for c in range(ug.GetNumberOfCells()):
        ids = ug.GetCell(c).GetPointIds()
        p = np.array([ug.GetPoint(ids.GetId(i)) for i in range(ids.GetNumberOfIds())])
        out.setdefault(ug.GetCellType(c), []).append(p)


def grids(dataset):
    if isinstance(dataset, vtk.vtkUnstructuredGrid):
        yield dataset
        return
    it = dataset.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        g = it.GetCurrentDataObject()
        if isinstance(g, vtk.vtkUnstructuredGrid):
            yield g
        it.GoToNextItem()


def read(reader, path):
    reader.SetFileName(path)
    reader.UpdateInformation()
    if isinstance(reader, vtk.vtkCGNSReader):
        reader.EnableAllBases()
    reader.Update()
    out = {}
    for g in grids(reader.GetOutput()):
        cells_of(g, out)
    return out


def by_centroid(cells):
    return sorted(cells, key=lambda p: tuple(np.round(p.mean(axis=0), 6)))


def main():
    vtu, exo, cgns = sys.argv[1:4]
    want = read(vtk.vtkXMLUnstructuredGridReader(), vtu)
    size = max(np.abs(p).max() for ps in want.values() for p in ps)
    for kind, reader, path in (("exodus", vtk.vtkExodusIIReader(), exo),
                               ("cgns", vtk.vtkCGNSReader(), cgns)):
        got = read(reader, path)
        for t, cells in sorted(want.items()):
            if t not in VOLUME_TYPES:
                continue  # boundary cells are not what this checks
            if t in READER_GAPS.get(kind, ()):
                print("skip", kind, t, "(not read by this VTK reader)")
                continue
            g = got.get(t, [])
            if len(g) != len(cells):
                print("%s: %s reader gives %d cells of VTK type %d, the .vtu %d" %
                      (path, kind, len(g), t, len(cells)))
                sys.exit(1)
            for a, b in zip(by_centroid(cells), by_centroid(g)):
                if t in MIRROR:
                    b = b[MIRROR[t]]
                d = np.abs(a - b).max(axis=1)
                if d.max() > 1e-6 * (1 + size):
                    print("%s: VTK type %d node %d is at %s in the %s reader, %s in the .vtu" %
                          (path, t, int(d.argmax()), b[d.argmax()], kind, a[d.argmax()]))
                    sys.exit(1)
            print("agree", kind, t, len(cells))


main()
