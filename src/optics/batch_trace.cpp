// The batch traces (film to scene, and scene to film): structure-of-arrays, single precision, one
// surface at a time over all rays so that the inner loop has no data-dependent control flow and
// vectorizes (blocked rays keep being computed and are masked out). The same kernel is compiled for
// AVX2+FMA and for the baseline ISA; the CPU picks at run time. The file is built with -O3
// -fno-math-errno -fno-trapping-math so that GCC vectorizes sqrtf (see src/optics/CMakeLists.txt).
//
// The geometry is the same as the scalar trace (surface_geometry.h): vertex-relative sphere
// intersection without cancellation, Heckbert's refraction.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <stdexcept>

#include <vector>

#include "optics/glass.h"
#include "optics/glass/dispersion_fit.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

// kTouchingSurfaceToleranceMm in single precision, where a hit's z carries some 1e-5 mm of
// rounding at a lens's distances from the film (a plane's hit takes its z exactly).
constexpr float kTouchingSurfaceToleranceF = 1e-4f;

// How a surface's ratio of indices is found: its own (the RGB trace), per ray from the model
// glasses' n = a + b / lambda^2, or per ray from each side's series (a catalogue glass).
constexpr int kFixedIndex = 0, kCauchyIndex = 1, kSeriesIndex = 2;
constexpr int kSeriesTerms = KernelDispersion::kMaxDegree + 2;

struct SurfaceF {
  float vertexZ, curvature, radius, semiApertureSq, eta;
  bool refracts, flat;
  // The stop's shape when it is not a circle (the hit is then also tested against it), else null.
  const StopShapeTest* shape = nullptr;
  // Per-ray indices (the spectral trace): n = a + b / lambda^2 on each side (glass.h). "Rear"
  // is the medium the ray comes from and "front" the one it enters (so for a trace from the
  // scene, the surface's front and rear media swapped). `disperses` when either has b != 0.
  float aRear = 1.0f, bRear = 0.0f, aFront = 1.0f, bFront = 0.0f;
  bool disperses = false;
  // The same for a lens with a catalogue glass: the slots of the media the ray comes from and
  // enters in the per-block table of indices (traceAll), each medium's series evaluated once per
  // ray there rather than at each of its two surfaces.
  int mediumFrom = 0, mediumTo = 0;
  // An aspheric surface (aspheric_profile.h) takes traceAspheric: 1 + k, and the terms A_i up to
  // the highest nonzero power (0: a conic without terms).
  bool aspheric = false;
  float conic1 = 1.0f;
  int highestPower = 0;
  float coefficient[AsphericProfile::kMaxPower + 1] = {};
};

// A shaped stop, after the stop surface's own trace has put the hits in ox, oy: a pass over the
// blades (each a branch-free test over the block, so it vectorizes), or a mask lookup per ray.
__attribute__((always_inline)) inline void applyStopShape(const StopShapeTest& shape,
                                                          const float* __restrict ox,
                                                          const float* __restrict oy,
                                                          std::uint8_t* __restrict alive,
                                                          std::size_t n) {
  if (shape.kind() == ApertureShape::Kind::Image) {
    // Without branches, so that the loop vectorizes into gathers: a hit outside the image (or
    // NaN) looks up a clamped pixel and is masked out. One bit a pixel, read as 32-bit words.
    const std::uint32_t* __restrict words = shape.maskBits();
    const int size = shape.maskSizePx();
    const float sizeF = static_cast<float>(size), lastF = sizeF - 1.0f;
    const float scale = static_cast<float>(shape.pixelsPerMm());
    const float radius = static_cast<float>(shape.radiusMm());
    for (std::size_t i = 0; i < n; ++i) {
      const float col = (ox[i] + radius) * scale, row = (radius - oy[i]) * scale;
      const int inside = (col >= 0.0f) & (row >= 0.0f) & (col < sizeF) & (row < sizeF);
      // (std::max(0, x) is 0 for a NaN x.)
      const int c = static_cast<int>(std::min(lastF, std::max(0.0f, col)));
      const int r = static_cast<int>(std::min(lastF, std::max(0.0f, row)));
      const int index = r * size + c;
      const int open = static_cast<int>(words[index >> 5] >> (index & 31)) & 1;
      alive[i] = alive[i] & static_cast<std::uint8_t>(inside & open);
    }
    return;
  }
  for (const StopShapeTest::Edge& e : shape.edges()) {
    const float s = e.s, wx = e.wx, wy = e.wy, k = e.k;
    for (std::size_t i = 0; i < n; ++i) {
      const float x = ox[i], y = oy[i];
      const int ok = s * (x * x + y * y) + wx * x + wy * y + k <= 0.0f;
      alive[i] = alive[i] & static_cast<std::uint8_t>(ok);
    }
  }
}

// The ratio of indices a ray meets at a surface: the surface's own (kFixedIndex), or the one at
// the ray's wavelength: from w = 1 / lambda^2 (nm^-2) and the model glasses' a + b w, one
// division per ray and surface (kCauchyIndex), or w itself, the ratio traceAll worked out per ray
// from its table of indices (kSeriesIndex). The coefficients are passed as locals read before the
// loop, which GCC needs to vectorize it.
template <int kPerRay>
__attribute__((always_inline)) inline float etaOf(float fixedEta, float aRear, float bRear,
                                                  float aFront, float bFront, float w) {
  if constexpr (kPerRay == kSeriesIndex) {
    (void)aRear, (void)bRear, (void)aFront, (void)bFront, (void)fixedEta;
    return w;
  } else if constexpr (kPerRay == kCauchyIndex) {
    (void)fixedEta;
    return (aRear + bRear * w) / (aFront + bFront * w);
  } else {
    (void)aRear, (void)bRear, (void)aFront, (void)bFront, (void)w;
    return fixedEta;
  }
}

// A plane z = vertexZ (the stop, flat refracting surfaces): one division, no square root.
template <bool kRefracts, int kPerRay = kFixedIndex>
__attribute__((always_inline)) inline void traceFlat(const SurfaceF& s, float* __restrict ox,
                                                     float* __restrict oy, float* __restrict oz,
                                                     float* __restrict dx, float* __restrict dy,
                                                     float* __restrict dz,
                                                     std::uint8_t* __restrict alive, std::size_t n,
                                                     const float* __restrict w = nullptr) {
  const float zv = s.vertexZ, semiSq = s.semiApertureSq, fixedEta = s.eta;
  const float aRear = s.aRear, bRear = s.bRear, aFront = s.aFront, bFront = s.bFront;
  for (std::size_t i = 0; i < n; ++i) {
    const float eta = etaOf<kPerRay>(fixedEta, aRear, bRear, aFront, bFront, kPerRay ? w[i] : 0.0f);
    const float uz = dz[i];
    const float t = (zv - oz[i]) / uz;
    const float hx = ox[i] + t * dx[i], hy = oy[i] + t * dy[i];
    int ok = (t >= -kTouchingSurfaceToleranceF) & (hx * hx + hy * hy <= semiSq);
    ox[i] = hx;
    oy[i] = hy;
    oz[i] = zv;
    if constexpr (kRefracts) {
      // Normal (0, 0, +-1): the tangential components scale by eta, the axial one renormalizes.
      const float ux = eta * dx[i], uy = eta * dy[i];
      const float k = 1.0f - ux * ux - uy * uy;
      ok &= k >= 0.0f;
      const float nz = std::sqrt(k > 0.0f ? k : 0.0f);
      dx[i] = ux;
      dy[i] = uy;
      dz[i] = uz >= 0.0f ? nz : -nz;
    }
    alive[i] = alive[i] & static_cast<std::uint8_t>(ok);
  }
}

// Snell's law in vector form (as surface_geometry.h's refract) for unit normal m and direction
// u: the refracted direction in n; 0 on total internal reflection. Without branches.
__attribute__((always_inline)) inline int refractF(float mx, float my, float mz, float ux, float uy,
                                                   float uz, float eta, float& nx, float& ny,
                                                   float& nz) {
  float cosI = -(mx * ux + my * uy + mz * uz);
  const float flip = cosI < 0.0f ? -1.0f : 1.0f;
  mx *= flip;
  my *= flip;
  mz *= flip;
  cosI *= flip;
  const float k = 1.0f - eta * eta * (1.0f - cosI * cosI);
  const float scale = eta * cosI - std::sqrt(k > 0.0f ? k : 0.0f);
  nx = eta * ux + scale * mx;
  ny = eta * uy + scale * my;
  nz = eta * uz + scale * mz;
  return k >= 0.0f;
}

template <bool kRefracts, int kPerRay = kFixedIndex>
__attribute__((always_inline)) inline void traceSurface(
    const SurfaceF& s, float* __restrict ox, float* __restrict oy, float* __restrict oz,
    float* __restrict dx, float* __restrict dy, float* __restrict dz,
    std::uint8_t* __restrict alive, std::size_t n, const float* __restrict w = nullptr) {
  const float c = s.curvature, radius = s.radius, zv = s.vertexZ, semiSq = s.semiApertureSq,
              fixedEta = s.eta;
  const float aRear = s.aRear, bRear = s.bRear, aFront = s.aFront, bFront = s.bFront;
  for (std::size_t i = 0; i < n; ++i) {
    const float eta = etaOf<kPerRay>(fixedEta, aRear, bRear, aFront, bFront, kPerRay ? w[i] : 0.0f);
    const float px = ox[i], py = oy[i], pz = oz[i] - zv;
    const float ux = dx[i], uy = dy[i], uz = dz[i];
    const float b = c * (px * ux + py * uy + pz * uz) + uz;
    const float cc = c * (px * px + py * py + pz * pz) + 2.0f * pz;
    const float disc = b * b - c * cc;
    const float root = std::sqrt(disc > 0.0f ? disc : 0.0f);
    const float q = b >= 0.0f ? -b - root : -b + root;
    // Both roots (q / c = q R; flat surfaces take traceFlat); keep the nearest
    // one in front of the origin on the vertex-side cap (1 + c z > 0).
    const float t1 = cc / q, t2 = q * radius;
    const bool ok1 = (t1 >= -kTouchingSurfaceToleranceF) & (1.0f + c * (pz + t1 * uz) > 0.0f);
    const bool ok2 = (t2 >= -kTouchingSurfaceToleranceF) & (1.0f + c * (pz + t2 * uz) > 0.0f);
    const float t = ok1 & ok2 ? (t1 < t2 ? t1 : t2) : (ok1 ? t1 : t2);
    const float hx = px + t * ux, hy = py + t * uy, hz = pz + t * uz;
    // Bitwise & rather than && keeps the loop free of branches.
    int ok = (disc >= 0.0f) & (ok1 | ok2) & (hx * hx + hy * hy <= semiSq);
    float nx = ux, ny = uy, nz = uz;
    if constexpr (kRefracts)
      ok &= refractF(c * hx, c * hy, c * hz + 1.0f, ux, uy, uz, eta, nx, ny, nz);
    ox[i] = hx;
    oy[i] = hy;
    oz[i] = hz + zv;
    dx[i] = nx;
    dy[i] = ny;
    dz[i] = nz;
    alive[i] = alive[i] & static_cast<std::uint8_t>(ok);
  }
}

// Newton steps of the float kernel for a surface with polynomial terms, from the conic's hit: the
// scalar trace's iteration (aspheric_profile.cpp) needs 3 to 6 to reach double precision, float's
// fewer; a fixed count keeps the loop free of branches, and unrolled it vectorizes. (4 agree with
// the scalar trace as 6 do on the aspheric double-Gauss of batch_trace_test.cpp.)
constexpr int kFloatNewtonSteps = 4;

// An aspheric surface (aspheric_profile.h) in single precision: the conic's hit in closed form
// (as traceSurface's sphere, with a = c (ux^2 + uy^2 + (1 + k) uz^2)), then, with polynomial
// terms, Newton's method on z + S(r) = 0 from it (or from the vertex plane). A ray whose last
// step is not below 1e-4 mm, or that ends where the sag is not real, is blocked.
// kTop: the terms are evaluated from r^kTop down (0: a conic without terms), a count fixed at
// compile time, so that the loops unroll and the loop over the rays vectorizes (the surface's own
// highest power may be lower: the coefficients above it are zero); kAnyTop: from the surface's
// own highest power, in a loop that does not vectorize (terms beyond r^10, which few lenses have:
// unrolled to r^20 as well, this file took three times as long to compile).
constexpr int kAnyTop = -1;
template <int kTop, bool kRefracts, int kPerRay = kFixedIndex>
__attribute__((always_inline)) inline void traceAspheric(
    const SurfaceF& s, float* __restrict ox, float* __restrict oy, float* __restrict oz,
    float* __restrict dx, float* __restrict dy, float* __restrict dz,
    std::uint8_t* __restrict alive, std::size_t n, const float* __restrict w = nullptr) {
  const float c = s.curvature, k1 = s.conic1, zv = s.vertexZ, semiSq = s.semiApertureSq,
              fixedEta = s.eta;
  const float aRear = s.aRear, bRear = s.bRear, aFront = s.aFront, bFront = s.bFront;
  const float* __restrict coefficient = s.coefficient;
  for (std::size_t i = 0; i < n; ++i) {
    const float eta = etaOf<kPerRay>(fixedEta, aRear, bRear, aFront, bFront, kPerRay ? w[i] : 0.0f);
    const float px = ox[i], py = oy[i], pz = oz[i] - zv;
    const float ux = dx[i], uy = dy[i], uz = dz[i];
    const float a = c * (ux * ux + uy * uy + k1 * uz * uz);
    const float b = c * (px * ux + py * uy + k1 * pz * uz) + uz;
    const float cc = c * (px * px + py * py + k1 * pz * pz) + 2.0f * pz;
    const float disc = b * b - a * cc;
    const float root = std::sqrt(disc > 0.0f ? disc : 0.0f);
    const float q = b >= 0.0f ? -b - root : -b + root;
    const float t1 = cc / q, t2 = q / a;
    const bool ok1 = (t1 >= -kTouchingSurfaceToleranceF) & (1.0f + c * k1 * (pz + t1 * uz) >= 0.0f);
    const bool ok2 = (t2 >= -kTouchingSurfaceToleranceF) & (1.0f + c * k1 * (pz + t2 * uz) >= 0.0f);
    float t = ok1 & ok2 ? (t1 < t2 ? t1 : t2) : (ok1 ? t1 : t2);
    int ok = (disc >= 0.0f) & (ok1 | ok2);
    float slope = 0.0f;  // S'(r) at the hit, for the normal (terms only)
    if constexpr (kTop != 0) {
      const int top = kTop == kAnyTop ? s.highestPower : kTop;
      t = ok ? t : -pz / uz;  // else from the vertex plane
      float step = 0.0f, rootS = 1.0f;
#pragma GCC unroll 4
      for (int it = 0; it < kFloatNewtonSteps; ++it) {
        const float x = px + t * ux, y = py + t * uy, z = pz + t * uz;
        const float r2 = x * x + y * y, r = std::sqrt(r2);
        rootS = 1.0f - k1 * c * c * r2;
        const float sq = std::sqrt(rootS > 0.0f ? rootS : 0.0f);
        float value = 0.0f, derivative = 0.0f;
#pragma GCC unroll 10
        for (int power = top; power >= AsphericProfile::kMinPower; --power) {
          value = value * r + coefficient[power];
          derivative = derivative * r + static_cast<float>(power) * coefficient[power];
        }
        const float sag = c * r2 / (1.0f + sq) + value * r2;
        slope = c * r / (sq > 1e-20f ? sq : 1e-20f) + derivative * r;
        const float drdt = r > 0.0f ? (x * ux + y * uy) / r : 0.0f;
        step = (z + sag) / (uz + slope * drdt);
        t -= step;
      }
      // The last step's size, and the sag at the point (the last iteration's, one step away).
      ok = (std::abs(step) <= 1e-4f * (1.0f + std::abs(t))) & (rootS >= 0.0f) &
           (t >= -kTouchingSurfaceToleranceF);
    }
    const float hx = px + t * ux, hy = py + t * uy, hz = pz + t * uz;
    ok &= hx * hx + hy * hy <= semiSq;
    float nx = ux, ny = uy, nz = uz;
    if constexpr (kRefracts) {
      float mx, my, mz;
      if constexpr (kTop != 0) {
        const float r = std::sqrt(hx * hx + hy * hy);
        const float along = r > 0.0f ? slope / r : 0.0f;
        mx = along * hx;
        my = along * hy;
        mz = 1.0f;
      } else {
        mx = c * hx;
        my = c * hy;
        mz = c * k1 * hz + 1.0f;
      }
      const float invLength = 1.0f / std::sqrt(mx * mx + my * my + mz * mz);
      ok &= refractF(mx * invLength, my * invLength, mz * invLength, ux, uy, uz, eta, nx, ny, nz);
    }
    // (A blocked ray may carry NaN; alive says it is blocked. x - x is 0 unless x is infinite or
    // NaN: a test that vectorizes, where std::isfinite does not.)
    ok &= (hx - hx == 0.0f) & (hy - hy == 0.0f) & (hz - hz == 0.0f);
    ox[i] = hx;
    oy[i] = hy;
    oz[i] = hz + zv;
    dx[i] = nx;
    dy[i] = ny;
    dz[i] = nz;
    alive[i] = alive[i] & static_cast<std::uint8_t>(ok);
  }
}

// An aspheric surface's kernel for its terms up to r^kTop (kAnyTop: its own): with a wavelength per
// ray (`w`, on a dispersive surface), refracting, or not (the stop).
template <int kTop>
__attribute__((always_inline)) inline void traceAsphericOf(
    const SurfaceF& s, float* __restrict ox, float* __restrict oy, float* __restrict oz,
    float* __restrict dx, float* __restrict dy, float* __restrict dz,
    std::uint8_t* __restrict alive, std::size_t n, const float* __restrict w, bool series) {
  if (w && s.disperses && series)
    traceAspheric<kTop, true, kSeriesIndex>(s, ox, oy, oz, dx, dy, dz, alive, n, w);
  else if (w && s.disperses)
    traceAspheric<kTop, true, kCauchyIndex>(s, ox, oy, oz, dx, dy, dz, alive, n, w);
  else if (s.refracts)
    traceAspheric<kTop, true>(s, ox, oy, oz, dx, dy, dz, alive, n);
  else
    traceAspheric<kTop, false>(s, ox, oy, oz, dx, dy, dz, alive, n);
}

// Each medium's index for a block of rays, from x = 2^18 / lambda^2 by Horner's rule as
// KernelDispersion::atFloat evaluates it: `series` holds `media` series of kSeriesTerms floats
// (c[0..7], then the lambda^2 term), `index` gets media rows of kBlock.
constexpr std::size_t kBlock = 256;
__attribute__((always_inline)) inline void indicesOfBlock(const float* __restrict series, int media,
                                                          const float* __restrict x, std::size_t m,
                                                          float* __restrict index) {
  float y[kBlock];
  for (std::size_t i = 0; i < m; ++i) y[i] = 1.0f / x[i];
  constexpr int top = KernelDispersion::kMaxDegree;
  for (int medium = 0; medium < media; ++medium) {
    const float* __restrict c = series + medium * kSeriesTerms;
    float* __restrict out = index + static_cast<std::size_t>(medium) * kBlock;
    const float c0 = c[0], c1 = c[1], c2 = c[2], c3 = c[3], c4 = c[4], c5 = c[5], c6 = c[6],
                c7 = c[7], cLambda2 = c[top + 1];
    for (std::size_t i = 0; i < m; ++i) {
      const float xi = x[i];
      float n = c7;
      n = c6 + xi * n;
      n = c5 + xi * n;
      n = c4 + xi * n;
      n = c3 + xi * n;
      n = c2 + xi * n;
      n = c1 + xi * n;
      n = c0 + xi * n;
      out[i] = n + cLambda2 * y[i];
    }
  }
}

// `invWavelengthSq`: null for the surfaces' own indices (the RGB trace, unchanged), else each
// ray's 1 / lambda^2 (the spectral trace: dispersive surfaces take their per-ray kernel), or, with
// `series` (media x kSeriesTerms floats, see indicesOfBlock), its x = 2^18 / lambda^2.
__attribute__((always_inline)) inline void traceAll(const SurfaceF* surfaces, int count,
                                                    LensRayBatch& rays,
                                                    const float* invWavelengthSq,
                                                    const float* series, int media) {
  const std::size_t n = rays.size();
  // Blocks keep the working set in L1 while all surfaces are applied.
  thread_local std::vector<float> indexTable;
  if (series) indexTable.resize(static_cast<std::size_t>(media) * kBlock);
  float etaOfRay[kBlock];
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t m = n - start < kBlock ? n - start : kBlock;
    float* ox = rays.ox.data() + start;
    float* oy = rays.oy.data() + start;
    float* oz = rays.oz.data() + start;
    float* dx = rays.dx.data() + start;
    float* dy = rays.dy.data() + start;
    float* dz = rays.dz.data() + start;
    std::uint8_t* alive = rays.alive.data() + start;
    const float* w = invWavelengthSq ? invWavelengthSq + start : nullptr;
    if (series) indicesOfBlock(series, media, w, m, indexTable.data());
    for (int k = 0; k < count; ++k) {
      const SurfaceF& s = surfaces[k];
      if (series && s.disperses) {
        // This surface's ratio for each ray, handed to its kernel in place of w.
        const float* __restrict from = indexTable.data() + s.mediumFrom * kBlock;
        const float* __restrict to = indexTable.data() + s.mediumTo * kBlock;
        for (std::size_t i = 0; i < m; ++i) etaOfRay[i] = from[i] / to[i];
        w = etaOfRay;
      }
      if (s.aspheric) {
        if (s.highestPower == 0)
          traceAsphericOf<0>(s, ox, oy, oz, dx, dy, dz, alive, m, w, series != nullptr);
        else if (s.highestPower <= 10)
          traceAsphericOf<10>(s, ox, oy, oz, dx, dy, dz, alive, m, w, series != nullptr);
        else
          traceAsphericOf<kAnyTop>(s, ox, oy, oz, dx, dy, dz, alive, m, w, series != nullptr);
      } else if (w && s.disperses && series) {
        if (s.flat)
          traceFlat<true, kSeriesIndex>(s, ox, oy, oz, dx, dy, dz, alive, m, w);
        else
          traceSurface<true, kSeriesIndex>(s, ox, oy, oz, dx, dy, dz, alive, m, w);
      } else if (w && s.disperses) {
        if (s.flat)
          traceFlat<true, kCauchyIndex>(s, ox, oy, oz, dx, dy, dz, alive, m, w);
        else
          traceSurface<true, kCauchyIndex>(s, ox, oy, oz, dx, dy, dz, alive, m, w);
      } else if (s.flat) {
        if (s.refracts)
          traceFlat<true>(s, ox, oy, oz, dx, dy, dz, alive, m);
        else
          traceFlat<false>(s, ox, oy, oz, dx, dy, dz, alive, m);
      } else if (s.refracts) {
        traceSurface<true>(s, ox, oy, oz, dx, dy, dz, alive, m);
      } else {
        traceSurface<false>(s, ox, oy, oz, dx, dy, dz, alive, m);
      }
      if (s.shape) applyStopShape(*s.shape, ox, oy, alive, m);
    }
  }
}

__attribute__((target("avx2,fma"))) void traceAvx2(const SurfaceF* surfaces, int count,
                                                   LensRayBatch& rays, const float* w,
                                                   const float* series, int media) {
  traceAll(surfaces, count, rays, w, series, media);
}

// 16 lanes. GCC keeps 256-bit vectors for AVX-512 targets unless told otherwise.
__attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,fma,prefer-vector-width=512"))) void
traceAvx512(const SurfaceF* surfaces, int count, LensRayBatch& rays, const float* w,
            const float* series, int media) {
  traceAll(surfaces, count, rays, w, series, media);
}

void tracePortable(const SurfaceF* surfaces, int count, LensRayBatch& rays, const float* w,
                   const float* series, int media) {
  traceAll(surfaces, count, rays, w, series, media);
}

bool cpuHasAvx512() {
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                          __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
  return has;
}

bool cpuHasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
}

}  // namespace

bool LensSystem::batchKernelAvailable(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::Auto:
    case BatchKernel::Portable:
      return true;
    case BatchKernel::Avx2:
      return cpuHasAvx2();
    case BatchKernel::Avx512:
      return cpuHasAvx512();
  }
  return false;
}

LensSystem::BatchKernel LensSystem::autoBatchKernel() {
  static const bool useAvx512 = cpuHasAvx512() && !std::getenv("LENSLAB_NO_AVX512");
  return useAvx512 ? BatchKernel::Avx512 : cpuHasAvx2() ? BatchKernel::Avx2 : BatchKernel::Portable;
}

void LensSystem::traceFromFilmBatch(LensRayBatch& rays) const {
  traceFromFilmBatch(rays, BatchKernel::Auto);
}

void LensSystem::traceFromFilmBatch(LensRayBatch& rays, BatchKernel kernel) const {
  traceBatch(rays, nullptr, kernel, true);
}

namespace {
const float* inverseSquares(const float* wavelengthsNm, std::size_t n) {
  thread_local std::vector<float> invWavelengthSq;
  invWavelengthSq.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    invWavelengthSq[i] = 1.0f / (wavelengthsNm[i] * wavelengthsNm[i]);
  return invWavelengthSq.data();
}
}  // namespace

void LensSystem::traceFromFilmBatch(LensRayBatch& rays, const float* wavelengthsNm,
                                    BatchKernel kernel) const {
  traceBatch(rays, inverseSquares(wavelengthsNm, rays.size()), kernel, true);
}

void LensSystem::traceFromSceneBatch(LensRayBatch& rays, const float* wavelengthsNm,
                                     BatchKernel kernel) const {
  traceBatch(rays, wavelengthsNm ? inverseSquares(wavelengthsNm, rays.size()) : nullptr, kernel,
             false);
}

void LensSystem::traceBatch(LensRayBatch& rays, const float* invWavelengthSq, BatchKernel kernel,
                            bool fromFilm) const {
  // Per-ray indices come from the model glasses' n = a + b / lambda^2, or, with a catalogue
  // glass, from every medium's series (glass/dispersion_fit.h), which holds to 1e-6 only where
  // spectralTraceProblem() is empty: the callers check it first.
  const bool series = invWavelengthSq && hasCatalogGlass_;
  // Slot 0 is the air in front of the lens, slot k + 1 the medium after surface k.
  thread_local std::vector<float> seriesOfMedia;
  if (series) {
    if (const std::string problem = spectralTraceProblem(); !problem.empty())
      throw std::logic_error("LensSystem: " + problem);
    const std::vector<KernelDispersion>& media = kernelDispersions();
    seriesOfMedia.assign((media.size() + 1) * kSeriesTerms, 0.0f);
    seriesOfMedia[0] = 1.0f;  // air
    for (std::size_t k = 0; k < media.size(); ++k) {
      float* out = seriesOfMedia.data() + (k + 1) * kSeriesTerms;
      for (int term = 0; term <= KernelDispersion::kMaxDegree; ++term)
        out[term] = static_cast<float>(media[k].c[static_cast<std::size_t>(term)]);
      out[kSeriesTerms - 1] = static_cast<float>(media[k].cLambda2);
    }
    // x = 2^18 / lambda^2 = 2^18 w: exact in float, a power of two.
    thread_local std::vector<float> x;
    x.resize(rays.size());
    const float scale = static_cast<float>(KernelDispersion::kReferenceWavelengthSqNm2);
    for (std::size_t i = 0; i < rays.size(); ++i) x[i] = scale * invWavelengthSq[i];
    invWavelengthSq = x.data();
  }
  // Room for the lens's surfaces on the stack, left uninitialised: each entry used is made
  // below. (An array of 64 SurfaceF, each with its default member initialisers and 21 aspheric
  // terms, was 10 KB of zeroes per call: a third of the spectral exit-pupil table's time, whose
  // probes trace small batches (perf, issue 39).)
  constexpr int kMaxOnStack = 64;
  alignas(SurfaceF) unsigned char stackStorage[kMaxOnStack * sizeof(SurfaceF)];
  std::vector<SurfaceF> heapSurfaces;
  SurfaceF* list = reinterpret_cast<SurfaceF*>(stackStorage);
  const int count = static_cast<int>(surfaces_.size());
  if (count > kMaxOnStack) {
    heapSurfaces.resize(count);
    list = heapSurfaces.data();
  }
  // Film to scene: rear surface first; the ray goes from the rear medium into the front one.
  // Scene to film: front surface first, from the front medium into the rear one. (The kernels
  // do not care which way a ray travels: they take the nearest hit ahead of it.)
  for (int step = 0; step < count; ++step) {
    const int k = fromFilm ? count - 1 - step : step;
    const SurfaceGeometry& s = surfaces_[k];
    const double eta = fromFilm ? s.indexRear / s.indexFront : s.indexFront / s.indexRear;
    const bool flat = s.curvaturePerMm == 0.0;
    new (list + step)
        SurfaceF{static_cast<float>(s.vertexZMm),
                 static_cast<float>(s.curvaturePerMm),
                 flat ? 0.0f : static_cast<float>(1.0 / s.curvaturePerMm),
                 static_cast<float>(clipRadiusSqMm2_[k]),
                 static_cast<float>(eta),
                 eta != 1.0,
                 flat,
                 k == static_cast<int>(stopIndex_) && !stopTest_.isCircle() ? &stopTest_ : nullptr};
    // A conic on a flat base is still the plane; terms are not.
    if (s.profile.hasPolynomial() || (s.profile.conic() != 0.0 && !flat)) {
      SurfaceF& f = list[step];
      f.aspheric = true;
      f.conic1 = static_cast<float>(1.0 + s.profile.conic());
      f.highestPower = s.profile.highestPower();
      for (int power = AsphericProfile::kMinPower; power <= f.highestPower; ++power)
        f.coefficient[power] = static_cast<float>(s.profile.coefficient(power));
    }
    if (invWavelengthSq) {
      // SurfaceF's "rear" is the medium the ray comes from, its "front" the one it enters.
      const CauchyCoefficients& rear = glassRear_[k];
      const CauchyCoefficients front = k == 0 ? CauchyCoefficients{} : glassRear_[k - 1];
      const CauchyCoefficients& from = fromFilm ? rear : front;
      const CauchyCoefficients& into = fromFilm ? front : rear;
      SurfaceF& f = list[step];
      f.aRear = static_cast<float>(from.a);
      f.bRear = static_cast<float>(from.bNm2);
      f.aFront = static_cast<float>(into.a);
      f.bFront = static_cast<float>(into.bNm2);
      f.disperses = rear.bNm2 != 0.0 || front.bNm2 != 0.0;
      if (series) {
        const int rearSlot = k + 1, frontSlot = k;
        f.mediumFrom = fromFilm ? rearSlot : frontSlot;
        f.mediumTo = fromFilm ? frontSlot : rearSlot;
        auto constant = [&](int slot) {
          const float* c = seriesOfMedia.data() + static_cast<std::size_t>(slot) * kSeriesTerms;
          return std::all_of(c + 1, c + kSeriesTerms, [](float term) { return term == 0.0f; });
        };
        f.disperses = !constant(rearSlot) || !constant(frontSlot);
      }
    }
  }
  if (!batchKernelAvailable(kernel) || kernel == BatchKernel::Auto) kernel = autoBatchKernel();
  const float* seriesTable = series ? seriesOfMedia.data() : nullptr;
  const int media = series ? count + 1 : 0;
  if (kernel == BatchKernel::Avx512)
    traceAvx512(list, count, rays, invWavelengthSq, seriesTable, media);
  else if (kernel == BatchKernel::Avx2)
    traceAvx2(list, count, rays, invWavelengthSq, seriesTable, media);
  else
    tracePortable(list, count, rays, invWavelengthSq, seriesTable, media);
}

}  // namespace lenslab::optics
