// tmop/target/composed_target.h
// Composed targets (TargetType::kComposed, "composed"): W = size x orientation x skew x aspect
// (target_factors.h gives the exact factorisation W = h R (v_t / det Q)^(1/d) Q D), each factor
// from its own source:
//
//   source     size h                 orientation R          skew Q / aspect D
//   ideal      1 (unit edge)          identity               the cell type's ideal element
//   equal      mean equivalent edge   -                      -
//              of the initial mesh
//   initial    the factor of the initial Jacobian A at the sample point (factor_jacobian: h from
//              det A, R, Q, D from the QR factorisation of A); A is the reference mesh's when
//              TargetSpec::reference is set. Needs det A > 0 there.
//   constant   `value`                `value`                `value`
//   field      a point_data array interpolated to the sample point with the cell's shape
//              functions (components = the value count below)
//   function   `function(x, values)` at the sample point's physical position x
//   smooth     aspect only: the initial mesh's stretch averaged over neighbouring cells
//              (smoothed_aspect.h): graded meshes keep their edge ratios, noise is removed
//
// Values, per factor, for d-dimensional elements (the same for constants, field components and
// function outputs):
//   size         1: h > 0, an equivalent edge length in the user's length units
//   orientation  2D: 2, the direction of R e1 (a 2D field may also have 3 components, the third
//                ignored, as .vtu vectors do); 3D: 6, R e1 and a vector in the plane of R e1 and
//                R e2. Directions in the user's axes.
//   skew         2D: 1, the angle between W's columns; 3D: 3, the angles (phi12, phi13, phi23);
//                degrees in (0, 180)
//   aspect       d positive relative lengths of W's columns (only ratios matter)
// "ideal" orientation is the identity of the frame the mesh is in (in a stage: the principal
// axes it solves in), as for every ideal target; constant, field and function orientations are
// directions in the user's frame (TargetSpec::frame maps them): "1,0" is the user's x axis. Surface
// meshes (2D cells in 3D) take their Jacobians in the cell's own plane (target_jacobian, target.h),
// so their orientation must be ideal or initial.
//
// With every factor from the initial mesh, W = A at every sample point (to rounding): "keep what
// is there", as TargetType::kReference. With every factor ideal and the size equal, W is the
// equal_size target (to rounding).
#ifndef TMOP_TARGET_COMPOSED_TARGET_H_
#define TMOP_TARGET_COMPOSED_TARGET_H_

#include <functional>
#include <string>
#include <vector>

#include "tmop/core/status.h"

namespace tmop {

class Mesh;
struct SampleSet;
struct TargetSpec;

enum class FactorSource {
  kIdeal,     // "ideal" ("identity" for the orientation)
  kMeanSize,  // "equal": the size only
  kInitial,   // "initial"
  kConstant,  // a list of numbers
  kField,     // "field:NAME"
  kFunction,  // C++ only
  kSmooth,    // "smooth": the aspect only, the initial mesh's smoothed stretch (smoothed_aspect.h)
};

enum class FactorKind { kSize, kOrientation, kSkew, kAspect };

struct TargetFactor {
  FactorSource source = FactorSource::kIdeal;
  std::vector<double> value;  // kConstant: the values listed above
  std::string field;          // kField: the name of a point_data array
  // kFunction: writes the values at x (3 coordinates in the user's frame, z = 0 for 2D meshes).
  // Called once per sample point, from the thread that builds the targets.
  std::function<void(const double* x, double* values)> function;
};

struct ComposedTarget {
  // The default is the equal_size target: mean size, identity, the ideal element's shape.
  TargetFactor size{FactorSource::kMeanSize, {}, {}, {}};
  TargetFactor orientation;
  TargetFactor skew;
  TargetFactor aspect;
};

// "size", "orientation", "skew", "aspect".
const char* factor_kind_name(FactorKind kind);

// Parses the command-line form of one factor's source:
//   ideal | initial | field:NAME | V1[,V2...]   (numbers: a constant)
//   size also: equal; orientation also: identity (= ideal) and angle:DEG (2D: R e1 at DEG
//   degrees from the x axis, counter-clockwise).
// Value counts are checked when the targets are built (they depend on the mesh's dimension).
// Fails for anything else with a one-line message naming the factor ("skew source 'x' is
// not ideal, initial, ...").
Status parse_target_factor(FactorKind kind, const std::string& text, TargetFactor* factor);

// What build_composed_targets would refuse before looking at any sample point (sources, value
// counts, constant values, fields, functions, the reference's topology): tools call it to tell
// a usage error from a mesh that cannot be optimized.
Status check_composed_target(const Mesh& mesh, const TargetSpec& spec);

// The composed branch of build_targets (target.h), which checks the mesh's dimension and the
// reference's topology first: call build_targets. W per point, d x d each, written to *W only on
// success. Fails, with a message naming the factor, for a source the factor does not have
// (equal for a non-size factor; a constant, field or function orientation on a surface mesh),
// a wrong value count, a missing field or function, values out of range (non-positive size,
// zero or parallel axes, impossible angles, non-positive lengths), and det A <= 0 at a point
// whose factors come from the initial mesh.
Status build_composed_targets(const Mesh& mesh, const SampleSet& points, const TargetSpec& spec,
                              std::vector<double>* W);

}  // namespace tmop

#endif  // TMOP_TARGET_COMPOSED_TARGET_H_
