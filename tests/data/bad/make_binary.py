#!/usr/bin/python3
"""Writes the binary members of tmop's bad-input corpus (run from this directory).

The text members are small hand-written files; these need exact bytes, so they are generated.
Deterministic: rerunning reproduces the committed files.
"""
import base64
import random
import struct

MSH22_HEAD = b"$MeshFormat\n2.2 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n"
MSH41_HEAD = b"$MeshFormat\n4.1 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n"


def nodes22(coords):
    out = b"$Nodes\n%d\n" % len(coords)
    for i, (x, y, z) in enumerate(coords):
        out += struct.pack("<iddd", i + 1, x, y, z)
    return out + b"\n$EndNodes\n"


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


rng = random.Random(1234)
write("binary_garbage.msh", bytes(rng.randrange(256) for _ in range(300)))
write("garbage_after_header41.msh",
      MSH41_HEAD + b"$Nodes\n" + bytes(rng.randrange(256) for _ in range(200)))
write("wrong_endianness22.msh",
      b"$MeshFormat\n2.2 1 8\n" + struct.pack(">i", 1) + b"\n$EndMeshFormat\n")
write("wrong_datasize22.msh", b"$MeshFormat\n2.2 1 4\n" + struct.pack("<i", 1) +
      b"\n$EndMeshFormat\n")
tri = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
# One tri3 with 2 tags: header (type, count, tags), then id, physical, elementary, three nodes.
elements = b"$Elements\n1\n" + struct.pack("<iii", 2, 1, 2) + struct.pack("<iii", 1, 0, 1)
write("truncated_binary22.msh", MSH22_HEAD + nodes22(tri) + elements)  # element nodes missing
write("nan_binary22.msh", MSH22_HEAD + nodes22([(0.0, float("nan"), 0.0)]))
write("bad_node_binary22.msh", MSH22_HEAD + nodes22(tri) + elements +
      struct.pack("<iii", 1, 2, 7) + b"\n$EndElements\n")  # node tag 7 is not defined
write("huge_count_binary41.msh",
      MSH41_HEAD + b"$Nodes\n" + struct.pack("<QQQQ", 1, 1 << 40, 1, 1 << 40) + b"\n$EndNodes\n")
write("truncated_binary.vtk", b"# vtk DataFile Version 3.0\nbad\nBINARY\n"
      b"DATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n" + struct.pack(">dd", 0.0, 1.0))
write("inf_binary.vtk", b"# vtk DataFile Version 3.0\nbad\nBINARY\n"
      b"DATASET UNSTRUCTURED_GRID\nPOINTS 1 float\n" + struct.pack(">fff", 0.0, float("inf"), 0.0)
      + b"\n")
write("truncated_binary.stl", b"tmop bad".ljust(80, b" ") + struct.pack("<I", 10) + bytes(50))

VTU = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
       'byte_order="LittleEndian" header_type="UInt64"%s>\n<UnstructuredGrid>\n'
       '<Piece NumberOfPoints="1" NumberOfCells="0">\n<Points>\n'
       '<DataArray type="Float64" NumberOfComponents="3" format="%s"%s>%s</DataArray>\n'
       '</Points>\n</Piece>\n</UnstructuredGrid>\n%s</VTKFile>\n')
point = struct.pack("<ddd", 0.0, 1.0, 2.0)
lying = base64.b64encode(struct.pack("<Q", 1000) + point).decode()
write("wrong_byte_count.vtu", (VTU % ("", "binary", "", lying, "")).encode())
zlib_garbage = base64.b64encode(struct.pack("<QQQQ", 1, 24, 24, 12)).decode() + \
    base64.b64encode(b"not zlib at all").decode()
write("corrupt_zlib.vtu",
      (VTU % (' compressor="vtkZLibDataCompressor"', "binary", "", zlib_garbage, "")).encode())
write("appended_offset_beyond.vtu",
      (VTU % ("", "appended", ' offset="999999"', "",
              '<AppendedData encoding="raw">\n_')).encode() + struct.pack("<Q", 24) + point +
      b"\n</AppendedData>\n")

# Surface formats (OpenMesh's binary layouts: little-endian, float32 coordinates).
PLY_HEAD = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
            b"property float y\nproperty float z\nelement face 1\n"
            b"property list uchar int vertex_indices\nend_header\n")
good_vertices = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
write("nan_binary.ply", PLY_HEAD + struct.pack("<9f", 0, 0, 0, 1, float("nan"), 0, 0, 1, 0) +
      struct.pack("<B3i", 3, 0, 1, 2))
write("index_out_of_range_binary.ply", PLY_HEAD + good_vertices + struct.pack("<B3i", 3, 0, 1, 3))
write("truncated_binary.ply", PLY_HEAD + good_vertices + struct.pack("<B2i", 3, 0, 1))
OFF_HEAD = b"OFF BINARY\n" + struct.pack("<3i", 3, 1, 0)
write("index_out_of_range_binary.off", OFF_HEAD + good_vertices + struct.pack("<4i", 3, 0, 1, 5))
write("truncated_binary.off", OFF_HEAD + good_vertices + struct.pack("<3i", 3, 0, 1))


def stl_binary(corners):
    out = b"tmop bad".ljust(80, b" ") + struct.pack("<I", len(corners))
    for tri in corners:
        out += struct.pack("<3f", 0, 0, 1) + struct.pack("<9f", *tri) + struct.pack("<H", 0)
    return out


write("nan_binary.stl", stl_binary([(0, 0, 0, 1, 0, 0, 0, 1, 0), (0, 0, 0, 0, 1, 0, 0, float("inf"), 1)]))
write("no_triangles_binary.stl", stl_binary([]))
