#include "tmop/geometry/geometry_manifold.h"

#include <cmath>

namespace tmop {

double GeometryManifold::Distance(const double* x) const {
  double p[3] = {0, 0, 0};
  Project(x, p);
  double s = 0;
  for (int i = 0; i < AmbientSize(); ++i) s += (x[i] - p[i]) * (x[i] - p[i]);
  return std::sqrt(s);
}

}  // namespace tmop
