#include "app/document/lens_problems.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "optics/lens_system.h"

namespace lenslab::app {

std::vector<LensProblem> findLensProblems(const optics::Prescription& lens,
                                          std::optional<std::size_t> intendedStop) {
  std::vector<std::size_t> stops;
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    if (lens.surfaces[i].isStop()) stops.push_back(i);
  }
  std::vector<LensProblem> problems;
  optics::Prescription checked = lens;
  std::size_t stop = stops.empty() ? 0 : stops.front();
  if (stops.size() > 1) {
    if (intendedStop && std::find(stops.begin(), stops.end(), *intendedStop) != stops.end()) {
      stop = *intendedStop;
    }
    // Validate the lens with the extra stops as flat surfaces: the same geometry (a stop is a
    // plane too), so every other problem is still found, and none is put on the real stop.
    for (std::size_t row : stops) {
      if (row == stop) continue;
      checked.surfaces[row].radiusMm = optics::kFlatRadius;
      problems.push_back(
          {static_cast<int>(row), "radius 0 makes this a second aperture stop (surface " +
                                      std::to_string(stop + 1) + " is the stop)"});
    }
  }
  for (const optics::ValidationError& error : optics::validate(checked)) {
    problems.push_back({error.surface, error.message});
  }
  for (std::size_t row : stops) {
    const double index = lens.surfaces[row].indexD;
    if (std::isfinite(index) && index > 1.0) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "a stop must have air after it (n_d 1), not glass (n_d %g)", index);
      problems.push_back({static_cast<int>(row), message});
    }
  }
  // Row order, the lens-wide problems first, so the list under the table reads top to bottom.
  std::stable_sort(
      problems.begin(), problems.end(),
      [](const LensProblem& a, const LensProblem& b) { return a.surface < b.surface; });
  return problems;
}

}  // namespace lenslab::app
