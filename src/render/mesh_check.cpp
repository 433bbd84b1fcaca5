#include "render/mesh_check.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace lenslab::render {

bool checkMesh(MeshData& mesh, const SourceLocation& where, Diagnostics& diagnostics) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3& p = mesh.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      diagnostics.error(where, "mesh vertex " + std::to_string(i) + " is not finite (NaN or inf)");
      return false;
    }
  }
  if (mesh.indices.size() % 3 != 0) {
    diagnostics.error(where, "mesh has " + std::to_string(mesh.indices.size()) +
                                 " indices (expected a multiple of 3)");
    return false;
  }
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= mesh.positions.size()) {
      diagnostics.error(where, "mesh index " + std::to_string(mesh.indices[i]) + " at position " +
                                   std::to_string(i) + " is out of range (" +
                                   std::to_string(mesh.positions.size()) + " vertices)");
      return false;
    }
  }
  std::vector<unsigned> kept;
  kept.reserve(mesh.indices.size());
  std::size_t dropped = 0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const glm::dvec3 a = mesh.positions[mesh.indices[t]];
    const glm::dvec3 b = mesh.positions[mesh.indices[t + 1]];
    const glm::dvec3 c = mesh.positions[mesh.indices[t + 2]];
    if (glm::length(glm::cross(b - a, c - a)) == 0.0) {
      ++dropped;
      continue;
    }
    kept.insert(kept.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
  }
  if (dropped > 0) {
    diagnostics.warning(
        where, std::to_string(dropped) + " zero-area triangle(s) in the mesh; they were dropped");
    mesh.indices = std::move(kept);
  }
  auto finite = [](auto v) {
    for (int i = 0; i < v.length(); ++i) {
      if (!std::isfinite(v[i])) return false;
    }
    return true;
  };
  for (const glm::dvec3& n : mesh.normals) {
    if (!finite(n) || glm::dot(n, n) == 0.0) {
      diagnostics.warning(where,
                          "mesh has a zero or non-finite normal; the mesh's normals are "
                          "ignored (faceted shading is used)");
      mesh.normals.clear();
      break;
    }
  }
  for (const glm::dvec2& uv : mesh.uvs) {
    if (!finite(uv)) {
      diagnostics.warning(where, "mesh has a non-finite uv; the mesh's uvs are ignored");
      mesh.uvs.clear();
      break;
    }
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
    diagnostics.warning(where, "mesh has a different number of normals than vertices; ignored");
    mesh.normals.clear();
  }
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
    diagnostics.warning(where, "mesh has a different number of uvs than vertices; ignored");
    mesh.uvs.clear();
  }
  return true;
}

}  // namespace lenslab::render
