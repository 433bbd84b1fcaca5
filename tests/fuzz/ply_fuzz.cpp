// libFuzzer target: the PLY mesh reader (render/ply_reader.h) on arbitrary bytes, ASCII or
// binary. Beyond not crashing, it holds the reader to its header: a mesh it accepts has whole
// triangles whose indices name its vertices, finite positions, and normals and uvs either absent
// or one per vertex.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.h"
#include "render/ply_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  render::MeshData mesh;
  Diagnostics diagnostics;
  const bool ok =
      render::readPlyMeshData(bytes, "mesh.ply", mesh, {"scene.pbrt", 3, 7}, diagnostics);
  fuzz::checkDiagnostics(diagnostics, ok);
  if (!ok) return 0;
  fuzz::check(mesh.indices.size() % 3 == 0, "the faces are whole triangles");
  for (unsigned index : mesh.indices)
    fuzz::check(index < mesh.positions.size(), "every index names a vertex");
  for (const auto& position : mesh.positions)
    fuzz::check(std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z),
                "vertex positions are finite");
  fuzz::check(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(),
              "normals are absent or one per vertex");
  fuzz::check(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size(),
              "uvs are absent or one per vertex");
  return 0;
}
