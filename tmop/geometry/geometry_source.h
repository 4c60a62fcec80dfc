// tmop/geometry/geometry_source.h
// Where sliding surface vertices get their geometry from, as given by the user (the tools'
// --geometry flag, BoundaryOptions::geometry):
//
//   ""                               the input mesh's own boundary (default): nothing to load
//   "sphere:cx,cy,cz,r"              analytic sphere (r > 0)
//   "plane:px,py,pz,nx,ny,nz"        analytic plane through p with normal n (n != 0)
//   "cylinder:px,py,pz,dx,dy,dz,r"   analytic cylinder: axis through p along d (d != 0), r > 0
//   "PATH.stl|.obj|.off|.ply"        a reference surface file, used as a triangle surface
//
// Output: GeometrySource owning the manifold (null for the own boundary). Failure (Status): a
// malformed spec (one line naming what is wrong), or the file's read error.
#ifndef TMOP_GEOMETRY_GEOMETRY_SOURCE_H_
#define TMOP_GEOMETRY_GEOMETRY_SOURCE_H_

#include <memory>
#include <string>

#include "tmop/core/status.h"
#include "tmop/geometry/geometry_frame.h"
#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

enum class GeometrySourceKind { kOwnBoundary, kAnalytic, kSurfaceFile };

struct GeometrySource {
  GeometrySourceKind kind = GeometrySourceKind::kOwnBoundary;
  std::unique_ptr<GeometryManifold> surface;  // analytic or the file's triangles; else null
  std::string description;                    // for reports: "own boundary", "sphere", PATH
};

Status load_geometry_source(const std::string& spec, GeometrySource* out,
                            const GeometryFrame& frame = GeometryFrame());

}  // namespace tmop

#endif  // TMOP_GEOMETRY_GEOMETRY_SOURCE_H_
