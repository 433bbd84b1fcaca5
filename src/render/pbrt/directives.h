#pragma once
// The table of pbrt directives: for each name, the handler that reads its arguments and applies
// it to the scene being built, and where in the file it may appear. Include/Import are not in
// it: reading another file is syntax, handled by the parser itself (pbrt_parser.cpp).

#include <string>
#include <string_view>

#include "common/diagnostics.h"
#include "render/pbrt/directive_reader.h"
#include "render/pbrt/parser_state.h"

namespace lenslab::render::pbrt {

// One directive being applied.
struct DirectiveCall {
  const std::string& name;   // as written, for messages
  const SourceLocation& at;  // of the name
  DirectiveReader& in;
  ParserState& state;
};

// Reads the directive's arguments and applies it. False after reporting an error.
using DirectiveHandler = bool (*)(const DirectiveCall& call);

enum class Placement {
  Anywhere,
  // Scene-wide options (Camera, Film, Sampler, ...): before WorldBegin only.
  BeforeWorld,
};

struct Directive {
  std::string_view name;
  DirectiveHandler handler;
  Placement placement;
};

// The directive called `name`, or null for a name pbrt does not know.
const Directive* findDirective(std::string_view name);

}  // namespace lenslab::render::pbrt
