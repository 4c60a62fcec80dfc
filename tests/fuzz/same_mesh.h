// tests/fuzz/same_mesh.h
// The fuzz target's round-trip check (docs/fuzzing.md): what a mesh written in a family and read
// back must keep, by what the format holds (docs/formats.md).
//
//   holds(family, binary): coordinates exact, or float32 (.obj .off .ply always: OpenMesh writes
//     float32; binary .stl), .obj's then in fixed notation with 17 decimals (OpenMesh's OBJ
//     writer: 3.3e-11 keeps 7 digits, below 5e-18 is 0), whether the vertex list is kept (not .stl:
//     vertices are merged points), whether a 2D mesh's plane_z is kept (not .su2), regions (all
//     cells; boundary cells only for .su2 and .ugrid; none for .stl .obj .off .ply) and names (.msh
//     .vtk .vtu .exo (up to 255 characters), .su2 boundary cells; not .cgns, whose rules on names
//     are narrower: formats.md).
//   mesh_difference(a, b, h): "" when b keeps what h says of a, else the first difference. A 3D
//     mesh read back flattened from a float32 format (its x, y rounded, finish_read then finds
//     its z within 1e-12 of the extent) is compared in x, y, its z against that bound. The
//     values of a are turned into what the format stores (float32, fixed decimals), those of b
//     must equal them bit for bit.
//     Vertices are compared index by index; cells as multisets keyed by (type, the coordinates of
//     their nodes in order; the polygon rotated to its least corner for OpenMesh) because
//     readers regroup cells by type or block. Regions: a cell's region may be renumbered (Exodus
//     block ids, msh entity splits) but consistently: (type, region in a) -> region in b is one
//     function and one-to-one; cells with a duplicate key are not used for it. Names: the name
//     of each cell's (dimension, region) is the same string.
#ifndef TMOP_TESTS_FUZZ_SAME_MESH_H_
#define TMOP_TESTS_FUZZ_SAME_MESH_H_

#include <cstddef>
#include <string>

#include "tmop/mesh/mesh.h"

namespace tmop_fuzz {

struct Holds {
  bool float32 = false;
  int fixed_decimals = 0;  // > 0: written as "%.*f" (OpenMesh's .obj: fixed, 17 decimals)
  bool vertices = true;
  bool plane_z = true;
  bool rotate_polygons = false;
  enum Regions { kNone, kBoundary, kAll } regions = kAll;
  bool names = true;
  std::size_t name_max = std::string::npos;
};

Holds holds(const std::string& family, bool binary);

std::string mesh_difference(const tmop::Mesh& a, const tmop::Mesh& b, const Holds& h);

}  // namespace tmop_fuzz

#endif  // TMOP_TESTS_FUZZ_SAME_MESH_H_
