#pragma once
// The CIE 1931 2-degree standard observer (tabulated colour-matching functions), the film's
// observer in a spectral render. The table and its source are in cie1931.cpp.

#include <array>
#include <cstddef>

namespace lenslab::render {

struct Cie1931Row {
  double x, y, z;
};

inline constexpr double kCie1931FirstNm = 360.0;
inline constexpr double kCie1931StepNm = 5.0;
inline constexpr std::size_t kCie1931Rows = 95;  // 360..830 nm
extern const std::array<Cie1931Row, kCie1931Rows> kCie1931;

// The functions between the tabulated wavelengths: linear interpolation (0 outside the table).
inline Cie1931Row cie1931At(double wavelengthNm) {
  const double t = (wavelengthNm - kCie1931FirstNm) / kCie1931StepNm;
  if (!(t >= 0.0) || t > static_cast<double>(kCie1931Rows - 1)) return {0.0, 0.0, 0.0};
  const auto i = static_cast<std::size_t>(t);
  if (i + 1 >= kCie1931Rows) return kCie1931[kCie1931Rows - 1];
  const double f = t - static_cast<double>(i);
  const Cie1931Row& a = kCie1931[i];
  const Cie1931Row& b = kCie1931[i + 1];
  return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.z + f * (b.z - a.z)};
}

}  // namespace lenslab::render
