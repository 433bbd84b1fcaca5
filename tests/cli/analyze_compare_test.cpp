// `lenslab analyze A --compare B --json`: both lenses' results in one file, each exactly what an
// independent run of `analyze` on that lens alone gives, and a reference that cannot be analysed
// (unreadable, or forming no image) said so by name.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/analyze_test_fixture.h"
#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class AnalyzeCompare : public AnalyzeTest {
 protected:
  AnalyzeCompare() : AnalyzeTest("analyze-compare") {}
};

TEST_F(AnalyzeCompare, HoldsBothLensesResultsAsTheirOwnRunsGiveThem) {
  const std::string a = lensPath("dgauss-50mm.dat"), b = lensPath("cooke-triplet-100mm.dat");
  const std::string options = " --fields 0,0.7,1 --film-diagonal 30";
  const nlohmann::json both = analyzeJson(a + " --compare " + b + options);
  ASSERT_TRUE(both.is_object());
  // Two members and nothing else: the lens and the reference.
  ASSERT_EQ(both.size(), 2u) << both.dump().substr(0, 400);
  ASSERT_TRUE(both.contains("lens"));
  ASSERT_TRUE(both.contains("reference"));
  // Each as `analyze` gives it for that lens alone, in a run of its own.
  const nlohmann::json aloneA = analyzeJson(a + options);
  const nlohmann::json aloneB = analyzeJson(b + options);
  EXPECT_EQ(both["lens"], aloneA);
  EXPECT_EQ(both["reference"], aloneB);
  EXPECT_EQ(both["lens"]["lens"], a);
  EXPECT_EQ(both["reference"]["lens"], b);
  // Some of the numbers, by name, so that a failure says which: the film distances each lens was
  // focused at, its spots and its MTF (two different lenses: different numbers).
  EXPECT_DOUBLE_EQ(both["lens"]["film_distance_mm"].get<double>(),
                   aloneA["film_distance_mm"].get<double>());
  EXPECT_DOUBLE_EQ(both["reference"]["film_distance_mm"].get<double>(),
                   aloneB["film_distance_mm"].get<double>());
  EXPECT_GT(std::abs(both["reference"]["film_distance_mm"].get<double>() -
                     both["lens"]["film_distance_mm"].get<double>()),
            10.0);
  ASSERT_TRUE(both["reference"].contains("spot")) << both["reference"].dump().substr(0, 300);
  EXPECT_EQ(both["reference"]["spot"], aloneB["spot"]);
  EXPECT_NE(both["reference"]["spot"], both["lens"]["spot"]);
  EXPECT_EQ(both["reference"]["mtf"], aloneB["mtf"]);
}

TEST_F(AnalyzeCompare, TextHasTheReferenceAfterTheLens) {
  const std::string a = lensPath("dgauss-50mm.dat"), b = lensPath("telephoto-250mm.dat");
  const auto run = testing::runProcess(
      lenslab("analyze " + a + " --compare " + b + " --only distortion"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const auto at = run.out.find("\n=== reference ===\n");
  ASSERT_NE(at, std::string::npos) << run.out;
  EXPECT_EQ(run.out.find(b), at + 19) << run.out;  // B's header starts with its path
  EXPECT_LT(run.out.find(a), at);
}

TEST_F(AnalyzeCompare, AReferenceThatFormsNoImageSaysSo) {
  // A diverging singlet forms no real image: it cannot be focused at infinity, and the command
  // says which lens and why, as `analyze` of it alone does.
  const std::string diverging = writeFile("diverging.dat", "-40 3 1.5 20\n40 2 1 20\n0 30 0 12\n");
  const auto refused = testing::runProcess(
      lenslab("analyze --json " + lensPath("dgauss-50mm.dat") + " --compare " + diverging),
      scratch);
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_TRUE(refused.out.empty()) << refused.out.substr(0, 200);
  EXPECT_NE(refused.err.find(diverging + ": cannot focus at infinity"), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("forms no real image"), std::string::npos) << refused.err;
  // With the film where it is given, both are analysed there, each as alone.
  const std::string options = " --film-distance 30 --only distortion,spot";
  const nlohmann::json both =
      analyzeJson(lensPath("dgauss-50mm.dat") + " --compare " + diverging + options);
  EXPECT_EQ(both["reference"], analyzeJson(diverging + options));
  EXPECT_EQ(both["lens"], analyzeJson(lensPath("dgauss-50mm.dat") + options));
  EXPECT_EQ(both["reference"]["focused_by"], "film_distance");
  EXPECT_FALSE(both["reference"]["object_in_focus"].get<bool>());
}

TEST_F(AnalyzeCompare, AnUnreadableReferenceIsNamed) {
  const std::string broken = writeFile("broken.dat", "29.4 3.7 1.67\n");
  const auto run = testing::runProcess(
      lenslab("analyze --json " + lensPath("dgauss-50mm.dat") + " --compare " + broken), scratch);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("broken.dat"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out.substr(0, 200);
  const auto missing = testing::runProcess(
      lenslab("analyze " + lensPath("dgauss-50mm.dat") + " --compare no-such.lens"), scratch);
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.err.find("no-such.lens"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace lenslab
