#pragma once
// Degrees and radians: users and the lens files speak degrees, the maths radians.

#include <numbers>

namespace lenslab {

inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

}  // namespace lenslab
