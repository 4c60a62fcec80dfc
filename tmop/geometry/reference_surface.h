// tmop/geometry/reference_surface.h
// Reads a user's reference surface (.stl .obj .off .ply) with tmop's own readers (io/) as a
// triangle soup with shared vertices: quads and polygons (up to 64 corners) are split into fans,
// facets with a repeated corner are dropped (counted in *report when given), vertices no
// triangle uses are left out.
//
// Output: vertices (nv * 3, vertex-major) and triangles (nt * 3 indices), replaced.
// Failure (Status "PATH: ...", with the line or byte for malformed files): unknown
// extension, unreadable or malformed file, no triangles.
#ifndef TMOP_GEOMETRY_REFERENCE_SURFACE_H_
#define TMOP_GEOMETRY_REFERENCE_SURFACE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/io/mesh_io.h"

namespace tmop {

Status read_reference_surface(const std::string& path, std::vector<double>* vertices,
                              std::vector<std::int32_t>* triangles,
                              SurfaceRepair* report = nullptr);

}  // namespace tmop

#endif  // TMOP_GEOMETRY_REFERENCE_SURFACE_H_
