#include "optics/aperture_shape.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>

namespace lenslab::optics {

namespace {

constexpr double kPi = std::numbers::pi;

// Blade k's edge runs from corner k to corner k + 1; its outward normal is half-way between.
struct BladeGeometry {
  double halfAngle;      // pi / N
  double apothem;        // cos(pi / N): distance of a straight edge from the centre
  double halfChord;      // sin(pi / N)
  double arcRadius;      // 1 / curvature (infinite when straight)
  double centreOffset;   // curved: the arc's centre along the normal
  double firstNormalAt;  // angle of blade 0's normal
};

BladeGeometry bladeGeometry(const ApertureShape& s) {
  BladeGeometry g{};
  g.halfAngle = kPi / s.bladeCount;
  g.apothem = std::cos(g.halfAngle);
  g.halfChord = std::sin(g.halfAngle);
  g.arcRadius = s.curvature > 0.0 ? 1.0 / s.curvature : INFINITY;
  // The arc passes through both corners: its centre lies on the normal, at apothem minus the
  // distance from the chord to the centre, sqrt(rho^2 - h^2). Curvature 1 puts it at the origin.
  g.centreOffset =
      s.curvature > 0.0
          ? g.apothem -
                std::sqrt(std::max(0.0, g.arcRadius * g.arcRadius - g.halfChord * g.halfChord))
          : 0.0;
  g.firstNormalAt = s.rotationDeg * kPi / 180.0 + g.halfAngle;
  return g;
}

std::string number(double value) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("0");
}

// Messages are joined with a stream: GCC 12 flags std::string operator+ chains with a false
// -Wrestrict positive (as lens_file.cpp notes).
template <typename... Parts>
std::string joined(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

}  // namespace

double ApertureMask::openFraction() const {
  if (open.empty()) return 0.0;
  std::size_t count = 0;
  for (std::uint8_t o : open) count += o;
  return static_cast<double>(count) / static_cast<double>(open.size());
}

void ApertureMask::finish() {
  measureOpenRadius();
  openBits.assign((open.size() + 31) / 32, 0u);
  for (std::size_t i = 0; i < open.size(); ++i)
    if (open[i]) openBits[i / 32] |= 1u << (i % 32);
}

void ApertureMask::measureOpenRadius() {
  double farthestSq = 0.0;
  const double half = 0.5 * sizePx;
  for (int row = 0; row < sizePx; ++row) {
    for (int col = 0; col < sizePx; ++col) {
      if (!open[static_cast<std::size_t>(row) * sizePx + col]) continue;
      // The pixel's farthest corner from the centre.
      const double x = std::max(std::abs(col - half), std::abs(col + 1 - half));
      const double y = std::max(std::abs(row - half), std::abs(row + 1 - half));
      farthestSq = std::max(farthestSq, x * x + y * y);
    }
  }
  openRadiusFactor = sizePx > 0 ? std::sqrt(farthestSq) / half : 0.0;
}

double ApertureShape::boundRadiusFactor() const {
  if (kind != Kind::Image) return 1.0;
  return mask ? mask->openRadiusFactor : std::numbers::sqrt2;
}

double ApertureShape::areaFactor() const {
  switch (kind) {
    case Kind::Circle:
      return kPi;
    case Kind::Blades: {
      const BladeGeometry g = bladeGeometry(*this);
      double area = bladeCount * g.apothem * g.halfChord;  // N triangles (centre, corner, corner)
      if (curvature > 0.0) {
        const double rho = g.arcRadius, h = g.halfChord;
        area += bladeCount * (rho * rho * std::asin(h / rho) - h * std::sqrt(rho * rho - h * h));
      }
      return area;
    }
    case Kind::Image:
      return mask ? 4.0 * mask->openFraction() : 0.0;
  }
  return 0.0;
}

double ApertureShape::edgeDistanceUnit(double angleRad) const {
  if (kind == Kind::Circle) return 1.0;
  if (kind == Kind::Image) return boundRadiusFactor();
  const BladeGeometry g = bladeGeometry(*this);
  const double ux = std::cos(angleRad), uy = std::sin(angleRad);
  double nearest = INFINITY;
  for (int k = 0; k < bladeCount; ++k) {
    const double at = g.firstNormalAt + 2.0 * g.halfAngle * k;
    const double along = std::cos(at) * ux + std::sin(at) * uy;  // n . u
    if (curvature > 0.0) {
      // |t u - c n|^2 = rho^2: the outer root of t^2 - 2 b t - q = 0, b = c (n.u),
      // q = rho^2 - c^2 = (rho - c)(rho + c) > 0. With c + rho written without the cancellation
      // of a nearly straight blade (c -> -infinity), as StopShapeTest does, and the root taken in
      // the form that does not subtract when b < 0.
      const double rho = g.arcRadius, h = g.halfChord;
      const double root = std::sqrt(std::max(0.0, rho * rho - h * h));
      const double c = g.apothem - root;
      const double cPlusRho = g.apothem + h * h / (rho + root);
      const double q = (rho - c) * cPlusRho, b = c * along;
      const double s = std::sqrt(b * b + q);
      nearest = std::min(nearest, b > 0.0 ? b + s : q / (s - b));
    } else if (along > 0.0) {
      nearest = std::min(nearest, g.apothem / along);
    }
  }
  return nearest;
}

bool ApertureShape::containsUnit(glm::dvec2 p) const {
  switch (kind) {
    case Kind::Circle:
      return p.x * p.x + p.y * p.y <= 1.0;
    case Kind::Blades: {
      const BladeGeometry g = bladeGeometry(*this);
      for (int k = 0; k < bladeCount; ++k) {
        const double at = g.firstNormalAt + 2.0 * g.halfAngle * k;
        const double nx = std::cos(at), ny = std::sin(at);
        if (curvature > 0.0) {
          const double dx = p.x - g.centreOffset * nx, dy = p.y - g.centreOffset * ny;
          if (dx * dx + dy * dy > g.arcRadius * g.arcRadius) return false;
        } else if (nx * p.x + ny * p.y > g.apothem) {
          return false;
        }
      }
      return true;
    }
    case Kind::Image: {
      if (!mask || mask->sizePx <= 0) return false;
      const double u = 0.5 * (p.x + 1.0), v = 1.0 - 0.5 * (p.y + 1.0);
      if (!(u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0)) return false;
      const int n = mask->sizePx;
      const int col = std::min(n - 1, static_cast<int>(u * n));
      const int row = std::min(n - 1, static_cast<int>(v * n));
      return mask->open[static_cast<std::size_t>(row) * n + col] != 0;
    }
  }
  return false;
}

std::vector<glm::dvec2> ApertureShape::outlineUnit(int pointsPerEdge) const {
  std::vector<glm::dvec2> out;
  if (kind == Kind::Circle || (kind == Kind::Blades && curvature >= 1.0)) {
    constexpr int kSteps = 96;
    for (int i = 0; i <= kSteps; ++i) {
      const double a = 2.0 * kPi * i / kSteps;
      out.push_back({std::cos(a), std::sin(a)});
    }
    return out;
  }
  if (kind == Kind::Image) return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  const BladeGeometry g = bladeGeometry(*this);
  const int steps = curvature > 0.0 ? std::max(1, pointsPerEdge) : 1;
  for (int k = 0; k < bladeCount; ++k) {
    const double normalAt = g.firstNormalAt + 2.0 * g.halfAngle * k;
    const double cornerAt = normalAt - g.halfAngle;
    const glm::dvec2 corner{std::cos(cornerAt), std::sin(cornerAt)};
    if (curvature <= 0.0) {
      out.push_back(corner);
      continue;
    }
    // Along the arc about its centre, from this corner to the next.
    const glm::dvec2 centre = g.centreOffset * glm::dvec2{std::cos(normalAt), std::sin(normalAt)};
    const double span = std::asin(std::min(1.0, g.halfChord / g.arcRadius));
    for (int i = 0; i < steps; ++i) {
      const double a = normalAt - span + 2.0 * span * i / steps;
      out.push_back(centre + g.arcRadius * glm::dvec2{std::cos(a), std::sin(a)});
    }
  }
  out.push_back(out.front());
  return out;
}

ApertureShape ApertureShape::mirroredLeftToRight() const {
  ApertureShape seen = *this;
  if (kind == Kind::Blades) seen.rotationDeg = 180.0 - rotationDeg;
  if (kind == Kind::Image) {
    seen.mirrored = !mirrored;
    if (mask) seen.mask = mirroredMask(*mask);
  }
  return seen;
}

void ApertureShape::attachLoadedMask(std::shared_ptr<const ApertureMask> loaded) {
  mask = mirrored && loaded ? mirroredMask(*loaded) : std::move(loaded);
}

std::shared_ptr<const ApertureMask> mirroredMask(const ApertureMask& mask) {
  auto seen = std::make_shared<ApertureMask>(mask);
  const int n = mask.sizePx;
  for (int row = 0; row < n; ++row) {
    auto first = seen->open.begin() + static_cast<std::ptrdiff_t>(row) * n;
    std::reverse(first, first + n);
  }
  seen->finish();  // (the farthest open corner's distance is the same in the mirror image)
  return seen;
}

std::string ApertureShape::spec() const {
  switch (kind) {
    case Kind::Circle:
      return "circle";
    case Kind::Blades:
      return joined("blades ", bladeCount, " curvature ", number(curvature), " rotation ",
                    number(rotationDeg));
    case Kind::Image:
      return joined(mirrored ? "image-mirrored " : "image ", imageName);
  }
  return "circle";
}

bool ApertureShape::operator==(const ApertureShape& o) const {
  if (kind != o.kind) return false;
  switch (kind) {
    case Kind::Circle:
      return true;
    case Kind::Blades:
      return bladeCount == o.bladeCount && curvature == o.curvature && rotationDeg == o.rotationDeg;
    case Kind::Image:
      return imageName == o.imageName && mirrored == o.mirrored &&
             (mask ? mask->source : std::filesystem::path()) ==
                 (o.mask ? o.mask->source : std::filesystem::path());
  }
  return false;
}

ApertureSpecResult parseApertureSpec(std::string_view text) {
  ApertureSpecResult result;
  struct Word {
    std::string_view text;
    int column;
  };
  std::vector<Word> words;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == ' ' || text[i] == '\t' || text[i] == '\r') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '\r') ++j;
    words.push_back({text.substr(i, j - i), static_cast<int>(i)});
    i = j;
  }
  auto fail = [&](int column, std::string message) {
    result.error = std::move(message);
    result.column = column;
    return result;
  };
  if (words.empty()) return fail(0, "expected circle, blades N or image FILE");
  ApertureShape shape;
  const Word& head = words[0];
  if (head.text == "circle") {
    if (words.size() > 1) return fail(words[1].column, "nothing may follow 'circle'");
    result.shape = shape;
    return result;
  }
  if (head.text == "image" || head.text == "image-mirrored") {
    if (words.size() < 2) return fail(head.column, joined("'", head.text, "' needs a file name"));
    // The name is the rest of the text (file names may hold spaces), trailing blanks dropped.
    std::string_view name = text.substr(static_cast<std::size_t>(words[1].column));
    while (!name.empty() && (name.back() == ' ' || name.back() == '\t' || name.back() == '\r'))
      name.remove_suffix(1);
    shape.kind = ApertureShape::Kind::Image;
    shape.imageName = std::string(name);
    shape.mirrored = head.text == "image-mirrored";
    result.shape = shape;
    return result;
  }
  if (head.text != "blades")
    return fail(head.column, joined("unknown aperture '", head.text,
                                    "' (expected circle, blades N or image FILE)"));
  auto parseValue = [&](const Word& w, double& value) {
    const char* end = w.text.data() + w.text.size();
    const char* begin = w.text.data() + (w.text.starts_with('+') ? 1 : 0);
    const auto [stop, error] = std::from_chars(begin, end, value);
    return error == std::errc() && stop == end && std::isfinite(value);
  };
  if (words.size() < 2) return fail(head.column, "'blades' needs a blade count (3 to 32)");
  double count = 0.0;
  if (!parseValue(words[1], count) || count != std::floor(count))
    return fail(words[1].column,
                joined("'", words[1].text, "' is not a whole number (expected the blade count)"));
  if (count < kMinApertureBlades || count > kMaxApertureBlades)
    return fail(words[1].column, joined("blade count ", words[1].text,
                                        " is out of range (an iris has 3 to 32 blades)"));
  shape.kind = ApertureShape::Kind::Blades;
  shape.bladeCount = static_cast<int>(count);
  for (std::size_t i = 2; i < words.size(); i += 2) {
    const Word& key = words[i];
    if (key.text != "curvature" && key.text != "rotation")
      return fail(key.column, joined("unknown blade setting '", key.text,
                                     "' (expected curvature or rotation)"));
    if (i + 1 >= words.size()) return fail(key.column, joined("'", key.text, "' needs a value"));
    const Word& valueWord = words[i + 1];
    double value = 0.0;
    if (!parseValue(valueWord, value))
      return fail(valueWord.column,
                  joined("'", valueWord.text, "' is not a number (expected the ", key.text, ")"));
    if (key.text == "curvature") {
      if (value < 0.0 || value > 1.0)
        return fail(valueWord.column, joined("curvature ", valueWord.text,
                                             " is out of range (0 straight to 1 round)"));
      shape.curvature = value;
    } else {
      if (std::abs(value) > 360.0)
        return fail(valueWord.column,
                    joined("rotation ", valueWord.text, " is out of range (-360 to 360 degrees)"));
      shape.rotationDeg = value;
    }
  }
  result.shape = shape;
  return result;
}

std::shared_ptr<const ApertureMask> rasterizeApertureMask(const std::vector<glm::dvec2>& polygon,
                                                          int sizePx, std::string name) {
  auto mask = std::make_shared<ApertureMask>();
  mask->sizePx = sizePx;
  mask->source = std::move(name);
  mask->open.assign(static_cast<std::size_t>(sizePx) * sizePx, 0);
  const std::size_t n = polygon.size();
  for (int row = 0; row < sizePx; ++row) {
    for (int col = 0; col < sizePx; ++col) {
      const double x = -1.0 + 2.0 * (col + 0.5) / sizePx;
      const double y = 1.0 - 2.0 * (row + 0.5) / sizePx;
      // Winding number: upward edges with the point on their left count +1, downward ones on
      // their right -1.
      int winding = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % n];
        const double side = (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y);
        if (a.y <= y) {
          if (b.y > y && side > 0.0) ++winding;
        } else if (b.y <= y && side < 0.0) {
          --winding;
        }
      }
      mask->open[static_cast<std::size_t>(row) * sizePx + col] = winding != 0 ? 1 : 0;
    }
  }
  mask->finish();
  return mask;
}

std::optional<ApertureShape> builtinPbrtAperture(std::string_view name) {
  ApertureShape shape;
  if (name == "square") {
    shape.kind = ApertureShape::Kind::Blades;
    shape.bladeCount = 4;
    shape.rotationDeg = 45.0;
    return shape;
  }
  if (name == "pentagon") {
    shape.kind = ApertureShape::Kind::Blades;
    shape.bladeCount = 5;
    shape.rotationDeg = 90.0;
    return shape;
  }
  if (name == "star") {
    // Ten corners alternating between the outer radius 1 and the inner radius of a regular
    // pentagram, cos 72 / cos 36, starting with a point on +x... as pbrt-v4 lays them out.
    std::vector<glm::dvec2> corners;
    const double inner = std::cos(72.0 * kPi / 180.0) / std::cos(36.0 * kPi / 180.0);
    for (int i = 0; i < 10; ++i) {
      const double r = (i & 1) ? 1.0 : inner;
      corners.push_back({r * std::cos(kPi * i / 5.0), r * std::sin(kPi * i / 5.0)});
    }
    shape.kind = ApertureShape::Kind::Image;
    shape.imageName = "star";
    shape.mask = rasterizeApertureMask(corners, 256, "star");
    return shape;
  }
  if (name == "gaussian") {
    shape.kind = ApertureShape::Kind::Image;
    shape.imageName = "gaussian";
    shape.mask = gaussianHalftoneMask(kGaussianMaskSizePx);
    return shape;
  }
  return std::nullopt;  // not built in: the caller resolves the name as an image file
}

double gaussianApertureTransmission(double xUnit, double yUnit) {
  // pbrt-v4's built-in "gaussian": exp(-r^2 / sigma^2) - exp(-1 / sigma^2) with sigma = 1, r in
  // units of the stop's radius, clamped at 0 (so it reaches 0 at the rim).
  const double r2 = xUnit * xUnit + yUnit * yUnit;
  return std::max(0.0, std::exp(-r2) - std::exp(-1.0));
}

std::shared_ptr<const ApertureMask> gaussianHalftoneMask(int sizePx) {
  // The 16 x 16 Bayer threshold matrix, built by the recursion M(2n) = [[4M, 4M + 2],
  // [4M + 3, 4M + 1]] from M(1) = [0]: each of 0..255 once, spread so that the first k of them
  // are as evenly scattered over the block as can be.
  constexpr int kBlock = 16;
  int bayer[kBlock][kBlock] = {{0}};
  for (int size = 1; size < kBlock; size *= 2)
    for (int row = size - 1; row >= 0; --row)
      for (int col = size - 1; col >= 0; --col) {
        const int m = 4 * bayer[row][col];
        bayer[row][col] = m;
        bayer[row][col + size] = m + 2;
        bayer[row + size][col] = m + 3;
        bayer[row + size][col + size] = m + 1;
      }
  auto mask = std::make_shared<ApertureMask>();
  mask->sizePx = sizePx;
  mask->source = "gaussian";
  mask->open.assign(static_cast<std::size_t>(sizePx) * sizePx, 0);
  for (int row = 0; row < sizePx; ++row) {
    for (int col = 0; col < sizePx; ++col) {
      const double x = -1.0 + 2.0 * (col + 0.5) / sizePx;
      const double y = 1.0 - 2.0 * (row + 0.5) / sizePx;
      const double threshold = (bayer[row % kBlock][col % kBlock] + 0.5) / (kBlock * kBlock);
      mask->open[static_cast<std::size_t>(row) * sizePx + col] =
          gaussianApertureTransmission(x, y) > threshold ? 1 : 0;
    }
  }
  mask->finish();
  return mask;
}

StopShapeTest::StopShapeTest(const ApertureShape& shape, double stopRadiusMm)
    : kind_(shape.kind), radiusSqMm2_(stopRadiusMm * stopRadiusMm), radiusMm_(stopRadiusMm) {
  if (kind_ == ApertureShape::Kind::Image && !shape.mask) kind_ = ApertureShape::Kind::Circle;
  if (kind_ == ApertureShape::Kind::Blades) {
    const BladeGeometry g = bladeGeometry(shape);
    const double R = stopRadiusMm;
    for (int k = 0; k < shape.bladeCount; ++k) {
      const double at = g.firstNormalAt + 2.0 * g.halfAngle * k;
      const double nx = std::cos(at), ny = std::sin(at);
      Edge e;
      if (shape.curvature > 0.0) {
        const double rho = g.arcRadius * R, h = g.halfChord * R, a = g.apothem * R;
        const double root = std::sqrt(std::max(0.0, rho * rho - h * h));
        const double c = a - root;
        // c + rho = a + h^2 / (rho + root), without the cancellation of a - root + rho.
        const double cPlusRho = a + h * h / (rho + root);
        e.s = static_cast<float>(0.5 / rho);
        e.wx = static_cast<float>(-c / rho * nx);
        e.wy = static_cast<float>(-c / rho * ny);
        e.k = static_cast<float>((c - rho) * cPlusRho / (2.0 * rho));
      } else {
        e.wx = static_cast<float>(nx);
        e.wy = static_cast<float>(ny);
        e.k = static_cast<float>(-g.apothem * R);
      }
      edges_.push_back(e);
    }
  }
  if (kind_ == ApertureShape::Kind::Image) {
    mask_ = shape.mask;
    pixelsPerMm_ = stopRadiusMm > 0.0 ? 0.5 * mask_->sizePx / stopRadiusMm : 0.0;
    if (mask_->openBits.size() != (mask_->open.size() + 31) / 32) {
      ApertureMask packed = *mask_;
      packed.finish();
      ownBits_ = std::move(packed.openBits);
    }
  }
}

bool StopShapeTest::maskContains(double xMm, double yMm) const {
  // Pixel column from the left edge x = -R, row from the top edge y = +R.
  const double colF = (xMm + radiusMm_) * pixelsPerMm_;
  const double rowF = (radiusMm_ - yMm) * pixelsPerMm_;
  const int n = mask_->sizePx;
  if (!(colF >= 0.0 && rowF >= 0.0 && colF < n && rowF < n)) return false;
  return mask_->open[static_cast<std::size_t>(rowF) * n + static_cast<std::size_t>(colF)] != 0;
}

}  // namespace lenslab::optics
