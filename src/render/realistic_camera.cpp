#include "render/realistic_camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <vector>

#include "render/sampling.h"

namespace lenslab::render {

namespace {

// Kolb's exposure weight for a film ray toward `pupil`: A cos^4(theta) / Z^2 with A = 1/pdf.
float exposureWeight(glm::dvec3 toPupil, const optics::PupilSample& pupil) {
  const double cosTheta = toPupil.z / glm::length(toPupil);
  const double cos2 = cosTheta * cosTheta;
  const double z = pupil.pointMm.z;
  return static_cast<float>(cos2 * cos2 / (pupil.pdfPerMm2 * z * z));
}

}  // namespace

RealisticCamera::RealisticCamera(std::shared_ptr<const optics::LensSystem> lens,
                                 const glm::dmat4& cameraFromWorld, int width, int height,
                                 double filmDiagonalMm, double sceneUnitsPerMm,
                                 double cameraOriginZMm, LensSampling sampling)
    : Camera(width, height),
      lens_(std::move(lens)),
      worldFromCamera_(glm::inverse(cameraFromWorld)),
      sceneUnitsPerMm_(sceneUnitsPerMm),
      cameraOriginZMm_(cameraOriginZMm),
      sampling_(sampling) {
  const double diagonalPixels = std::hypot(static_cast<double>(width), static_cast<double>(height));
  filmWidthMm_ = filmDiagonalMm * width / diagonalPixels;
  filmHeightMm_ = filmDiagonalMm * height / diagonalPixels;
}

float RealisticCamera::pixelSpreadRadians() const {
  const double efl = lens_->firstOrder().eflMm;
  const double focal = efl > 0.0 ? efl : lens_->filmDistanceMm();
  return static_cast<float>(filmHeightMm_ / height_ / focal);
}

std::optional<optics::PupilSample> RealisticCamera::samplePupil(glm::dvec2 filmMm,
                                                               glm::vec2 u) const {
  if (sampling_ == LensSampling::ExitPupil) return lens_->sampleExitPupil(filmMm, glm::dvec2(u));
  // Uniform on the rear aperture's disk (concentric map keeps the stratification).
  const double radius = lens_->rearApertureRadiusMm();
  const glm::vec2 disk = concentricDisk(u);
  return optics::PupilSample{{radius * disk.x, radius * disk.y, lens_->rearVertexZ()},
                             1.0 / (3.14159265358979323846 * radius * radius)};
}

glm::dvec2 RealisticCamera::filmPointMm(glm::vec2 raster) const {
  // pbrt's film mapping: raster x runs toward -x on the film and raster y toward +y, because the
  // lens turns the image upside down and mirrors it; the scene then appears upright.
  return {0.5 * filmWidthMm_ - raster.x / width_ * filmWidthMm_,
          -0.5 * filmHeightMm_ + raster.y / height_ * filmHeightMm_};
}

void RealisticCamera::finishRay(glm::dvec3 exitOriginMm, glm::dvec3 exitDirection,
                                CameraRay& ray) const {
  const glm::dvec3 origin =
      (exitOriginMm - glm::dvec3(0.0, 0.0, cameraOriginZMm_)) * sceneUnitsPerMm_;
  ray.origin = glm::vec3(worldFromCamera_ * glm::dvec4(origin, 1.0));
  ray.direction =
      glm::vec3(glm::normalize(glm::dvec3(worldFromCamera_ * glm::dvec4(exitDirection, 0.0))));
}

bool RealisticCamera::generateRay(glm::vec2 raster, glm::vec2 lensSample, CameraRay& ray) const {
  const glm::dvec2 film = filmPointMm(raster);
  const auto pupil = samplePupil(film, lensSample);
  if (!pupil || pupil->pdfPerMm2 <= 0.0) return false;
  const glm::dvec3 start(film, 0.0);
  const glm::dvec3 toPupil = pupil->pointMm - start;
  const auto out = lens_->traceFromFilm({start, glm::normalize(toPupil)});
  if (!out) return false;
  ray.weight = exposureWeight(toPupil, *pupil);
  finishRay(out->origin, out->direction, ray);
  return true;
}

void RealisticCamera::generateRays(std::size_t count, const glm::vec2* rasterPoints,
                                   const glm::vec2* lensSamples, CameraRay* rays,
                                   std::uint8_t* passed) const {
  thread_local optics::LensRayBatch batch;
  batch.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec2 film = filmPointMm(rasterPoints[i]);
    const auto pupil = samplePupil(film, lensSamples[i]);
    batch.alive[i] = pupil && pupil->pdfPerMm2 > 0.0;
    if (!batch.alive[i]) continue;
    const glm::dvec3 toPupil = pupil->pointMm - glm::dvec3(film, 0.0);
    const glm::dvec3 direction = glm::normalize(toPupil);
    batch.ox[i] = static_cast<float>(film.x);
    batch.oy[i] = static_cast<float>(film.y);
    batch.oz[i] = 0.0f;
    batch.dx[i] = static_cast<float>(direction.x);
    batch.dy[i] = static_cast<float>(direction.y);
    batch.dz[i] = static_cast<float>(direction.z);
    rays[i].weight = exposureWeight(toPupil, *pupil);
  }
  lens_->traceFromFilmBatch(batch);
  for (std::size_t i = 0; i < count; ++i) {
    passed[i] = batch.alive[i];
    if (!passed[i]) continue;
    finishRay({batch.ox[i], batch.oy[i], batch.oz[i]}, {batch.dx[i], batch.dy[i], batch.dz[i]},
              rays[i]);
  }
}

}  // namespace lenslab::render
