// tmop/geometry/triangle_surface_manifold.h
// TriangleSurfaceManifold: a triangle mesh in 3D used as a surface (ambient 3, tangent 2): the
// discrete boundary patches of the input mesh (built from the ORIGINAL facets, so repeated
// projections do not drift) or a user's reference surface.
//
// Chart at x: x's closest triangle T(x) (box-tree query) gives the unit normal n and the tangent
// pair (u, v) (vec3::tangent_basis, fixed per triangle). Plus(x, d) walks the straightest path
// from x in the direction w = d0 u + d1 v for the length |w| ON the triangle mesh: inside a
// triangle it moves straight; crossing an edge it unfolds the direction into the neighbouring
// triangle's plane (keeping its angle to the edge), so it needs no projection at all and can
// never jump to another sheet, however close (two parallel sheets, the sides of a thin plate).
// The walk stops at a border edge of the mesh (an open patch's rim) and after 4096 crossings.
// Why not "tangent step + closest-point projection within a radius ~ edge length": tested on two
// coarse concentric spheres 0.2 edge lengths apart, the projection landed on the outer sheet for
// steps of half an edge (a step leaves a coarse surface by ~ step x sin(dihedral angle)).
// Minus(y, x) = [u v]^T (y - x) when y is in T(x) (exact), y unfolded across the shared edge
// when y is in a neighbouring triangle (exact for one crossing), otherwise the length-preserving
// projection of y - x onto T(x)'s plane (first order). PlusJacobian = [u v], MinusJacobian =
// [u v]^T. Results of Plus are snapped onto their final triangle: on the mesh to round-off.
//
// Smooth shape (Shape::kSmooth, the own-boundary patches of boundary_constraints.h): the walk
// above runs on the flat triangles as a parameter domain, and every point is mapped onto a
// smooth surface through the vertices: per triangle a cubic Bezier patch built from the vertex
// normals (angle-weighted facet normals), like Vlachos et al.'s PN triangles but with the edge
// handles of a circular arc (length |c| / (3 cos^2(a/2)) along the chord c projected onto the
// vertex's tangent plane, a the chord's angle to that plane), so a sphere or cylinder through
// the vertices is reproduced to O(h^6) instead of O(h^4). An edge's curve depends only on its
// two vertices and their normals: neighbouring patches meet exactly (C0; G1 at the vertices).
// Where the normals agree with the facet (a flat region) the patch is the flat triangle, to
// round-off. A point x is located by solving b_T(lambda) + s n_T = x (Newton, 3 unknowns) on
// the triangles whose control-point boxes (which hold their patches) are nearest, so Plus(x, 0)
// = x to round-off; PlusJacobian = Db [u v] (the walk's tangent pair pushed onto the patch: a
// tangent basis, not orthonormal), MinusJacobian its left inverse along n_T, Normal the patch
// normal. Edges whose chord makes more than 60 degrees with a vertex's tangent plane stay
// straight (a normal that does not describe them).
//
// Construction: vertices (nv * 3) and triangles (nt * 3 indices, consistently oriented for
// Normal() to be meaningful). Triangles sharing an edge with exactly one other triangle are
// neighbours; edges of 1 or >= 3 triangles are borders. Zero-area triangles are dropped. At least
// one triangle must remain (CHECK).
#ifndef TMOP_GEOMETRY_TRIANGLE_SURFACE_MANIFOLD_H_
#define TMOP_GEOMETRY_TRIANGLE_SURFACE_MANIFOLD_H_

#include <cstdint>
#include <vector>

#include "tmop/geometry/aabb_tree.h"
#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

class TriangleSurfaceManifold : public GeometryManifold {
 public:
  enum class Shape { kFlat, kSmooth };
  TriangleSurfaceManifold(std::vector<double> vertices, const std::vector<std::int32_t>& triangles,
                          Shape shape = Shape::kFlat);

  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 2; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // 3x2 row-major
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 2x3 row-major

  void Project(const double* x, double* closest) const override;
  bool Normal(const double* x, double* n) const override;  // of the closest triangle

  int num_triangles() const { return static_cast<int>(triangles_.size() / 3); }
  bool smooth() const { return !patches_.empty(); }

 private:
  // Closest triangle to x among those within sqrt(max_dist2) (infinity: all) -> index (or -1)
  // and the closest point.
  int locate(const double* x, double max_dist2, double* closest) const;
  const double* corner(int tri, int k) const {
    return vertices_.data() + 3 * triangles_[3 * tri + k];
  }
  const double* frame(int tri) const { return frames_.data() + 9 * tri; }  // n, u, v
  // Walks from p (on triangle *tri) for the length len along the unit direction w (in the
  // triangle's plane); updates p, w and *tri.
  void walk(int* tri, double* p, double* w, double len) const;
  // Leaving the mesh vertex at corner `corner_index` of tri in direction w: the triangle of the
  // vertex's fan that w points into; w is projected onto its plane.
  int leave_vertex(int tri, int corner_index, double* w) const;

  // Smooth shape (triangle_surface_smooth.cc): the vertex normals and patches, built after the
  // flat triangles; lo / hi: the flat triangles' boxes in, the patches' boxes out.
  void build_smooth(std::vector<double>* lo, std::vector<double>* hi);
  // Smooth shape: x's triangle, barycentric coordinates lam[3] and point of the patch.
  int locate_smooth(const double* x, double* lam, double* on) const;
  // Solves b_tri(lam) + s n_tri = x from the flat projection; lam clamped to the triangle
  // (returns false when it had to be).
  bool solve_patch(int tri, const double* x, double* lam, double* on) const;
  // The patch point at lam and its partial derivatives d/dlam_a (homogeneous, dl[3 * a + i]).
  void eval_patch(int tri, const double* lam, double* out, double* dl) const;
  // The patch's tangents along the flat frame's u and v at lam: columns ju, jv.
  void patch_tangents(int tri, const double* lam, double* ju, double* jv) const;
  // Minus of two points ON the flat triangles (y in ty, x in tx).
  void flat_minus(const double* y, int ty, const double* x, int tx, double* y_minus_x) const;
  const double* patch(int tri) const { return patches_.data() + 30 * tri; }

  std::vector<double> vertices_;
  std::vector<std::int32_t> triangles_;
  std::vector<double> frames_;            // per triangle: unit normal, u, v
  std::vector<std::int32_t> neighbours_;  // per triangle: across the edge opposite corner k
  std::vector<double> patches_;           // smooth shape: per triangle 10 Bezier control points
  AabbTree tree_;       // boxes of the triangles (smooth: of their control points)
  AabbTree flat_tree_;  // smooth shape: boxes of the flat triangles
  double scale_ = 1;    // bounding-box diagonal of the vertices
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_TRIANGLE_SURFACE_MANIFOLD_H_
