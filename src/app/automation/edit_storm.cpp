#include "app/automation/edit_storm.h"

#include <cmath>
#include <limits>

namespace lenslab::app {

namespace {
constexpr std::size_t kSurfacesNamed = 16;
}  // namespace

double EditStorm::uniform(double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(random_);
}

EditCommand EditStorm::next() {
  // 0..100 the edits of a spherical lens; 100..110 a conic or an aspheric term (issue 40).
  const double kind = uniform(0.0, 110.0);
  const auto surface = std::uniform_int_distribution<std::size_t>(0, kSurfacesNamed - 1)(random_);
  const double odd = uniform(0.0, 1.0);  // picks the absurd value of a field now and then
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (kind < 36) {
    // Radii: mostly a real lens's, sometimes 0 (a second stop), flat, or so small that the
    // surface's sag passes its neighbours.
    const double sign = uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    const double radius = odd < 0.08   ? 0.0
                          : odd < 0.16 ? std::numeric_limits<double>::infinity()
                          : odd < 0.26 ? sign * uniform(0.05, 2.0)
                                       : sign * uniform(12.0, 200.0);
    return SetSurfaceField{surface, SurfaceField::RadiusMm, radius};
  }
  if (kind < 52) {
    const double thickness = odd < 0.05 ? nan : odd < 0.2 ? uniform(-5.0, 0.0) : uniform(0.2, 25.0);
    return SetSurfaceField{surface, SurfaceField::ThicknessMm, thickness};
  }
  if (kind < 62) {
    const double index = odd < 0.15 ? uniform(0.0, 1.0) : uniform(1.0, 2.0);
    return SetSurfaceField{surface, SurfaceField::IndexD, index};
  }
  if (kind < 67) {
    // NaN clears the Abbe number (a non-dispersive glass); negative ones are invalid.
    const double abbe = odd < 0.2 ? nan : odd < 0.3 ? uniform(-10.0, 0.0) : uniform(18.0, 95.0);
    return SetSurfaceField{surface, SurfaceField::AbbeD, abbe};
  }
  if (kind < 77) {
    const double aperture = odd < 0.1   ? 0.0
                            : odd < 0.2 ? uniform(80.0, 1000.0)
                                        : uniform(4.0, 60.0);
    return SetSurfaceField{surface, SurfaceField::ApertureDiameterMm, aperture};
  }
  if (kind < 83) return SetFilmDistance{odd < 0.1 ? uniform(-20.0, 0.0) : uniform(5.0, 120.0)};
  if (kind < 89) return SetStopDiameter{odd < 0.1 ? uniform(100.0, 1000.0) : uniform(0.5, 50.0)};
  if (kind < 91) return FlipLens{};
  if (kind < 93) return ScaleLens{uniform(0.5, 2.0)};
  if (kind < 95) return MakeStop{surface};
  if (kind < 97) return DeleteSurface{surface};
  if (kind >= 105) {
    // A term worth a few hundredths of a millimetre at 10 mm from the axis, as real aspheres'
    // are; now and then one whose term overflows a double long before the rim (1e30 r^20), or
    // one on the stop (refused), or a power there is none of (refused).
    const int power = std::uniform_int_distribution<int>(odd < 0.05 ? 0 : 2, 20)(random_);
    const double sign = uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    const double value =
        odd < 0.1 ? sign * 1e30 : sign * uniform(0.01, 0.05) / std::pow(10.0, power);
    return SetAsphericTerm{surface, power, value};
  }
  if (kind >= 100) {
    // Conics: ellipsoids, paraboloids and hyperboloids; now and then one so steep that its sag
    // has no real value inside the aperture.
    const double conic = odd < 0.1 ? uniform(50.0, 1e4) : uniform(-4.0, 1.0);
    return SetSurfaceField{surface, SurfaceField::Conic, conic};
  }
  optics::Surface inserted;
  inserted.radiusMm = uniform(-150.0, 150.0);
  inserted.thicknessMm = uniform(-1.0, 12.0);
  inserted.indexD = uniform(1.0, 1.9);
  inserted.apertureDiameterMm = uniform(5.0, 50.0);
  return InsertSurface{surface, inserted};
}

}  // namespace lenslab::app
