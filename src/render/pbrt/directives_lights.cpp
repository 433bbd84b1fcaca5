// Light sources and the area light that the following shapes emit.

#include "render/pbrt/handlers.h"
#include "render/transform_check.h"

namespace lenslab::render::pbrt {

namespace {

constexpr int kMaxLightSamples = 4096;

}  // namespace

bool lightSource(const DirectiveCall& call) {
  ParserState& state = call.state;
  Diagnostics& diagnostics = state.diagnostics;
  const auto type = call.in.string("LightSource");
  auto set = type ? call.in.params("LightSource \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  LightDescription light;
  light.type = type->text;
  light.location = type->location;
  light.worldFromLight = state.graphics.ctm;
  if (light.type == "infinite") {
    const Param* map = set->find("mapname");
    if (!map) map = set->find("filename");
    if (map && !map->strings.empty()) {
      light.mapPath = call.in.resolve(map->strings[0]);
      if (const auto problem = call.in.files().problem(light.mapPath, "environment map")) {
        diagnostics.error(map->location, *problem);
        return false;
      }
    }
  } else if (light.type != "point" && light.type != "spot" && light.type != "distant") {
    diagnostics.warning(type->location,
                        "light \"" + light.type + "\" is not supported; it is left out");
    return true;
  }
  if (const auto problem = transformProblem(state.graphics.ctm)) {
    diagnostics.warning(type->location, "the transform of light \"" + light.type + "\" " +
                                            *problem + "; the light is left out");
    return true;
  }
  light.params = std::move(*set);
  state.scene.lights.push_back(std::move(light));
  return true;
}

bool areaLightSource(const DirectiveCall& call) {
  ParserState& state = call.state;
  Diagnostics& diagnostics = state.diagnostics;
  const auto type = call.in.string("AreaLightSource");
  auto set = type ? call.in.params("AreaLightSource \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  if (type->text != "diffuse" && type->text != "area") {
    diagnostics.warning(type->location, "area light \"" + type->text +
                                            "\" is not supported; a diffuse emitter is used");
  }
  if (type->text == "area") state.v2Forms = true;
  AreaLightDescription area;
  area.radiance = set->getTriple("L", glm::dvec3(1.0)) * set->getFloat("scale", 1.0);
  area.twoSided = set->getBool("twosided", false);
  const auto v2Samples = set->getInt("samples", 1, 1, kMaxLightSamples, diagnostics);
  const auto samples =
      set->getInt("nsamples", v2Samples.value_or(1), 1, kMaxLightSamples, diagnostics);
  if (!samples || !v2Samples) return false;
  area.samples = *samples;
  state.graphics.areaLight = area;
  state.scene.parsedParams.push_back(std::move(*set));
  return true;
}

}  // namespace lenslab::render::pbrt
