// Shapes, with the current transform, material, area light and orientation.

#include <cmath>
#include <limits>

#include "render/mesh_check.h"
#include "render/pbrt/diagnostic_text.h"
#include "render/pbrt/handlers.h"
#include "render/ply_reader.h"
#include "render/transform_check.h"

namespace lenslab::render::pbrt {

namespace {

// The indices of a trianglemesh: whole numbers that fit an unsigned index.
bool meshIndices(const ParamSet& set, std::vector<unsigned>& out, Diagnostics& diagnostics) {
  const Param* indices = set.find("indices");
  if (!indices) return true;
  out.reserve(indices->numbers.size());
  for (std::size_t i = 0; i < indices->numbers.size(); ++i) {
    const double index = indices->numbers[i];
    if (!(index >= 0.0) || index != std::trunc(index) ||
        index > std::numeric_limits<unsigned>::max()) {
      diagnostics.error(indices->location, "trianglemesh index " + formatNumber(index) +
                                               " at position " + std::to_string(i) +
                                               " is not a vertex index (a whole number >= 0)");
      return false;
    }
    out.push_back(static_cast<unsigned>(index));
  }
  return true;
}

bool readTriangleMesh(ShapeDescription& shape, const ParamSet& set, Diagnostics& diagnostics) {
  const std::vector<double> points = set.getNumbers("P");
  const std::vector<double> normals = set.getNumbers("N");
  std::vector<double> uvs = set.getNumbers("uv");
  if (uvs.empty()) uvs = set.getNumbers("st");
  if (points.size() % 3 != 0) {
    diagnostics.error(shape.location, "trianglemesh \"point P\" has " +
                                          std::to_string(points.size()) +
                                          " numbers (expected a multiple of 3)");
    return false;
  }
  for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
    shape.mesh.positions.emplace_back(points[i], points[i + 1], points[i + 2]);
  }
  for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
    shape.mesh.normals.emplace_back(normals[i], normals[i + 1], normals[i + 2]);
  }
  for (std::size_t i = 0; i + 1 < uvs.size(); i += 2) {
    shape.mesh.uvs.emplace_back(uvs[i], uvs[i + 1]);
  }
  if (!meshIndices(set, shape.mesh.indices, diagnostics)) return false;
  if (!set.find("indices") && shape.mesh.positions.size() == 3) shape.mesh.indices = {0, 1, 2};
  return checkMesh(shape.mesh, shape.location, diagnostics);
}

// A plymesh becomes a trianglemesh read from its file.
bool readPlyShape(ShapeDescription& shape, const ParamSet& set, const DirectiveReader& in,
                  Diagnostics& diagnostics) {
  const Param* file = set.find("filename");
  if (!file || file->strings.empty()) {
    diagnostics.error(shape.location, "plymesh needs \"string filename\"");
    return false;
  }
  const auto path = in.resolve(file->strings[0]);
  if (const auto problem = in.files().problem(path, "PLY file")) {
    diagnostics.error(file->location, *problem);
    return false;
  }
  const std::optional<std::string> data = in.files().read(path);
  if (!data) {
    diagnostics.error(file->location, "cannot open PLY file " + path.string());
    return false;
  }
  if (!readPlyMeshData(*data, path.string(), shape.mesh, file->location, diagnostics)) return false;
  if (!checkMesh(shape.mesh, file->location, diagnostics)) return false;
  shape.type = "trianglemesh";
  return true;
}

}  // namespace

bool shape(const DirectiveCall& call) {
  ParserState& state = call.state;
  Diagnostics& diagnostics = state.diagnostics;
  const auto type = call.in.string("Shape");
  auto set = type ? call.in.params("Shape \"" + type->text + "\"") : std::nullopt;
  if (!type || !set) return false;
  ShapeDescription shape;
  shape.type = type->text;
  shape.location = type->location;
  shape.worldFromObject = state.graphics.ctm;
  shape.materialIndex = state.graphics.materialIndex;
  shape.areaLight = state.graphics.areaLight;
  shape.reverseOrientation = state.graphics.reverseOrientation;
  if (shape.type == "trianglemesh") {
    if (!readTriangleMesh(shape, *set, diagnostics)) return false;
  } else if (shape.type == "plymesh") {
    if (!readPlyShape(shape, *set, call.in, diagnostics)) return false;
  } else if (shape.type != "sphere" && shape.type != "disk" && shape.type != "cone" &&
             shape.type != "cylinder") {
    diagnostics.warning(shape.location,
                        "shape \"" + shape.type + "\" is not supported; it is left out");
    return true;
  }
  if (const auto problem = transformProblem(shape.worldFromObject)) {
    diagnostics.warning(shape.location, "the transform of shape \"" + type->text + "\" " +
                                            *problem + "; the shape is left out");
    return true;
  }
  shape.params = std::move(*set);
  if (state.currentObject >= 0) {
    state.scene.objects[static_cast<std::size_t>(state.currentObject)].shapes.push_back(
        std::move(shape));
  } else {
    state.scene.shapes.push_back(std::move(shape));
  }
  return true;
}

bool reverseOrientation(const DirectiveCall& call) {
  call.state.graphics.reverseOrientation = !call.state.graphics.reverseOrientation;
  return true;
}

}  // namespace lenslab::render::pbrt
