#include "optics/lens_system.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

#include "optics/exit_pupil.h"
#include "optics/glass.h"
#include "optics/glass/kernel_dispersion_cache.h"

namespace lenslab::optics {

namespace {

// Where a ray blocked at surface s ends in its RayPath (see the comment there). tHit is the
// ray's hit on the extended sphere, when it has one.
glm::dvec3 blockedEndPoint(const SurfaceGeometry& s, const LensRay& ray,
                           std::optional<double> tHit) {
  const glm::dvec3& o = ray.origin;
  const glm::dvec3& d = ray.direction;
  const double a = s.semiApertureMm;
  // Sag at the rim: the sphere's c a^2 / (1 + sqrt(1 - c^2 a^2)), or the conic's and its terms'
  // (validation keeps the sag real out to the rim either way).
  const double c = s.curvaturePerMm;
  const double sag = s.profile.isSphere()
                         ? c * a * a / (1.0 + std::sqrt(std::max(0.0, 1.0 - c * c * a * a)))
                         : sagMm(c, s.profile, a).value_or(0.0);
  const double zRim = s.vertexZMm - sag;
  const double tPlane = d.z != 0.0 ? (zRim - o.z) / d.z : -1.0;
  const bool planeAhead = std::isfinite(tPlane) && tPlane > 0.0;
  if (planeAhead) {
    const glm::dvec3 p = o + tPlane * d;
    if (p.x * p.x + p.y * p.y >= a * a * (1.0 - 1e-12)) return p;
    // Inside the opening at the rim plane: it leaves through the side, where it exits the
    // cylinder r = a (the larger root of |o_xy + t d_xy|^2 = a^2).
    const double qa = d.x * d.x + d.y * d.y;
    const double qb = o.x * d.x + o.y * d.y;
    const double qc = o.x * o.x + o.y * o.y - a * a;
    const double disc = qb * qb - qa * qc;
    if (qa > 0.0 && disc >= 0.0) {
      const double tSide = (-qb + std::sqrt(disc)) / qa;
      if (tSide > tPlane && (!tHit || tSide <= *tHit)) return o + tSide * d;
    }
  }
  if (tHit) return o + *tHit * d;
  if (planeAhead) return o + tPlane * d;
  return o;
}

}  // namespace

void LensRayBatch::resize(std::size_t n) {
  ox.resize(n);
  oy.resize(n);
  oz.resize(n);
  dx.resize(n);
  dy.resize(n);
  dz.resize(n);
  alive.resize(n, 1);
}

const char* toString(RayStop stop) {
  switch (stop) {
    case RayStop::Passed:
      return "passed";
    case RayStop::ClippedByAperture:
      return "clipped by aperture";
    case RayStop::MissedSurface:
      return "missed surface";
    case RayStop::TotalInternalReflection:
      return "total internal reflection";
  }
  return "?";
}

LensSystem::LensSystem(Private, Prescription prescription, double wavelengthNm,
                       ApertureClipping clipping)
    : prescription_(std::move(prescription)), wavelengthNm_(wavelengthNm), clipping_(clipping) {
  stopIndex_ = *prescription_.stopIndex();
  place();
}

LensSystem::~LensSystem() = default;

void LensSystem::place() {
  const auto& rows = prescription_.surfaces;
  surfaces_.resize(rows.size());
  double z = 0.0;  // film plane
  for (std::size_t k = rows.size(); k-- > 0;) {
    z += rows[k].thicknessMm;
    SurfaceGeometry& s = surfaces_[k];
    s.vertexZMm = z;
    s.curvaturePerMm = rows[k].curvaturePerMm();
    s.profile = rows[k].isStop() ? AsphericProfile{} : rows[k].profile;
    s.semiApertureMm = 0.5 * rows[k].apertureDiameterMm;
    s.isStop = rows[k].isStop();
    // build() and withWavelength() have checked that every catalogue glass covers the wavelength.
    s.indexRear = mediumIndexAt(rows[k], wavelengthNm_).index.value_or(rows[k].mediumIndexD());
  }
  for (std::size_t k = 0; k < rows.size(); ++k)
    surfaces_[k].indexFront = k == 0 ? 1.0 : surfaces_[k - 1].indexRear;
  glassRear_.resize(rows.size());
  disperses_ = false;
  hasCatalogGlass_ = false;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    glassRear_[k] = cauchyCoefficients(rows[k].mediumIndexD(), rows[k].abbeD);
    disperses_ = disperses_ || glassRear_[k].bNm2 != 0.0 || rows[k].glass;
    hasCatalogGlass_ = hasCatalogGlass_ || rows[k].glass;
  }
  firstOrder_ = computeFirstOrder(surfaces_, stopIndex_, wavelengthNm_);
  clipRadiusSqMm2_.resize(surfaces_.size());
  for (std::size_t k = 0; k < surfaces_.size(); ++k) {
    const bool clips = clipping_ == ApertureClipping::EveryRim || surfaces_[k].isStop;
    clipRadiusSqMm2_[k] = clips ? surfaces_[k].semiApertureMm * surfaces_[k].semiApertureMm
                                : std::numeric_limits<double>::infinity();
  }
  // A shaped stop clips at its bounding circle first (cheap, and what the exit-pupil table of a
  // mask is built for), then by its shape.
  const double stopRadiusMm = surfaces_[stopIndex_].semiApertureMm;
  const double boundMm = stopRadiusMm * prescription_.stopShape.boundRadiusFactor();
  clipRadiusSqMm2_[stopIndex_] = boundMm * boundMm;
  stopTest_ = StopShapeTest(prescription_.stopShape, stopRadiusMm);
}

std::vector<ValidationError> LensSystem::wavelengthProblems(const Prescription& prescription,
                                                            double wavelengthNm) {
  std::vector<ValidationError> errors;
  if (!(std::isfinite(wavelengthNm) && wavelengthNm > 0.0)) {
    errors.push_back({-1, "wavelength must be a positive number of nanometres"});
    return errors;
  }
  for (std::size_t k = 0; k < prescription.surfaces.size(); ++k) {
    const IndexAtWavelength n = mediumIndexAt(prescription.surfaces[k], wavelengthNm);
    if (!n) errors.push_back({static_cast<int>(k), n.error});
  }
  return errors;
}

BuildResult LensSystem::build(const Prescription& prescription, double wavelengthNm) {
  BuildResult result;
  result.errors = validate(prescription);
  if (!result.errors.empty()) return result;
  result.errors = wavelengthProblems(prescription, wavelengthNm);
  if (!result.errors.empty()) return result;
  result.system = std::make_shared<LensSystem>(Private{}, prescription, wavelengthNm);
  return result;
}

std::shared_ptr<const LensSystem> LensSystem::withFilmDistance(double filmDistanceMm) const {
  if (!(std::isfinite(filmDistanceMm) && filmDistanceMm > 0.0 && filmDistanceMm <= kMaxLengthMm))
    return nullptr;
  Prescription p = prescription_;
  p.surfaces.back().thicknessMm = filmDistanceMm;
  return std::make_shared<LensSystem>(Private{}, std::move(p), wavelengthNm_, clipping_);
}

std::shared_ptr<const LensSystem> LensSystem::withStopDiameter(double stopDiameterMm) const {
  if (!(std::isfinite(stopDiameterMm) && stopDiameterMm > 0.0 &&
        stopDiameterMm <= kMaxApertureDiameterMm))
    return nullptr;
  Prescription p = prescription_;
  p.surfaces[stopIndex_].apertureDiameterMm = stopDiameterMm;
  return std::make_shared<LensSystem>(Private{}, std::move(p), wavelengthNm_, clipping_);
}

std::shared_ptr<const LensSystem> LensSystem::withWavelength(double wavelengthNm) const {
  if (!wavelengthProblems(prescription_, wavelengthNm).empty()) return nullptr;
  return std::make_shared<LensSystem>(Private{}, prescription_, wavelengthNm, clipping_);
}

std::shared_ptr<const LensSystem> LensSystem::withApertureClipping(
    ApertureClipping clipping) const {
  return std::make_shared<LensSystem>(Private{}, prescription_, wavelengthNm_, clipping);
}

std::shared_ptr<const LensSystem> LensSystem::withStopShape(const ApertureShape& shape) const {
  if (shape.kind == ApertureShape::Kind::Blades &&
      (shape.bladeCount < kMinApertureBlades || shape.bladeCount > kMaxApertureBlades ||
       !(shape.curvature >= 0.0 && shape.curvature <= 1.0) || !std::isfinite(shape.rotationDeg)))
    return nullptr;
  if (shape.kind == ApertureShape::Kind::Image && (!shape.mask || shape.mask->sizePx <= 0))
    return nullptr;
  Prescription p = prescription_;
  p.stopShape = shape;
  return std::make_shared<LensSystem>(Private{}, std::move(p), wavelengthNm_, clipping_);
}

std::shared_ptr<const LensSystem> LensSystem::withCircumscribedStop() const {
  Prescription p = prescription_;
  p.surfaces[stopIndex_].apertureDiameterMm *= p.stopShape.boundRadiusFactor();
  p.stopShape = ApertureShape{};
  return std::make_shared<LensSystem>(Private{}, std::move(p), wavelengthNm_, clipping_);
}

std::optional<FirstOrderData> LensSystem::firstOrderAt(double wavelengthNm) const {
  if (wavelengthNm == wavelengthNm_) return firstOrder_;
  const auto atWavelength = withWavelength(wavelengthNm);
  if (!atWavelength) return std::nullopt;
  return atWavelength->firstOrder();
}

const std::vector<KernelDispersion>& LensSystem::kernelDispersions() const {
  std::call_once(seriesOnce_, [this] {
    const std::vector<Surface>& rows = prescription_.surfaces;
    seriesRear_.resize(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::shared_ptr<const CatalogGlass>& glass = rows[k].glass;
      if (!glass) {
        seriesRear_[k] = modelGlassKernelDispersion(glassRear_[k]);
        continue;
      }
      const std::optional<KernelDispersion> fit = cachedKernelDispersion(glass);
      const std::string which = "surface " + std::to_string(k + 1) + "'s glass " + glass->name +
                                " (" + glass->maker + ")";
      std::ostringstream problem;
      if (!fit || fit->fromNm > kSpectralMinNm || fit->toNm < kSpectralMaxNm) {
        problem << which << ": its formula covers " << glass->formula.minimumUm * 1000.0 << "-"
                << glass->formula.maximumUm * 1000.0 << " nm, not all of the spectral render's "
                << kSpectralMinNm << "-" << kSpectralMaxNm << " nm: rendering in RGB";
      } else if (!fit->withinTolerance) {
        problem << which << " is a measured table that no series the spectral batch trace "
                << "evaluates follows to 1e-6 (the closest misses it by " << fit->maxErrorAbs
                << "): rendering in RGB";
      }
      if (seriesProblem_.empty()) seriesProblem_ = problem.str();
      if (fit) seriesRear_[k] = *fit;
    }
  });
  return seriesRear_;
}

std::string LensSystem::spectralTraceProblem() const {
  if (!hasCatalogGlass_) return {};
  kernelDispersions();
  return seriesProblem_;
}

template <bool kRecord>
std::optional<LensRay> LensSystem::trace(LensRay ray, bool fromFilm, RayPath* path,
                                         double* opticalPathMm) const {
  const int n = static_cast<int>(surfaces_.size());
  if constexpr (kRecord) {
    path->points.assign(1, ray.origin);
    path->surfaceIndices.clear();
    path->stop = RayStop::Passed;
    path->stopSurface = -1;
    path->exitRay.reset();
  }
  auto fail = [&](RayStop why, int k) -> std::optional<LensRay> {
    if constexpr (kRecord) {
      path->stop = why;
      path->stopSurface = k;
    }
    return std::nullopt;
  };
  for (int step = 0; step < n; ++step) {
    const int k = fromFilm ? n - 1 - step : step;
    const SurfaceGeometry& s = surfaces_[k];
    double t = 0.0;
    if (!intersectSurface(s, ray.origin, ray.direction, t)) {
      if constexpr (kRecord) {
        path->points.push_back(blockedEndPoint(s, ray, std::nullopt));
        path->surfaceIndices.push_back(k);
      }
      return fail(RayStop::MissedSurface, k);
    }
    const glm::dvec3 hit = ray.origin + t * ray.direction;
    if (opticalPathMm) *opticalPathMm += t * (fromFilm ? s.indexRear : s.indexFront);
    if (hit.x * hit.x + hit.y * hit.y > clipRadiusSqMm2_[k] ||
        (k == static_cast<int>(stopIndex_) && !stopTest_.isCircle() &&
         !stopTest_.contains(hit.x, hit.y))) {
      if constexpr (kRecord) {
        path->points.push_back(blockedEndPoint(s, ray, t));
        path->surfaceIndices.push_back(k);
      }
      return fail(RayStop::ClippedByAperture, k);
    }
    if constexpr (kRecord) {
      path->points.push_back(hit);
      path->surfaceIndices.push_back(k);
    }
    ray.origin = hit;
    const double eta = fromFilm ? s.indexRear / s.indexFront : s.indexFront / s.indexRear;
    if (eta != 1.0) {
      glm::dvec3 refracted;
      if (!refract(ray.direction, surfaceNormal(s, hit), eta, refracted))
        return fail(RayStop::TotalInternalReflection, k);
      ray.direction = refracted;
    }
  }
  if constexpr (kRecord) path->exitRay = ray;
  return ray;
}

std::optional<LensRay> LensSystem::traceFromFilm(const LensRay& ray) const {
  return trace<false>(ray, true, nullptr, nullptr);
}
std::optional<LensRay> LensSystem::traceFromScene(const LensRay& ray) const {
  return trace<false>(ray, false, nullptr, nullptr);
}
std::optional<LensRay> LensSystem::traceFromScene(const LensRay& ray, double& opticalPathMm) const {
  opticalPathMm = 0.0;
  return trace<false>(ray, false, nullptr, &opticalPathMm);
}
RayPath LensSystem::traceFromFilmPath(const LensRay& ray) const {
  RayPath path;
  trace<true>(ray, true, &path, nullptr);
  return path;
}
RayPath LensSystem::traceFromScenePath(const LensRay& ray) const {
  RayPath path;
  trace<true>(ray, false, &path, nullptr);
  return path;
}

const ExitPupilTable& LensSystem::exitPupilTable() const {
  std::call_once(pupilOnce_, [this] { pupil_ = std::make_unique<ExitPupilTable>(*this); });
  return *pupil_;
}

const ExitPupilTable& LensSystem::spectralExitPupilTable() const {
  if (!disperses_) return exitPupilTable();
  std::call_once(spectralPupilOnce_, [this] {
    spectralPupil_ = std::make_unique<ExitPupilTable>(
        *this, ExitPupilTable::kDefaultRadialBins, 2,
        std::vector<double>(std::begin(ExitPupilTable::kSpectralProbeWavelengthsNm),
                            std::end(ExitPupilTable::kSpectralProbeWavelengthsNm)));
  });
  return *spectralPupil_;
}

void LensSystem::sampleSpectralCameraRays(const float* filmXMm, const float* filmYMm,
                                          const float* u0, const float* u1, std::size_t n,
                                          LensRayBatch& rays, float* pdfPerMm2,
                                          BatchKernel kernel) const {
  if (kernel == BatchKernel::Auto || !batchKernelAvailable(kernel)) kernel = autoBatchKernel();
  using Sample = ExitPupilTable::SampleKernel;
  const Sample sampleKernel = kernel == BatchKernel::Avx512 ? Sample::Avx512
                              : kernel == BatchKernel::Avx2 ? Sample::Avx2
                                                            : Sample::Portable;
  spectralExitPupilTable().sampleRays(filmXMm, filmYMm, u0, u1, n, rays, pdfPerMm2, sampleKernel);
}

double LensSystem::imageCircleBoundMm() const { return exitPupilTable().imageCircleBoundMm(); }

void LensSystem::sampleCameraRays(const float* filmXMm, const float* filmYMm, const float* u0,
                                  const float* u1, std::size_t n, LensRayBatch& rays,
                                  float* pdfPerMm2, BatchKernel kernel) const {
  if (kernel == BatchKernel::Auto || !batchKernelAvailable(kernel)) kernel = autoBatchKernel();
  using Sample = ExitPupilTable::SampleKernel;
  const Sample sampleKernel = kernel == BatchKernel::Avx512 ? Sample::Avx512
                              : kernel == BatchKernel::Avx2 ? Sample::Avx2
                                                            : Sample::Portable;
  exitPupilTable().sampleRays(filmXMm, filmYMm, u0, u1, n, rays, pdfPerMm2, sampleKernel);
}

std::optional<PupilSample> LensSystem::sampleExitPupil(glm::dvec2 filmPointMm, glm::dvec2 u) const {
  return exitPupilTable().sample(filmPointMm, u);
}

}  // namespace lenslab::optics
