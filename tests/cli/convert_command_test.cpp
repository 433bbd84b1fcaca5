// `lenslab convert IN OUT`, run as a real process: a lens from another program's file becomes a
// .lens that lenslab reads back to the same optics, and a .dat that cannot hold it is refused with
// nothing written.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

// Edmund 47728, an even asphere in Ohara L-BAL35, as OpticStudio wrote it (UTF-16).
const std::string kLens2 =
    std::string(LENSLAB_SOURCE_DIR) + "/../shared/reference/import/optiland/zemax/lens2.zmx";

class ConvertCommand : public ::testing::Test {
 protected:
  std::filesystem::path scratch = testing::makeTestDirectory("convert-command");

  testing::ProcessResult run(const std::string& arguments) {
    return testing::runProcess(lenslab(arguments), scratch);
  }
  nlohmann::json info(const std::string& path) {
    const auto result = run("info --json '" + path + "'");
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }
};

TEST_F(ConvertCommand, AZemaxLensBecomesALensFileWithTheSameOptics) {
  const std::filesystem::path out = scratch / "lens2.lens";
  const auto result = run("convert '" + kLens2 + "' '" + out.string() + "'");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string text = testing::readWholeFile(out);
  EXPECT_EQ(text.rfind("lenslab-lens 1\n", 0), 0u) << text;
  EXPECT_NE(text.find("glass L-BAL35 maker OHARA"), std::string::npos) << text;
  EXPECT_NE(text.find(" conic "), std::string::npos) << text;
  EXPECT_NE(text.find("design_aperture"), std::string::npos) << text;
  // Everything lenslab reports of the two files is the same: every surface and the first-order
  // data, to the last digit (the .lens numbers read back exactly).
  const nlohmann::json original = info(kLens2), converted = info(out.string());
  for (const char* key : {"surfaces", "efl_mm", "bfl_mm", "f_number", "entrance_pupil",
                          "exit_pupil", "total_track_mm", "stop_surface", "title"}) {
    ASSERT_TRUE(original.contains(key)) << key;
    EXPECT_EQ(converted[key], original[key]) << key;
  }
  EXPECT_NEAR(converted["efl_mm"].get<double>(), 22.5, 0.2);  // Edmund's 22.5 mm
}

TEST_F(ConvertCommand, ADatThatCannotHoldTheLensIsRefusedAndNothingIsWritten) {
  const std::filesystem::path out = scratch / "lens2.dat";
  const auto result = run("convert '" + kLens2 + "' '" + out.string() + "'");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("lens2.dat"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("surface"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  // A spherical lens with model glasses fits, and reads back with the same first-order data.
  const std::filesystem::path dat = scratch / "dgauss.dat";
  const auto fits = run("convert '" + lensPath("dgauss-50mm.dat") + "' '" + dat.string() + "'");
  ASSERT_EQ(fits.exitCode, 0) << fits.err;
  const nlohmann::json datInfo = info(dat.string()), original = info(lensPath("dgauss-50mm.dat"));
  for (const char* key : {"surfaces", "efl_mm", "bfl_mm", "f_number", "entrance_pupil"})
    EXPECT_EQ(datInfo[key], original[key]) << key;
}

TEST_F(ConvertCommand, BadInputExitsOneWithAMessage) {
  const auto unknownFormat = run("convert '" + kLens2 + "' '" + (scratch / "x.zmx").string() + "'");
  EXPECT_EQ(unknownFormat.exitCode, 1);
  EXPECT_NE(unknownFormat.err.find("not '.zmx'"), std::string::npos) << unknownFormat.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "x.zmx"));
  const auto missing = run("convert '" + (scratch / "nope.zmx").string() + "' '" +
                           (scratch / "y.lens").string() + "'");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("nope.zmx"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "y.lens"));
}

}  // namespace
}  // namespace lenslab
