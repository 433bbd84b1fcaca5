#include "optics/stop_cells.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <numbers>

namespace lenslab::optics {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kSectorRad = kTwoPi / kStarHullSectors;
// Cells at most this wide (15 degrees): the sweep of three straight blades is then 23% larger
// than the triangle, of six 7%. Each measured cell costs about twice the circle's whole table to
// build (a full circle of directions, not a half-plane): with 7.5 degrees three blades kept 83%
// of the samples instead of 76%, but their table took 32 ms instead of 16-20 (the circle's: 3).
// (So three blades, the widest period, get 8 cells.)
constexpr double kCellWidthRad = 15.0 * std::numbers::pi / 180.0;
// Blades' hull counts as mirror-symmetric about a corner's direction when making it so grows
// it by at most this (it is, but for the sectors' rounding).
constexpr double kMirrorGrowth = 1.001;
// A hull this close to its circumscribed circle gains too little from cells to pay for them.
constexpr double kCircleLikeShare = 0.9;
constexpr int kSweptMaskPx = 256;

int sectorOf(double angleRad) { return static_cast<int>(std::floor(angleRad / kSectorRad)); }

// Largest value of a periodic table over any range of sectors (a sparse table over two periods).
class RangeMax {
 public:
  explicit RangeMax(const std::vector<float>& values) : n_(static_cast<int>(values.size())) {
    levels_.push_back(values);
    levels_[0].insert(levels_[0].end(), values.begin(), values.end());
    for (int width = 2; width <= n_; width *= 2) {
      const std::vector<float>& last = levels_.back();
      std::vector<float> next(last.size() - width / 2);
      for (std::size_t i = 0; i < next.size(); ++i)
        next[i] = std::max(last[i], last[i + width / 2]);
      levels_.push_back(std::move(next));
    }
    overall_ = *std::max_element(values.begin(), values.end());
  }
  // Sectors first..last (last >= first; any integers, taken modulo the period).
  float over(int first, int last) const {
    if (last - first + 1 >= n_) return overall_;
    const int start = ((first % n_) + n_) % n_;
    const int count = last - first + 1;
    int level = 0;
    while ((2 << level) <= count) ++level;
    const std::vector<float>& row = levels_[level];
    return std::max(row[start], row[start + count - (1 << level)]);
  }
  // Angles [from, to) (radians, to > from), every sector they reach into. (Both ends are taken a
  // hair inward, so that a range starting or ending on a sector boundary, up to rounding, does not
  // take in the sector beyond it.)
  float overAngles(double fromRad, double toRad) const {
    const int first = sectorOf(fromRad + 1e-9);
    return over(first, std::max(first, sectorOf(toRad - 1e-9)));
  }

 private:
  int n_;
  std::vector<std::vector<float>> levels_;
  float overall_ = 0.0f;
};

double hullArea(const std::vector<float>& rho) {
  double sum = 0.0;
  for (const float r : rho) sum += static_cast<double>(r) * r;
  return 0.5 * sum * kSectorRad;
}

// The hull folded to repeat after `periodRad`: sector k takes the largest rho over the sector
// and its turns by the multiples of the period.
std::vector<float> folded(const RangeMax& rho, double periodRad, int repeats) {
  std::vector<float> out(kStarHullSectors, 0.0f);
  for (int k = 0; k < kStarHullSectors; ++k) {
    float best = 0.0f;
    for (int m = 0; m < repeats; ++m)
      best = std::max(best, rho.overAngles(k * kSectorRad + m * periodRad,
                                           (k + 1) * kSectorRad + m * periodRad));
    out[k] = best;
  }
  return out;
}

// The hull made mirror-symmetric about the axis at angle m pi / kStarHullSectors (m half-sectors):
// sector k's mirror image is sector m - 1 - k.
std::vector<float> symmetrized(const std::vector<float>& hull, int m) {
  std::vector<float> out(hull.size());
  const int n = static_cast<int>(hull.size());
  for (int k = 0; k < n; ++k) out[k] = std::max(hull[k], hull[(((m - 1 - k) % n) + n) % n]);
  return out;
}

// Whether the hull is mirror-symmetric, to within kMirrorGrowth, about the axis at m
// half-sectors.
bool mirrorsAbout(const std::vector<float>& hull, int m) {
  return hullArea(symmetrized(hull, m)) <= kMirrorGrowth * hullArea(hull);
}

}  // namespace

std::vector<float> starHullUnit(const ApertureShape& shape) {
  switch (shape.kind) {
    case ApertureShape::Kind::Circle:
      return std::vector<float>(kStarHullSectors, 1.0f);
    case ApertureShape::Kind::Image:  // the circle through the farthest open pixel
      return std::vector<float>(kStarHullSectors, static_cast<float>(shape.boundRadiusFactor()));
    case ApertureShape::Kind::Blades:
      break;
  }
  // Blades are convex and contain the centre; along each edge (straight, or an arc bulging out
  // less than the stop circle) the distance from the centre grows monotonically from the
  // edge's middle to its corners. So over a sector it is largest at one of the sector's ends,
  // or 1 at a corner inside it.
  std::vector<double> atEdge(kStarHullSectors + 1);
  for (int k = 0; k <= kStarHullSectors; ++k) atEdge[k] = shape.edgeDistanceUnit(k * kSectorRad);
  std::vector<float> rho(kStarHullSectors);
  for (int k = 0; k < kStarHullSectors; ++k)
    rho[k] = static_cast<float>(std::min(1.0, std::max(atEdge[k], atEdge[k + 1])) * (1.0 + 1e-6));
  for (int c = 0; c < shape.bladeCount; ++c) {
    double corner = std::fmod(
        (shape.rotationDeg + 360.0 * c / shape.bladeCount) * std::numbers::pi / 180.0, kTwoPi);
    if (corner < 0.0) corner += kTwoPi;
    // The corner's sector, and its neighbour when it sits on the boundary between them.
    for (const int k : {sectorOf(corner - 1e-9), sectorOf(corner + 1e-9)})
      rho[((k % kStarHullSectors) + kStarHullSectors) % kStarHullSectors] = 1.0f + 1e-6f;
  }
  return rho;
}

StopCells planStopCells(const ApertureShape& shape) {
  StopCells plan;
  plan.periodRad = kTwoPi;
  // Masks keep the circle's table: their regions need not be convex nor star-shaped about any
  // point, and a search of the sweep of pbrt's star or of an irregular mask missed 2-30 in
  // 10,000 passing rays near the rim of a telephoto's image circle (stop_cells_test.cpp's rim
  // test), where the circle's table misses none.
  if (shape.kind != ApertureShape::Kind::Blades) return plan;
  const std::vector<float> rho = starHullUnit(shape);
  const RangeMax range(rho);
  plan.periodRad = kTwoPi / shape.bladeCount;
  std::vector<float> hull = folded(range, plan.periodRad, shape.bladeCount);
  const double bound = shape.boundRadiusFactor();
  if (hullArea(hull) >= kCircleLikeShare * std::numbers::pi * bound * bound) return plan;

  plan.count = std::max(1, static_cast<int>(std::ceil(plan.periodRad / kCellWidthRad - 1e-9)));
  const double width = plan.periodRad / plan.count;
  // Blades are symmetric about each corner's direction.
  const double corner = std::fmod(shape.rotationDeg * std::numbers::pi / 180.0, plan.periodRad);
  const int axis = static_cast<int>(
      std::lround((corner < 0.0 ? corner + plan.periodRad : corner) * 2.0 / kSectorRad));
  if (mirrorsAbout(hull, axis)) {
    hull = symmetrized(hull, axis);
    plan.mirrored = true;
    plan.offsetRad = 0.5 * axis * kSectorRad;
  }
  const int measured = plan.mirrored ? (plan.count + 1) / 2 : plan.count;
  const RangeMax hullRange(hull);
  // Each mask pixel as seen from the centre, in units of R: distance, direction, and the
  // half-angle its circumscribed disk subtends.
  const int n = kSweptMaskPx;
  const double pixel = 2.0 * bound / n;
  const double halfDiagonal = pixel * std::numbers::sqrt2 / 2.0;
  struct Polar {
    double nearest, direction, halfAngle;
  };
  std::vector<Polar> pixels(static_cast<std::size_t>(n) * n);
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const double x = -bound + (col + 0.5) * pixel, y = bound - (row + 0.5) * pixel;
      const double t = std::hypot(x, y);
      Polar& p = pixels[static_cast<std::size_t>(row) * n + col];
      p.nearest = t - halfDiagonal;
      p.direction = std::atan2(y, x);
      p.halfAngle = t > halfDiagonal ? std::asin(halfDiagonal / t) : std::numbers::pi;
    }
  }
  double sweptArea = 0.0;
  for (int cell = 0; cell < measured; ++cell) {
    // A plane point p (film on +x) is in the sweep when, for a film azimuth psi of the cell,
    // the stop turned by -psi holds it: |p| <= hull(angle of p + psi).
    const double from = plan.offsetRad + cell * width - kCellSweepMarginRad;
    const double to = plan.offsetRad + (cell + 1) * width + kCellSweepMarginRad;
    auto mask = std::make_shared<ApertureMask>();
    mask->sizePx = n;
    mask->source = "sweep";
    mask->open.assign(pixels.size(), 0);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      const Polar& p = pixels[i];
      const bool open = p.nearest <= 0.0 ||
                        (p.halfAngle >= std::numbers::pi
                             ? true
                             : p.nearest <= hullRange.overAngles(p.direction - p.halfAngle + from,
                                                                 p.direction + p.halfAngle + to));
      mask->open[i] = open ? 1 : 0;
    }
    mask->finish();
    sweptArea += mask->openFraction() * 4.0 * bound * bound;
    plan.sweptMasks.push_back(std::move(mask));
  }
  plan.shapeShareOfSweep = shape.areaFactor() / (sweptArea / measured);
  return plan;
}

std::shared_ptr<const StopCells> stopCellsFor(const ApertureShape& shape) {
  // Keyed by the shape and its mask's identity: the cache holds the mask, so a mask loaded
  // again (a changed file) is a new key, never an old plan's address reused.
  struct Entry {
    ApertureShape shape;
    std::shared_ptr<const StopCells> plan;
  };
  constexpr std::size_t kRemembered = 4;
  static std::mutex mutex;
  static std::deque<Entry> entries;
  {
    const std::lock_guard lock(mutex);
    for (const Entry& e : entries)
      if (e.shape == shape && e.shape.mask == shape.mask) return e.plan;
  }
  auto plan = std::make_shared<const StopCells>(planStopCells(shape));  // outside the lock
  const std::lock_guard lock(mutex);
  entries.push_front({shape, plan});
  if (entries.size() > kRemembered) entries.pop_back();
  return plan;
}

}  // namespace lenslab::optics
