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
// Cells about this wide (7.5 degrees): the sweep of three straight blades is then 11% larger
// than the triangle, of five 4%; at most kMaxCells of them, as each costs a table's worth of
// rays to build.
constexpr double kCellWidthRad = 7.5 * std::numbers::pi / 180.0;
constexpr int kMaxCells = 16;
// A mask's hull counts as repeating N-fold (or as mirror-symmetric) when making it so grows its
// area by at most this: pbrt's star, rasterized at 256 px, grows by 1.9% folded five-fold.
constexpr double kFoldGrowth = 1.03;
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
  // Angles [from, to) (radians, to > from), every sector they reach into. (`to` is taken a
  // hair short, so that a range ending on a sector's start does not take that sector in.)
  float overAngles(double fromRad, double toRad) const {
    return over(sectorOf(fromRad), std::max(sectorOf(fromRad), sectorOf(toRad - 1e-9)));
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
std::vector<float> folded(const RangeMax& rho, double periodRad, int repeats, int step = 1) {
  std::vector<float> out(kStarHullSectors, 0.0f);
  for (int k = 0; k < kStarHullSectors; k += step) {
    float best = 0.0f;
    for (int m = 0; m < repeats; ++m)
      best = std::max(best, rho.overAngles(k * kSectorRad + m * periodRad,
                                           (k + 1) * kSectorRad + m * periodRad));
    out[k] = best;
  }
  return out;
}

// Largest N (2..32) after which the mask's hull repeats within kFoldGrowth; 1 if none.
int maskRepeats(const std::vector<float>& rho, const RangeMax& range) {
  const double area = hullArea(rho);
  for (int n = kMaxApertureBlades; n >= 2; --n) {
    const double period = kTwoPi / n;
    // A coarse look at every 16th sector rejects most N cheaply.
    constexpr int kCoarse = 16;
    const std::vector<float> coarse = folded(range, period, n, kCoarse);
    double coarseFolded = 0.0, coarseOwn = 0.0;
    for (int k = 0; k < kStarHullSectors; k += kCoarse) {
      coarseFolded += static_cast<double>(coarse[k]) * coarse[k];
      coarseOwn += static_cast<double>(rho[k]) * rho[k];
    }
    if (coarseFolded > kFoldGrowth * coarseOwn) continue;
    if (hullArea(folded(range, period, n)) <= kFoldGrowth * area) return n;
  }
  return 1;
}

// The hull made mirror-symmetric about the axis at angle m pi / kStarHullSectors (m half-sectors):
// sector k's mirror image is sector m - 1 - k.
std::vector<float> symmetrized(const std::vector<float>& hull, int m) {
  std::vector<float> out(hull.size());
  const int n = static_cast<int>(hull.size());
  for (int k = 0; k < n; ++k) out[k] = std::max(hull[k], hull[(((m - 1 - k) % n) + n) % n]);
  return out;
}

// The mirror axis (in half-sectors, within one period) about which making the hull symmetric
// grows it least, if by at most kFoldGrowth; -1 if none. `hint`: try this axis alone (blades:
// a corner's direction).
int mirrorAxis(const std::vector<float>& hull, double periodRad, int hint) {
  const double area = hullArea(hull);
  if (hint >= 0) return hullArea(symmetrized(hull, hint)) <= kFoldGrowth * area ? hint : -1;
  const int n = static_cast<int>(hull.size());
  const int candidates = static_cast<int>(std::lround(2.0 * periodRad / kSectorRad));
  int best = -1;
  double bestArea = kFoldGrowth * area;
  for (int m = 0; m < candidates; ++m) {
    // A coarse look at every 16th sector first.
    double coarse = 0.0, own = 0.0;
    for (int k = 0; k < n; k += 16) {
      const float r = std::max(hull[k], hull[(((m - 1 - k) % n) + n) % n]);
      coarse += static_cast<double>(r) * r;
      own += static_cast<double>(hull[k]) * hull[k];
    }
    if (coarse > kFoldGrowth * own) continue;
    const double symmetricArea = hullArea(symmetrized(hull, m));
    if (symmetricArea <= bestArea) {
      bestArea = symmetricArea;
      best = m;
    }
  }
  return best;
}

}  // namespace

std::vector<float> maskStarHullUnit(const ApertureMask& mask) {
  std::vector<float> rho(kStarHullSectors, 0.0f);
  const int n = mask.sizePx;
  if (n <= 0 || mask.open.size() != static_cast<std::size_t>(n) * n) return rho;
  auto open = [&](int row, int col) {
    return row >= 0 && row < n && col >= 0 && col < n &&
           mask.open[static_cast<std::size_t>(row) * n + col] != 0;
  };
  const double pixel = 2.0 / n;  // in units of R
  const double halfDiagonal = pixel * std::numbers::sqrt2 / 2.0;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      if (!open(row, col)) continue;
      // Only pixels with a closed neighbour (or on the border) can be the farthest in a
      // direction: beyond an interior pixel, the ray runs on to the region's edge.
      bool edge = false;
      for (int dr = -1; dr <= 1 && !edge; ++dr)
        for (int dc = -1; dc <= 1 && !edge; ++dc) edge = !open(row + dr, col + dc);
      if (!edge) continue;
      const double x0 = -1.0 + col * pixel, x1 = x0 + pixel;
      const double y1 = 1.0 - row * pixel, y0 = y1 - pixel;
      const double farX = std::max(std::abs(x0), std::abs(x1));
      const double farY = std::max(std::abs(y0), std::abs(y1));
      const auto farthest = static_cast<float>(std::sqrt(farX * farX + farY * farY) * (1.0 + 1e-6));
      const double cx = x0 + 0.5 * pixel, cy = y0 + 0.5 * pixel;
      const double t = std::hypot(cx, cy);
      int first = 0, last = kStarHullSectors - 1;
      if (t > halfDiagonal) {
        // The pixel lies within its circumscribed disk, which subtends +-asin(d / t).
        double centre = std::atan2(cy, cx);
        if (centre < 0.0) centre += kTwoPi;
        const double half = std::asin(halfDiagonal / t);
        first = sectorOf(centre - half);
        last = sectorOf(centre + half);
      }
      for (int k = first; k <= last; ++k) {
        float& r = rho[((k % kStarHullSectors) + kStarHullSectors) % kStarHullSectors];
        r = std::max(r, farthest);
      }
    }
  }
  return rho;
}

std::vector<float> starHullUnit(const ApertureShape& shape) {
  switch (shape.kind) {
    case ApertureShape::Kind::Circle:
      return std::vector<float>(kStarHullSectors, 1.0f);
    case ApertureShape::Kind::Image:
      if (!shape.mask) return std::vector<float>(kStarHullSectors, 0.0f);
      if (shape.mask->starHull.size() == static_cast<std::size_t>(kStarHullSectors))
        return shape.mask->starHull;
      return maskStarHullUnit(*shape.mask);
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
  if (shape.isCircle()) return plan;
  const std::vector<float> rho = starHullUnit(shape);
  const RangeMax range(rho);
  const int repeats =
      shape.kind == ApertureShape::Kind::Blades ? shape.bladeCount : maskRepeats(rho, range);
  plan.periodRad = kTwoPi / repeats;
  std::vector<float> hull = repeats > 1 ? folded(range, plan.periodRad, repeats) : rho;
  const double bound = shape.boundRadiusFactor();
  if (hullArea(hull) >= kCircleLikeShare * std::numbers::pi * bound * bound) return plan;

  plan.count =
      std::clamp(static_cast<int>(std::ceil(plan.periodRad / kCellWidthRad - 1e-9)), 1, kMaxCells);
  const double width = plan.periodRad / plan.count;
  plan.convex = shape.kind == ApertureShape::Kind::Blades;
  // Blades are symmetric about each corner's direction.
  int hint = -1;
  if (shape.kind == ApertureShape::Kind::Blades) {
    const double corner = std::fmod(shape.rotationDeg * std::numbers::pi / 180.0, plan.periodRad);
    hint = static_cast<int>(
        std::lround((corner < 0.0 ? corner + plan.periodRad : corner) * 2.0 / kSectorRad));
  }
  const int axis = mirrorAxis(hull, plan.periodRad, hint);
  if (axis >= 0) {
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
    mask->finish(/*withStarHull=*/false);
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
