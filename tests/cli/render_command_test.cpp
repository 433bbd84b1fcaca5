// `lenslab render`, run as a real process.

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(scratch / "scene.pbrt")
        << "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
           "Film \"image\" \"integer xresolution\" [32] \"integer yresolution\" [24]\n"
           "WorldBegin\nLightSource \"distant\" \"point from\" [1 4 2] \"rgb L\" [3 3 3]\n"
           "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n"
           "Material \"plastic\" \"rgb Kd\" [0.6 0.2 0.1]\n"
           "Shape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n";
  }
  std::filesystem::path scratch = testing::makeTestDirectory("render-cli");
};

TEST_F(RenderCommand, WritesTheImageAndTheStatistics) {
  const auto result =
      testing::runProcess(lenslab("render '" + (scratch / "scene.pbrt").string() +
                                  "' --spp 4 --resolution 40x30 "
                                  "--threads 2 --seed 3 --integrator path --out '" +
                                  (scratch / "out.png").string() + "' --stats-json '" +
                                  (scratch / "stats.json").string() + "'"),
                          scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load((scratch / "out.png").c_str(), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(width, 40);
  EXPECT_EQ(height, 30);
  int lit = 0;
  for (int i = 0; i < width * height; ++i) lit += pixels[4 * i] > 20;
  EXPECT_GT(lit, 10);  // not black
  stbi_image_free(pixels);
  const auto stats = nlohmann::json::parse(testing::readWholeFile(scratch / "stats.json"));
  for (const char* key : {"wall_seconds", "setup_seconds", "render_seconds", "spp",
                          "camera_samples", "lens_pass_fraction"}) {
    EXPECT_TRUE(stats.contains(key)) << key;
  }
  EXPECT_EQ(stats["spp"], 4);
  EXPECT_EQ(stats["camera_samples"], 40 * 30 * 4);
  EXPECT_DOUBLE_EQ(stats["lens_pass_fraction"].get<double>(), 1.0);
}

TEST_F(RenderCommand, FormatFollowsTheExtension) {
  for (const char* name : {"out.exr", "out.pfm"}) {
    const auto result =
        testing::runProcess(lenslab("render '" + (scratch / "scene.pbrt").string() +
                                    "' --spp 1 --out '" + (scratch / name).string() + "'"),
                            scratch);
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::string bytes = testing::readWholeFile(scratch / name);
    if (std::string(name) == "out.exr") {
      EXPECT_EQ(bytes.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));  // OpenEXR magic
    } else {
      EXPECT_EQ(bytes.substr(0, 3), "PF\n");
    }
  }
}

TEST_F(RenderCommand, SceneErrorsExitNonZeroAndWriteNothing) {
  std::ofstream(scratch / "bad.pbrt") << "WorldBegin\nShape \"sphere\" \"float radius\" [1\n";
  const auto result =
      testing::runProcess(lenslab("render '" + (scratch / "bad.pbrt").string() + "' --out '" +
                                  (scratch / "bad.png").string() + "'"),
                          scratch);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("bad.pbrt:"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "bad.png"));

  const auto missing =
      testing::runProcess(lenslab("render '" + (scratch / "nope.pbrt").string() + "'"), scratch);
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.err.find("nope.pbrt"), std::string::npos);

  const auto extension =
      testing::runProcess(lenslab("render '" + (scratch / "scene.pbrt").string() + "' --out '" +
                                  (scratch / "x.bmp").string() + "'"),
                          scratch);
  EXPECT_EQ(extension.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(scratch / "x.bmp"));
}

TEST_F(RenderCommand, LensOptionReplacesTheCamerasLens) {
  std::ofstream(scratch / "lens.dat")
      << "# a thick single lens\n50 5 1.5 20\n0 5 0 10\n-50 40 1 20\n";
  std::ofstream(scratch / "real.pbrt")
      << "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"realistic\" \"string lensfile\" \"nope.dat\" "
         "\"float aperturediameter\" [5] \"float focusdistance\" [4]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\nWorldEnd\n";
  const auto withoutLens =
      testing::runProcess(lenslab("render '" + (scratch / "real.pbrt").string() + "' --out '" +
                                  (scratch / "a.png").string() + "'"),
                          scratch);
  EXPECT_NE(withoutLens.exitCode, 0);
  EXPECT_NE(withoutLens.err.find("nope.dat"), std::string::npos) << withoutLens.err;
}

TEST_F(RenderCommand, ACatalogueGlassRendersSpectrallyAndOneThatFallsShortSaysItRendersInRgb) {
  // The spectral batch trace follows N-BK7 by its formula; CDGM's formulas end at 706.5 nm, so a
  // lens of H-LAK67 asked for spectral renders in RGB, and a note at the lens file says why.
  auto writeSinglet = [&](const std::string& name, const std::string& glass) {
    std::ofstream(scratch / name) << "lenslab-lens 1\n"
                                     "surface radius 50 thickness 5 glass "
                                  << glass
                                  << " diameter 20\n"
                                     "surface radius -50 thickness 1 diameter 20\n"
                                     "stop thickness 45 diameter 10\n";
  };
  writeSinglet("bk7.lens", "N-BK7");
  writeSinglet("cdgm.lens", "H-LAK67 maker CDGM");
  auto render = [&](const std::string& lens, const std::string& mode) {
    return testing::runProcess(
        lenslab("render '" + (scratch / "scene.pbrt").string() + "' --spp 1 --lens '" +
                (scratch / lens).string() + "' --out '" + (scratch / "out.png").string() +
                "' --stats-json '" + (scratch / "out.json").string() + "' --spectral " + mode),
        scratch);
  };
  auto renderedSpectrally = [&] {
    return nlohmann::json::parse(testing::readWholeFile(scratch / "out.json"))["spectral"]
        .get<bool>();
  };
  const auto bk7 = render("bk7.lens", "on");
  ASSERT_EQ(bk7.exitCode, 0) << bk7.err;
  EXPECT_EQ(bk7.err.find("RGB"), std::string::npos) << bk7.err;
  EXPECT_TRUE(renderedSpectrally());
  const auto cdgm = render("cdgm.lens", "on");
  ASSERT_EQ(cdgm.exitCode, 0) << cdgm.err;
  EXPECT_NE(cdgm.err.find("cdgm.lens: note: surface 1's glass H-LAK67 (CDGM): its formula covers "
                          "365-706.5 nm"),
            std::string::npos)
      << cdgm.err;
  EXPECT_FALSE(renderedSpectrally());
  const auto off = render("cdgm.lens", "off");
  ASSERT_EQ(off.exitCode, 0) << off.err;
  EXPECT_EQ(off.err.find("H-LAK67"), std::string::npos) << off.err;  // nothing to say
}

TEST_F(RenderCommand, LensOptionPutsTheLensInPlaceOfAPinhole) {
  // A perspective scene with --lens is seen through the lens (documented in --help), not
  // silently rendered through the pinhole.
  std::ofstream(scratch / "lens.dat")
      << "# a thick single lens\n50 5 1.5 20\n0 5 0 10\n-50 40 1 20\n";
  const auto result = testing::runProcess(
      lenslab("render '" + (scratch / "scene.pbrt").string() + "' --spp 4 --lens '" +
              (scratch / "lens.dat").string() + "' --out '" + (scratch / "lens.png").string() +
              "' --stats-json '" + (scratch / "lens.json").string() + "'"),
      scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto stats = nlohmann::json::parse(testing::readWholeFile(scratch / "lens.json"));
  // A pinhole passes every camera ray; a real lens's stop and rims do not.
  EXPECT_LT(stats["lens_pass_fraction"].get<double>(), 0.99);
  EXPECT_GT(stats["lens_pass_fraction"].get<double>(), 0.0);

  const auto missing = testing::runProcess(
      lenslab("render '" + (scratch / "scene.pbrt").string() + "' --lens '" +
              (scratch / "nope.dat").string() + "' --out '" + (scratch / "n.png").string() + "'"),
      scratch);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("nope.dat"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "n.png"));

  const auto help = testing::runProcess(lenslab("render --help"), scratch);
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("A perspective camera becomes a realistic one"), std::string::npos)
      << help.out;
}

TEST_F(RenderCommand, UpperCaseExtensionsAreAccepted) {
  const auto result =
      testing::runProcess(lenslab("render '" + (scratch / "scene.pbrt").string() +
                                  "' --spp 1 --out '" + (scratch / "a.PNG").string() + "'"),
                          scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(testing::readWholeFile(scratch / "a.PNG").substr(1, 3), "PNG");
}

// A scene with nothing to render used to render black and exit 0; it is an error at the file.
TEST_F(RenderCommand, AnEmptySceneIsAnErrorAndWritesNoImage) {
  const std::string camera = "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"perspective\"\n";
  const std::string sphere = "Shape \"sphere\" \"float radius\" [0.5]\n";
  struct Case {
    const char* name;
    std::string scene;
    const char* message;
  };
  const Case cases[] = {
      {"comments", "# only a comment\n# and another\n", "the scene has no shapes"},
      {"noshapes", camera + "WorldBegin\nLightSource \"point\" \"rgb I\" [5 5 5]\nWorldEnd\n",
       "the scene has no shapes"},
      {"nolights", camera + "WorldBegin\n" + sphere + "WorldEnd\n", "the scene has no lights"},
  };
  for (const Case& empty : cases) {
    const auto path = scratch / (std::string(empty.name) + ".pbrt");
    std::ofstream(path) << empty.scene;
    const auto result = testing::runProcess(
        lenslab("render '" + path.string() + "' --spp 1 --resolution 8x6 --out '" +
                (scratch / "empty.png").string() + "'"),
        scratch);
    EXPECT_EQ(result.exitCode, 1) << empty.name << "\n" << result.err;
    EXPECT_NE(result.err.find(path.string() + ": error: " + empty.message), std::string::npos)
        << empty.name << "\n"
        << result.err;
    EXPECT_FALSE(std::filesystem::exists(scratch / "empty.png")) << empty.name;
  }
  // Light from an area light alone is light, and an instanced object's shapes are shapes.
  std::ofstream(scratch / "emitter.pbrt")
      << camera << "WorldBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
      << sphere << "WorldEnd\n";
  std::ofstream(scratch / "instanced.pbrt")
      << camera << "WorldBegin\nLightSource \"point\" \"rgb I\" [5 5 5]\nObjectBegin \"ball\"\n"
      << sphere << "ObjectEnd\nObjectInstance \"ball\"\nWorldEnd\n";
  for (const char* name : {"emitter", "instanced"}) {
    const auto out = scratch / (std::string(name) + ".png");
    const auto result = testing::runProcess(
        lenslab("render '" + (scratch / (std::string(name) + ".pbrt")).string() +
                "' --spp 1 --resolution 8x6 --out '" + out.string() + "'"),
        scratch);
    EXPECT_EQ(result.exitCode, 0) << name << "\n" << result.err;
    EXPECT_TRUE(std::filesystem::exists(out)) << name;
  }
}

// A sky alone is a picture, as in pbrt: through a pinhole every pixel is the sky's radiance L.
TEST_F(RenderCommand, ASceneOfOnlyASkyRendersTheSky) {
  std::ofstream(scratch / "sky.pbrt")
      << "LookAt 0 0 0  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.25 0.5 1.5]\nWorldEnd\n";
  const auto out = scratch / "sky.pfm";
  const auto result = testing::runProcess(
      lenslab("render '" + (scratch / "sky.pbrt").string() +
              "' --spp 4 --resolution 16x12 --quiet --out '" + out.string() + "'"),
      scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::ifstream in(out, std::ios::binary);
  std::string magic;
  int width = 0, height = 0;
  double scale = 0;
  in >> magic >> width >> height >> scale;
  in.get();
  ASSERT_EQ(magic, "PF");
  ASSERT_EQ(width * height, 16 * 12);
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  in.read(reinterpret_cast<char*>(rgb.data()), static_cast<std::streamsize>(rgb.size() * 4));
  ASSERT_TRUE(in) << "short PFM";
  const float L[3] = {0.25f, 0.5f, 1.5f};
  for (std::size_t i = 0; i < rgb.size(); ++i)
    ASSERT_NEAR(rgb[i], L[i % 3], 1e-3 * L[i % 3]) << "value " << i;
}

// Where the picture cannot go is said before any rendering: a render of 2^20 samples per pixel
// (hours) ends at once (`timeout` stops a render that started: exit 124).
TEST_F(RenderCommand, ChecksItsOutputBeforeRendering) {
  std::filesystem::create_directories(scratch / "folder.png");
  std::ofstream(scratch / "plain-file") << "not a directory\n";
  struct Case {
    std::string out;
    int exitCode;
    std::string message;
  };
  const Case cases[] = {
      {(scratch / "no-such-directory" / "out.png").string(), 1,
       "the directory " + (scratch / "no-such-directory").string() + " does not exist"},
      {(scratch / "folder.png").string(), 1, "it is a directory"},
      {(scratch / "plain-file" / "out.png").string(), 1, "plain-file is not a directory"},
      {(scratch / "out.tiff").string(), 2, "unknown image format"},
  };
  const std::string slow = "--spp 1048576 --resolution 64x48 --quiet";
  for (const Case& c : cases) {
    const auto result =
        testing::runProcess("timeout 60 " + lenslab("render '" + (scratch / "scene.pbrt").string() +
                                                    "' " + slow + " --out '" + c.out + "'"),
                            scratch);
    EXPECT_EQ(result.exitCode, c.exitCode) << c.out << "\n" << result.err;
    EXPECT_NE(result.err.find(c.message), std::string::npos) << c.out << "\n" << result.err;
  }
  // Without --out, the scene's Film "filename" is checked as soon as the scene is read.
  std::ofstream(scratch / "elsewhere.pbrt")
      << "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
         "Film \"image\" \"string filename\" \"gone/picture.png\"\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.3 0.3 0.3]\n"
         "Shape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n";
  const auto film = testing::runProcess(
      "cd '" + scratch.string() + "' && timeout 60 " +
          lenslab("render '" + (scratch / "elsewhere.pbrt").string() + "' " + slow),
      scratch);
  EXPECT_EQ(film.exitCode, 1) << film.err;
  EXPECT_NE(film.err.find("cannot write gone/picture.png: the directory gone does not exist"),
            std::string::npos)
      << film.err;
  // The statistics' file too.
  const auto stats = testing::runProcess(
      "timeout 60 " + lenslab("render '" + (scratch / "scene.pbrt").string() + "' " + slow +
                              " --out '" + (scratch / "fine.png").string() + "' --stats-json '" +
                              (scratch / "nowhere" / "stats.json").string() + "'"),
      scratch);
  EXPECT_EQ(stats.exitCode, 1) << stats.err;
  EXPECT_NE(stats.err.find("nowhere does not exist"), std::string::npos) << stats.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "fine.png"));
}

// Unless --quiet, a closing line says what was made and where: with no --out, the full path of
// the file and why it is there.
TEST_F(RenderCommand, AClosingLineSaysWhatWasWrittenAndWhere) {
  const auto named = testing::runProcess(
      lenslab("render '" + (scratch / "scene.pbrt").string() +
              "' --spp 2 --resolution 20x10 --out '" + (scratch / "named.png").string() + "'"),
      scratch);
  ASSERT_EQ(named.exitCode, 0) << named.err;
  EXPECT_NE(named.err.find("lenslab render: 20x10, 2 spp, "), std::string::npos) << named.err;
  EXPECT_NE(named.err.find("wrote " + (scratch / "named.png").string() + "\n"), std::string::npos)
      << named.err;

  const auto defaulted = testing::runProcess(
      "cd '" + scratch.string() + "' && " +
          lenslab("render '" + (scratch / "scene.pbrt").string() + "' --spp 1 --resolution 8x6"),
      scratch);
  ASSERT_EQ(defaulted.exitCode, 0) << defaulted.err;
  EXPECT_TRUE(std::filesystem::exists(scratch / "out.png"));
  EXPECT_NE(defaulted.err.find("wrote " + (scratch / "out.png").string() +
                               " (no --out, the default name)"),
            std::string::npos)
      << defaulted.err;

  const auto quiet = testing::runProcess(lenslab("render '" + (scratch / "scene.pbrt").string() +
                                                 "' --spp 1 --resolution 8x6 --quiet --out '" +
                                                 (scratch / "quiet.png").string() + "'"),
                                         scratch);
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
}

// On a terminal the progress bar says how long is left; `script` gives the render a terminal.
TEST_F(RenderCommand, ProgressOnATerminalShowsTheTimeLeft) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const std::string command =
      lenslab("render '" + (scratch / "scene.pbrt").string() +
              "' --spp 16 --resolution 32x24 --out '" + (scratch / "tty.png").string() + "'");
  std::ofstream(scratch / "tty.sh") << command << "\n";
  const auto result = testing::runProcess(
      "script -qefc 'sh " + (scratch / "tty.sh").string() + "' /dev/null", scratch);
  ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("% "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find(" left"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("done in "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("wrote " + (scratch / "tty.png").string()), std::string::npos)
      << result.out;
}

// --exposure auto meters the PNG as the viewer's auto exposure does: a uniform sky of luminance
// 0.05 is metered at log2(0.8 / 0.05) = 4 stops, so every pixel encodes sRGB(0.8); numbers of
// stops still work.
TEST_F(RenderCommand, ExposureAutoMetersThePngAsTheViewerDoes) {
  std::ofstream(scratch / "grey-sky.pbrt")
      << "LookAt 0 0 0  0 0 -1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n"
         "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.05 0.05 0.05]\nWorldEnd\n";
  auto srgb8 = [](double linear) {
    const double encoded =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<int>(std::lround(255.0 * std::clamp(encoded, 0.0, 1.0)));
  };
  struct Case {
    const char* exposure;
    double linear;  // what every pixel shows
  };
  for (const Case c : {Case{"auto", 0.8}, Case{"2", 0.2}, Case{"0", 0.05}}) {
    const std::string name = std::string("sky-") + c.exposure;
    const auto result = testing::runProcess(
        lenslab("render '" + (scratch / "grey-sky.pbrt").string() +
                "' --spp 2 --resolution 16x12 --exposure " + c.exposure + " --out '" +
                (scratch / (name + ".png")).string() + "' --stats-json '" +
                (scratch / (name + ".json")).string() + "'"),
        scratch);
    ASSERT_EQ(result.exitCode, 0) << c.exposure << ": " << result.err;
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load((scratch / (name + ".png")).c_str(), &width, &height, &channels, 4);
    ASSERT_NE(pixels, nullptr) << c.exposure;
    const int expected = srgb8(c.linear);
    for (int i = 0; i < width * height * 4; ++i) {
      if (i % 4 == 3) continue;
      ASSERT_NEAR(pixels[i], expected, 1) << c.exposure << " value " << i;
    }
    stbi_image_free(pixels);
    const auto stats = nlohmann::json::parse(testing::readWholeFile(scratch / (name + ".json")));
    EXPECT_NEAR(stats.at("exposure_stops").get<double>(), std::log2(c.linear / 0.05), 1e-3)
        << c.exposure;
  }
  const auto refused = testing::runProcess(
      lenslab("render '" + (scratch / "grey-sky.pbrt").string() + "' --exposure automatic"),
      scratch);
  EXPECT_EQ(refused.exitCode, 2) << refused.err;
  EXPECT_NE(refused.err.find("'automatic' is neither a number of stops nor auto"),
            std::string::npos)
      << refused.err;
}

TEST_F(RenderCommand, BadInputNeverCrashes) {
  // Each used to abort: a zero view direction reached Embree (exit 134), a 300-character name
  // threw filesystem_error.
  const std::string longName(300, 'n');
  struct Case {
    const char* name;
    std::string scene;
    std::string message;
  };
  const Case cases[] = {
      {"lookat", "LookAt 0 0 0 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\nWorldEnd\n",
       "lookat.pbrt:1:1: error: LookAt: the eye and the target are the same point"},
      {"scale", "Scale 0 0 0\nCamera \"perspective\"\nWorldBegin\nWorldEnd\n",
       "scale.pbrt:2:1: error: the camera transform is singular"},
      {"include", "WorldBegin\nInclude \"" + longName + "\"\nWorldEnd\n",
       "include.pbrt:2:9: error: cannot open included file"},
  };
  for (const Case& bad : cases) {
    const auto path = scratch / (std::string(bad.name) + ".pbrt");
    std::ofstream(path) << bad.scene;
    const auto result = testing::runProcess(
        lenslab("render '" + path.string() + "' --out '" + (scratch / "bad.png").string() + "'"),
        scratch);
    EXPECT_EQ(result.exitCode, 1) << bad.name << "\n" << result.err;
    EXPECT_NE(result.err.find(bad.message), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(scratch / "bad.png"));
  }
  // A long output name is an error message too.
  const auto out = testing::runProcess(
      lenslab("render '" + (scratch / "scene.pbrt").string() + "' --spp 1 --out '" +
              (scratch / (longName + ".png")).string() + "'"),
      scratch);
  EXPECT_EQ(out.exitCode, 1) << out.err;
  EXPECT_NE(out.err.find("File name too long"), std::string::npos) << out.err;
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// A PFM's green channel (rows bottom to top, as the format stores them).
std::vector<float> readPfmGreen(const std::filesystem::path& path, int& width, int& height) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  double scale = 0;
  in >> magic >> width >> height >> scale;
  in.get();
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  in.read(reinterpret_cast<char*>(rgb.data()), static_cast<std::streamsize>(rgb.size() * 4));
  std::vector<float> green(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < green.size(); ++i) green[i] = rgb[3 * i + 1];
  return green;
}

// `--no-cos4 --no-rims`: the flat-field demo through the wide 22 mm comes out nearly flat, where
// the physical camera darkens its corners to about a third; the statistics say what was off.
TEST(RenderCommandFalloff, NoCos4AndNoRimsFlattenTheDemoScene) {
  const auto scratch = testing::makeTestDirectory("render-cli-falloff");
  const std::string scene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/vignetting.pbrt";
  auto cornerOverCentre = [&](const std::string& flags, const std::string& name) {
    const auto result = testing::runProcess(
        lenslab("render '" + scene + "' --spp 64 --resolution 60x40 --quiet " + flags + " --out '" +
                (scratch / (name + ".pfm")).string() + "' --stats-json '" +
                (scratch / (name + ".json")).string() + "'"),
        scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    int width = 0, height = 0;
    const std::vector<float> green = readPfmGreen(scratch / (name + ".pfm"), width, height);
    if (width != 60 || height != 40) return -1.0;
    auto mean = [&](int x0, int y0) {  // a 4 x 4 block
      double sum = 0;
      for (int y = y0; y < y0 + 4; ++y)
        for (int x = x0; x < x0 + 4; ++x) sum += green[static_cast<std::size_t>(y * width + x)];
      return sum / 16;
    };
    return mean(0, 0) / mean(28, 18);
  };
  const double physical = cornerOverCentre("", "physical");
  const double flat = cornerOverCentre("--no-cos4 --no-rims", "flat");
  EXPECT_LT(physical, 0.45);
  EXPECT_GT(flat, 0.85);
  const auto stats = nlohmann::json::parse(testing::readWholeFile(scratch / "flat.json"));
  EXPECT_EQ(stats["falloff"], "cos4 off, rims off");
  const auto physicalStats =
      nlohmann::json::parse(testing::readWholeFile(scratch / "physical.json"));
  EXPECT_EQ(physicalStats["falloff"], "cos4 on, rims on");
}

}  // namespace
}  // namespace lenslab

namespace lenslab {
namespace {

// `lenslab render` honours a lens file's aperture line and a scene's "string aperture": under a
// uniform sky the picture's brightness falls with the stop's area (a square inscribed in the
// circle lets through 2/pi of its light, a pentagon (5/2) sin 72 / pi = 0.76).
TEST(RenderCommandAperture, HonoursTheLensFilesShapeAndTheScenesAperture) {
  const auto scratch = testing::makeTestDirectory("render-cli-aperture");
  const std::string rows = "50 5 1.5 20\n0 5 0 6\n-50 40 1 20\n";
  std::ofstream(scratch / "round.dat") << rows;
  std::ofstream(scratch / "square.dat") << "# lenslab aperture: blades 4 rotation 45\n" << rows;
  auto scene = [&](const std::string& lens, const std::string& aperture) {
    const auto path = scratch / (lens + aperture + ".pbrt");
    std::ofstream(path)
        << "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"realistic\" \"string lensfile\" \"" << lens
        << "\" \"float focusdistance\" [4]"
        << (aperture.empty() ? "" : " \"string aperture\" \"" + aperture + "\"")
        << "\nFilm \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]"
           " \"float diagonal\" [2]\n"
           "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
           // A shape behind the camera: a scene needs one.
           "AttributeBegin\nTranslate 0 0 -50\nShape \"sphere\" \"float radius\" [1]\n"
           "AttributeEnd\nWorldEnd\n";
    return path;
  };
  auto brightness = [&](const std::filesystem::path& path) {
    const auto pfm = scratch / (path.stem().string() + ".pfm");
    const auto result = testing::runProcess(
        lenslab("render '" + path.string() + "' --spp 256 --out '" + pfm.string() + "'"), scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    if (result.exitCode != 0) return 0.0;
    int width = 0, height = 0;
    const std::vector<float> green = readPfmGreen(pfm, width, height);
    double sum = 0.0;
    for (const float g : green) sum += g;
    return green.empty() ? 0.0 : sum / static_cast<double>(green.size());
  };
  const double round = brightness(scene("round.dat", ""));
  const double square = brightness(scene("square.dat", ""));
  const double pentagon = brightness(scene("round.dat", "pentagon"));
  ASSERT_GT(round, 0.0);
  EXPECT_NEAR(square / round, 2.0 / 3.141592653589793, 0.03);
  EXPECT_NEAR(pentagon / round, 2.5 * std::sin(0.4 * 3.141592653589793) / 3.141592653589793, 0.03);
}

}  // namespace
}  // namespace lenslab
