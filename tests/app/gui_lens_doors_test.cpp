// Issue 41's doors in the real viewer: an OpticStudio .zmx opens through the script's load-lens,
// a drop onto the window and File > Open's browser, and is captioned by its title; an imported
// lens is never written back as .zmx; and a .lens keeps what it says of its lens (title, source,
// published focal length, design conditions) through an edit and a save.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "optics/native_lens_file.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

// Edmund's 15 mm f/1.5 asphere (#47728), as Optiland's tests have it: UTF-16 with CRLF, its
// NAME "47728 Asphere F/1.5".
const std::filesystem::path kZmx = std::filesystem::path(LENSLAB_SOURCE_DIR) /
                                   "../shared/reference/import/optiland/zemax/lens2.zmx";
const std::string kDat = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";

class LensDoors : public ::testing::Test {
 protected:
  // The saved .lens names catalogue glasses: reading it back here needs the checkout's
  // catalogues (test programs run outside the trees the resource lookup knows).
  LensDoors() {
    ::setenv("LENSLAB_GLASS_DIR", (std::string(LENSLAB_SOURCE_DIR) + "/data/glass").c_str(), 0);
  }
  testing::ProcessResult runScript(const std::string& script) {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << script;
    return testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                   "' --size 1280x800 --script '" + path.string() + "'",
                               scratch);
  }
  nlohmann::json state(const std::string& name) {
    std::ifstream file(scratch / name);
    return nlohmann::json::parse(file, nullptr, false)["state"];
  }
  static bool loggedError(const nlohmann::json& dumped) {
    for (const auto& entry : dumped["log"])
      if (entry["level"] == "error") return true;
    return false;
  }
  std::filesystem::path scratch = testing::makeTestDirectory("lens-doors");
};

TEST_F(LensDoors, AZmxOpensThroughTheScriptADropAndTheOpenDialog) {
  ASSERT_TRUE(std::filesystem::exists(kZmx)) << kZmx;
  const std::string zmx = std::filesystem::canonical(kZmx).string();
  // Each door after the .dat, so that each one has to change the lens.
  const auto result = runScript("wait-frames 2\nload-lens " + zmx +
                                "\nwait-frames 3\ndump-ui loaded.json\nscreenshot loaded.png\n"
                                "load-lens " +
                                kDat + "\ndrop " + zmx +
                                "\nwait-frames 3\ndump-ui dropped.json\n"
                                "load-lens " +
                                kDat +
                                "\nopen-dialog open-lens\nwait-frames 2\ndump-ui browser.json\n"
                                "dialog-choose " +
                                zmx +
                                "\nwait-frames 3\ndump-ui chosen.json\n"
                                "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  for (const char* dump : {"loaded.json", "dropped.json", "chosen.json"}) {
    const nlohmann::json s = state(dump);
    EXPECT_EQ(s["lens_path"], zmx) << dump;
    EXPECT_EQ(s["lens_valid"], true) << dump;
    // Its NAME, without the nominal f-number (lens_caption.h), not the file's name.
    EXPECT_EQ(s["lens_name"], "47728 Asphere") << dump;
    EXPECT_FALSE(loggedError(s)) << dump << ": " << s["log"];
  }
  EXPECT_EQ(state("browser.json")["file_browser"], "Open lens");
  // Opened by the user (drop, dialog): a recent file, as any lens.
  const nlohmann::json chosen = state("chosen.json");
  bool recent = false;
  for (const auto& path : chosen["recent_files"]) recent |= path == zmx;
  EXPECT_TRUE(recent) << chosen["recent_files"];
}

TEST_F(LensDoors, AnImportedLensIsNeverWrittenAsZmx) {
  const std::string zmx = std::filesystem::canonical(kZmx).string();
  const auto refused =
      runScript("load-lens " + zmx + "\nwait-frames 2\nsave-lens copy.zmx\nquit\n");
  EXPECT_NE(refused.exitCode, 0);
  EXPECT_NE((refused.out + refused.err).find("does not write them (save the lens as .lens)"),
            std::string::npos)
      << refused.out << refused.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "copy.zmx"));
  const auto saved = runScript("load-lens " + zmx + "\nwait-frames 2\nsave-lens copy.lens\nquit\n");
  ASSERT_EQ(saved.exitCode, 0) << saved.err;
  const optics::LensFileResult read = optics::parseNativeLensText(
      testing::readWholeFile(scratch / "copy.lens"), (scratch / "copy.lens").string());
  ASSERT_TRUE(read.ok()) << read.diagnostics.formatAll() << "\n"
                         << testing::readWholeFile(scratch / "copy.lens");
  EXPECT_EQ(read.lens->title, "47728 Asphere F/1.5");
  EXPECT_EQ(read.lens->headerComments, std::vector<std::string>{"Lens Asphere 15mm F/1.5 UNCTD"});
  // ENPD 15, WAVM 1 0.5876: the design conditions go with it.
  ASSERT_TRUE(read.lens->design.aperture);
  EXPECT_EQ(read.lens->design.aperture->value, 15.0);
  ASSERT_EQ(read.lens->design.wavelengths.nanometres.size(), 1u);
  EXPECT_NEAR(read.lens->design.wavelengths.nanometres[0], 587.6, 1e-9);
}

TEST_F(LensDoors, SavingALensKeepsWhatItsFileSaysOfIt) {
  std::ofstream(scratch / "achromat.lens")
      << "lenslab-lens 1\n"
         "title Achromat 100 mm f/5\n"
         "source Smith, Modern Lens Design, p. 2\n"
         "published_efl_mm 100.5\n"
         "note cemented\n"
         "design_wavelengths_nm 486.13 587.56 656.27 primary 587.56\n"
         "design_fields angle_deg 0 3 5\n"
         "design_aperture f_number 5\n"
         "surface radius 61.07 thickness 4.0 nd 1.5168 vd 64.17 diameter 21\n"
         "surface radius -44.28 thickness 2.5 nd 1.6727 vd 32.21 diameter 21\n"
         "surface radius -129.3 thickness 2 diameter 21\n"
         "stop thickness 93.5 diameter 18\n";
  const auto result = runScript(
      "load-lens achromat.lens\nwait-frames 2\ndump-ui opened.json\n"
      "set surface 1 radius 62.5\nwait-frames 2\nsave-lens saved.lens\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json opened = state("opened.json");
  EXPECT_EQ(opened["lens_name"], "Achromat 100 mm");
  EXPECT_EQ(opened["lens_source"], "Smith, Modern Lens Design, p. 2");
  const std::string text = testing::readWholeFile(scratch / "saved.lens");
  const optics::LensFileResult read =
      optics::parseNativeLensText(text, (scratch / "saved.lens").string());
  ASSERT_TRUE(read.ok()) << read.diagnostics.formatAll() << "\n" << text;
  const optics::LensFile& lens = *read.lens;
  EXPECT_EQ(lens.prescription.surfaces.at(0).radiusMm, 62.5);  // the edit
  EXPECT_EQ(lens.title, "Achromat 100 mm f/5");
  EXPECT_EQ(lens.source, "Smith, Modern Lens Design, p. 2");
  EXPECT_EQ(lens.publishedEflMm, 100.5);
  EXPECT_EQ(lens.headerComments, std::vector<std::string>{"cemented"});
  EXPECT_EQ(lens.design.wavelengths.nanometres, (std::vector<double>{486.13, 587.56, 656.27}));
  EXPECT_EQ(lens.design.wavelengths.primaryIndex, 1);
  EXPECT_EQ(lens.design.fields.kind, optics::FieldKind::ObjectAngleDeg);
  EXPECT_EQ(lens.design.fields.values, (std::vector<double>{0, 3, 5}));
  ASSERT_TRUE(lens.design.aperture);
  EXPECT_EQ(lens.design.aperture->kind, optics::ApertureKind::ImageFNumber);
  EXPECT_EQ(lens.design.aperture->value, 5.0);
}

}  // namespace
}  // namespace lenslab
