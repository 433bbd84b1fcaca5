// libFuzzer target: the pbrt scene parser (render/pbrt_parser.h) with Include, plymesh and the
// files a scene names resolved against a set of files in memory (render/scene_file_access.h), so
// one input is a scene and its files and the target never reads the disk.
//
// Input: the scene, then any number of parts "\n#file NAME\n" + contents (a pbrt comment line,
// so a plain scene file is an input too). NAME is relative to the scene's folder; the scene
// itself is "scene.pbrt" in it (so a scene can include itself).
//
// Beyond not crashing, it holds the parser to its promises: a scene it accepts has film and
// sampling settings a renderer can use, finite transforms, meshes whose indices name their
// vertices, and indices into its own materials and objects.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "render/pbrt_parser.h"
#include "render/scene_file_access.h"

namespace {

using namespace lenslab;

bool finite(const glm::dmat4& matrix) {
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(matrix[column][row])) return false;
  return true;
}

void checkShape(const render::ShapeDescription& shape, const render::SceneDescription& scene) {
  fuzz::check(finite(shape.worldFromObject), "a shape's transform is finite");
  fuzz::check(shape.materialIndex >= 0 &&
                  static_cast<std::size_t>(shape.materialIndex) < scene.materials.size(),
              "a shape's material index names a material");
  const render::MeshData& mesh = shape.mesh;
  fuzz::check(mesh.indices.size() % 3 == 0, "a mesh has whole triangles");
  for (unsigned index : mesh.indices)
    fuzz::check(index < mesh.positions.size(), "a mesh's indices name its vertices");
  for (const auto& p : mesh.positions)
    fuzz::check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z),
                "mesh positions are finite");
}

void checkScene(const render::SceneDescription& scene) {
  fuzz::check(scene.film.xResolution > 0 && scene.film.yResolution > 0,
              "the film has a positive resolution");
  fuzz::check(scene.pixelSamples > 0, "a scene asks for at least one sample per pixel");
  fuzz::check(finite(scene.camera.cameraFromWorld), "the camera transform is finite");
  fuzz::check(!scene.materials.empty(), "the default material is there");
  for (const auto& shape : scene.shapes) checkShape(shape, scene);
  for (const auto& object : scene.objects)
    for (const auto& shape : object.shapes) checkShape(shape, scene);
  for (const auto& instance : scene.instances) {
    fuzz::check(instance.objectIndex >= 0 &&
                    static_cast<std::size_t>(instance.objectIndex) < scene.objects.size(),
                "an instance names an object");
    fuzz::check(finite(instance.worldFromInstance), "an instance's transform is finite");
  }
  for (const auto& light : scene.lights)
    fuzz::check(finite(light.worldFromLight), "a light's transform is finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path folder = "/lenslab-fuzz";
  constexpr std::string_view kPart = "\n#file ";
  std::size_t end = input.find(kPart);
  const std::string scene(input.substr(0, end));
  render::InMemorySceneFiles files;
  files.add(folder / "scene.pbrt", scene);
  while (end != std::string_view::npos) {
    const std::size_t nameStart = end + kPart.size();
    const std::size_t nameEnd = input.find('\n', nameStart);
    if (nameEnd == std::string_view::npos) break;
    end = input.find(kPart, nameEnd);
    const std::string_view contents = input.substr(nameEnd + 1, end - (nameEnd + 1));
    files.add(folder / std::string(input.substr(nameStart, nameEnd - nameStart)),
              std::string(contents));
  }
  const render::ParseResult result = render::parsePbrtText(scene, "scene.pbrt", folder, files);
  fuzz::checkDiagnostics(result.diagnostics, result.scene.has_value());
  if (result.scene) checkScene(*result.scene);
  return 0;
}
