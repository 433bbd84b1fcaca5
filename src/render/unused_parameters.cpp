#include "render/unused_parameters.h"

#include <algorithm>
#include <tuple>

namespace lenslab::render {

void reportUnusedParameters(const SceneDescription& description, Diagnostics& diagnostics) {
  std::vector<const ParamSet*> sets;
  for (const ParamSet& set : description.parsedParams) sets.push_back(&set);
  sets.push_back(&description.camera.params);
  for (const TextureDescription& texture : description.textures) sets.push_back(&texture.params);
  for (const MaterialDescription& material : description.materials)
    sets.push_back(&material.params);
  for (const ShapeDescription& shape : description.shapes) sets.push_back(&shape.params);
  for (const ObjectDescription& object : description.objects) {
    for (const ShapeDescription& shape : object.shapes) sets.push_back(&shape.params);
  }
  for (const LightDescription& light : description.lights) sets.push_back(&light.params);

  Diagnostics found;
  for (const ParamSet* set : sets) set->reportUnused(found);
  // Warnings for parameters nothing uses, errors for ones given more values than they take.
  std::vector<Diagnostic> warnings = found.all();
  // Named materials are stored in the order they are defined, but a file's directives come from
  // several lists: sort so that the report reads in file order.
  std::stable_sort(warnings.begin(), warnings.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.location.file, a.location.line, a.location.column) <
           std::tie(b.location.file, b.location.line, b.location.column);
  });
  for (const Diagnostic& warning : warnings) diagnostics.add(warning);
}

}  // namespace lenslab::render
