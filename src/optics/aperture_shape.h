#pragma once
// The shape of the aperture stop: the default circle, N straight or curved blades with a
// rotation, or an image mask (white = open). It belongs to the stop of a Prescription; the traces
// test a ray's hit on the stop plane against it (StopShapeTest, below) and the exit-pupil table
// bounds the pass region of a stop that contains it (the circle that circumscribes it,
// boundRadiusFactor, or per azimuth cell the shape's sweep: stop_cells.h), so sampling stays
// unbiased for any shape: rays through the bound but outside the shape are simply blocked.
//
// Geometry, in units of the stop's semi-diameter R (the stop row's aperture diameter / 2), lens
// frame x and y (y up in the cross-section):
// - Circle: |p| <= R.
// - Blades: a regular N-gon inscribed in the circle of radius R, corner k at the angle
//   rotation + k 360/N degrees from +x toward +y. Each blade edge is an arc through its two
//   corners bulging outward with radius R / curvature: curvature 0 is a straight edge, 1 is the
//   stop circle itself (a fully rounded iris). The shape is the intersection of the N half-planes
//   (straight) or N disks (curved): convex.
// - Image: a square bitmap spanning the square circumscribed about the stop circle, as pbrt-v4's
//   realistic camera maps its aperture image ((x/R + 1)/2, 1 - (y/R + 1)/2 as image u, v: the
//   image's top row is +y). A pixel is open when the mean of its colour channels is at least half
//   of white. Unlike pbrt-v4, which weighs by the image's value and rescales it to the circle's
//   brightness, lenslab's stop is physical: a binary mask that passes less light when it is
//   smaller (a square stop takes in its area, not the circle's).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

namespace lenslab::optics {

inline constexpr int kMinApertureBlades = 3;
inline constexpr int kMaxApertureBlades = 32;

// A thresholded, square aperture image.
struct ApertureMask {
  int sizePx = 0;                  // width = height
  std::vector<std::uint8_t> open;  // sizePx * sizePx, row 0 at the top (+y), 1 = open
  std::filesystem::path source;    // the file it came from, or a name ("star") for a built-in
  double openFraction() const;     // share of open pixels
  // Largest distance of an open pixel's corner from the centre, over half the side (at most
  // sqrt(2)): the radius that bounds the open part, for the exit-pupil table. Set by
  // finish() when the mask is made (loaded, rasterized or mirrored).
  double openRadiusFactor = 1.4142135623730951;
  // `open` packed 32 pixels to a word, pixel i = row * sizePx + col at bit i % 32 of word i / 32:
  // what the batch trace gathers (a 1024 px mask is 128 kB, not 1 MB, and a word is what a
  // vector gather loads). Set by finish().
  std::vector<std::uint32_t> openBits;
  // Sets openRadiusFactor and openBits from `open`: call after making or changing the pixels.
  void finish();

 private:
  void measureOpenRadius();
};

struct ApertureShape {
  enum class Kind { Circle, Blades, Image };
  Kind kind = Kind::Circle;
  int bladeCount = 6;        // Blades: 3..32
  double curvature = 0.0;    // Blades: 0 straight .. 1 round
  double rotationDeg = 0.0;  // Blades: angle of the first corner from +x toward +y
  // Image: the mask, and the name as written (in a lens file, relative to its folder).
  std::shared_ptr<const ApertureMask> mask;
  std::string imageName;
  // Image: the file's picture mirrored left to right (x -> -x), as the iris of a lens turned
  // front to back is seen from the film. `mask` then holds the mirrored pixels.
  bool mirrored = false;

  bool isCircle() const { return kind == Kind::Circle; }
  // Radius of the circle around the axis that contains the shape, over R: 1, or for an image
  // the farthest open pixel's corner (sqrt(2) at most: the square's corners).
  double boundRadiusFactor() const;
  // Area over R^2: pi for the circle, the polygon plus its N circular segments for blades, the
  // open pixels' share of the square 2R x 2R for an image.
  double areaFactor() const;
  // Inside test in units of R (the reference form; traces use StopShapeTest).
  bool containsUnit(glm::dvec2 p) const;
  // Circle and blades (convex, around the centre): the distance in units of R from the centre
  // to the edge in the direction at angleRad from +x. (An image shape answers its bound.)
  double edgeDistanceUnit(double angleRad) const;
  // The boundary for drawing, in units of R, counter-clockwise and closed (first point repeated);
  // an image gives its bounding square. `pointsPerEdge` subdivides curved edges.
  std::vector<glm::dvec2> outlineUnit(int pointsPerEdge = 8) const;

  // The same iris seen from its other side (the lens turned front to back): mirrored left to
  // right. A circle stays a circle; blades' corners at angle a go to 180 - a; an image toggles
  // `mirrored` and its mask is mirrored.
  ApertureShape mirroredLeftToRight() const;
  // Sets the mask of an image shape from the file's pixels as loaded, mirroring them when the
  // shape is `mirrored`.
  void attachLoadedMask(std::shared_ptr<const ApertureMask> loaded);

  // "circle", "blades 6 curvature 0.5 rotation 15", "image NAME", "image-mirrored NAME": the
  // lens-file and script form, which parseApertureSpec reads back (the mask is loaded by the
  // caller).
  std::string spec() const;
  // Same shape (a mask compares by its source).
  bool operator==(const ApertureShape& other) const;
};

// What parseApertureSpec makes of "circle" / "blades N [curvature C] [rotation D]" /
// "image NAME" / "image-mirrored NAME".
// On an error, `column` (0-based offset into the text) points at the offending word.
struct ApertureSpecResult {
  std::optional<ApertureShape> shape;  // an image shape has imageName set and no mask yet
  std::string error;
  int column = 0;
};
ApertureSpecResult parseApertureSpec(std::string_view text);

// Loads and thresholds an aperture image (PNG and what else stb_image reads). A missing,
// unreadable, non-square or all-black image is refused with the reason in `error`.
std::shared_ptr<const ApertureMask> loadApertureMask(const std::filesystem::path& path,
                                                     std::string* error);
// The mask mirrored left to right (column c -> size - 1 - c); same source.
std::shared_ptr<const ApertureMask> mirroredMask(const ApertureMask& mask);
// A mask rasterized from a polygon in units of R (the image's square is [-1, 1]^2), the
// non-zero winding rule, at the pixel centres: pbrt-v4's built-in "star" is made this way.
std::shared_ptr<const ApertureMask> rasterizeApertureMask(const std::vector<glm::dvec2>& polygon,
                                                          int sizePx, std::string name);

// pbrt-v4's realistic camera "string aperture": "square", "pentagon", "star" and "gaussian"
// (built in); other values are image files (resolved by the caller), for which it returns
// nullopt.
//   square   -> 4 straight blades, edges along x and y (inscribed in the stop circle)
//   pentagon -> 5 straight blades, a corner up (pbrt draws it at 0.8 R; lenslab inscribes it)
//   star     -> pbrt-v4's five-pointed star (outer radius R, inner R cos 72 / cos 36), as a mask
//   gaussian -> pbrt-v4's graded transmission T(r) = max(0, exp(-r^2) - exp(-1)) (r in units of
//               R) as a halftone mask (gaussianHalftoneMask): it passes pi (1 - 2/e) R^2 =
//               0.830 R^2 of light, 26% of the circle's, and its bokeh fades toward the rim
std::optional<ApertureShape> builtinPbrtAperture(std::string_view name);

// pbrt-v4's "gaussian" transmission at (x, y) in units of R.
double gaussianApertureTransmission(double xUnit, double yUnit);
// lenslab's stop is binary (a ray passes or not), so a graded transmission is laid down as a
// halftone, as apodization filters have been made: ordered dithering with the 16 x 16 Bayer
// matrix, a pixel open when T at its centre exceeds its threshold (k + 0.5) / 256. Over any
// aligned 16 x 16 block the open share is T to within 1/256 plus T's change across the block, so
// at 1024 pixels (64 blocks across the stop) a bokeh disc or a pixel's bundle sees the graded
// transmission, not the dots.
inline constexpr int kGaussianMaskSizePx = 1024;
std::shared_ptr<const ApertureMask> gaussianHalftoneMask(int sizePx);

// The shape compiled for one stop radius: what the traces test hits against.
class StopShapeTest {
 public:
  StopShapeTest() = default;
  StopShapeTest(const ApertureShape& shape, double stopRadiusMm);

  bool isCircle() const { return kind_ == ApertureShape::Kind::Circle; }
  // Whether the hit (x, y) on the stop plane, in mm, is inside the opening.
  bool contains(double xMm, double yMm) const {
    switch (kind_) {
      case ApertureShape::Kind::Circle:
        return xMm * xMm + yMm * yMm <= radiusSqMm2_;
      case ApertureShape::Kind::Blades:
        for (const Edge& e : edges_)
          if (!edgeContains(e, xMm, yMm)) return false;
        return true;
      case ApertureShape::Kind::Image:
        return maskContains(xMm, yMm);
    }
    return false;
  }

  // The blades, for the vectorized batch trace: a point is inside blade e when
  //   e.s (x^2 + y^2) + e.wx x + e.wy y + e.k <= 0.
  // A straight edge has s = 0, (wx, wy) its outward normal and -k its distance from the centre.
  // A curved one, the disk |p - c n|^2 <= rho^2 divided by 2 rho: s = 1 / (2 rho),
  // (wx, wy) = -(c / rho) n and k = (c^2 - rho^2) / (2 rho), which stays well conditioned in
  // single precision as the curvature goes to 0 (rho and |c| to infinity).
  struct Edge {
    float wx = 0, wy = 0, s = 0, k = 0;
  };
  ApertureShape::Kind kind() const { return kind_; }
  const std::vector<Edge>& edges() const { return edges_; }
  bool maskContains(double xMm, double yMm) const;
  // The mask's pixels and mapping, for the batch trace's branch-free lookup: column
  // (x + R) * pixelsPerMm, row (R - y) * pixelsPerMm; pixel i = row * size + col is bit i % 32
  // of maskBits()[i / 32].
  const std::uint32_t* maskBits() const {
    if (!ownBits_.empty()) return ownBits_.data();
    return mask_ ? mask_->openBits.data() : nullptr;
  }
  int maskSizePx() const { return mask_ ? mask_->sizePx : 0; }
  double pixelsPerMm() const { return pixelsPerMm_; }
  double radiusMm() const { return radiusMm_; }

 private:
  static bool edgeContains(const Edge& e, double x, double y) {
    return e.s * (x * x + y * y) + e.wx * x + e.wy * y + e.k <= 0.0;
  }

  ApertureShape::Kind kind_ = ApertureShape::Kind::Circle;
  double radiusSqMm2_ = 0.0;
  std::vector<Edge> edges_;
  std::shared_ptr<const ApertureMask> mask_;
  // The mask's openBits, or, for a mask made without ApertureMask::finish(), a packing of its
  // own (so that the batch trace never reads past the bits).
  std::vector<std::uint32_t> ownBits_;
  double pixelsPerMm_ = 0.0, radiusMm_ = 0.0;
};

}  // namespace lenslab::optics
