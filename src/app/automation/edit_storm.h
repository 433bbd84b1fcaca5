#pragma once
// Random lens edits for the edit-storm test (issue 24): what a user typing fast into every cell,
// dragging every slider and pressing every button of the lens editor could produce, sensible
// values and absurd ones alike (a zero or tiny radius, a negative thickness, an index below 1, a
// NaN, a surface that does not exist), so that the viewer meets lenses that fail to build while
// the preview and the analyses run. The script's `edit-storm COUNT SEED` issues them.

#include <cstdint>
#include <random>

#include "app/document/lens_document.h"

namespace lenslab::app {

class EditStorm {
 public:
  explicit EditStorm(std::uint64_t seed) : random_(seed) {}
  // The next edit. Surface numbers go a few past the longest bundled lens, so that some edits
  // are refused for naming no surface.
  EditCommand next();

 private:
  double uniform(double low, double high);
  std::mt19937_64 random_;
};

}  // namespace lenslab::app
