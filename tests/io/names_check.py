#!/usr/bin/python3
"""Independent makers and readers of physical names for tmop's io tests (/usr/bin/python3).

  names_check.py make-gmsh DIR    mesh a unit square with python3-gmsh: physical groups
                                  "fluid domain" (2, 7), "inlet" (1, 3), "outlet" (1, 4),
                                  "wall" (1, 5), left / right curves periodic (x + 1); writes
                                  DIR/named.msh (4.1) and DIR/named22.msh (2.2)
  names_check.py names FILE...    print "FILE<TAB>name|name|..." (sorted) as the format's
                                  client reads it: .msh the Gmsh API, .vtu meshio's field_data
                                  (and VTK's field data when python3-vtk9 is there: both must
                                  agree), .vtk VTK's field data (meshio 5 does not keep it), .exo netCDF4's eb_names, .su2 the MARKER_TAG lines of
                                  a file meshio parses (meshio keeps no marker names), .cgns
                                  the element section names (other than tmop's Region_R_TYPE)
                                  of the first zone through h5py
  names_check.py sides FILE...    print "FILE<TAB>name|name|..." (sorted) of the boundary sets
                                  solvers read: .exo netCDF4's ss_names (side sets), .cgns the
                                  BC_t names under ZoneBC_t of the first zone through h5py; with
                                  python3-vtk9, vtkExodusIIReader's side set names and
                                  vtkCGNSReader's BC patch names must be the same
  names_check.py periodic FILE    print the number of periodic node pairs the Gmsh API reads
"""
import sys


def gmsh_names(path):
    import gmsh
    gmsh.clear()
    gmsh.open(path)
    return [gmsh.model.getPhysicalName(d, t) for d, t in gmsh.model.getPhysicalGroups()]


def vtu_names(path):
    import meshio
    m = meshio.read(path)
    names = sorted(m.field_data.keys())
    try:
        import vtk
    except ImportError:
        return names
    if path.endswith(".vtk"):
        # meshio 5 files dataset-level FIELD arrays of legacy files under its dataset info, not
        # field_data: VTK alone reads the names there.
        names = sorted(vtk_field_names(path))
        m.field_data = {n: None for n in names}
    r = vtk.vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else vtk.vtkUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    fd = r.GetOutput().GetFieldData()
    vnames = sorted(fd.GetArrayName(i) for i in range(fd.GetNumberOfArrays()))
    if vnames != names:
        raise SystemExit("VTK reads field data %s, meshio %s" % (vnames, names))
    for i in range(fd.GetNumberOfArrays()):
        a = fd.GetArray(i)
        values = m.field_data[fd.GetArrayName(i)]
        if a.GetNumberOfTuples() != 2 or (values is not None and list(values) != [
                a.GetValue(0), a.GetValue(1)]):
            raise SystemExit("VTK and meshio disagree on " + fd.GetArrayName(i))
    return names


def vtk_field_names(path):
    import vtk
    r = vtk.vtkUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    fd = r.GetOutput().GetFieldData()
    return [fd.GetArrayName(i) for i in range(fd.GetNumberOfArrays())]


def exo_names(path):
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        if "eb_names" not in nc.variables:
            return []
        v = nc.variables["eb_names"]
        v.set_auto_mask(False)
        return [b"".join(row).decode().rstrip("\0") for row in v[:]]


def su2_names(path):
    import meshio
    meshio.read(path)  # meshio parses the file (it replaces names by numbers)
    out = []
    with open(path) as f:
        for line in f:
            if line.strip().startswith("MARKER_TAG"):
                out.append(line.split("=", 1)[1].strip())
    return out


def cgns_names(path):
    import h5py

    def children(node, label):
        return [k for k in node.keys() if node[k].attrs.get("label", b"") == label]
    with h5py.File(path, "r") as f:
        base = f[children(f, b"CGNSBase_t")[0]]
        zone = base[children(base, b"Zone_t")[0]]
        return [k for k in children(zone, b"Elements_t") if not k.startswith("Region_")]


def exo_side_names(path):
    import netCDF4
    with netCDF4.Dataset(path) as nc:
        names = []
        if "ss_names" in nc.variables:
            v = nc.variables["ss_names"]
            v.set_auto_mask(False)
            names = [b"".join(row).decode().rstrip("\0") for row in v[:]]
    try:
        import vtk
    except ImportError:
        return names
    r = vtk.vtkExodusIIReader()
    r.SetFileName(path)
    r.UpdateInformation()
    E = vtk.vtkExodusIIReader
    vnames = [r.GetObjectName(E.SIDE_SET, i) for i in range(r.GetNumberOfObjects(E.SIDE_SET))]
    if sorted(vnames) != sorted(names):
        raise SystemExit("VTK reads side sets %s, netCDF4 %s" % (vnames, names))
    return names


def cgns_bc_names(path):
    import h5py

    def children(node, label):
        return [k for k in node.keys() if node[k].attrs.get("label", b"") == label]
    with h5py.File(path, "r") as f:
        base = f[children(f, b"CGNSBase_t")[0]]
        zone = base[children(base, b"Zone_t")[0]]
        names = []
        for zbc in children(zone, b"ZoneBC_t"):
            names += children(zone[zbc], b"BC_t")
    try:
        import vtk
    except ImportError:
        return names
    r = vtk.vtkCGNSReader()
    r.SetFileName(path)
    r.UpdateInformation()
    r.EnableAllBases()
    r.LoadBndPatchOn()
    r.Update()
    vnames = []
    out = r.GetOutput()
    for b in range(out.GetNumberOfBlocks()):
        base = out.GetBlock(b)
        for z in range(base.GetNumberOfBlocks()):
            zone = base.GetBlock(z)
            for p in range(zone.GetNumberOfBlocks()):
                if zone.GetMetaData(p).Get(vtk.vtkCompositeDataSet.NAME()) != "Patches":
                    continue
                patches = zone.GetBlock(p)
                vnames += [patches.GetMetaData(i).Get(vtk.vtkCompositeDataSet.NAME())
                           for i in range(patches.GetNumberOfBlocks())]
    if sorted(vnames) != sorted(names):
        raise SystemExit("VTK reads BC patches %s, h5py %s" % (vnames, names))
    return names


def make_gmsh(outdir):
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("named")
    gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    # OCC numbers the rectangle's curves bottom 1, right 2, top 3, left 4.
    gmsh.model.mesh.setPeriodic(1, [2], [4], [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])
    for dim, tags, tag, name in ((2, [1], 7, "fluid domain"), (1, [4], 3, "inlet"),
                                 (1, [2], 4, "outlet"), (1, [1, 3], 5, "wall")):
        gmsh.model.addPhysicalGroup(dim, tags, tag)
        gmsh.model.setPhysicalName(dim, tag, name)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.1)
    gmsh.model.mesh.generate(2)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.write(outdir + "/named.msh")
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(outdir + "/named22.msh")
    gmsh.finalize()


def periodic_pairs(path):
    import gmsh
    gmsh.clear()
    gmsh.open(path)
    n = 0
    for dim, tag in gmsh.model.getEntities():
        master, nodes, _, _ = gmsh.model.mesh.getPeriodicNodes(dim, tag)
        if master != tag:
            n += len(nodes)
    return n


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    if sys.argv[1] == "make-gmsh":
        make_gmsh(sys.argv[2])
        return
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    if sys.argv[1] == "periodic":
        print(periodic_pairs(sys.argv[2]))
    elif sys.argv[1] == "names":
        readers = {"msh": gmsh_names, "vtu": vtu_names, "vtk": vtu_names, "exo": exo_names, "su2": su2_names,
                   "cgns": cgns_names}
        for path in sys.argv[2:]:
            names = readers[path.rsplit(".", 1)[-1]](path)
            print(path + "\t" + "|".join(sorted(names)))
    elif sys.argv[1] == "sides":
        readers = {"exo": exo_side_names, "cgns": cgns_bc_names}
        for path in sys.argv[2:]:
            names = readers[path.rsplit(".", 1)[-1]](path)
            print(path + "\t" + "|".join(sorted(names)))
    else:
        sys.exit(__doc__)
    gmsh.finalize()


if __name__ == "__main__":
    main()
