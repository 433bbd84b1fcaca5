#pragma once
// Furnace tests: a camera inside a uniform emitter sees, at each film point, the radiance times
// the film's relative illumination there, which a fine grid over the lens gives independently.

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "optics/lens_system.h"

namespace lenslab::render::testing {

// A uniform emitter all around the camera: a two-sided emitting sphere with a black surface.
inline std::string furnaceWorld(double radiance) {
  const std::string l = std::to_string(radiance);
  return "WorldBegin\nAttributeBegin\nMaterial \"matte\" \"rgb Kd\" [0 0 0]\n"
         "AreaLightSource \"diffuse\" \"rgb L\" [" +
         l + " " + l + " " + l +
         "] \"bool twosided\" \"true\"\nShape \"sphere\" \"float radius\" [50]\nAttributeEnd\n"
         "WorldEnd\n";
}

// Relative illumination at a film point by brute force: a fine grid over a disk of radius
// `radiusMm` on the rear vertex plane, each point traced exactly;
// E/L = (1/Z^2) * sum over passing points of cos^4(theta) dA.
inline double relativeIllumination(const optics::LensSystem& lens, glm::dvec2 film,
                                   double radiusMm) {
  const double z = lens.rearVertexZ();
  constexpr int kSteps = 240;
  const double step = 2.0 * radiusMm / kSteps;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    for (int j = 0; j < kSteps; ++j) {
      const glm::dvec2 p(-radiusMm + (i + 0.5) * step, -radiusMm + (j + 0.5) * step);
      if (glm::dot(p, p) > radiusMm * radiusMm) continue;
      const glm::dvec3 direction = glm::normalize(glm::dvec3(p, z) - glm::dvec3(film, 0.0));
      if (!lens.traceFromFilm({glm::dvec3(film, 0.0), direction})) continue;
      sum += std::pow(direction.z, 4.0) * step * step;
    }
  }
  return sum / (z * z);
}

}  // namespace lenslab::render::testing
