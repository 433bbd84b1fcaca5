#pragma once
// How the pbrt parser writes locations and numbers inside its messages.

#include <string>

#include "common/diagnostics.h"

namespace lenslab::render::pbrt {

// "file:line:column", for messages that point at a second place (where a block began).
std::string locationText(const SourceLocation& at);
// A number as a stream prints it (45, 0.5, 1e+06): the form every message uses.
std::string formatNumber(double value);

}  // namespace lenslab::render::pbrt
