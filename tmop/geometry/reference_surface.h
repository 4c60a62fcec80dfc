// tmop/geometry/reference_surface.h
// Reads a user's reference surface (.stl .obj .off .ply, through OpenMesh) as a triangle soup
// with shared vertices: polygons are split into fans. geometry/ reads the file itself rather
// than through io/ so that the geometry library keeps depending on mesh/ only (io/ sits beside
// it, not below it: docs/architecture.md).
//
// Output: vertices (nv * 3, vertex-major) and triangles (nt * 3 indices), replaced.
// Failure (Status "PATH: ..."): unknown extension, unreadable file, no triangles.
#ifndef TMOP_GEOMETRY_REFERENCE_SURFACE_H_
#define TMOP_GEOMETRY_REFERENCE_SURFACE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "tmop/core/status.h"

namespace tmop {

Status read_reference_surface(const std::string& path, std::vector<double>* vertices,
                              std::vector<std::int32_t>* triangles);

}  // namespace tmop

#endif  // TMOP_GEOMETRY_REFERENCE_SURFACE_H_
