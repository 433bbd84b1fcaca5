#include "optics/exit_pupil.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <numbers>
#include <thread>

#include <glm/geometric.hpp>

#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

constexpr int kHalfDirections = ExitPupilTable::kSectors + 1;  // angles m * pi / 32, m = 0..32
constexpr int kGrid = 16;  // coarse search grid over the plane (half of it in y on the half-plane)
// Brackets grow by a factor of 2 from the smallest step; bisection then halves the bracket 12
// times: 1/4096 of the bracket's lower end, about 0.012% of the radius. (A finer growth, 1.25 with
// 10 bisections, reaches the same precision with twice the rays: the table is on the critical path
// of every viewer edit.)
constexpr double kBracketGrowth = 2.0;
constexpr int kBisections = 12;
// A boundary expected near a known radius g (the neighbouring bin's, in the same direction from
// its centre) is first tried with the bracket g (1 -/+ kWarmBracket): where that brackets it, 9
// bisections reach the same precision as the growth and 12 bisections (2 g / 16 / 2^9 = g /
// 4096), in 11 rays instead of about 24. Where it does not (the region changed faster than that,
// near the rim of the image circle), the direction is searched as without a guess. (With 1/64
// and 7 bisections, 42% of the double-Gauss's directions missed their bracket; with 1/16, 10%.)
constexpr double kWarmBracket = 1.0 / 16.0;
constexpr int kWarmBisections = 9;
// The spectral table (four probe wavelengths, up to four traces per point) stops two bisections
// earlier, warm and cold: g / 1024 and r / 2048, still 2.5 and 5 times finer than the margin
// below. A bound is the bracket's failing end, so a coarser one is only larger, never short of
// the region: the sampler loses at most 0.2% of its efficiency, and the table, on the critical
// path of every edit in the viewer's default (spectral) mode, about a sixth of its rays (issue 39).
constexpr int kSpectralBisectionsSaved = 2;
// The margin on every bound: about twenty times the bisection's precision. (It was 1% before the
// convexity construction in measure() bounded the region between measured directions. The
// spectral table needs no more: its bounds at four probe wavelengths contain the region at every
// wavelength between them with this margin and also with none, in a brute-force check of 465k
// passing rays of the bundled dispersive lenses at random wavelengths; a margin of -1% misses
// 127 of them.)
constexpr double kRelativeMargin = 0.0025;

// Traces rays from the film point (filmR, 0, 0) through points of the plane z = planeZ. Many at
// once through the vectorized batch trace: the table build is thousands of such rays per bin.
// (Single precision; the margins are far larger than its rounding.)
struct Probe {
  const LensSystem& lens;
  double planeZ;
  const std::vector<double>& wavelengthsNm;  // empty: the lens's own
  LensRayBatch batch{};
  LensRayBatch traced{};
  std::vector<float> wavelengths{};
  std::vector<std::size_t> pending{};  // rays no probe wavelength has let through yet

  bool passes(double filmR, double px, double py) {
    const glm::dvec2 point{px, py};
    std::vector<std::uint8_t> result;
    passesAll(filmR, &point, 1, result);
    return result[0] != 0;
  }
  void passesAll(double filmR, const glm::dvec2* points, std::size_t n,
                 std::vector<std::uint8_t>& result) {
    batch.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 d = glm::normalize(glm::dvec3{points[i].x - filmR, points[i].y, planeZ});
      batch.ox[i] = static_cast<float>(filmR);
      batch.oy[i] = 0.0f;
      batch.oz[i] = 0.0f;
      batch.dx[i] = static_cast<float>(d.x);
      batch.dy[i] = static_cast<float>(d.y);
      batch.dz[i] = static_cast<float>(d.z);
      batch.alive[i] = 1;
    }
    if (wavelengthsNm.empty()) {
      lens.traceFromFilmBatch(batch);
      result.assign(batch.alive.begin(), batch.alive.begin() + static_cast<std::ptrdiff_t>(n));
      return;
    }
    // The union of the pass regions at the probe wavelengths: each wavelength traces only the
    // rays no earlier one let through (the answer is the same; about half the traces).
    result.assign(n, 0);
    pending.resize(n);
    for (std::size_t i = 0; i < n; ++i) pending[i] = i;
    for (const double wavelength : wavelengthsNm) {
      const std::size_t m = pending.size();
      if (m == 0) break;
      traced.resize(m);
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = pending[k];
        traced.ox[k] = batch.ox[i];
        traced.oy[k] = batch.oy[i];
        traced.oz[k] = batch.oz[i];
        traced.dx[k] = batch.dx[i];
        traced.dy[k] = batch.dy[i];
        traced.dz[k] = batch.dz[i];
        traced.alive[k] = 1;
      }
      wavelengths.assign(m, static_cast<float>(wavelength));
      lens.traceFromFilmBatch(traced, wavelengths.data());
      std::size_t still = 0;
      for (std::size_t k = 0; k < m; ++k) {
        if (traced.alive[k])
          result[pending[k]] = 1;
        else
          pending[still++] = pending[k];
      }
      pending.resize(still);
    }
  }
};

// Distance from the centre to the region's boundary along each angle, all directions in
// lock-step: first radii growing by kBracketGrowth from minStep until a ray fails (the first
// failure brackets the boundary, as the region is an interval along each ray), then bisection.
// Returns the failing end of each bracket (conservative). With `guesses` (one radius per angle,
// from the neighbouring bin), each direction first tries its guess's bracket (kWarmBracket).
std::vector<double> boundaries(Probe& probe, double filmR, glm::dvec2 centre,
                               const std::vector<double>& angles, double minStep, double maxR,
                               const std::vector<double>& guesses = {}) {
  const std::size_t m = angles.size();
  std::vector<double> result(m, 0.0);
  // Directions with a guess: its bracket first, all in one batch.
  std::vector<std::size_t> cold;  // the directions still to search from the centre out
  if (guesses.size() == m) {
    std::vector<glm::dvec2> ends(2 * m);
    std::vector<glm::dvec2> dirs(m);
    for (std::size_t a = 0; a < m; ++a) {
      dirs[a] = {std::cos(angles[a]), std::sin(angles[a])};
      ends[2 * a] = centre + guesses[a] * (1.0 - kWarmBracket) * dirs[a];
      ends[2 * a + 1] = centre + guesses[a] * (1.0 + kWarmBracket) * dirs[a];
    }
    std::vector<std::uint8_t> pass;
    probe.passesAll(filmR, ends.data(), ends.size(), pass);
    std::vector<std::size_t> warm;
    std::vector<double> lo, hi;
    for (std::size_t a = 0; a < m; ++a) {
      const bool brackets = guesses[a] > 0.0 && pass[2 * a] && !pass[2 * a + 1];
      if (!brackets) {
        cold.push_back(a);
        continue;
      }
      warm.push_back(a);
      lo.push_back(guesses[a] * (1.0 - kWarmBracket));
      hi.push_back(guesses[a] * (1.0 + kWarmBracket));
    }
    std::vector<glm::dvec2> points(warm.size());
    const int warmBisections =
        kWarmBisections - (probe.wavelengthsNm.empty() ? 0 : kSpectralBisectionsSaved);
    for (int i = 0; i < warmBisections && !warm.empty(); ++i) {
      for (std::size_t w = 0; w < warm.size(); ++w)
        points[w] = centre + 0.5 * (lo[w] + hi[w]) * dirs[warm[w]];
      probe.passesAll(filmR, points.data(), points.size(), pass);
      for (std::size_t w = 0; w < warm.size(); ++w)
        (pass[w] ? lo[w] : hi[w]) = 0.5 * (lo[w] + hi[w]);
    }
    for (std::size_t w = 0; w < warm.size(); ++w) result[warm[w]] = hi[w];
    if (cold.empty()) return result;
  } else {
    for (std::size_t a = 0; a < m; ++a) cold.push_back(a);
  }
  if (cold.size() < m) {
    std::vector<double> coldAngles;
    for (std::size_t a : cold) coldAngles.push_back(angles[a]);
    const std::vector<double> found = boundaries(probe, filmR, centre, coldAngles, minStep, maxR);
    for (std::size_t c = 0; c < cold.size(); ++c) result[cold[c]] = found[c];
    return result;
  }
  std::vector<double> radii;
  for (double r = minStep; r < maxR * kBracketGrowth; r *= kBracketGrowth) radii.push_back(r);
  const std::size_t steps = radii.size();
  std::vector<glm::dvec2> points(m * steps), dirs(m);
  for (std::size_t a = 0; a < m; ++a) dirs[a] = {std::cos(angles[a]), std::sin(angles[a])};
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t j = 0; j < steps; ++j) points[a * steps + j] = centre + radii[j] * dirs[a];
  std::vector<std::uint8_t> pass;
  probe.passesAll(filmR, points.data(), points.size(), pass);
  std::vector<double> lo(m, 0.0), hi(m, radii.back());
  for (std::size_t a = 0; a < m; ++a) {
    for (std::size_t j = 0; j < steps; ++j) {
      if (!pass[a * steps + j]) {
        hi[a] = radii[j];
        lo[a] = j > 0 ? radii[j - 1] : 0.0;
        break;
      }
    }
  }
  points.resize(m);
  const int bisections = kBisections - (probe.wavelengthsNm.empty() ? 0 : kSpectralBisectionsSaved);
  for (int i = 0; i < bisections; ++i) {
    for (std::size_t a = 0; a < m; ++a) {
      const double mid = 0.5 * (lo[a] + hi[a]);
      points[a] = centre + mid * dirs[a];
    }
    probe.passesAll(filmR, points.data(), m, pass);
    for (std::size_t a = 0; a < m; ++a) (pass[a] ? lo[a] : hi[a]) = 0.5 * (lo[a] + hi[a]);
  }
  return hi;
}

// Raw bound of the pass region for the film point (filmR, 0): centre and the bound radius per
// sector (before the margin and the neighbour union); empty when no ray passes. A region
// symmetric about the x axis (a round stop) is measured on the half-plane y >= 0 and mirrored;
// otherwise (a cell of a shaped stop) over the full circle.
struct RawBin {
  bool empty = true;
  double centreX = 0.0, centreY = 0.0;                          // centreY: 0 on the half-plane
  std::array<double, ExitPupilTable::kSectors> vertexRadius{};  // angles k * 2 pi / kSectors
  // The boundary's distance from the centre along each measured direction (measure()), and
  // along the re-centring directions: the next bin's guesses.
  std::vector<double> directionRadius, recentreRadius;
};

std::vector<glm::dvec2> gridPoints(double domainR, bool mirrored) {
  const double spacing = 2.0 * domainR / kGrid;
  std::vector<glm::dvec2> points;
  for (int iy = mirrored ? kGrid / 2 : 0; iy < kGrid; ++iy) {
    for (int ix = 0; ix < kGrid; ++ix) {
      const double x = -domainR + (ix + 0.5) * spacing;
      const double y = (iy - kGrid / 2 + 0.5) * spacing;
      if (x * x + y * y <= domainR * domainR * 1.1) points.push_back({x, y});
    }
  }
  return points;
}

// Where the paraxial chief ray from (filmR, 0, 0) crosses the plane: aimed at the centre of the
// exit pupil. It passes even when the stop is far too small for the coarse grid to find.
double chiefAimX(const Probe& probe, double filmR) {
  const PupilData& exitPupil = probe.lens.firstOrder().exitPupil;
  if (exitPupil.atInfinity || exitPupil.zMm <= 0.0) return 0.0;
  return filmR * (1.0 - probe.planeZ / exitPupil.zMm);
}

// `mirrored`: measure the half-plane y >= 0 and mirror it.
// `previous`: the neighbouring bin's result (or null), whose boundaries guess this bin's.
RawBin measure(Probe& probe, double filmR, double domainR, bool mirrored,
               const std::vector<glm::dvec2>& extraSeeds = {}, const RawBin* previous = nullptr) {
  RawBin out;
  if (previous != nullptr && previous->empty) previous = nullptr;
  std::vector<glm::dvec2> passing;
  std::vector<std::uint8_t> pass;
  const std::vector<glm::dvec2> grid = gridPoints(domainR, mirrored);
  probe.passesAll(filmR, grid.data(), grid.size(), pass);
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (pass[i]) passing.push_back(grid[i]);
  // Near the rim of the image circle the region is a sliver the grid can miss: the caller passes
  // seeds from the neighbouring bin.
  if (passing.empty() && !extraSeeds.empty()) {
    std::vector<glm::dvec2> seeds;
    for (const auto& p : extraSeeds) seeds.push_back({p.x, mirrored ? std::abs(p.y) : p.y});
    probe.passesAll(filmR, seeds.data(), seeds.size(), pass);
    for (std::size_t i = 0; i < seeds.size(); ++i)
      if (pass[i]) passing.push_back(seeds[i]);
  }
  // The region may be too small for the grid (tiny stop): try the aim at the paraxial exit
  // pupil centre as well.
  glm::dvec2 centre{0.0};
  bool found = false;
  if (!passing.empty()) {
    glm::dvec2 sum{0.0};
    for (const auto& p : passing) sum += p;
    centre = sum / static_cast<double>(passing.size());
    if (mirrored) centre.y = 0.0;
    found = probe.passes(filmR, centre.x, centre.y);
    if (!found) {
      // Not convex around the centroid: on the half-plane, fall back to the passing point nearest
      // the axis line; round the circle (a shaped stop's cell, whose region need not cross the
      // film point's radial line near the rim) to the passing point nearest the centroid.
      const glm::dvec2 centroid = centre;
      const auto nearest =
          std::min_element(passing.begin(), passing.end(), [&](glm::dvec2 a, glm::dvec2 b) {
            return mirrored ? std::abs(a.y) < std::abs(b.y)
                            : glm::dot(a - centroid, a - centroid) <
                                  glm::dot(b - centroid, b - centroid);
          });
      centre = {nearest->x, mirrored ? 0.0 : nearest->y};
      found = probe.passes(filmR, centre.x, centre.y);
    }
  }
  if (!found) {
    centre = {chiefAimX(probe, filmR), 0.0};
    found = probe.passes(filmR, centre.x, centre.y);
  }
  if (!found) return out;
  out.empty = false;

  // Boundary distance along a direction from the centre: expand until a ray fails, then bisect;
  // keep the failing end of the bracket (conservative).
  // (Round the full circle, a shaped stop's cell, the brackets start at 1/64 of the domain: four
  // steps fewer per direction on a table several times the circle's size; a boundary nearer
  // than that is still bisected to 1/4096 of it.)
  const double minStep = (mirrored ? 1e-3 : 1.0 / 64.0) * domainR, maxR = 4.0 * domainR;
  // Re-centre on the middle of the region's extent along x (and round the circle along y), so
  // that centres vary smoothly from bin to bin (the grid centroid jitters with the grid).
  // (Guesses from the neighbouring bin: its extents from its own centre, shifted by where this
  // centre lies against it.)
  auto guessed = [&](std::size_t first, std::size_t count, glm::dvec2 along) {
    std::vector<double> guesses;
    if (previous == nullptr || previous->recentreRadius.size() < first + count) return guesses;
    const glm::dvec2 offset = centre - glm::dvec2(previous->centreX, previous->centreY);
    const double shift = glm::dot(offset, along);
    guesses = {previous->recentreRadius[first] - shift,
               previous->recentreRadius[first + 1] + shift};
    return guesses;
  };
  {
    const auto ends = boundaries(probe, filmR, centre, {0.0, std::numbers::pi}, minStep, maxR,
                                 guessed(0, 2, {1.0, 0.0}));
    out.recentreRadius = ends;
    const glm::dvec2 shifted{centre.x + 0.5 * (ends[0] - ends[1]), centre.y};
    if (probe.passes(filmR, shifted.x, shifted.y)) {
      centre = shifted;
      const double half = 0.5 * (ends[0] + ends[1]);
      out.recentreRadius = {half, half};
    }
  }
  if (!mirrored) {
    const auto ends =
        boundaries(probe, filmR, centre, {0.5 * std::numbers::pi, 1.5 * std::numbers::pi}, minStep,
                   maxR, guessed(2, 2, {0.0, 1.0}));
    out.recentreRadius.insert(out.recentreRadius.end(), ends.begin(), ends.end());
    const glm::dvec2 shifted{centre.x, centre.y + 0.5 * (ends[0] - ends[1])};
    if (probe.passes(filmR, shifted.x, shifted.y)) {
      centre = shifted;
      const double half = 0.5 * (ends[0] + ends[1]);
      out.recentreRadius[2] = out.recentreRadius[3] = half;
    }
  }
  out.centreX = centre.x;
  out.centreY = centre.y;

  // Directions m pi / 32: m = 0..32 on the half-plane, 0..63 round the circle (m and m + 64
  // alike). Vertex k of the polygon lies on direction 2k.
  constexpr int kSectors = ExitPupilTable::kSectors;
  const int directions = mirrored ? kHalfDirections : 2 * (kHalfDirections - 1);
  const int vertices = mirrored ? kSectors / 2 + 1 : kSectors;  // measured, not mirrored
  const int edges = mirrored ? kSectors / 2 : kSectors;         // vertex k to k + 1
  auto vertexAfter = [&](int k) { return (k + 1) % kSectors; };

  // Polygon vertices on the sector edges, at the boundary; each edge is then pushed out until it
  // also contains the boundary point measured half-way between its vertices. For chord ends at
  // radii a, b and half-angle h, the chord crosses the bisector at 2 a b cos(h) / (a + b).
  std::vector<double> angles(directions);
  for (int m = 0; m < directions; ++m) angles[m] = m * std::numbers::pi / (kHalfDirections - 1);
  std::vector<double> guesses;
  if (previous != nullptr && previous->directionRadius.size() == angles.size()) {
    // The neighbour's boundary point in each direction, seen from this centre along the same
    // direction (close enough for a guess: the bracket is checked).
    const glm::dvec2 offset = glm::dvec2(previous->centreX, previous->centreY) - centre;
    for (std::size_t a = 0; a < angles.size(); ++a) {
      const glm::dvec2 dir{std::cos(angles[a]), std::sin(angles[a])};
      guesses.push_back(std::max(0.0, previous->directionRadius[a] + glm::dot(offset, dir)));
    }
  }
  const std::vector<double> rho = boundaries(probe, filmR, centre, angles, minStep, maxR, guesses);
  out.directionRadius = rho;
  auto rhoAt = [&](int m) { return rho[m % directions]; };  // full circle: 64 is 0
  const double cosHalf = std::cos(std::numbers::pi / kSectors);
  for (int k = 0; k < vertices; ++k) out.vertexRadius[k] = rho[2 * k];
  for (int k = 0; k < edges; ++k) {
    const double a = rhoAt(2 * k), b = rhoAt(2 * k + 2);
    const double crossing = 2.0 * a * b * cosHalf / (a + b);
    const double scale = std::max(1.0, rho[2 * k + 1] / crossing);
    out.vertexRadius[k] = std::max(out.vertexRadius[k], a * scale);
    out.vertexRadius[vertexAfter(k)] = std::max(out.vertexRadius[vertexAfter(k)], b * scale);
  }
  // Grow the two vertices of a point's sector until their edge contains the point (the
  // crossing distance along the ray through it scales with them). On the half-plane a point
  // below the axis stands for its mirror image.
  const double sectorAngle = 2.0 * std::numbers::pi / kSectors;
  auto contain = [&](double dx, double dy) {
    const double r = std::hypot(dx, dy);
    if (r == 0.0) return;
    if (mirrored) dy = std::abs(dy);
    double angle = std::atan2(dy, dx);
    if (angle < 0.0) angle += 2.0 * std::numbers::pi;
    const int k = std::clamp(static_cast<int>(angle / sectorAngle), 0, edges - 1);
    const int next = vertexAfter(k);
    const double a = out.vertexRadius[k], b = out.vertexRadius[next];
    const double t0 = k * sectorAngle, t1 = t0 + sectorAngle;
    const double ax = a * std::cos(t0), ay = a * std::sin(t0);
    const double bx = b * std::cos(t1), by = b * std::sin(t1);
    const double ux = dx / r, uy = dy / r;
    const double crossing = (ax * by - ay * bx) / (ux * (by - ay) - uy * (bx - ax));
    if (crossing > 0.0 && crossing < r) {
      const double scale = r / crossing;
      out.vertexRadius[k] = a * scale;
      out.vertexRadius[next] = b * scale;
    }
  };
  // A convex region, between two neighbouring boundary points P_m, P_m+1, lies inside the lines
  // through P_m-1 P_m and P_m+2 P_m+1, extended: within the triangle P_m X P_m+1, X where they
  // meet. Each edge must therefore contain those X too, not only the boundary points. Where the
  // boundary turns sharply between two measured directions (the tips of a cat's eye at the rim
  // of the image circle) the region otherwise reached past the chords: points there lay in one
  // of the two bins the sampler blends only, and the density it reported was up to twice the
  // true one (exit_pupil_test.cpp). X is taken where the lines meet outside the chord and within
  // the wedge, however far (a sharp tip); only a point beyond 100 times the farther boundary
  // point, which no real region has, is left out as a numerical accident. The pass region of one
  // wavelength is an intersection of the clear apertures' images, convex in practice; the
  // spectral table's union of four wavelengths' regions need not be, and there the bound rests
  // on the brute-force test in spectral_trace_test.cpp. The sweep of blades over a cell
  // (stop_cells.h) is convex but for shallow notches where two turned edges meet (15 degrees
  // at most): the bound rests there on the brute-force tests in stop_cells_test.cpp, over every
  // course lens up to the rim of its image circle.
  {
    // m = -1 .. directions + 1: mirrored at the ends of the half-plane, cyclic round the circle.
    std::vector<glm::dvec2> boundary(directions + 3);
    for (int m = -1; m <= directions + 1; ++m) {
      int at = m;
      if (mirrored)
        at = m < 0 ? -m : m >= directions ? 2 * (directions - 1) - m : m;
      else
        at = (m + directions) % directions;
      const double t = m * std::numbers::pi / (kHalfDirections - 1);
      boundary[m + 1] = {rho[at] * std::cos(t), rho[at] * std::sin(t)};
    }
    auto cross = [](glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; };
    const int gaps = mirrored ? directions - 1 : directions;
    for (int m = 0; m < gaps; ++m) {
      const glm::dvec2 before = boundary[m], p = boundary[m + 1], q = boundary[m + 2],
                       after = boundary[m + 3];
      const glm::dvec2 d1 = p - before, d2 = q - after;  // outward along each line
      const double denominator = cross(d1, d2);
      if (std::abs(denominator) < 1e-12 * glm::dot(d1, d1)) continue;  // parallel
      const double s1 = cross(q - p, d2) / denominator, s2 = cross(q - p, d1) / denominator;
      if (!(s1 > 0.0 && s2 > 0.0)) continue;  // they do not meet beyond both points
      const glm::dvec2 x = p + s1 * d1;
      const bool outsideChord = cross(q - p, x - p) < 0.0;  // right of p -> q (counter-clockwise)
      const bool inWedge = cross(p, x) >= 0.0 && cross(x, q) >= 0.0;
      const double limit = 100.0 * std::max(glm::length(p), glm::length(q));
      if (outsideChord && inWedge && glm::length(x) <= limit) contain(x.x, x.y);
    }
  }
  // Grid points found passing also bound the region (in case a direction's bracket skipped a
  // bulge).
  for (const auto& p : passing) contain(p.x - centre.x, p.y - centre.y);
  return out;
}

bool anyPasses(Probe& probe, double filmR, double domainR) {
  if (probe.passes(filmR, chiefAimX(probe, filmR), 0.0)) return true;
  const std::vector<glm::dvec2> grid = gridPoints(domainR, /*mirrored=*/true);
  std::vector<std::uint8_t> pass;
  probe.passesAll(filmR, grid.data(), grid.size(), pass);
  return std::any_of(pass.begin(), pass.end(), [](std::uint8_t p) { return p != 0; });
}

}  // namespace

// Walker's alias method (Vose's construction, "A linear algorithm for generating random numbers
// with a given distribution", IEEE TSE 17(9), 1991): sector k is drawn in O(1) from one uniform.
static void buildAliasTable(ExitPupilTable::Bin& b) {
  constexpr int n = ExitPupilTable::kSectors;
  std::array<double, n> scaled{};
  std::array<int, n> small{}, large{};
  int smallCount = 0, largeCount = 0;
  for (int k = 0; k < n; ++k) {
    scaled[k] = (b.cdf[k] - (k == 0 ? 0.0 : b.cdf[k - 1])) * n;
    if (scaled[k] < 1.0)
      small[smallCount++] = k;
    else
      large[largeCount++] = k;
  }
  while (smallCount > 0 && largeCount > 0) {
    const int s = small[--smallCount], l = large[--largeCount];
    b.aliasProbability[s] = scaled[s];
    b.alias[s] = l;
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0)
      small[smallCount++] = l;
    else
      large[largeCount++] = l;
  }
  for (int i = 0; i < largeCount; ++i) {
    b.aliasProbability[large[i]] = 1.0;
    b.alias[large[i]] = large[i];
  }
  for (int i = 0; i < smallCount; ++i) {  // rounding leftovers
    b.aliasProbability[small[i]] = 1.0;
    b.alias[small[i]] = small[i];
  }
}

ExitPupilTable::ExitPupilTable(const LensSystem& lens, int radialBins, int threads,
                               std::vector<double> probeWavelengthsNm) {
  planeZMm_ = lens.rearVertexZ();
  fallbackRadiusMm_ = 1.5 * lens.rearApertureRadiusMm();
  if (lens.apertureClipping() == ApertureClipping::StopOnly) {
    // No rear rim bounds the region then: rays cross the plane wherever the stop's image through
    // the rear group lies, which off axis reaches past the rear element (out toward the widest
    // element, seen through a wide-angle's strongly bending rear group).
    for (const SurfaceGeometry& s : lens.surfaces())
      fallbackRadiusMm_ = std::max(fallbackRadiusMm_, 1.5 * s.semiApertureMm);
  }
  const double sectorAngle = 2.0 * std::numbers::pi / kSectors;
  for (int k = 0; k <= kSectors; ++k) {
    cosAt_[k] = std::cos(k * sectorAngle);
    sinAt_[k] = std::sin(k * sectorAngle);
  }
  // A shaped stop: the table bounds the pass region of the circle around the shape, which
  // contains the shaped one's, so the estimator stays unbiased (rays outside the shape are
  // blocked by the trace and count as black); except for blades far from their circle in the
  // one-wavelength table, where each azimuth cell has its own bounds, measured with the cell's
  // sweep of the blades as the stop (stop_cells.h).
  std::shared_ptr<const LensSystem> circumscribed;
  if (!lens.stopShape().isCircle()) circumscribed = lens.withCircumscribedStop();
  const LensSystem& bounded = circumscribed ? *circumscribed : lens;
  Probe probe{bounded, planeZMm_, probeWavelengthsNm};
  if (!(planeZMm_ > 0.0)) return;  // film at the rear vertex: nothing to tabulate

  // Image circle: the largest of 24 coarse radii where some ray passes, plus one step.
  constexpr int kCoarse = 24;
  int lastPassing = -1;
  for (int i = 0; i <= kCoarse; ++i)
    if (anyPasses(probe, kMaxFilmRadiusMm * i / kCoarse, fallbackRadiusMm_)) lastPassing = i;
  if (lastPassing < 0) return;
  filmRadiusMaxMm_ = kMaxFilmRadiusMm * std::min(lastPassing + 1, kCoarse) / kCoarse;
  invFilmRadiusMaxMm_ = filmRadiusMaxMm_ > 0.0 ? 1.0 / filmRadiusMaxMm_ : 0.0;
  // Rays pass at the last searched radius: the image circle may reach beyond the search.
  if (lastPassing < kCoarse) imageCircleBoundMm_ = filmRadiusMaxMm_;

  // One probe lens per cell to measure: the circumscribed circle, or each cell's sweep.
  std::vector<std::shared_ptr<const LensSystem>> cellLenses;
  bool mirroredCells = false;
  // The spectral table (probe wavelengths) keeps the circle's bounds: its four wavelengths cost
  // several times one, and with cells the viewer's first pass after an edit of a dispersive lens
  // took 116 ms for six blades and 185 ms for three, over its 100 ms (bench/README.md).
  if (circumscribed && probeWavelengthsNm.empty()) {
    const StopCells& plan = *stopCellsFor(lens.stopShape());
    for (const auto& mask : plan.sweptMasks) {
      ApertureShape sweep;
      sweep.kind = ApertureShape::Kind::Image;
      sweep.mask = mask;
      if (auto cellLens = circumscribed->withStopShape(sweep)) cellLenses.push_back(cellLens);
    }
    if (cellLenses.size() == plan.sweptMasks.size() && plan.count > 1) {
      cells_ = plan.count;
      cellOffsetRadF_ = static_cast<float>(plan.offsetRad);
      cellPeriodRadF_ = static_cast<float>(plan.periodRad);
      cellsPerRadF_ = static_cast<float>(plan.count / plan.periodRad);
      shapeShareOfSweep_ = plan.shapeShareOfSweep;
      mirroredCells = plan.mirrored;
      // (Each cell keeps the circle's radial bins: with half as many, a few passing rays near the
      // rim of the fisheye's image circle, where the cat's eye changes fastest, fell outside both
      // of the bins blended there.)
    } else {
      cellLenses.clear();
    }
  }
  if (circumscribed && cells_ == 1) {
    const double bound = lens.stopShape().boundRadiusFactor();
    shapeShareOfSweep_ = lens.stopShape().areaFactor() / (std::numbers::pi * bound * bound);
  }
  // The circle's regions are symmetric about the x axis: measured on the half-plane.
  const bool halfPlane = cells_ == 1;
  const int measuredCells = cellLenses.empty() ? 1 : static_cast<int>(cellLenses.size());
  auto probeLens = [&](int cell) -> const LensSystem& {
    return cellLenses.empty() ? bounded : *cellLenses[cell];
  };

  radialBins = std::max(radialBins, 2);
  radialBins_ = radialBins;
  binScale_ = radialBins - 1;

  // Raw bins, cell by cell. (Each run of bins is measured in order by one thread, so the table
  // does not depend on which thread took which run.)
  const int binCount = cells_ * radialBins;
  // The threads take runs of kRun neighbouring bins in turn and measure each run in order, each
  // bin from the guesses the one before it gives (measure()'s `previous`).
  std::vector<RawBin> raw(binCount);
  constexpr int kRun = 8;
  const int runsPerCell = (radialBins + kRun - 1) / kRun;
  std::atomic<int> nextRun{0};
  auto work = [&] {
    std::vector<std::unique_ptr<Probe>> probes(measuredCells);  // each thread its own batches
    for (int run = nextRun++; run < measuredCells * runsPerCell; run = nextRun++) {
      const int cell = run / runsPerCell, begin = (run % runsPerCell) * kRun;
      if (!probes[cell])
        probes[cell] =
            std::make_unique<Probe>(Probe{probeLens(cell), planeZMm_, probeWavelengthsNm});
      const RawBin* previous = nullptr;
      for (int j = begin; j < std::min(begin + kRun, radialBins); ++j) {
        const int at = cell * radialBins + j;
        raw[at] =
            measure(*probes[cell], binRadiusMm(j), fallbackRadiusMm_, halfPlane, {}, previous);
        previous = &raw[at];
      }
    }
  };
  threads = std::max(1, threads);
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& thread : pool) thread.join();

  // Empty bins next to non-empty ones: retry with seeds over the neighbour's extent, shifted as
  // the centre moves, outward and inward until the region is really gone.
  auto seedsFrom = [&](const RawBin& near, const RawBin* nearer) {
    std::vector<glm::dvec2> seeds;
    const double shift = nearer && !nearer->empty ? near.centreX - nearer->centreX : 0.0;
    const double shiftY = nearer && !nearer->empty ? near.centreY - nearer->centreY : 0.0;
    const double cx = near.centreX + shift, cy = near.centreY + shiftY;
    const double left = near.vertexRadius[kSectors / 2], right = near.vertexRadius[0];
    const double up = near.vertexRadius[kSectors / 4];
    const double down = halfPlane ? 0.0 : near.vertexRadius[3 * kSectors / 4];
    constexpr int kSeeds = 9;
    for (int i = 0; i < kSeeds; ++i)
      for (int k = 0; k < kSeeds; ++k)
        seeds.push_back({cx - left + (left + right) * (i + 0.5) / kSeeds,
                         cy - down + (up + down) * (k + 0.5) / kSeeds});
    return seeds;
  };
  for (int cell = 0; cell < measuredCells; ++cell) {
    Probe own{probeLens(cell), planeZMm_, probeWavelengthsNm};
    RawBin* row = raw.data() + cell * radialBins;
    for (int j = 1; j < radialBins; ++j)
      if (row[j].empty && !row[j - 1].empty)
        row[j] = measure(own, binRadiusMm(j), fallbackRadiusMm_, halfPlane,
                         seedsFrom(row[j - 1], j >= 2 ? &row[j - 2] : nullptr));
    for (int j = radialBins - 2; j >= 0; --j)
      if (row[j].empty && !row[j + 1].empty)
        row[j] = measure(own, binRadiusMm(j), fallbackRadiusMm_, halfPlane,
                         seedsFrom(row[j + 1], j + 2 < radialBins ? &row[j + 2] : nullptr));
  }
  // Mirrored cells: cell cells_ - 1 - a is cell a with y -> -y (vertex k -> vertex -k).
  if (mirroredCells) {
    for (int cell = measuredCells; cell < cells_; ++cell) {
      for (int j = 0; j < radialBins; ++j) {
        const RawBin& source = raw[(cells_ - 1 - cell) * radialBins + j];
        RawBin& image = raw[cell * radialBins + j];
        image = source;
        image.centreY = -source.centreY;
        for (int k = 0; k < kSectors; ++k)
          image.vertexRadius[k] = source.vertexRadius[(kSectors - k) % kSectors];
      }
    }
  }

  // Union with the neighbours (along the radius, within the cell), margin, triangle areas and
  // their CDF.
  bins_.resize(binCount);
  const double absoluteMargin = 1e-4 * fallbackRadiusMm_;
  const double halfSin = 0.5 * std::sin(sectorAngle);
  const int measured = halfPlane ? kSectors / 2 + 1 : kSectors;
  for (int at = 0; at < binCount; ++at) {
    if (raw[at].empty) continue;
    const int j = at % radialBins;
    Bin& b = bins_[at];
    b.empty = false;
    b.centreXMm = raw[at].centreX;
    b.centreYMm = raw[at].centreY;
    for (int k = 0; k < measured; ++k) {
      double r = raw[at].vertexRadius[k];
      for (int n : {j - 1, j + 1})
        if (n >= 0 && n < radialBins && !raw[at - j + n].empty)
          r = std::max(r, raw[at - j + n].vertexRadius[k]);
      const double v = r * (1.0 + kRelativeMargin) + absoluteMargin;
      b.vertexRadiusMm[k] = v;
      if (halfPlane && k > 0 && k < kSectors / 2) b.vertexRadiusMm[kSectors - k] = v;  // below x
    }
    double total = 0.0;
    for (int k = 0; k < kSectors; ++k) {
      total += halfSin * b.vertexRadiusMm[k] * b.vertexRadiusMm[(k + 1) % kSectors];
      b.cdf[k] = total;
    }
    for (auto& c : b.cdf) c /= total;
    b.cdf[kSectors - 1] = 1.0;
    buildAliasTable(b);
    for (int k = 0; k < kSectors; ++k) {
      const double keep = b.aliasProbability[k];
      b.invAliasProbability[k] = keep > 0.0 ? 1.0 / keep : 0.0;
      b.invAliasComplement[k] = keep < 1.0 ? 1.0 / (1.0 - keep) : 0.0;
    }
    b.areaMm2 = total;
    b.invAreaPerMm2 = 1.0 / total;
  }
  // Empty bins take the centre of the nearest non-empty bin of their cell (used by the centre
  // interpolation): outward first, then inward for those still without one.
  for (int cell = 0; cell < cells_; ++cell) {
    Bin* row = bins_.data() + cell * radialBins;
    std::vector<bool> given(radialBins, false);
    for (int pass = 0; pass < 2; ++pass) {
      int last = -1;
      for (int step = 0; step < radialBins; ++step) {
        const int j = pass == 0 ? step : radialBins - 1 - step;
        if (!row[j].empty) {
          last = j;
        } else if (last >= 0 && !given[j]) {
          row[j].centreXMm = row[last].centreXMm;
          row[j].centreYMm = row[last].centreYMm;
          given[j] = true;
        }
      }
    }
  }
  buildSamplingBins();
}

void ExitPupilTable::buildSamplingBins() {
  samplingBins_.resize(bins_.size());
  for (std::size_t j = 0; j < bins_.size(); ++j) {
    const Bin& b = bins_[j];
    SamplingBin& out = samplingBins_[j];
    out.empty = b.empty;
    out.centreXMm = static_cast<float>(b.centreXMm);
    out.centreYMm = static_cast<float>(b.centreYMm);
    out.invAreaPerMm2 = static_cast<float>(b.invAreaPerMm2);
    for (int k = 0; k < kSectors; ++k) {
      out.slots[k] = {static_cast<float>(b.aliasProbability[k]),
                      static_cast<float>(b.invAliasProbability[k]),
                      static_cast<float>(b.invAliasComplement[k]), b.alias[k]};
      const double ra = b.vertexRadiusMm[k], rb = b.vertexRadiusMm[(k + 1) % kSectors];
      out.sectors[k] = {static_cast<float>(ra * cosAt_[k]), static_cast<float>(ra * sinAt_[k]),
                        static_cast<float>(rb * cosAt_[k + 1]),
                        static_cast<float>(rb * sinAt_[k + 1])};
    }
  }
}

double ExitPupilTable::binRadiusMm(int j) const {
  // Inverse of t = (x + x^2) / 2 * binScale_, x = r / filmRadiusMaxMm_.
  const double s = j / binScale_;
  return filmRadiusMaxMm_ * 0.5 * (std::sqrt(1.0 + 8.0 * s) - 1.0);
}

ExitPupilTable::Lookup ExitPupilTable::lookup(glm::dvec2 film) const {
  Lookup out;
  const double r = std::sqrt(film.x * film.x + film.y * film.y);
  const int last = radialBins_ - 1;
  const double x = r / filmRadiusMaxMm_;
  const double t = 0.5 * (x + x * x) * binScale_;
  const int j = std::min(static_cast<int>(t), last - 1);
  out.f = std::clamp(t - j, 0.0, 1.0);
  out.j = cellFirstBin(film.x, film.y) + j;
  const Bin& b0 = bins_[out.j];
  const Bin& b1 = bins_[out.j + 1];
  out.centreX = (1.0 - out.f) * b0.centreXMm + out.f * b1.centreXMm;  // as in sample()
  out.centreY = (1.0 - out.f) * b0.centreYMm + out.f * b1.centreYMm;
  return out;
}

double ExitPupilTable::imageCircleRadiusMm() const {
  int widest = -1;
  for (std::size_t at = 0; at < bins_.size(); ++at)
    if (!bins_[at].empty) widest = std::max(widest, static_cast<int>(at) % radialBins_);
  return widest >= 0 ? binRadiusMm(widest) : 0.0;
}

bool ExitPupilTable::inside(const Bin& b, double centreX, double centreY, double x,
                            double y) const {
  if (b.empty) return false;
  const double dx = x - centreX, dy = y - centreY;
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
    if (std::abs(point.x) > fallbackRadiusMm_ || std::abs(point.y) > fallbackRadiusMm_) return 0.0;
    return 1.0 / (4.0 * fallbackRadiusMm_ * fallbackRadiusMm_);
  }
  double c = 1.0, sn = 0.0;
  if (r > 0.0) {
    c = film.x / r;
    sn = film.y / r;
  }
  const double lx = c * point.x + sn * point.y, ly = -sn * point.x + c * point.y;
  const auto [j, f, centreX, centreY] = lookup(film);
  double density = 0.0;
  if (inside(bins_[j], centreX, centreY, lx, ly)) density += (1.0 - f) / bins_[j].areaMm2;
  if (inside(bins_[j + 1], centreX, centreY, lx, ly)) density += f / bins_[j + 1].areaMm2;
  return density;
}

double ExitPupilTable::pdfInPassRegion(glm::dvec2 film) const {
  const double r = std::sqrt(film.x * film.x + film.y * film.y);
  if (bins_.empty() || r > filmRadiusMaxMm_) {
    if (bins_.empty() && filmRadiusMaxMm_ == 0.0 && planeZMm_ <= 0.0) return 0.0;  // no sample
    return 1.0 / (4.0 * fallbackRadiusMm_ * fallbackRadiusMm_);
  }
  // As sampleInline: bin j with probability 1 - f, bin j + 1 with f, each uniform over its area
  // (an empty bin's inverse area is 0: its share of the samples is dropped).
  const Lookup l = lookup(film);
  return (1.0 - l.f) * bins_[l.j].invAreaPerMm2 + l.f * bins_[l.j + 1].invAreaPerMm2;
}

void ExitPupilTable::pdfInPassRegion(const float* filmXMm, const float* filmYMm, float* pdfPerMm2,
                                     std::size_t n) const {
  if (bins_.empty()) {
    const auto none = static_cast<float>(pdfInPassRegion(glm::dvec2{0.0}));
    for (std::size_t i = 0; i < n; ++i) pdfPerMm2[i] = none;
    return;
  }
  // As lookup() and the scalar form, without branches.
  const auto fallback = static_cast<float>(1.0 / (4.0 * fallbackRadiusMm_ * fallbackRadiusMm_));
  const auto rMax = static_cast<float>(filmRadiusMaxMm_);
  const auto invRMax = static_cast<float>(invFilmRadiusMaxMm_);
  const auto scale = static_cast<float>(binScale_);
  const int lastPair = radialBins_ - 2;
  for (std::size_t i = 0; i < n; ++i) {
    const float fx = filmXMm[i], fy = filmYMm[i];
    const float r = std::sqrt(fx * fx + fy * fy);
    const int first = cellFirstBin(fx, fy);
    const float x = r * invRMax;
    // (Clamped before the conversion: a radius beyond the table, answered below, must not
    // overflow it.)
    const float t = std::clamp(0.5f * (x + x * x) * scale, 0.0f, scale);
    const int j = std::clamp(static_cast<int>(t), 0, lastPair);
    const float f = std::clamp(t - static_cast<float>(j), 0.0f, 1.0f);
    const float inside = (1.0f - f) * samplingBins_[first + j].invAreaPerMm2 +
                         f * samplingBins_[first + j + 1].invAreaPerMm2;
    pdfPerMm2[i] = r > rMax ? fallback : inside;
  }
}

// The sampling routine shared by sample() and sampleRays(); false when there is no sample.
inline bool ExitPupilTable::sampleInline(double filmX, double filmY, double u0, double u1,
                                         double& pointX, double& pointY, double& pdf) const {
  const double r = std::sqrt(filmX * filmX + filmY * filmY);
  if (bins_.empty() || r > filmRadiusMaxMm_) {
    if (bins_.empty() && filmRadiusMaxMm_ == 0.0 && planeZMm_ <= 0.0) return false;
    // Outside the table: uniform over the square around the disk the table search covered
    // (no trigonometry; rays through the corners are simply blocked).
    const double half = fallbackRadiusMm_;
    pointX = half * (2.0 * u0 - 1.0);
    pointY = half * (2.0 * u1 - 1.0);
    pdf = 1.0 / (4.0 * half * half);
    return true;
  }
  // Written without unpredictable branches: the renderer calls this for every camera ray.
  const double x = r * invFilmRadiusMaxMm_;
  const double t = 0.5 * (x + x * x) * binScale_;
  const int radial = std::min(static_cast<int>(t), radialBins_ - 2);
  const double f = std::clamp(t - radial, 0.0, 1.0);
  const int j = cellFirstBin(filmX, filmY) + radial;
  const Bin& b0 = bins_[j];
  const Bin& b1 = bins_[j + 1];
  // Empty bins carry their non-empty neighbour's centre (see the constructor), so the lerp is
  // always meaningful.
  const double centreX = (1.0 - f) * b0.centreXMm + f * b1.centreXMm;
  const double centreY = (1.0 - f) * b0.centreYMm + f * b1.centreYMm;  // 0 on the half-plane
  const bool second = u0 >= 1.0 - f;
  const Bin& chosen = second ? b1 : b0;
  if (chosen.empty) return false;
  const double ux =
      std::min((second ? u0 - (1.0 - f) : u0) / (second ? f : 1.0 - f), 0.99999999999);
  // Alias method: slot = floor(32 ux); its fractional part decides between the slot's sector and
  // its alias and is then stretched back to [0, 1) for the position inside the triangle.
  const double scaled = ux * kSectors;
  const int slot = std::min(static_cast<int>(scaled), kSectors - 1);
  const double fraction = scaled - slot;
  const double keep = chosen.aliasProbability[slot];
  const bool stay = fraction < keep;
  const int k = stay ? slot : chosen.alias[slot];
  const double w = stay ? fraction * chosen.invAliasProbability[slot]
                        : (fraction - keep) * chosen.invAliasComplement[slot];
  // Uniform in the triangle (centre, A, B): p = centre + sqrt(w) ((1 - v) A + v B).
  const double s = std::sqrt(w);
  const double a = (1.0 - u1) * chosen.vertexRadiusMm[k];
  const double bb = u1 * chosen.vertexRadiusMm[(k + 1) & (kSectors - 1)];
  const double lx = centreX + s * (a * cosAt_[k] + bb * cosAt_[k + 1]);
  const double ly = centreY + s * (a * sinAt_[k] + bb * sinAt_[k + 1]);
  // Rotate from the bin frame (film point on +x) to the film point's azimuth.
  const double invR = r > 0.0 ? 1.0 / r : 0.0;
  const double c = r > 0.0 ? filmX * invR : 1.0;
  const double sn = filmY * invR;
  pointX = c * lx - sn * ly;
  pointY = sn * lx + c * ly;
  pdf = (1.0 - f) * b0.invAreaPerMm2 + f * b1.invAreaPerMm2;
  return true;
}

std::optional<PupilSample> ExitPupilTable::sample(glm::dvec2 film, glm::dvec2 u) const {
  double x = 0.0, y = 0.0, pdf = 0.0;
  if (!sampleInline(film.x, film.y, u.x, u.y, x, y, pdf)) return std::nullopt;
  return PupilSample{{x, y, planeZMm_}, pdf};
}

void ExitPupilTable::sampleRaysOneByOne(const float* filmX, const float* filmY, const float* u0,
                                        const float* u1, std::size_t n, LensRayBatch& rays,
                                        float* pdfPerMm2) const {
  const float planeZ = static_cast<float>(planeZMm_);
  for (std::size_t i = 0; i < n; ++i) {
    double x = 0.0, y = 0.0, pdf = 0.0;
    const bool ok = sampleInline(filmX[i], filmY[i], u0[i], u1[i], x, y, pdf);
    const float dx = static_cast<float>(x) - filmX[i], dy = static_cast<float>(y) - filmY[i];
    const float invLength = 1.0f / std::sqrt(dx * dx + dy * dy + planeZ * planeZ);
    rays.ox[i] = filmX[i];
    rays.oy[i] = filmY[i];
    rays.oz[i] = 0.0f;
    rays.dx[i] = dx * invLength;
    rays.dy[i] = dy * invLength;
    rays.dz[i] = planeZ * invLength;
    rays.alive[i] = ok ? 1 : 0;
    pdfPerMm2[i] = ok ? static_cast<float>(pdf) : 0.0f;
  }
}

}  // namespace lenslab::optics
