#include "render/pbrt_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::writeFile;

ParseResult parsePbrt(const std::string& text) {
  return parsePbrtText(text, "test.pbrt", std::filesystem::temp_directory_path());
}

std::string allMessages(const ParseResult& result) { return result.diagnostics.formatAll(); }

TEST(PbrtParser, ReadsCameraFilmSamplerIntegratorAndShapes) {
  const auto result = parsePbrt(R"(
    LookAt 0 0 5  0 0 0  0 1 0
    Camera "perspective" "float fov" [45]
    Film "image" "integer xresolution" [320] "integer yresolution" 200 "string filename" "a.exr"
    Sampler "halton" "integer pixelsamples" [8]
    Integrator "path" "integer maxdepth" [3]
    WorldBegin
    AttributeBegin
      Material "plastic" "rgb Kd" [.5 .1 .1]
      Translate 1 2 3
      Shape "sphere" "float radius" 2
    AttributeEnd
    Shape "trianglemesh" "point P" [0 0 0 1 0 0 0 1 0] "integer indices" [0 1 2]
    WorldEnd)");
  ASSERT_TRUE(result.scene) << allMessages(result);
  const SceneDescription& scene = *result.scene;
  EXPECT_EQ(scene.film.xResolution, 320);
  EXPECT_EQ(scene.film.yResolution, 200);
  EXPECT_EQ(scene.film.filename, "a.exr");
  EXPECT_EQ(scene.pixelSamples, 8);
  EXPECT_EQ(scene.integrator.kind, IntegratorKind::Path);
  EXPECT_EQ(scene.integrator.maxDepth, 3);
  ASSERT_EQ(scene.shapes.size(), 2u);
  EXPECT_EQ(scene.shapes[0].type, "sphere");
  // The sphere's transform is the attribute's Translate; the mesh's is back to identity.
  EXPECT_DOUBLE_EQ(scene.shapes[0].worldFromObject[3][1], 2.0);
  EXPECT_DOUBLE_EQ(scene.shapes[1].worldFromObject[3][1], 0.0);
  EXPECT_EQ(scene.materials[static_cast<std::size_t>(scene.shapes[0].materialIndex)].type,
            "plastic");
  // LookAt from +z toward the origin: the world origin is 5 units ahead on camera +z.
  const glm::dvec4 origin = scene.camera.cameraFromWorld * glm::dvec4(0, 0, 0, 1);
  EXPECT_NEAR(origin.z, 5.0, 1e-12);
  EXPECT_NEAR(origin.x, 0.0, 1e-12);
}

TEST(PbrtParser, TransformTakesPbrtsColumnOrder) {
  const auto result = parsePbrt(R"(Transform [1 0 0 0  0 1 0 0  0 0 1 0  7 8 9 1]
    Camera "perspective" WorldBegin WorldEnd)");
  ASSERT_TRUE(result.scene) << allMessages(result);
  EXPECT_DOUBLE_EQ(result.scene->camera.cameraFromWorld[3][0], 7.0);
  EXPECT_DOUBLE_EQ(result.scene->camera.cameraFromWorld[3][2], 9.0);
}

TEST(PbrtParser, ObjectInstancesKeepTheirTransforms) {
  const auto result = parsePbrt(R"(WorldBegin
    ObjectBegin "thing" Shape "cone" "float height" 0.15 "float radius" 0.05 ObjectEnd
    Translate 1 0 0 ObjectInstance "thing"
    Translate 1 0 0 ObjectInstance "thing"
    WorldEnd)");
  ASSERT_TRUE(result.scene) << allMessages(result);
  ASSERT_EQ(result.scene->objects.size(), 1u);
  EXPECT_EQ(result.scene->objects[0].shapes.size(), 1u);
  ASSERT_EQ(result.scene->instances.size(), 2u);
  EXPECT_DOUBLE_EQ(result.scene->instances[1].worldFromInstance[3][0], 2.0);
  EXPECT_TRUE(result.scene->shapes.empty());
}

TEST(PbrtParser, PbrtV2FormsDefaultToDirectLighting) {
  const auto result = parsePbrt(R"(WorldBegin
    AttributeBegin AreaLightSource "area" "color L" [4 4 4] "integer nsamples" [4]
    Shape "disk" "float radius" [8] AttributeEnd WorldEnd)");
  ASSERT_TRUE(result.scene) << allMessages(result);
  EXPECT_EQ(result.scene->integrator.kind, IntegratorKind::DirectLighting);
  ASSERT_TRUE(result.scene->shapes[0].areaLight);
  EXPECT_EQ(result.scene->shapes[0].areaLight->samples, 4);
  EXPECT_DOUBLE_EQ(result.scene->shapes[0].areaLight->radiance.x, 4.0);
}

TEST(PbrtParser, UnknownDirectiveIsAnErrorWithLineAndColumn) {
  const auto result = parsePbrt("WorldBegin\n  Frobnicate 1 2\n");
  EXPECT_FALSE(result.scene);
  EXPECT_NE(allMessages(result).find("test.pbrt:2:3: error: unknown directive 'Frobnicate'"),
            std::string::npos)
      << allMessages(result);
}

TEST(PbrtParser, SyntaxErrorsPointAtTheToken) {
  const auto unterminated = parsePbrt("WorldBegin\nShape \"sphere \n");
  EXPECT_FALSE(unterminated.scene);
  EXPECT_NE(allMessages(unterminated).find("test.pbrt:2:7: error: unterminated string"),
            std::string::npos)
      << allMessages(unterminated);

  const auto badNumber = parsePbrt("Translate 1 x 3\n");
  EXPECT_FALSE(badNumber.scene);
  EXPECT_NE(allMessages(badNumber).find("test.pbrt:1:13: error: expected a number"),
            std::string::npos)
      << allMessages(badNumber);

  const auto unbalanced = parsePbrt("WorldBegin AttributeEnd");
  EXPECT_FALSE(unbalanced.scene);
  EXPECT_NE(allMessages(unbalanced).find("1:12: error: AttributeEnd without"), std::string::npos);
}

TEST(PbrtParser, MissingFilesAreErrorsAtTheirNames) {
  const auto include = parsePbrt("WorldBegin\nInclude \"no-such-file.pbrt\"\n");
  EXPECT_FALSE(include.scene);
  EXPECT_NE(allMessages(include).find("test.pbrt:2:9: error: included file"), std::string::npos)
      << allMessages(include);

  const auto texture = parsePbrt(
      "WorldBegin\nTexture \"t\" \"color\" \"imagemap\" \"string filename\" \"missing.exr\"\n");
  EXPECT_FALSE(texture.scene);
  EXPECT_NE(allMessages(texture).find("test.pbrt:2:32: error: texture file"), std::string::npos)
      << allMessages(texture);

  const auto lens =
      parsePbrt("Camera \"realistic\" \"string lensfile\" \"missing.dat\"\nWorldBegin\n");
  EXPECT_FALSE(lens.scene);
  EXPECT_NE(allMessages(lens).find("test.pbrt:1:20: error: lens file"), std::string::npos)
      << allMessages(lens);
}

TEST(PbrtParser, DegenerateMeshesAreReported) {
  const auto nan = parsePbrt(
      "WorldBegin\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1e999 0] \"integer indices\" "
      "[0 1 2]\n");
  EXPECT_FALSE(nan.scene);
  // Caught where it is written: non-finite numbers are errors in any parameter.
  EXPECT_NE(allMessages(nan).find("test.pbrt:2:47: error: \"point P\": '1e999' is not a finite "
                                  "number"),
            std::string::npos)
      << allMessages(nan);

  const auto range = parsePbrt(
      "WorldBegin\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" "
      "[0 1 3]\n");
  EXPECT_FALSE(range.scene);
  EXPECT_NE(allMessages(range).find("error: mesh index 3 at position 2 is out of range"),
            std::string::npos)
      << allMessages(range);

  const auto flat = parsePbrt(
      "WorldBegin\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 2 0 0 0 1 0] "
      "\"integer indices\" [0 1 2 0 1 3]\nWorldEnd\n");
  ASSERT_TRUE(flat.scene) << allMessages(flat);
  EXPECT_NE(allMessages(flat).find("test.pbrt:2:7: warning: 1 zero-area triangle(s)"),
            std::string::npos)
      << allMessages(flat);
  EXPECT_EQ(flat.scene->shapes[0].mesh.indices.size(), 3u);
}

TEST(PbrtParser, UnsupportedThingsWarnAndSaySubstitute) {
  const auto result = parsePbrt(R"(PixelFilter "gaussian"
    Camera "orthographic"
    WorldBegin Material "kdsubsurface" Shape "curve" WorldEnd)");
  ASSERT_TRUE(result.scene) << allMessages(result);
  const std::string messages = allMessages(result);
  EXPECT_NE(messages.find("1:13: warning: pixel filter \"gaussian\" is not supported; a box "
                          "filter is used"),
            std::string::npos)
      << messages;
  EXPECT_NE(messages.find("a perspective camera is used"), std::string::npos);
  EXPECT_NE(messages.find("matte is used"), std::string::npos);
  EXPECT_NE(messages.find("shape \"curve\" is not supported; it is left out"), std::string::npos);
}

TEST(PbrtParser, IncludeResolvesRelativeToTheIncludingFile) {
  const auto directory = lenslab::testing::makeTestDirectory("include");
  writeFile(directory / "main.pbrt", "WorldBegin\nInclude \"sub/world.pbrt\"\nWorldEnd\n");
  writeFile(directory / "sub" / "world.pbrt", "Include \"more.pbrt\"\n");
  writeFile(directory / "sub" / "more.pbrt", "Shape \"sphere\"\nBogus\n");
  const auto result = parsePbrtFile(directory / "main.pbrt");
  EXPECT_FALSE(result.scene);
  EXPECT_NE(allMessages(result).find("more.pbrt:2:1: error: unknown directive 'Bogus'"),
            std::string::npos)
      << allMessages(result);
}

TEST(PbrtParser, ReadsAsciiAndBinaryPly) {
  const auto directory = lenslab::testing::makeTestDirectory("ply");
  writeFile(directory / "ascii.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float vertices[9] = {0, 0, 0, 2, 0, 0, 0, 2, 0};
  binary.append(reinterpret_cast<const char*>(vertices), sizeof(vertices));
  binary.push_back(3);
  const int indices[3] = {0, 1, 2};
  binary.append(reinterpret_cast<const char*>(indices), sizeof(indices));
  writeFile(directory / "binary.ply", binary);
  writeFile(directory / "scene.pbrt",
            "WorldBegin\nShape \"plymesh\" \"string filename\" \"ascii.ply\"\n"
            "Shape \"plymesh\" \"string filename\" \"binary.ply\"\nWorldEnd\n");
  const auto result = parsePbrtFile(directory / "scene.pbrt");
  ASSERT_TRUE(result.scene) << allMessages(result);
  ASSERT_EQ(result.scene->shapes.size(), 2u);
  EXPECT_EQ(result.scene->shapes[0].mesh.indices.size(), 6u);  // the quad, split
  EXPECT_EQ(result.scene->shapes[1].mesh.positions.size(), 3u);
  EXPECT_DOUBLE_EQ(result.scene->shapes[1].mesh.positions[1].x, 2.0);
}

TEST(PbrtParser, ReadsTheCourseAndBenchmarkScenes) {
  const auto shared = render::testing::sharedDirectory();
  if (!std::filesystem::exists(shared)) GTEST_SKIP() << shared << " is absent";
  for (const char* name : {"dgauss", "fisheye", "telephoto", "wide"}) {
    const auto result = parsePbrtFile(shared / "reference" / "scenes" /
                                      (std::string("dof-dragons.") + name + ".pbrt"));
    ASSERT_TRUE(result.scene) << allMessages(result);
    EXPECT_EQ(result.scene->camera.type, "realistic");
    EXPECT_TRUE(result.scene->camera.courseParameters);
    EXPECT_EQ(result.scene->instances.size(), 11u);
    EXPECT_EQ(result.scene->integrator.kind, IntegratorKind::DirectLighting);
  }
  for (const char* name : {"bench-dgauss.pbrt", "bench-perspective.pbrt"}) {
    const auto result = parsePbrtFile(shared / "bench" / name);
    ASSERT_TRUE(result.scene) << allMessages(result);
    EXPECT_EQ(result.scene->integrator.kind, IntegratorKind::Path);
    EXPECT_EQ(result.scene->shapes.size(), 6u);
  }
}

}  // namespace
}  // namespace lenslab::render
