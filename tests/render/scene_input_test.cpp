// Bad scene input: degenerate transforms, impossible numbers, long and odd file names, corrupt
// PLY files and misnested blocks each give a file:line:column error or warning, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "render/pbrt_parser.h"
#include "render/scene_builder.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::writeFile;

ParseResult parse(const std::string& text) {
  return parsePbrtText(text, "test.pbrt", std::filesystem::temp_directory_path());
}

std::string messages(const ParseResult& result) { return result.diagnostics.formatAll(); }

// Expects an error (no scene) whose messages contain `expected`.
void expectError(const std::string& text, const std::string& expected) {
  const ParseResult result = parse(text);
  EXPECT_FALSE(result.scene) << text;
  EXPECT_NE(messages(result).find(expected), std::string::npos) << "scene:\n"
                                                                << text << "\nmessages:\n"
                                                                << messages(result);
}

// Expects a scene, with a warning containing `expected`.
ParseResult expectWarning(const std::string& text, const std::string& expected) {
  ParseResult result = parse(text);
  EXPECT_TRUE(result.scene) << messages(result);
  EXPECT_NE(messages(result).find(expected), std::string::npos) << "scene:\n"
                                                                << text << "\nmessages:\n"
                                                                << messages(result);
  return result;
}

TEST(SceneInput, DegenerateLookAtIsAnErrorAtTheDirective) {
  expectError("LookAt 0 0 0  0 0 0  0 1 0\nCamera \"perspective\"\n",
              "test.pbrt:1:1: error: LookAt: the eye and the target are the same point");
  expectError("WorldBegin\n  LookAt 0 0 0  0 0 5  0 0 1\n",
              "test.pbrt:2:3: error: LookAt: the up vector is parallel to the view direction");
  expectError("LookAt 0 0 0  0 0 5  0 0 0\n",
              "test.pbrt:1:1: error: LookAt: the up vector is zero");
}

TEST(SceneInput, NonFiniteTransformNumbersAreErrorsAtTheNumber) {
  expectError("Translate 1e999 0 0\n",
              "test.pbrt:1:11: error: Translate (3 numbers): '1e999' is not a finite number");
  expectError("Scale 1 -nan 1\n",
              "test.pbrt:1:9: error: Scale (3 numbers): '-nan' is not a finite");
  expectError("Rotate 1e400 0 1 0\n", "test.pbrt:1:8: error: Rotate (4 numbers)");
  expectError("Translate nan 0 0\n", "test.pbrt:1:11: error: expected a number for Translate");
  // Too large without an exponent: a 400-digit integer was read as 0 (from_chars gives no value
  // on overflow, and only exponents were taken for large), a sphere's radius 0 a silent warning.
  expectError("Translate " + std::string(400, '7') + " 0 0\n",
              "test.pbrt:1:11: error: Translate (3 numbers): '7777");
  expectError("WorldBegin\nShape \"sphere\" \"float radius\" [-" + std::string(400, '9') + "]\n",
              "test.pbrt:2:32: error: \"float radius\": '-999");
  // Underflow is still zero, as before: 1e-999 is a number, just a small one.
  expectError("Translate 1e-999 0 0\nLookAt 0 0 0  0 0 0  0 1 0\n",
              "test.pbrt:2:1: error: LookAt: the eye and the target are the same point");
}

TEST(SceneInput, SingularCameraTransformIsAnErrorAtCamera) {
  expectError("Scale 0 0 0\nCamera \"perspective\"\n",
              "test.pbrt:2:1: error: the camera transform is singular");
  expectError("Transform [1 0 0 0  2 0 0 0  0 0 1 0  0 0 0 1]\n  Camera \"perspective\"\n",
              "test.pbrt:2:3: error: the camera transform is singular");
  expectError("Scale 1e200 1e200 1e200\nCamera \"perspective\"\n",
              "test.pbrt:2:1: error: the camera transform scales beyond the range of double");
}

TEST(SceneInput, SingularObjectTransformsLeaveTheirShapeOutWithAWarning) {
  const auto result = expectWarning(
      "WorldBegin\nAttributeBegin\nScale 0 1 1\nShape \"sphere\"\n"
      "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0]\n"
      "LightSource \"point\"\nAttributeEnd\n"
      "ObjectBegin \"o\" Shape \"sphere\" ObjectEnd\n"
      "AttributeBegin Scale 1 1 0 ObjectInstance \"o\" AttributeEnd\n"
      "Shape \"disk\"\nWorldEnd\n",
      "test.pbrt:4:7: warning: the transform of shape \"sphere\" is singular");
  ASSERT_TRUE(result.scene);
  const std::string all = messages(result);
  EXPECT_NE(all.find("test.pbrt:5:7: warning: the transform of shape \"trianglemesh\" is singular"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("test.pbrt:6:13: warning: the transform of light \"point\" is singular"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("test.pbrt:9:28: warning: the transform of this instance of \"o\""),
            std::string::npos)
      << all;
  // Only the disk after the instance is left, and it builds: nothing NaN reaches Embree.
  ASSERT_EQ(result.scene->shapes.size(), 1u);
  EXPECT_EQ(result.scene->shapes[0].type, "disk");
  EXPECT_TRUE(result.scene->instances.empty());
  EXPECT_TRUE(result.scene->lights.empty());
  EXPECT_TRUE(buildScene(*result.scene).scene);
}

TEST(SceneInput, LongFileNamesAreErrorsNotExceptions) {
  const std::string longName(300, 'x');
  expectError("WorldBegin\nInclude \"" + longName + ".pbrt\"\n",
              "test.pbrt:2:9: error: cannot open included file");
  expectError("WorldBegin\nTexture \"t\" \"color\" \"imagemap\" \"string filename\" \"" + longName +
                  ".png\"\n",
              "test.pbrt:2:32: error: cannot open texture file");
  expectError("WorldBegin\nShape \"plymesh\" \"string filename\" \"" + longName + ".ply\"\n",
              "test.pbrt:2:17: error: cannot open PLY file");
  expectError("WorldBegin\nLightSource \"infinite\" \"string mapname\" \"" + longName + ".exr\"\n",
              "test.pbrt:2:24: error: cannot open environment map");
  expectError("Camera \"realistic\" \"string lensfile\" \"" + longName + ".dat\"\n",
              "test.pbrt:1:20: error: cannot open lens file");
  const ParseResult top = parsePbrtFile(std::filesystem::temp_directory_path() / longName);
  EXPECT_FALSE(top.scene);
  EXPECT_NE(messages(top).find("cannot open scene file"), std::string::npos) << messages(top);
}

TEST(SceneInput, IncludingADirectoryIsAnError) {
  const auto directory = lenslab::testing::makeTestDirectory("include-directory");
  std::filesystem::create_directories(directory / "sub");
  writeFile(directory / "main.pbrt", "WorldBegin\nInclude \"sub\"\nWorldEnd\n");
  const ParseResult result = parsePbrtFile(directory / "main.pbrt");
  EXPECT_FALSE(result.scene);
  EXPECT_NE(messages(result).find("main.pbrt:2:9: error: included file"), std::string::npos)
      << messages(result);
  EXPECT_NE(messages(result).find("is a directory, not a file"), std::string::npos)
      << messages(result);
}

TEST(SceneInput, MeshIndicesMustBeWholeNumbersInRange) {
  const std::string mesh = "WorldBegin\nShape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] ";
  // 2^32 + 1 used to wrap around to 1 and render.
  expectError(mesh + "\"integer indices\" [0 4294967297 2]\n",
              "test.pbrt:2:73: error: \"integer indices\": '4294967297' is not a whole number");
  expectError(mesh + "\"integer indices\" [0 1 2.7]\n",
              "test.pbrt:2:75: error: \"integer indices\": '2.7' is not a whole number");
  expectError(mesh + "\"integer indices\" [0 -1 2]\n",
              "test.pbrt:2:52: error: trianglemesh index -1 at position 1 is not a vertex index");
  expectError(mesh + "\"float indices\" [0 1.5 2]\n",
              "error: trianglemesh index 1.5 at position 1 is not a vertex index");
  expectError(mesh + "\"float indices\" [0 4294967297 2]\n",
              "error: trianglemesh index 4.29497e+09 at position 1 is not a vertex index");
}

TEST(SceneInput, IntegerParametersAreRangeChecked) {
  expectError("Film \"image\" \"integer xresolution\" [0]\n",
              "test.pbrt:1:14: error: \"integer xresolution\" is 0, outside 1 to 16384");
  expectError("Film \"image\" \"integer yresolution\" [100000]\n",
              "\"integer yresolution\" is 100000, outside 1 to 16384");
  expectError("Film \"image\" \"float xresolution\" [12.5]\n",
              "test.pbrt:1:14: error: \"float xresolution\" must be a whole number, found 12.5");
  expectError("Sampler \"halton\" \"integer pixelsamples\" [0]\n",
              "test.pbrt:1:18: error: \"integer pixelsamples\" is 0, outside 1 to 1048576");
  expectError("Sampler \"halton\" \"integer pixelsamples\" [2.5]\n",
              "test.pbrt:1:42: error: \"integer pixelsamples\": '2.5' is not a whole number");
  expectError("Integrator \"path\" \"integer maxdepth\" [-1]\n",
              "test.pbrt:1:19: error: \"integer maxdepth\" is -1, outside 0 to 10000");
  expectError("WorldBegin\nAreaLightSource \"diffuse\" \"integer nsamples\" [0]\n",
              "test.pbrt:2:27: error: \"integer nsamples\" is 0, outside 1 to 4096");
  expectError("Film \"image\" \"integer xresolution\" [1e10]\n",
              "\"integer xresolution\": '1e10' is not a whole number in the range of a 32-bit");
}

TEST(SceneInput, OtherParameterValuesAreChecked) {
  expectError("WorldBegin\nShape \"sphere\" \"floot radius\" 1\n",
              "test.pbrt:2:16: error: unknown parameter type \"floot\" in \"floot radius\"");
  expectError("WorldBegin\nShape \"sphere\" \"float radius\" [1e999]\n",
              "test.pbrt:2:32: error: \"float radius\": '1e999' is not a finite number");
  expectError("WorldBegin\nMaterial \"matte\" \"rgb Kd\" [.5 .5]\n",
              "test.pbrt:2:18: error: \"rgb Kd\" needs r g b (three numbers), found 2");
  expectError("WorldBegin\nLightSource \"point\" \"bool twosided\" \"yes\"\n",
              "test.pbrt:2:37: error: \"bool twosided\": expected \"true\" or \"false\"");
  expectError("Camera \"perspective\" \"float fov\" [0]\n",
              "test.pbrt:1:22: error: \"float fov\" is 0; it must be positive and at most 179");
}

// pbrt's scene-wide options belong before WorldBegin; media, colour spaces and options may also
// come inside it (pbrt-v3 and v4 file format documentation).
TEST(SceneInput, OnlyTheSceneWideOptionsMustComeBeforeWorldBegin) {
  for (const char* directive :
       {"Camera \"perspective\"", "Film \"image\"", "Sampler \"halton\"", "PixelFilter \"box\"",
        "Integrator \"path\"", "SurfaceIntegrator \"path\"", "VolumeIntegrator \"single\"",
        "Accelerator \"bvh\"", "Renderer \"sampler\""}) {
    const std::string name =
        std::string(directive).substr(0, std::strchr(directive, ' ') - directive);
    expectError(std::string("WorldBegin\n") + directive + "\n",
                "test.pbrt:2:1: error: " + name +
                    " must come before WorldBegin (the world block began at test.pbrt:1:1)");
    const ParseResult before = parse(std::string(directive) + "\nWorldBegin\nWorldEnd\n");
    EXPECT_TRUE(before.scene) << directive << "\n" << messages(before);
  }
  for (const char* directive :
       {"MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"", "ColorSpace \"aces2065-1\"",
        "Option \"seed\"", "MediumInterface \"fog\" \"\"", "TransformTimes 0 1"}) {
    const ParseResult inside = parse(std::string("WorldBegin\n") + directive + "\nWorldEnd\n");
    EXPECT_TRUE(inside.scene) << directive << "\n" << messages(inside);
  }
}

TEST(SceneInput, StructureErrorsAreReported) {
  expectError(
      "WorldBegin\nObjectBegin \"a\" ObjectEnd\nObjectBegin \"b\"\n  ObjectInstance \"a\"\n",
      "test.pbrt:4:3: error: ObjectInstance inside ObjectBegin \"b\"");
  expectError("WorldBegin\nCamera \"perspective\"\n",
              "test.pbrt:2:1: error: Camera must come before WorldBegin (the world block began at "
              "test.pbrt:1:1)");
  expectError("Film \"image\"\nWorldBegin\nSampler \"halton\"\n",
              "test.pbrt:3:1: error: Sampler must come before WorldBegin");
  expectError("WorldBegin\nAttributeBegin\nTransformEnd\n",
              "test.pbrt:3:1: error: TransformEnd closes the AttributeBegin at test.pbrt:2:1 "
              "(mismatched nesting)");
  expectError("WorldBegin\nTransformBegin\n AttributeEnd\n",
              "test.pbrt:3:2: error: AttributeEnd closes the TransformBegin at test.pbrt:2:1");
  expectError("WorldBegin\nObjectBegin \"o\"\nAttributeEnd\n",
              "test.pbrt:3:1: error: AttributeEnd closes the ObjectBegin at test.pbrt:2:1");
  expectError("WorldBegin\nAttributeBegin\nObjectBegin \"o\"\nAttributeEnd\n",
              "test.pbrt:4:1: error: AttributeEnd closes the ObjectBegin at test.pbrt:3:1");
  expectError("WorldBegin\nTransformEnd\n",
              "test.pbrt:2:1: error: TransformEnd without a matching TransformBegin");
  expectError("WorldBegin\nObjectEnd\n", "test.pbrt:2:1: error: ObjectEnd without ObjectBegin");
  expectError("WorldEnd\n", "test.pbrt:1:1: error: WorldEnd without WorldBegin");
  expectError("WorldBegin\nWorldEnd\nWorldEnd\n", "test.pbrt:3:1: error: a second WorldEnd");
  expectError("WorldBegin\nWorldBegin\n", "test.pbrt:2:1: error: a second WorldBegin");
}

TEST(SceneInput, UnfinishedFilesWarnOrFail) {
  // A file that ends inside the world block was cut short: an error (issue 24).
  expectError("WorldBegin\nShape \"sphere\"\n",
              "test.pbrt:3:1: error: missing WorldEnd at the end of the file: it ends inside the "
              "world block (was it cut short?)");
  // Cut short inside blocks: the blocks are named too.
  expectError("WorldBegin\nAttributeBegin\n  AttributeBegin\nShape \"sphere\"\n",
              "test.pbrt:5:1: warning: end of file with 2 unclosed block(s); the innermost is "
              "the AttributeBegin at test.pbrt:3:3");
  expectWarning("WorldBegin\nAttributeBegin\nWorldEnd\n",
                "test.pbrt:3:1: warning: WorldEnd with 1 unclosed block(s); the innermost is the "
                "AttributeBegin at test.pbrt:2:1");
  // A complete file has no such warnings.
  const ParseResult complete = parse("WorldBegin\nAttributeBegin\nAttributeEnd\nWorldEnd\n");
  ASSERT_TRUE(complete.scene);
  EXPECT_TRUE(complete.diagnostics.all().empty()) << messages(complete);
}

// ---- PLY ----

class PlyInput : public ::testing::Test {
 protected:
  // Parses a scene whose only shape is `ply`, written as mesh.ply.
  ParseResult parsePly(const std::string& ply) {
    writeFile(directory / "mesh.ply", ply);
    writeFile(directory / "scene.pbrt",
              "WorldBegin\nShape \"plymesh\" \"string filename\" \"mesh.ply\"\nWorldEnd\n");
    return parsePbrtFile(directory / "scene.pbrt");
  }
  void expectPlyError(const std::string& ply, const std::string& expected) {
    const ParseResult result = parsePly(ply);
    EXPECT_FALSE(result.scene);
    EXPECT_NE(messages(result).find(expected), std::string::npos) << messages(result);
  }
  std::filesystem::path directory = lenslab::testing::makeTestDirectory("ply-input");
  const std::string asciiHeader =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
  const std::string binaryHeader =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list int int vertex_indices\nend_header\n";
  std::string binaryVertices() const {
    const float vertices[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(vertices), sizeof(vertices));
  }
  static std::string binaryInt(std::int32_t value) {
    return std::string(reinterpret_cast<const char*>(&value), sizeof(value));
  }
};

// Items without properties take no bytes: a huge count of them is an error at the element, not
// a billion-step loop (tests/fuzz/regressions/ply/element-without-properties.ply).
TEST_F(PlyInput, AnElementWithoutPropertiesIsAnError) {
  expectPlyError("ply\nformat ascii 1.0\nelement vertex 1000000000\nend_header\n",
                 "mesh.ply:3:1: error: element \"vertex\" declares 1000000000 items but no "
                 "properties");
}

// Faces that come before the vertices (or a file whose vertex element is misspelt) are checked
// once the whole file is read (tests/fuzz/regressions/ply/misspelt-vertex-element.ply).
TEST_F(PlyInput, FaceIndicesWithoutTheirVerticesAreAnError) {
  expectPlyError(
      "ply\nformat ascii 1.0\nelement vertexes 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      "mesh.ply: vertex index 0 is out of range (0 vertices)");
}

TEST_F(PlyInput, NegativeFaceCountIsAnErrorAtItsPlace) {
  expectPlyError(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n",
                 "mesh.ply:13:1: error: face 0: the vertex_indices list has a count of -1");
  expectPlyError(binaryHeader + binaryVertices() + binaryInt(-1),
                 "scene.pbrt:2:17: error: " + (directory / "mesh.ply").string() +
                     ": face 0: the vertex_indices list has a count of -1 (byte ");
}

TEST_F(PlyInput, HugeFaceCountIsAnErrorNotAnAllocation) {
  expectPlyError(binaryHeader + binaryVertices() + binaryInt(2000000000) + binaryInt(0),
                 "face 0: the vertex_indices list has a count of 2000000000, more than the rest "
                 "of the file holds");
  expectPlyError(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n",
                 "mesh.ply:13:1: error: face 0: the vertex_indices list has a count of 2000000000");
  expectPlyError(
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
      "end_header\n" +
          binaryVertices(),
      "mesh.ply:3:1: error: element \"vertex\" declares 4000000000 items, more than the 36 "
      "bytes of data after the header can hold");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex -3\nend_header\n",
                 "mesh.ply:3:1: error: element \"vertex\" has an invalid count '-3'");
}

TEST_F(PlyInput, NanVertexSaysNotFinite) {
  expectPlyError(asciiHeader + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",
                 "mesh.ply:11:3: error: vertex 1 is not finite (y is nan)");
  const float nan = std::nanf("");
  std::string binary = binaryVertices();
  std::memcpy(binary.data() + 8 * sizeof(float), &nan, sizeof(float));
  expectPlyError(binaryHeader + binary + binaryInt(3) + binaryInt(0) + binaryInt(1) + binaryInt(2),
                 ": vertex 2 is not finite (z is nan) (byte ");
  expectPlyError(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
                 "mesh.ply:14:1: error: the data ends early");
  expectPlyError(asciiHeader + "0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n",
                 "mesh.ply:11:5: error: expected a number, found 'x'");
  // A file may end without a newline.
  const ParseResult unterminated = parsePly(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2");
  EXPECT_TRUE(unterminated.scene) << messages(unterminated);
}

TEST_F(PlyInput, BadIndicesAreReportedAsWritten) {
  expectPlyError(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
                 "mesh.ply:13:5: error: face 0: vertex index -1 is not a valid index");
  expectPlyError(
      binaryHeader + binaryVertices() + binaryInt(3) + binaryInt(0) + binaryInt(-1) + binaryInt(2),
      ": face 0: vertex index -1 is not a valid index (byte 211)");
  expectPlyError(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
                 "mesh.ply:13:7: error: face 0: vertex index 3 is out of range (3 vertices)");
  // A good file still reads.
  const ParseResult good = parsePly(asciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ASSERT_TRUE(good.scene) << messages(good);
  EXPECT_EQ(good.scene->shapes[0].mesh.indices.size(), 3u);
}

}  // namespace
}  // namespace lenslab::render
