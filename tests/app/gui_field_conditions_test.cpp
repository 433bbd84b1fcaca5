// What the analysis panels' figures are for (issue 38): each panel states its object and film
// distance, and on the fisheye, whose image circle ends inside a full frame, it gives the
// cross-section's warning that the fields spread over the image circle. In the real viewer, read
// back from dump-ui.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_process.h"

namespace lenslab {
namespace {

nlohmann::json dumped(const std::filesystem::path& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file)["state"];
}

TEST(FieldConditions, EachPanelSaysItsObjectFilmDistanceAndTheImageCircle) {
  const auto scratch = testing::makeTestDirectory("field-conditions");
  const std::string lenses = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
  std::ofstream script(scratch / "commands.script");
  const char* panels[] = {"spot",   "ray-fan",    "mtf",         "colour",
                          "seidel", "distortion", "field-curves"};
  // Each panel shown and dumped in turn, with no wait between: a capture waits until the panel
  // shown has drawn its worker's current figures (analysis/drawn_figures.h), and the line it
  // records is drawn with them.
  for (const char* lens : {"dgauss-50mm", "fisheye-10mm"}) {
    script << "load-lens " << lenses << lens << ".dat\n";
    for (const char* panel : panels)
      script << "show-panel " << panel << "\ndump-ui " << lens << "-" << panel << ".json\n";
  }
  script << "quit\n";
  script.close();
  const auto run = testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                           "' --size 1600x900 --script commands.script",
                                       scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;

  // The double-Gauss, focused at the scene's 3.6 m: every panel says so, and its film distance
  // (the lens table's, to the digits millimetresText keeps); its film is covered: no warning.
  const nlohmann::json dgauss = dumped(scratch / "dgauss-50mm-spot.json");
  const std::string inFocus = dgauss["in_focus_text"];
  ASSERT_EQ(inFocus.rfind("3.600 m", 0), 0u) << inFocus;
  char film[32];
  // Its first digits, truncated: millimetresText writes up to six.
  std::snprintf(film, sizeof film, "%.2f",
                std::floor(dgauss["film_distance_mm"].get<double>() * 100.0) / 100.0);
  for (const char* panel : panels) {
    const nlohmann::json shown = dumped(scratch / ("dgauss-50mm-" + std::string(panel) + ".json"));
    ASSERT_TRUE(shown["analysis_conditions"].contains(panel)) << panel;
    const std::string text = shown["analysis_conditions"][panel];
    EXPECT_NE(text.find("object at 3.600 m from the film"), std::string::npos) << text;
    EXPECT_NE(text.find(std::string("film distance ") + film), std::string::npos)
        << text << " (film " << film << ")";
    EXPECT_EQ(text.find("beyond"), std::string::npos) << text;
  }
  // The fisheye on a full frame: each panel warns as the cross-section does.
  for (const char* panel : panels) {
    const nlohmann::json shown = dumped(scratch / ("fisheye-10mm-" + std::string(panel) + ".json"));
    const std::string text = shown["analysis_conditions"][panel];
    EXPECT_NE(text.find("the film corner (21.6 mm) is beyond the lens's coverage: fields spread "
                        "over its image circle"),
              std::string::npos)
        << panel << ": " << text;
  }
}

}  // namespace
}  // namespace lenslab
