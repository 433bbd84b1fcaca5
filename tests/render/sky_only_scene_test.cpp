// A scene of nothing but a sky (an infinite light) is a picture, as in pbrt: every camera ray
// escapes to the light, so through a pinhole each pixel is the sky's radiance. A scene through
// which no light can reach the camera (no shapes and no sky) stays an error.

#include <gtest/gtest.h>

#include <numeric>
#include <string>

#include "render/pbrt_parser.h"
#include "render/progressive_renderer.h"
#include "render/scene_content.h"
#include "render_support.h"

namespace lenslab::render {
namespace {

constexpr const char* kCamera =
    "LookAt 0 0 0  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n"
    "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [12]\n";

TEST(SkyOnlyScene, RendersTheSkysConstantRadiance) {
  const float L[3] = {0.25f, 0.5f, 1.5f};
  const std::string text = std::string(kCamera) +
                           "WorldBegin\nLightSource \"infinite\" \"rgb L\" [" +
                           std::to_string(L[0]) + " " + std::to_string(L[1]) + " " +
                           std::to_string(L[2]) + "]\nWorldEnd\n";
  const ParseResult parsed = parsePbrtText(text, "sky.pbrt", ".");
  ASSERT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  Diagnostics content;
  reportEmptyScene(*parsed.scene, content);
  EXPECT_FALSE(content.hasErrors()) << content.formatAll();

  RenderJob job = testing::jobFromParsed(parsed, 4);
  ASSERT_TRUE(job.camera && job.scene);
  job.camera->prepare();
  const auto snapshot = renderToCompletion(job);
  ASSERT_TRUE(snapshot);
  ASSERT_EQ(snapshot->width * snapshot->height * 3, static_cast<int>(snapshot->rgb.size()));
  // A constant sky seen through a pinhole has no noise to speak of: every sample sees L.
  for (std::size_t i = 0; i < snapshot->rgb.size(); ++i)
    ASSERT_NEAR(snapshot->rgb[i], L[i % 3], 1e-3 * L[i % 3]) << "value " << i;
}

TEST(SkyOnlyScene, NoShapesAndNoSkyIsStillAnError) {
  const std::string text =
      std::string(kCamera) + "WorldBegin\nLightSource \"point\" \"rgb I\" [5 5 5]\nWorldEnd\n";
  const ParseResult parsed = parsePbrtText(text, "dark.pbrt", ".");
  ASSERT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  Diagnostics content;
  reportEmptyScene(*parsed.scene, content);
  EXPECT_TRUE(content.hasErrors());
  EXPECT_NE(content.formatAll().find("no shapes and no infinite light"), std::string::npos)
      << content.formatAll();
}

}  // namespace
}  // namespace lenslab::render
