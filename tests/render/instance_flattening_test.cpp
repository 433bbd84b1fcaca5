// Small object instances become copies of their shapes in the top-level scene (SceneBuilder's
// instancesToFlatten); big ones stay Embree instances. Neither changes the picture, nor what is a
// light.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "render/camera_factory.h"
#include "render/image_compare.h"
#include "render/pbrt_parser.h"
#include "render/progressive_renderer.h"
#include "render/scene_builder.h"

namespace lenslab::render {
namespace {

// A strip of `triangles` triangles along x, 1 unit long and 0.3 high, in the z = 0 plane; with
// `withUv`, u runs 0..1 along it and v 0..1 across.
std::string strip(int triangles, bool withUv = false) {
  std::ostringstream points, indices, uvs;
  const int columns = triangles / 2 + 1;
  for (int c = 0; c < columns; ++c) {
    const double x = static_cast<double>(c) / (columns - 1);
    points << x << " 0 0 " << x << " 0.3 0 ";
    uvs << x << " 0 " << x << " 1 ";
  }
  for (int c = 0; c + 1 < columns; ++c) {
    const int a = 2 * c;
    indices << a << ' ' << a + 2 << ' ' << a + 1 << ' ' << a + 1 << ' ' << a + 2 << ' ' << a + 3
            << ' ';
  }
  return "Shape \"trianglemesh\" \"integer indices\" [" + indices.str() + "] \"point P\" [" +
         points.str() + "]" + (withUv ? " \"float uv\" [" + uvs.str() + "]" : std::string()) + "\n";
}

const std::string kHeader =
    "LookAt 0 1.5 4  0 0.4 0  0 1 0\n"
    "Camera \"perspective\" \"float fov\" [40]\n"
    "Film \"image\" \"integer xresolution\" [64] \"integer yresolution\" [48]\n"
    "Integrator \"path\" \"integer maxdepth\" [3]\n"
    "WorldBegin\n"
    "LightSource \"infinite\" \"rgb L\" [0.6 0.6 0.7]\n"
    "LightSource \"distant\" \"point from\" [-2 5 3] \"point to\" [0 0 0] \"rgb L\" [3 3 3]\n"
    "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
    "  \"point P\" [-5 0 -5  5 0 -5  5 0 5  -5 0 5]\n";

// The post: a cylinder, a disk on top, a small plate. `place` transforms come before it.
const std::string kPost =
    "Material \"plastic\" \"rgb Kd\" [0.7 0.2 0.1] \"rgb Ks\" [0.3 0.3 0.3]\n"
    "Rotate -90 1 0 0\n"
    "Shape \"cylinder\" \"float radius\" [0.1] \"float zmin\" [0] \"float zmax\" [0.8]\n"
    "Translate 0 0 0.8\n"
    "Shape \"disk\" \"float radius\" [0.1]\n" +
    strip(4);
const char* kPlaces[] = {"Translate -1 0 0\n", "Translate 0 0 -0.5 Rotate 30 0 1 0\n",
                         "Translate 1 0 0.3 Scale 1.2 0.8 1.2\n"};

std::string instancedScene(int bigTriangles) {
  std::string text = kHeader + "ObjectBegin \"post\"\n" + kPost + "ObjectEnd\n";
  text += "ObjectBegin \"big\"\nMaterial \"matte\" \"rgb Kd\" [0.2 0.6 0.2]\n" +
          strip(bigTriangles) + "ObjectEnd\n";
  for (const char* place : kPlaces) {
    text += std::string("AttributeBegin\n") + place + "ObjectInstance \"post\"\nAttributeEnd\n";
  }
  text += "AttributeBegin\nTranslate -0.5 0.2 1\nObjectInstance \"big\"\nAttributeEnd\n";
  return text + "WorldEnd\n";
}

std::string writtenOutScene(int bigTriangles) {
  std::string text = kHeader;
  for (const char* place : kPlaces) {
    text += std::string("AttributeBegin\n") + place + kPost + "AttributeEnd\n";
  }
  text += "AttributeBegin\nTranslate -0.5 0.2 1\nMaterial \"matte\" \"rgb Kd\" [0.2 0.6 0.2]\n" +
          strip(bigTriangles) + "AttributeEnd\n";
  return text + "WorldEnd\n";
}

struct Built {
  std::optional<SceneDescription> description;
  std::shared_ptr<const Scene> scene;
  std::string messages;
};

Built buildFlattened(const std::string& text) {
  Built out;
  ParseResult parsed = parsePbrtText(text, "test.pbrt", ".");
  out.messages = parsed.diagnostics.formatAll();
  if (!parsed.scene) return out;
  BuildResult built = buildScene(*parsed.scene);
  out.messages += built.diagnostics.formatAll();
  out.scene = built.scene;
  out.description = std::move(parsed.scene);
  return out;
}

FloatImage renderFlattened(const Built& built) {
  RenderJob job;
  Diagnostics diagnostics;
  job.camera = makeCamera(*built.description, {}, diagnostics);
  job.scene = built.scene;
  job.settings.samplesPerPixel = 16;
  job.settings.threads = 2;
  job.settings.integrator.kind = built.description->integrator.kind;
  job.settings.integrator.maxDepth = built.description->integrator.maxDepth;
  const auto snapshot = renderToCompletion(job);
  return {snapshot->width, snapshot->height, snapshot->rgb};
}

TEST(InstanceFlattening, SmallObjectsAreCopiedAndBigOnesStayInstances) {
  const Built built =
      buildFlattened(instancedScene(100));  // the big strip: 100 triangles, above 64
  ASSERT_TRUE(built.scene) << built.messages;
  EXPECT_EQ(built.scene->flattenedInstances(), 3u);
  EXPECT_EQ(built.scene->embreeInstances(), 1u);
  const Built small = buildFlattened(instancedScene(8));
  ASSERT_TRUE(small.scene) << small.messages;
  EXPECT_EQ(small.scene->flattenedInstances(), 4u);
  EXPECT_EQ(small.scene->embreeInstances(), 0u);
}

TEST(InstanceFlattening, ThePictureIsTheSceneWrittenOut) {
  const Built instanced = buildFlattened(instancedScene(100));
  const Built writtenOut = buildFlattened(writtenOutScene(100));
  ASSERT_TRUE(instanced.scene && writtenOut.scene) << instanced.messages << writtenOut.messages;
  const FloatImage a = renderFlattened(instanced), b = renderFlattened(writtenOut);
  // Same samples, same surfaces; only rounding differs (the instance transform is composed with
  // the shape's in another order, and Embree applies the big strip's in single precision).
  const ImageComparison comparison = compareImages(a, b);
  EXPECT_LT(comparison.relativeRmse, 1e-3);
  EXPECT_NEAR(comparison.bestScale, 1.0, 1e-3);
  // And the posts are in it: without them the picture differs.
  const std::string noPosts = kHeader + "WorldEnd\n";
  const Built empty = buildFlattened(noPosts);
  ASSERT_TRUE(empty.scene);
  EXPECT_GT(compareImages(renderFlattened(empty), b).relativeRmse, 0.05);
}

TEST(InstanceFlattening, AnEmitterInAFlattenedObjectIsNoLightAndSaysSo) {
  const std::string text =
      kHeader +
      "ObjectBegin \"lamp\"\nAreaLightSource \"diffuse\" \"rgb L\" [5 5 5]\n"
      "Shape \"sphere\" \"float radius\" [0.1]\nObjectEnd\n"
      "AttributeBegin\nTranslate 0 1 0\nObjectInstance \"lamp\"\nAttributeEnd\n"
      "AttributeBegin\nTranslate 1 1 0\nObjectInstance \"lamp\"\nAttributeEnd\nWorldEnd\n";
  const Built built = buildFlattened(text);
  ASSERT_TRUE(built.scene) << built.messages;
  EXPECT_EQ(built.scene->flattenedInstances(), 2u);
  EXPECT_EQ(built.scene->lights().size(), 2u);  // the sky and the sun only
  EXPECT_NE(built.messages.find("area lights inside object instances are not supported"),
            std::string::npos)
      << built.messages;
}

TEST(InstanceFlattening, AScaledInstanceFiltersTexturesAsItsWrittenOutCopy) {
  // The texture rate per world unit sets the mip level. An instance kept in Embree (100
  // triangles) gets it from its object's own space, so the instance's scale must be counted.
  struct Place {
    const char* text;
    glm::mat4 worldFromStrip;
  };
  const glm::mat4 identity(1.0f);
  const glm::mat4 moved = glm::translate(identity, glm::vec3(-0.5f, 0.2f, 1.0f));
  const glm::mat4 turned = glm::rotate(identity, glm::radians(20.0f), glm::vec3(0, 1, 0));
  const glm::mat4 stretched = glm::scale(identity, glm::vec3(3, 2, 1));
  const Place places[] = {
      {"Translate -0.5 0.2 1\n", moved},
      {"Scale 3 2 1\n", stretched},
      {"Rotate 20 0 1 0 Scale 3 2 1\n", turned * stretched},
      {"Translate -0.5 0.2 1 Scale 3 2 1\n", moved * stretched},
      {"Translate -0.5 0.2 1 Rotate 20 0 1 0\n", moved * turned},
      {"Translate -0.5 0.2 1 Rotate 20 0 1 0 Scale 3 2 1\n", moved * turned * stretched},
  };
  for (const Place& place : places) {
    SCOPED_TRACE(place.text);
    const std::string instanced = kHeader + "ObjectBegin \"big\"\n" + strip(100, true) +
                                  "ObjectEnd\nAttributeBegin\n" + place.text +
                                  "ObjectInstance \"big\"\nAttributeEnd\nWorldEnd\n";
    const std::string writtenOut =
        kHeader + "AttributeBegin\n" + place.text + strip(100, true) + "AttributeEnd\nWorldEnd\n";
    const Built a = buildFlattened(instanced), b = buildFlattened(writtenOut);
    ASSERT_TRUE(a.scene && b.scene) << a.messages << b.messages;
    ASSERT_EQ(a.scene->embreeInstances(), 1u);
    // The strip spans x 0..1, y 0..0.3 in its own space: aim inside one triangle near its
    // middle (not at an edge, where Embree's fast triangle test may let the ray through).
    const glm::vec3 origin(0.0f, 1.5f, 4.0f);
    const glm::vec3 target = glm::vec3(place.worldFromStrip * glm::vec4(0.47f, 0.1f, 0.0f, 1.0f));
    SurfaceHit hitA, hitB;
    ASSERT_TRUE(a.scene->intersect(origin, glm::normalize(target - origin), 1e30f, hitA));
    ASSERT_TRUE(b.scene->intersect(origin, glm::normalize(target - origin), 1e30f, hitB));
    EXPECT_NEAR(hitB.t, glm::length(target - origin), 1e-4f);
    EXPECT_NEAR(hitA.t, hitB.t, 1e-4f);
    ASSERT_GT(hitB.uvPerWorldUnit, 0.0f);
    EXPECT_NEAR(hitA.uvPerWorldUnit / hitB.uvPerWorldUnit, 1.0f, 1e-4f);
  }
}

}  // namespace
}  // namespace lenslab::render
