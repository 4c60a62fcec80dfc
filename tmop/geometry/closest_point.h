// tmop/geometry/closest_point.h
// Closest points on the primitives of discrete geometry, exact up to round-off.
//
// closest_point_segment(dim, q, a, b, out, t): the point of segment [a, b] (dim 2 or 3) nearest
//   to q, written to out; *t in [0, 1] is its parameter (a + t (b - a)). Returns the squared
//   distance. A degenerate segment (a == b) returns a.
// closest_point_triangle(q, a, b, c, out): the point of triangle abc (3D) nearest to q. Returns
//   the squared distance. Degenerate (zero-area) triangles are handled through their edges.
#ifndef TMOP_GEOMETRY_CLOSEST_POINT_H_
#define TMOP_GEOMETRY_CLOSEST_POINT_H_

namespace tmop {

double closest_point_segment(int dim, const double* q, const double* a, const double* b,
                             double* out, double* t);
double closest_point_triangle(const double* q, const double* a, const double* b, const double* c,
                              double* out);

}  // namespace tmop

#endif  // TMOP_GEOMETRY_CLOSEST_POINT_H_
