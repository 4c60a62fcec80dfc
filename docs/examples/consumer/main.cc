// Improves the shape of a small 2D mesh built in code and prints the worst quality before and
// after: the smallest complete use of the C++ API.
#include <cstdio>

#include "tmop/tmop.h"

int main() {
  tmop::Mesh mesh;
  mesh.space_dim = 2;
  // a 3x3 vertex patch of quads with the centre vertex pulled off-centre
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double x[2] = {i * 0.5 + (i == 1 && j == 1 ? 0.2 : 0.0), j * 0.5};
      mesh.add_vertex(x);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const std::int32_t q[4] = {3 * j + i, 3 * j + i + 1, 3 * (j + 1) + i + 1, 3 * (j + 1) + i};
      mesh.add_cell(tmop::CellType::kQuad4, q);
    }
  tmop::RecipeResult result;
  tmop::Status s = tmop::improve_shape(&mesh, tmop::ShapeOptions(), &result);
  if (!s.ok()) {
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return 1;
  }
  std::printf("worst quality %.6f -> %.6f, centre at (%.6f, %.6f)\n", result.before.min_quality,
              result.after.min_quality, mesh.vertex(4)[0], mesh.vertex(4)[1]);
  // Quads are given ideal angles with their neighbourhood's aspect (docs/quality.md): in a patch
  // this small the boundary corners' cells keep a little of the pulled vertex's stretch.
  return result.after.min_quality > 0.99 ? 0 : 1;
}
