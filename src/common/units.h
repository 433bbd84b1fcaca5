#pragma once
// Unit conversions the lens's millimetres need: spots, fans and blur are read in micrometres.

namespace lenslab {

inline constexpr double kMicronsPerMm = 1000.0;

}  // namespace lenslab
