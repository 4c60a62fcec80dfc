// tmop/tmop.h — the umbrella header of the C++ API: mesh model, file formats, quality, targets,
// metrics, optimization stages and recipes. Users never need Ceres headers.
#ifndef TMOP_TMOP_H_
#define TMOP_TMOP_H_

#include "tmop/core/status.h"
#include "tmop/element/cell_type.h"
#include "tmop/element/sample_points.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"
#include "tmop/mesh/orientation.h"
#include "tmop/mesh/topology.h"
#include "tmop/mesh/validate.h"
#include "tmop/metric/metric.h"
#include "tmop/optimize/stage.h"
#include "tmop/quality/quality_json.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/equal_edge.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/improve_surface.h"
#include "tmop/recipes/laplace.h"
#include "tmop/recipes/preserve.h"
#include "tmop/recipes/quadratic_shape.h"
#include "tmop/recipes/recipe.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/recipe_result.h"
#include "tmop/recipes/size_adapt.h"
#include "tmop/recipes/sliver.h"
#include "tmop/recipes/untangle.h"
#include "tmop/target/target.h"

#endif  // TMOP_TMOP_H_
