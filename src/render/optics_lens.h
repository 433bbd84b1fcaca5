#pragma once
// The optics library's LensSystem as the realistic camera's lens.

#include <memory>

#include "optics/lens_system.h"
#include "render/camera_lens.h"

namespace lenslab::render {

class OpticsLens final : public CameraLens {
 public:
  explicit OpticsLens(std::shared_ptr<const optics::LensSystem> system)
      : system_(std::move(system)) {}

  std::optional<LensRayMm> traceFromFilm(const LensRayMm& ray) const override {
    const auto out = system_->traceFromFilm({ray.origin, glm::normalize(ray.direction)});
    if (!out) return std::nullopt;
    return LensRayMm{out->origin, out->direction};
  }
  std::optional<PupilSampleMm> sampleExitPupil(glm::dvec2 filmPointMm,
                                               glm::dvec2 u) const override {
    const auto sample = system_->sampleExitPupil(filmPointMm, u);
    if (!sample) return std::nullopt;
    return PupilSampleMm{sample->pointMm, sample->pdfPerMm2};
  }
  const optics::LensSystem& system() const { return *system_; }

 private:
  std::shared_ptr<const optics::LensSystem> system_;
};

}  // namespace lenslab::render
