#include "render/transform_check.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace lenslab::render {

std::optional<std::string> transformProblem(const glm::dmat4& m) {
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      if (!std::isfinite(m[column][row])) return "has a non-finite entry (NaN or infinity)";
    }
  }
  // |det| against the product of the column lengths (Hadamard's bound): 1 for any rotation and
  // scale, 0 for a collapsed axis, whatever the scene's units.
  const glm::dmat3 linear(m);
  const double bound = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
  const double det = glm::determinant(linear);
  if (!std::isfinite(bound) || !std::isfinite(det)) {
    return "scales beyond the range of double precision";
  }
  if (!(std::abs(det) > 1e-12 * bound)) {
    return "is singular (it collapses space onto a plane, a line or a point)";
  }
  const glm::dmat4 inverse = glm::inverse(m);
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      if (!std::isfinite(inverse[column][row])) return "cannot be inverted in double precision";
    }
  }
  return std::nullopt;
}

}  // namespace lenslab::render
