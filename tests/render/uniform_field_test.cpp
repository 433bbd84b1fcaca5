// Which scenes are flat fields (render/uniform_field.h): the vignetting demo is, its chart
// version and anything with a reflecting or non-emitting object in view are not.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "render/pbrt_parser.h"
#include "render/scene_builder.h"
#include "render/uniform_field.h"

namespace lenslab::render {
namespace {

std::filesystem::path scenes() { return std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes"; }

bool uniform(const std::filesystem::path& path) {
  ParseResult parsed = parsePbrtFile(path);
  EXPECT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  if (!parsed.scene) return false;
  BuildResult built = buildScene(*parsed.scene);
  EXPECT_TRUE(built.scene) << built.diagnostics.formatAll();
  return built.scene && isUniformField(*parsed.scene, *built.scene);
}

// The demo's text with `edit` applied, written beside the test's other files (the lens path made
// absolute).
std::filesystem::path editedDemo(const std::string& name, const std::string& from,
                                 const std::string& to) {
  std::ifstream in(scenes() / "vignetting.pbrt");
  std::stringstream text;
  text << in.rdbuf();
  // (The quote inserted, not prepended with "\"" + ...: GCC 12 warns falsely on that.)
  std::string lenses = (scenes() / ".." / "lenses").string();
  lenses.insert(lenses.begin(), '"');
  std::string scene = std::regex_replace(text.str(), std::regex("\"\\.\\./lenses"), lenses);
  const auto at = scene.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) scene.replace(at, from.size(), to);
  const auto path = std::filesystem::temp_directory_path() /
                    ("lenslab-uniform-" + std::to_string(::getpid()) + "-" + name + ".pbrt");
  std::ofstream(path) << scene;
  return path;
}

TEST(UniformField, TheVignettingDemoIsOne) { EXPECT_TRUE(uniform(scenes() / "vignetting.pbrt")); }

TEST(UniformField, TheChartAndTheDefaultSceneAreNot) {
  EXPECT_FALSE(uniform(scenes() / "vignetting-chart.pbrt"));
  EXPECT_FALSE(uniform(scenes() / "default.pbrt"));
}

TEST(UniformField, AnObjectInViewOrAReflectingEmitterOrAGapIsNot) {
  const auto sphere = editedDemo("sphere", "WorldEnd",
                                 "AttributeBegin\nTranslate 0 0 -3\nMaterial \"matte\"\n"
                                 "Shape \"sphere\" \"float radius\" [0.2]\nAttributeEnd\nWorldEnd");
  EXPECT_FALSE(uniform(sphere));
  const auto grey = editedDemo("grey", "\"rgb Kd\" [0 0 0]", "\"rgb Kd\" [0.5 0.5 0.5]");
  EXPECT_FALSE(uniform(grey));
  // A field 2 m wide at 10 m: the view's edges see past it.
  const auto small =
      editedDemo("small", "-100 -100 -10   100 -100 -10   100 100 -10   -100 100 -10",
                 "-1 -1 -10   1 -1 -10   1 1 -10   -1 1 -10");
  EXPECT_FALSE(uniform(small));
  for (const auto& path : {sphere, grey, small}) std::filesystem::remove(path);
}

}  // namespace
}  // namespace lenslab::render
