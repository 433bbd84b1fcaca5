// The pbrt parser reading a scene's files through an in-memory SceneFiles
// (render/scene_file_access.h), as the fuzz target does: Include and plymesh resolve against the
// including file's folder in the set, and nothing outside the set is read, even when it exists on
// disk.
#include <gtest/gtest.h>

#include "render/pbrt_parser.h"
#include "render/scene_file_access.h"

namespace lenslab::render {
namespace {

const std::string kTriangle =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n2 0 0\n0 3 0\n3 0 1 2\n";

TEST(InMemorySceneFiles, IncludeAndPlyMeshResolveInTheSet) {
  InMemorySceneFiles files;
  // parts/world.pbrt names its mesh relative to its own folder, parts/.
  files.add("/scenes/parts/world.pbrt",
            "Shape \"plymesh\" \"string filename\" \"meshes/tri.ply\"\n");
  files.add("/scenes/parts/meshes/tri.ply", kTriangle);
  const ParseResult result =
      parsePbrtText("WorldBegin\nLightSource \"point\"\nInclude \"parts/world.pbrt\"\nWorldEnd\n",
                    "main.pbrt", "/scenes", files);
  ASSERT_TRUE(result.scene) << result.diagnostics.formatAll();
  ASSERT_EQ(result.scene->shapes.size(), 1u);
  const MeshData& mesh = result.scene->shapes[0].mesh;
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[1], glm::dvec3(2, 0, 0));
  EXPECT_EQ(mesh.positions[2], glm::dvec3(0, 3, 0));
  EXPECT_EQ(mesh.indices, (std::vector<unsigned>{0, 1, 2}));
}

TEST(InMemorySceneFiles, AFileOutsideTheSetDoesNotExistEvenOnDisk) {
  InMemorySceneFiles files;
  // /etc/hostname exists on every Debian system; the set does not hold it.
  const ParseResult result = parsePbrtText("WorldBegin\n  Include \"/etc/hostname\"\nWorldEnd\n",
                                           "main.pbrt", "/scenes", files);
  EXPECT_FALSE(result.scene);
  EXPECT_EQ(result.diagnostics.formatAll(),
            "main.pbrt:2:11: error: included file /etc/hostname does not exist\n");
}

TEST(InMemorySceneFiles, AMissingMeshIsAnErrorWhereTheSceneNamesIt) {
  InMemorySceneFiles files;
  const ParseResult result =
      parsePbrtText("WorldBegin\nShape \"plymesh\" \"string filename\" \"none.ply\"\nWorldEnd\n",
                    "main.pbrt", "/scenes", files);
  EXPECT_FALSE(result.scene);
  EXPECT_EQ(result.diagnostics.formatAll(),
            "main.pbrt:2:17: error: PLY file /scenes/none.ply does not exist\n");
}

}  // namespace
}  // namespace lenslab::render
