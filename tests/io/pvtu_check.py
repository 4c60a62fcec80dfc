# Reads tmop's X.vtu and X.pvtu (its pieces) with VTK's own XML readers (python3-vtk9:
# vtkXMLUnstructuredGridReader, vtkXMLPUnstructuredGridReader) and checks that the pieces hold
# the .vtu's cells in the same order: types, node coordinates, and every cell and point data
# array, value for value.   pvtu_check.py VTU PVTU PIECES
# Prints "pvtu ok CELLS PIECES" or one line saying what differs, exit 1.
import sys

import numpy as np
import vtk


def read(reader, path):
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def main():
    vtu, pvtu, pieces = sys.argv[1], sys.argv[2], int(sys.argv[3])
    a = read(vtk.vtkXMLUnstructuredGridReader(), vtu)
    pr = vtk.vtkXMLPUnstructuredGridReader()
    b = read(pr, pvtu)
    if pr.GetNumberOfPieces() != pieces:
        print("%s: %d pieces, expected %d" % (pvtu, pr.GetNumberOfPieces(), pieces))
        sys.exit(1)
    if a.GetNumberOfCells() != b.GetNumberOfCells():
        print("%s: %d cells, the .vtu %d" % (pvtu, b.GetNumberOfCells(), a.GetNumberOfCells()))
        sys.exit(1)
    for c in range(a.GetNumberOfCells()):
        ia, ib = a.GetCell(c).GetPointIds(), b.GetCell(c).GetPointIds()
        if a.GetCellType(c) != b.GetCellType(c) or ia.GetNumberOfIds() != ib.GetNumberOfIds():
            print("%s: cell %d: type %d, the .vtu %d" % (pvtu, c, b.GetCellType(c),
                                                        a.GetCellType(c)))
            sys.exit(1)
        for i in range(ia.GetNumberOfIds()):
            pa, pb = a.GetPoint(ia.GetId(i)), b.GetPoint(ib.GetId(i))
            if pa != pb:
                print("%s: cell %d node %d at %s, the .vtu %s" % (pvtu, c, i, pb, pa))
                sys.exit(1)
            pd_a, pd_b = a.GetPointData(), b.GetPointData()
            for k in range(pd_a.GetNumberOfArrays()):
                name = pd_a.GetArrayName(k)
                xb = pd_b.GetArray(name)
                if xb is None or pd_a.GetArray(k).GetTuple(ia.GetId(i)) != xb.GetTuple(ib.GetId(i)):
                    print("%s: point data %s differs at cell %d node %d" % (pvtu, name, c, i))
                    sys.exit(1)
        cd_a, cd_b = a.GetCellData(), b.GetCellData()
        for k in range(cd_a.GetNumberOfArrays()):
            name = cd_a.GetArrayName(k)
            xb = cd_b.GetArray(name)
            va = cd_a.GetArray(k).GetTuple(c)
            if xb is None or not np.array_equal(va, xb.GetTuple(c), equal_nan=True):
                print("%s: cell data %s differs at cell %d" % (pvtu, name, c))
                sys.exit(1)
    print("pvtu ok", a.GetNumberOfCells(), pieces)


main()
