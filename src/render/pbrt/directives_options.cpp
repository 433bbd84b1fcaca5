// Scene-wide options: film, sampler, pixel filter, integrator, and the options lenslab reads
// past with a warning (volume integrators, media, colour spaces, ...).

#include "render/pbrt/handlers.h"
#include "render/pbrt/param_checks.h"

namespace lenslab::render::pbrt {

namespace {

constexpr int kMaxResolution = 16384;      // per side: 16384² RGB floats are 3 GB already
constexpr int kMaxPixelSamples = 1 << 20;  // as `lenslab render --spp`
constexpr int kMaxDepth = 10000;

}  // namespace

bool film(const DirectiveCall& call) {
  ParserState& state = call.state;
  Diagnostics& diagnostics = state.diagnostics;
  const auto type = call.in.string("Film");
  auto set = type ? call.in.params("Film \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  if (type->text != "image" && type->text != "rgb") {
    diagnostics.warning(type->location,
                        "film \"" + type->text + "\" is not supported; an image film is used");
  }
  FilmDescription& film = state.scene.film;
  const auto x = set->getInt("xresolution", film.xResolution, 1, kMaxResolution, diagnostics);
  const auto y = set->getInt("yresolution", film.yResolution, 1, kMaxResolution, diagnostics);
  const auto diagonal = positiveParam(*set, "diagonal", film.diagonalMm, diagnostics, 1e9);
  const auto scale = positiveParam(*set, "scale", 1.0, diagnostics, 1e9);
  if (!x || !y || !diagonal || !scale) return false;
  if (set->find("scale")) film.scale = *scale;
  film.xResolution = *x;
  film.yResolution = *y;
  film.diagonalMm = *diagonal;
  film.filename = set->getString("filename", film.filename);
  set->unsupported("cropwindow", "the whole image is rendered");
  set->unsupported("pixelbounds", "the whole image is rendered");
  set->unsupported("maxsampleluminance", "samples are not clamped");
  state.scene.parsedParams.push_back(std::move(*set));
  return true;
}

bool sampler(const DirectiveCall& call) {
  ParserState& state = call.state;
  Diagnostics& diagnostics = state.diagnostics;
  const auto type = call.in.string("Sampler");
  auto set = type ? call.in.params("Sampler \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  if (type->text == "stratified") {
    const auto x = set->getInt("xsamples", 1, 1, 1024, diagnostics);
    const auto y = set->getInt("ysamples", 1, 1, 1024, diagnostics);
    if (!x || !y) return false;
    state.stratified.emplace();
    if (set->find("xsamples")) state.stratified->first = *x;
    if (set->find("ysamples")) state.stratified->second = *y;
    set->unsupported("pixelsamples", "xsamples * ysamples samples per pixel are taken");
    if (!set->getBool("jitter", true)) {
      set->unsupported("jitter", "the renderer's own low-discrepancy samples are used");
    }
  } else {
    const auto samples =
        set->getInt("pixelsamples", state.scene.pixelSamples, 1, kMaxPixelSamples, diagnostics);
    if (!samples) return false;
    state.scene.pixelSamples = *samples;
    state.stratified.reset();
  }
  state.scene.parsedParams.push_back(std::move(*set));
  return true;
}

bool pixelFilter(const DirectiveCall& call) {
  const auto type = call.in.string("PixelFilter");
  auto set = type ? call.in.params("PixelFilter \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  if (type->text != "box") {
    call.state.diagnostics.warning(type->location, "pixel filter \"" + type->text +
                                                       "\" is not supported; a box filter is used");
    // The warning covers the filter's parameters.
    for (const Param& param : set->items()) set->find(param.name);
  } else {
    for (const char* width : {"xwidth", "ywidth"}) {
      if (set->getFloat(width, 0.5) != 0.5) {
        set->unsupported(width, "a box of one pixel (width 0.5) is used");
      }
    }
  }
  call.state.scene.parsedParams.push_back(std::move(*set));
  return true;
}

bool integrator(const DirectiveCall& call) {
  ParserState& state = call.state;
  const auto type = call.in.string(call.name);
  auto set = type ? call.in.params(call.name + " \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  if (call.name == "SurfaceIntegrator") state.v2Forms = true;
  IntegratorDescription& integrator = state.scene.integrator;
  integrator.explicitlyNamed = true;
  if (type->text == "path") {
    integrator.kind = IntegratorKind::Path;
  } else if (type->text == "directlighting") {
    integrator.kind = IntegratorKind::DirectLighting;
    if (set->getString("strategy", "all") != "all") {
      set->unsupported("strategy", "\"all\" is used (every light is sampled at each hit)");
    }
  } else {
    state.diagnostics.warning(type->location, "integrator \"" + type->text +
                                                  "\" is not supported; the path tracer is used");
    integrator.kind = IntegratorKind::Path;
  }
  const auto depth = set->getInt("maxdepth", 5, 0, kMaxDepth, state.diagnostics);
  if (!depth) return false;
  integrator.maxDepth = *depth;
  state.scene.parsedParams.push_back(std::move(*set));
  return true;
}

bool unsupportedWithParams(const DirectiveCall& call) {
  const auto type = call.in.string(call.name);
  auto set = type ? call.in.params(call.name) : std::nullopt;
  if (!type || !set) return false;
  // Directives only pbrt-v2 has.
  if (call.name == "VolumeIntegrator" || call.name == "Renderer") call.state.v2Forms = true;
  // Every scene may name an accelerator; lenslab always uses Embree's, without a word.
  if (call.name != "Accelerator") {
    call.state.diagnostics.warning(call.at,
                                   call.name + " \"" + type->text + "\" is not supported; ignored");
  }
  return true;
}

bool mediumInterface(const DirectiveCall& call) {
  const auto inside = call.in.string(call.name);
  if (!inside) return false;
  // The exterior medium is optional.
  if (call.in.peek().kind == TokenKind::String) call.in.next();
  call.state.diagnostics.warning(call.at,
                                 "participating media are not supported; MediumInterface ignored");
  return true;
}

}  // namespace lenslab::render::pbrt
