#include "optics/exit_pupil.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

constexpr int kHalfDirections = ExitPupilTable::kSectors + 1;  // angles m * pi / 32, m = 0..32
constexpr int kGrid = 16;  // coarse search grid over the plane (x), half of it in y
constexpr int kBisections = 16;
constexpr double kBracket = 0.002;  // relative precision of a boundary radius
constexpr double kRelativeMargin = 0.01;

struct Probe {
  const LensSystem& lens;
  double planeZ;
  bool passes(double filmR, double px, double py) const {
    const glm::dvec3 origin{filmR, 0.0, 0.0};
    const glm::dvec3 direction = glm::normalize(glm::dvec3{px - filmR, py, planeZ});
    return lens.traceFromFilm({origin, direction}).has_value();
  }
};

// Raw bound of the pass region for the film point (filmR, 0): centre and the bound radius per
// half-plane sector (before the margin and the neighbour union). Returns false when no ray passes.
struct RawBin {
  bool empty = true;
  double centreX = 0.0;
  std::array<double, ExitPupilTable::kSectors / 2 + 1>
      vertexRadius{};  // angles k * 2 pi / kSectors
};

RawBin measure(const Probe& probe, double filmR, double domainR,
               const std::vector<glm::dvec2>& extraSeeds = {}) {
  RawBin out;
  const double spacing = 2.0 * domainR / kGrid;
  std::vector<glm::dvec2> passing;
  for (int iy = 0; iy < kGrid / 2; ++iy) {
    for (int ix = 0; ix < kGrid; ++ix) {
      const double x = -domainR + (ix + 0.5) * spacing;
      const double y = (iy + 0.5) * spacing;
      if (x * x + y * y > domainR * domainR * 1.1) continue;
      if (probe.passes(filmR, x, y)) passing.push_back({x, y});
    }
  }
  // Near the rim of the image circle the region is a sliver the grid can miss: the caller passes
  // seeds from the neighbouring bin.
  if (passing.empty())
    for (const auto& p : extraSeeds)
      if (probe.passes(filmR, p.x, std::abs(p.y))) passing.push_back({p.x, std::abs(p.y)});
  // The region may be too small for the grid (tiny stop): try the aim at the paraxial exit
  // pupil centre as well.
  const FirstOrderData& fo = probe.lens.firstOrder();
  double centre = 0.0;
  bool found = false;
  if (!passing.empty()) {
    double sum = 0.0;
    for (const auto& p : passing) sum += p.x;
    centre = sum / passing.size();
    found = probe.passes(filmR, centre, 0.0);
    if (!found) {
      // Not convex around the centroid: fall back to the passing point nearest the axis line.
      const auto nearest = std::min_element(passing.begin(), passing.end(),
                                            [](auto a, auto b) { return a.y < b.y; });
      centre = nearest->x;
      found = probe.passes(filmR, centre, 0.0);
    }
  }
  if (!found && !fo.exitPupil.atInfinity && fo.exitPupil.zMm > 0.0) {
    centre = filmR * (1.0 - probe.planeZ / fo.exitPupil.zMm);
    found = probe.passes(filmR, centre, 0.0);
  }
  if (!found) return out;
  out.empty = false;

  // Boundary distance along a direction from the centre: expand until a ray fails, then bisect;
  // keep the failing end of the bracket (conservative).
  // `guess` (the previous direction's answer) starts the bracket; the bracket is refined to 0.2%.
  const double minStep = 1e-3 * domainR;
  auto boundary = [&](double angle, double guess) {
    const double cx = std::cos(angle), cy = std::sin(angle);
    double lo = 0.0, hi = std::max(guess, minStep);
    if (probe.passes(filmR, centre + hi * cx, hi * cy)) {
      lo = hi;
      hi *= 1.25;
      while (hi < 4.0 * domainR && probe.passes(filmR, centre + hi * cx, hi * cy)) {
        lo = hi;
        hi *= 1.25;
      }
    } else if (hi > minStep) {
      lo = hi * 0.8;
      while (lo > minStep && !probe.passes(filmR, centre + lo * cx, lo * cy)) {
        hi = lo;
        lo *= 0.8;
      }
      if (lo <= minStep) lo = 0.0;
    }
    for (int i = 0; i < kBisections && hi - lo > kBracket * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (probe.passes(filmR, centre + mid * cx, mid * cy))
        lo = mid;
      else
        hi = mid;
    }
    return hi;
  };
  // Re-centre on the middle of the region's extent along the x axis, so that centres vary smoothly
  // from bin to bin (the grid centroid jitters with the grid).
  {
    const double right = boundary(0.0, spacing), left = boundary(std::numbers::pi, spacing);
    const double shifted = centre + 0.5 * (right - left);
    if (probe.passes(filmR, shifted, 0.0)) centre = shifted;
  }
  out.centreX = centre;

  // Polygon vertices on the sector edges, at the boundary; each edge is then pushed out until it
  // also contains the boundary point measured half-way between its vertices. For chord ends at
  // radii a, b and half-angle h, the chord crosses the bisector at 2 a b cos(h) / (a + b).
  std::array<double, kHalfDirections> rho{};
  for (int m = 0; m < kHalfDirections; ++m)
    rho[m] = boundary(m * std::numbers::pi / (kHalfDirections - 1), m == 0 ? spacing : rho[m - 1]);
  constexpr int kHalfVertices = ExitPupilTable::kSectors / 2 + 1;
  const double cosHalf = std::cos(std::numbers::pi / ExitPupilTable::kSectors);
  for (int k = 0; k < kHalfVertices; ++k) out.vertexRadius[k] = rho[2 * k];
  for (int k = 0; k + 1 < kHalfVertices; ++k) {
    const double a = rho[2 * k], b = rho[2 * k + 2];
    const double crossing = 2.0 * a * b * cosHalf / (a + b);
    const double scale = std::max(1.0, rho[2 * k + 1] / crossing);
    out.vertexRadius[k] = std::max(out.vertexRadius[k], a * scale);
    out.vertexRadius[k + 1] = std::max(out.vertexRadius[k + 1], b * scale);
  }
  // Grid points found passing also bound the region (in case a direction's bracket skipped a
  // bulge): grow the two vertices of their sector until the edge contains them.
  const double sectorAngle = 2.0 * std::numbers::pi / ExitPupilTable::kSectors;
  for (const auto& p : passing) {
    const double dx = p.x - centre, dy = p.y;
    const double angle = std::atan2(std::abs(dy), dx);
    const int k = std::clamp(static_cast<int>(angle / sectorAngle), 0, kHalfVertices - 2);
    const double a = out.vertexRadius[k], b = out.vertexRadius[k + 1];
    // Where the edge AB crosses the ray from the centre through the point: if nearer than the
    // point, scale both vertices (the crossing distance scales with them).
    const double t0 = k * sectorAngle, t1 = t0 + sectorAngle;
    const double ax = a * std::cos(t0), ay = a * std::sin(t0);
    const double bx = b * std::cos(t1), by = b * std::sin(t1);
    const double r = std::hypot(dx, dy);
    if (r == 0.0) continue;
    const double ux = dx / r, uy = std::abs(dy) / r;
    const double crossing = (ax * by - ay * bx) / (ux * (by - ay) - uy * (bx - ax));
    if (crossing > 0.0 && crossing < r) {
      const double scale = r / crossing;
      out.vertexRadius[k] = a * scale;
      out.vertexRadius[k + 1] = b * scale;
    }
  }
  return out;
}

bool anyPasses(const Probe& probe, double filmR, double domainR) {
  const double spacing = 2.0 * domainR / kGrid;
  for (int iy = 0; iy < kGrid / 2; ++iy)
    for (int ix = 0; ix < kGrid; ++ix)
      if (probe.passes(filmR, -domainR + (ix + 0.5) * spacing, (iy + 0.5) * spacing)) return true;
  return false;
}

}  // namespace

ExitPupilTable::ExitPupilTable(const LensSystem& lens, int radialBins, int threads) {
  planeZMm_ = lens.rearVertexZ();
  fallbackRadiusMm_ = 1.5 * lens.rearApertureRadiusMm();
  const double sectorAngle = 2.0 * std::numbers::pi / kSectors;
  for (int k = 0; k <= kSectors; ++k) {
    cosAt_[k] = std::cos(k * sectorAngle);
    sinAt_[k] = std::sin(k * sectorAngle);
  }
  const Probe probe{lens, planeZMm_};
  if (!(planeZMm_ > 0.0)) return;  // film at the rear vertex: nothing to tabulate

  // Image circle: the largest of 24 coarse radii where some ray passes, plus one step.
  constexpr int kCoarse = 24;
  int lastPassing = -1;
  for (int i = 0; i <= kCoarse; ++i)
    if (anyPasses(probe, kMaxFilmRadiusMm * i / kCoarse, fallbackRadiusMm_)) lastPassing = i;
  if (lastPassing < 0) return;
  filmRadiusMaxMm_ = kMaxFilmRadiusMm * std::min(lastPassing + 1, kCoarse) / kCoarse;
  radialBins = std::max(radialBins, 2);
  binScale_ = radialBins - 1;

  std::vector<RawBin> raw(radialBins);
  auto work = [&](int first, int stride) {
    for (int j = first; j < radialBins; j += stride)
      raw[j] = measure(probe, binRadiusMm(j), fallbackRadiusMm_);
  };
  threads = std::max(1, threads);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t, threads);
  work(0, threads);
  for (auto& thread : pool) thread.join();

  // Empty bins next to non-empty ones: retry with seeds over the neighbour's extent, shifted as
  // the centre moves, outward and inward until the region is really gone.
  auto seedsFrom = [&](const RawBin& near, const RawBin* nearer) {
    std::vector<glm::dvec2> seeds;
    const double shift = nearer && !nearer->empty ? near.centreX - nearer->centreX : 0.0;
    const double cx = near.centreX + shift;
    const double left = near.vertexRadius[kSectors / 2], right = near.vertexRadius[0];
    const double up = near.vertexRadius[kSectors / 4];
    constexpr int kSeeds = 9;
    for (int i = 0; i < kSeeds; ++i)
      for (int k = 0; k < kSeeds; ++k)
        seeds.push_back({cx - left + (left + right) * (i + 0.5) / kSeeds, up * (k + 0.5) / kSeeds});
    return seeds;
  };
  for (int j = 1; j < radialBins; ++j)
    if (raw[j].empty && !raw[j - 1].empty)
      raw[j] = measure(probe, binRadiusMm(j), fallbackRadiusMm_,
                       seedsFrom(raw[j - 1], j >= 2 ? &raw[j - 2] : nullptr));
  for (int j = radialBins - 2; j >= 0; --j)
    if (raw[j].empty && !raw[j + 1].empty)
      raw[j] = measure(probe, binRadiusMm(j), fallbackRadiusMm_,
                       seedsFrom(raw[j + 1], j + 2 < radialBins ? &raw[j + 2] : nullptr));

  // Union with the neighbours, margin, triangle areas and their CDF.
  bins_.resize(radialBins);
  const double absoluteMargin = 1e-4 * fallbackRadiusMm_;
  const double halfSin = 0.5 * std::sin(sectorAngle);
  for (int j = 0; j < radialBins; ++j) {
    if (raw[j].empty) continue;
    Bin& b = bins_[j];
    b.empty = false;
    b.centreXMm = raw[j].centreX;
    for (int k = 0; k <= kSectors / 2; ++k) {
      double r = raw[j].vertexRadius[k];
      for (int n : {j - 1, j + 1})
        if (n >= 0 && n < radialBins && !raw[n].empty) r = std::max(r, raw[n].vertexRadius[k]);
      const double v = r * (1.0 + kRelativeMargin) + absoluteMargin;
      b.vertexRadiusMm[k] = v;
      if (k > 0 && k < kSectors / 2) b.vertexRadiusMm[kSectors - k] = v;  // mirror below x
    }
    double total = 0.0;
    for (int k = 0; k < kSectors; ++k) {
      total += halfSin * b.vertexRadiusMm[k] * b.vertexRadiusMm[(k + 1) % kSectors];
      b.cdf[k] = total;
    }
    for (auto& c : b.cdf) c /= total;
    b.cdf[kSectors - 1] = 1.0;
    b.areaMm2 = total;
  }
}

double ExitPupilTable::binRadiusMm(int j) const {
  // Inverse of t = (x + x^2) / 2 * binScale_, x = r / filmRadiusMaxMm_.
  const double s = j / binScale_;
  return filmRadiusMaxMm_ * 0.5 * (std::sqrt(1.0 + 8.0 * s) - 1.0);
}

ExitPupilTable::Lookup ExitPupilTable::lookup(double r) const {
  Lookup out;
  const int last = static_cast<int>(bins_.size()) - 1;
  const double x = r / filmRadiusMaxMm_;
  const double t = 0.5 * (x + x * x) * binScale_;
  out.j = std::min(static_cast<int>(t), last - 1);
  out.f = std::clamp(t - out.j, 0.0, 1.0);
  const Bin& b0 = bins_[out.j];
  const Bin& b1 = bins_[out.j + 1];
  out.centreX = b0.empty   ? b1.centreXMm
                : b1.empty ? b0.centreXMm
                           : (1.0 - out.f) * b0.centreXMm + out.f * b1.centreXMm;
  return out;
}

double ExitPupilTable::imageCircleRadiusMm() const {
  for (int j = static_cast<int>(bins_.size()) - 1; j >= 0; --j)
    if (!bins_[j].empty) return binRadiusMm(j);
  return 0.0;
}

bool ExitPupilTable::inside(const Bin& b, double centreX, double x, double y) const {
  if (b.empty) return false;
  const double dx = x - centreX, dy = y;
  const double sectorAngle = 2.0 * std::numbers::pi / kSectors;
  double angle = std::atan2(dy, dx);
  if (angle < 0.0) angle += 2.0 * std::numbers::pi;
  const int k = std::clamp(static_cast<int>(angle / sectorAngle), 0, kSectors - 1);
  // Inside the triangle (centre, A, B) iff on the centre's side of the edge AB.
  const double ax = b.vertexRadiusMm[k] * cosAt_[k], ay = b.vertexRadiusMm[k] * sinAt_[k];
  const int k1 = (k + 1) % kSectors;
  const double bx = b.vertexRadiusMm[k1] * cosAt_[k + 1], by = b.vertexRadiusMm[k1] * sinAt_[k + 1];
  return (bx - ax) * (dy - ay) - (by - ay) * (dx - ax) >= 0.0;
}

double ExitPupilTable::pdf(glm::dvec2 film, glm::dvec2 point) const {
  const double r = std::sqrt(film.x * film.x + film.y * film.y);
  if (bins_.empty() || r > filmRadiusMaxMm_) {
    if (point.x * point.x + point.y * point.y > fallbackRadiusMm_ * fallbackRadiusMm_) return 0.0;
    return 1.0 / (std::numbers::pi * fallbackRadiusMm_ * fallbackRadiusMm_);
  }
  double c = 1.0, sn = 0.0;
  if (r > 0.0) {
    c = film.x / r;
    sn = film.y / r;
  }
  const double lx = c * point.x + sn * point.y, ly = -sn * point.x + c * point.y;
  const auto [j, f, centreX] = lookup(r);
  double density = 0.0;
  if (inside(bins_[j], centreX, lx, ly)) density += (1.0 - f) / bins_[j].areaMm2;
  if (inside(bins_[j + 1], centreX, lx, ly)) density += f / bins_[j + 1].areaMm2;
  return density;
}

std::optional<PupilSample> ExitPupilTable::sample(glm::dvec2 film, glm::dvec2 u) const {
  const double r = std::sqrt(film.x * film.x + film.y * film.y);
  if (bins_.empty() || r > filmRadiusMaxMm_) {
    if (bins_.empty() && filmRadiusMaxMm_ == 0.0 && planeZMm_ <= 0.0) return std::nullopt;
    // Outside the table: uniform over the disk the table search covered (concentric mapping
    // would do as well; polar is enough here).
    const double radius = fallbackRadiusMm_ * std::sqrt(u.x);
    const double angle = 2.0 * std::numbers::pi * u.y;
    return PupilSample{{radius * std::cos(angle), radius * std::sin(angle), planeZMm_},
                       1.0 / (std::numbers::pi * fallbackRadiusMm_ * fallbackRadiusMm_)};
  }
  const auto [j, f, centreX] = lookup(r);
  const Bin& b0 = bins_[j];
  const Bin& b1 = bins_[j + 1];
  double ux = u.x;
  const Bin* chosen;
  if (ux < 1.0 - f) {
    chosen = &b0;
    ux /= (1.0 - f);
  } else {
    chosen = &b1;
    ux = (ux - (1.0 - f)) / f;
  }
  if (chosen->empty) return std::nullopt;
  ux = std::min(ux, 0.99999999999);
  const int k = static_cast<int>(std::upper_bound(chosen->cdf.begin(), chosen->cdf.end(), ux) -
                                 chosen->cdf.begin());
  const double lo = k == 0 ? 0.0 : chosen->cdf[k - 1];
  const double width = chosen->cdf[k] - lo;
  const double w = width > 0.0 ? (ux - lo) / width : 0.5;
  // Uniform in the triangle (centre, A, B): p = centre + sqrt(w) ((1 - v) A + v B).
  const double s = std::sqrt(w);
  const double v = u.y;
  const double a = (1.0 - v) * chosen->vertexRadiusMm[k];
  const double bb = v * chosen->vertexRadiusMm[(k + 1) % kSectors];
  const double lx = centreX + s * (a * cosAt_[k] + bb * cosAt_[k + 1]);
  const double ly = s * (a * sinAt_[k] + bb * sinAt_[k + 1]);
  // Rotate from the bin frame (film point on +x) to the film point's azimuth.
  double c = 1.0, sn = 0.0;
  if (r > 0.0) {
    c = film.x / r;
    sn = film.y / r;
  }
  double pdf = 0.0;
  if (!b0.empty) pdf += (1.0 - f) / b0.areaMm2;
  if (!b1.empty) pdf += f / b1.areaMm2;
  return PupilSample{{c * lx - sn * ly, sn * lx + c * ly, planeZMm_}, pdf};
}

}  // namespace lenslab::optics
