#include "render/pbrt/diagnostic_text.h"

#include <sstream>

namespace lenslab::render::pbrt {

std::string locationText(const SourceLocation& at) {
  return at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
}

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace lenslab::render::pbrt
