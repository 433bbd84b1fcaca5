// Parameter values and the parameters nothing uses: spectra become RGB properly (named metal
// spectra, sampled spectra through the CIE matching functions, scaled blackbodies), and every
// unsupported parameter is reported once, with its location and what is done instead.
#include <gtest/gtest.h>

#include <cmath>

#include "course_scenes.h"
#include "render/pbrt_parser.h"
#include "render/scene_builder.h"
#include "render/spectrum.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::writeFile;

ParseResult parseParameters(const std::string& text) {
  return parsePbrtText(text, "test.pbrt", std::filesystem::temp_directory_path());
}

std::string parameterMessages(const ParseResult& result) { return result.diagnostics.formatAll(); }

// ---- spectra ----

TEST(Spectrum, ColourMatchingFitAgreesWithTheCieTable) {
  // CIE 1931 2-degree values (CIE 015:2004, table T.4): ȳ(555) = 1.0000, x̄(600) = 1.0622,
  // z̄(445) = 1.7826 (the fit is within a few percent).
  EXPECT_NEAR(cieColourMatching(555.0).y, 1.0, 0.03);
  EXPECT_NEAR(cieColourMatching(600.0).x, 1.0622, 0.04);
  EXPECT_NEAR(cieColourMatching(445.0).z, 1.7826, 0.07);
  // The three functions have (nearly) equal integrals: an equal-energy white has x = y = 1/3.
  glm::dvec3 sum(0.0);
  for (double nm = 360.0; nm <= 830.0; nm += 1.0) sum += cieColourMatching(nm);
  EXPECT_NEAR(sum.x / sum.y, 1.0, 0.02);
  EXPECT_NEAR(sum.z / sum.y, 1.0, 0.02);
}

TEST(Spectrum, SampledSpectraBecomeRgb) {
  const double flat[] = {300, 0.3, 800, 0.3};
  const auto grey = sampledSpectrumToRgb(flat);
  ASSERT_TRUE(grey);
  EXPECT_NEAR(grey->r, 0.3, 1e-9);
  EXPECT_NEAR(grey->g, 0.3, 1e-9);
  EXPECT_NEAR(grey->b, 0.3, 1e-9);
  const double longWaves[] = {400, 0, 590, 0, 600, 1, 700, 1};
  const auto red = sampledSpectrumToRgb(longWaves);
  ASSERT_TRUE(red);
  EXPECT_GT(red->r, 2.0 * red->g);
  EXPECT_GT(red->r, 5.0 * std::abs(red->b));
  const double shortWaves[] = {400, 1, 480, 1, 490, 0};
  const auto blue = sampledSpectrumToRgb(shortWaves);
  ASSERT_TRUE(blue);
  EXPECT_GT(blue->b, 2.0 * blue->r);
  std::string whyNot;
  const double decreasing[] = {500, 1, 400, 1};
  EXPECT_FALSE(sampledSpectrumToRgb(decreasing, &whyNot));
  EXPECT_NE(whyNot.find("must increase"), std::string::npos) << whyNot;
  const double odd[] = {500, 1, 400};
  EXPECT_FALSE(sampledSpectrumToRgb(odd, &whyNot));
}

TEST(Spectrum, BlackbodyColourFollowsTemperature) {
  const glm::dvec3 candle = blackbodyToRgb(1900.0);
  const glm::dvec3 sky = blackbodyToRgb(12000.0);
  EXPECT_GT(candle.r, candle.g);
  EXPECT_GT(candle.g, candle.b);
  EXPECT_GT(sky.b, sky.r);
  // Normalised to 1 at the peak: nothing exceeds 1 by much after the white balance.
  EXPECT_LT(std::max({candle.r, candle.g, candle.b}), 1.3);
}

TEST(Spectrum, NamedMetalsHaveTheirMeasuredCharacter) {
  const auto goldEta = namedSpectrumRgb("metal-Au-eta");
  const auto goldK = namedSpectrumRgb("metal-Au-k");
  ASSERT_TRUE(goldEta && goldK);
  // Johnson and Christy: n about 0.15 in the red, 1.4 in the blue; k falls from 3.5 to 1.9.
  EXPECT_LT(goldEta->r, 0.35);
  EXPECT_GT(goldEta->b, 1.1);
  EXPECT_GT(goldK->r, goldK->g);
  EXPECT_GT(goldK->g, goldK->b);
  const auto silverEta = namedSpectrumRgb("metal-Ag-eta");
  ASSERT_TRUE(silverEta);
  EXPECT_LT(std::max({silverEta->r, silverEta->g, silverEta->b}), 0.2);
  const auto copperEta = namedSpectrumRgb("metal-Cu-eta");
  ASSERT_TRUE(copperEta);
  EXPECT_LT(copperEta->r, copperEta->b);
  const auto aluminiumK = namedSpectrumRgb("metal-Al-k");
  ASSERT_TRUE(aluminiumK);
  EXPECT_GT(std::min({aluminiumK->r, aluminiumK->g, aluminiumK->b}), 5.0);
  // pbrt-v3's scenes name the same data by file.
  EXPECT_EQ(*namedSpectrumRgb("spds/metals/Au.eta.spd"), *goldEta);
  EXPECT_FALSE(namedSpectrumRgb("metal-Xx-eta"));
  EXPECT_FALSE(namedSpectrumRgb("xAu.eta.spd"));
}

TEST(Spectrum, SpectrumParametersAreConverted) {
  const auto result = parseParameters(
      "WorldBegin\n"
      "Material \"metal\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\"\n"
      "Material \"matte\" \"spectrum Kd\" [300 .3 800 .3]\n"
      "LightSource \"point\" \"blackbody I\" [3000 2]\n"
      "LightSource \"point\" \"blackbody I\" [3000]\n"
      "Material \"matte\" \"xyz Kd\" [0.9505 1 1.089]\nWorldEnd\n");
  ASSERT_TRUE(result.scene) << parameterMessages(result);
  EXPECT_TRUE(result.diagnostics.all().empty()) << parameterMessages(result);
  const auto& materials = result.scene->materials;
  ASSERT_EQ(materials.size(), 4u);
  EXPECT_EQ(*materials[1].params.getTriple("eta"), *namedSpectrumRgb("metal-Au-eta"));
  EXPECT_EQ(*materials[1].params.getTriple("k"), *namedSpectrumRgb("metal-Au-k"));
  const glm::dvec3 kd = *materials[2].params.getTriple("Kd");
  EXPECT_NEAR(kd.r, 0.3, 1e-9);
  EXPECT_NEAR(kd.b, 0.3, 1e-9);
  // The blackbody's scale is applied.
  const glm::dvec3 scaled = *result.scene->lights[0].params.getTriple("I");
  const glm::dvec3 unscaled = *result.scene->lights[1].params.getTriple("I");
  EXPECT_NEAR(scaled.r, 2.0 * unscaled.r, 1e-12);
  EXPECT_NEAR(scaled.b, 2.0 * unscaled.b, 1e-12);
  EXPECT_GT(unscaled.r, unscaled.b);
  // D65's XYZ is sRGB white.
  const glm::dvec3 white = *materials[3].params.getTriple("Kd");
  EXPECT_NEAR(white.r, 1.0, 2e-3);
  EXPECT_NEAR(white.g, 1.0, 2e-3);
  EXPECT_NEAR(white.b, 1.0, 2e-3);
}

TEST(Spectrum, UnknownNamedSpectrumWarnsAndUsesTheDefault) {
  const auto result = parseParameters(
      "WorldBegin\nMaterial \"metal\" \"spectrum eta\" \"metal-Unobtainium-eta\"\nWorldEnd\n");
  ASSERT_TRUE(result.scene) << parameterMessages(result);
  EXPECT_NE(
      parameterMessages(result).find("test.pbrt:2:18: warning: \"spectrum eta\": "
                                     "\"metal-Unobtainium-eta\" is neither a known named spectrum"),
      std::string::npos)
      << parameterMessages(result);
  EXPECT_NE(parameterMessages(result).find("; the default value is used"), std::string::npos);
  EXPECT_FALSE(result.scene->materials[1].params.find("eta"));
}

TEST(Spectrum, SpdFilesAreRead) {
  const auto directory = lenslab::testing::makeTestDirectory("spd");
  writeFile(directory / "grey.spd", "# wavelength value\n400 0.25\n700 0.25\n");
  writeFile(directory / "scene.pbrt",
            "WorldBegin\nMaterial \"matte\" \"spectrum Kd\" \"grey.spd\"\nWorldEnd\n");
  const auto result = parsePbrtFile(directory / "scene.pbrt");
  ASSERT_TRUE(result.scene) << parameterMessages(result);
  EXPECT_NEAR(result.scene->materials[1].params.getTriple("Kd")->g, 0.25, 1e-9);
}

TEST(Spectrum, MalformedSpectraAreErrors) {
  const auto odd = parseParameters("WorldBegin\nMaterial \"matte\" \"spectrum Kd\" [.5 .5 .5]\n");
  EXPECT_FALSE(odd.scene);
  EXPECT_NE(parameterMessages(odd).find(
                "test.pbrt:2:18: error: \"spectrum Kd\": a sampled spectrum needs "
                "(wavelength, value) pairs, found 3 numbers (for a colour, write "
                "\"rgb Kd\" [r g b])"),
            std::string::npos)
      << parameterMessages(odd);
  const auto cold = parseParameters("WorldBegin\nLightSource \"point\" \"blackbody I\" [0 1]\n");
  EXPECT_FALSE(cold.scene);
  EXPECT_NE(parameterMessages(cold).find("\"blackbody I\": temperature 0 K is not positive"),
            std::string::npos)
      << parameterMessages(cold);
}

// ---- unused and unsupported parameters ----

// Parses and builds; returns every diagnostic.
std::string parseAndBuild(const std::filesystem::path& path, SceneDescription* keep = nullptr) {
  ParseResult parsed = parsePbrtFile(path);
  std::string all = parsed.diagnostics.formatAll();
  if (!parsed.scene) return all + "(no scene)";
  const BuildResult built = buildScene(*parsed.scene);
  if (keep) *keep = *parsed.scene;
  return all + built.diagnostics.formatAll() + (built.scene ? "" : "(not built)");
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t found = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++found;
  }
  return found;
}

TEST(UnusedParameters, EachDirectiveSaysWhatIsUsedInstead) {
  const auto directory = lenslab::testing::makeTestDirectory("unused-parameters");
  const auto path = writeFile(
      directory / "scene.pbrt",
      "Camera \"perspective\" \"float screenwindow\" [-1 1 -1 1] \"float frameaspectratio\" 1\n"
      "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8 "
      "\"float cropwindow\" [0 .5 0 .5] \"float scale\" 2\n"
      "Sampler \"stratified\" \"integer xsamples\" 3 \"integer ysamples\" 2 "
      "\"integer pixelsamples\" 64\n"
      "Integrator \"directlighting\" \"string strategy\" \"one\" \"integer maxdepth\" 3\n"
      "PixelFilter \"box\" \"float xwidth\" 2\n"
      "WorldBegin\n"
      "Texture \"c\" \"spectrum\" \"checkerboard\" \"float frobnicate\" 1 \"float uscale\" 4\n"
      "Material \"matte\" \"texture Kd\" \"c\" \"texture bumpmap\" \"c\"\n"
      "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"float power\" 3\n"
      "Shape \"sphere\" \"float radius\" 1 \"float wobble\" 2\n"
      "WorldEnd\n");
  SceneDescription scene;
  const std::string all = parseAndBuild(path, &scene);
  const std::string of = "scene.pbrt:";
  for (const char* expected :
       {":1:22: warning: parameter \"float screenwindow\" of Camera \"perspective\" is not "
        "supported; the screen window follows the image's aspect ratio",
        ":1:55: warning: parameter \"float frameaspectratio\" of Camera \"perspective\" is not "
        "supported; the aspect ratio of the resolution is used",
        ":2:62: warning: parameter \"float cropwindow\" of Film \"image\" is not supported; the "
        "whole image is rendered",
        ":3:64: warning: parameter \"integer pixelsamples\" of Sampler \"stratified\" is not "
        "supported; xsamples * ysamples samples per pixel are taken",
        ":4:29: warning: parameter \"string strategy\" of Integrator \"directlighting\" is not "
        "supported; \"all\" is used",
        ":5:19: warning: parameter \"float xwidth\" of PixelFilter \"box\" is not supported; a "
        "box of one pixel (width 0.5) is used",
        ":7:39: warning: parameter \"float frobnicate\" of Texture \"c\" (checkerboard) is not "
        "supported; ignored",
        ":8:35: warning: parameter \"texture bumpmap\" of Material \"matte\" is not supported; "
        "the surface is shaded without bump mapping",
        ":9:43: warning: parameter \"float power\" of AreaLightSource \"diffuse\" is not "
        "supported; ignored",
        ":10:33: warning: parameter \"float wobble\" of Shape \"sphere\" is not supported; "
        "ignored"}) {
    EXPECT_EQ(count(all, of + std::string(expected).substr(1)), 1u) << expected << "\n" << all;
  }
  // Film "scale" is read (the scene's exposure: FilmScaleIsTheScenesExposure).
  EXPECT_EQ(count(all, "warning"), 10u) << all;  // nothing else, nothing twice
  EXPECT_EQ(scene.pixelSamples, 6);              // pbrt's stratified sampler: xsamples * ysamples
  EXPECT_EQ(scene.integrator.maxDepth, 3);
  EXPECT_EQ(scene.film.scale.value_or(0.0), 2.0);  // the scene's exposure: +1 EV
}

TEST(UnusedParameters, StratifiedDefaultsFollowThePbrtVersion) {
  const auto v3 = parseParameters("Sampler \"stratified\"\nWorldBegin WorldEnd");
  ASSERT_TRUE(v3.scene) << parameterMessages(v3);
  EXPECT_EQ(v3.scene->pixelSamples, 16);  // pbrt-v3: 4 x 4
  const auto v2 = parseParameters(
      "Sampler \"stratified\" \"integer xsamples\" 3\n"
      "SurfaceIntegrator \"directlighting\"\nWorldBegin WorldEnd");
  ASSERT_TRUE(v2.scene) << parameterMessages(v2);
  EXPECT_EQ(v2.scene->pixelSamples, 6);  // pbrt-v2: ysamples defaults to 2
}

TEST(UnusedParameters, RealisticSimpleWeightingSaysWhichWeightIsUsed) {
  const auto directory = lenslab::testing::makeTestDirectory("simpleweighting");
  writeFile(directory / "lens.dat", render::testing::kDoubleGauss50);
  const auto path = writeFile(
      directory / "scene.pbrt",
      "Camera \"realistic\" \"string lensfile\" \"lens.dat\" \"bool simpleweighting\" \"true\"\n"
      "WorldBegin\nWorldEnd\n");
  const std::string all = parseAndBuild(path);
  EXPECT_NE(all.find("scene.pbrt:1:49: warning: parameter \"bool simpleweighting\" of Camera "
                     "\"realistic\" is not supported; the full exposure weight"),
            std::string::npos)
      << all;
  writeFile(path,
            "Camera \"realistic\" \"string lensfile\" \"lens.dat\" \"bool simpleweighting\" "
            "\"false\"\nWorldBegin\nWorldEnd\n");
  EXPECT_EQ(parseAndBuild(path), "");  // false is what lenslab does anyway
}

TEST(UnusedParameters, TheCourseScenesUseEverythingTheySay) {
  const auto scenes = render::testing::courseScenesDirectory();
  if (!std::filesystem::exists(scenes)) GTEST_SKIP() << scenes << " is absent";
  for (const char* lens : {"dgauss", "fisheye", "telephoto", "wide"}) {
    EXPECT_EQ(parseAndBuild(scenes / (std::string("dof-dragons.") + lens + ".pbrt")), "") << lens;
  }
  EXPECT_EQ(parseAndBuild(std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "default.pbrt"),
            "");
}

}  // namespace
}  // namespace lenslab::render

namespace lenslab::render {
namespace {

// A parameter given more values than its reader takes is an error at the parameter (issue 24:
// 3 million numbers for a sphere's radius rendered without a word); lists (a mesh's points, a
// colour's three numbers, one grey value for a colour) stay fine.
TEST(ParameterCounts, MoreValuesThanTheParameterTakesIsAnError) {
  const auto directory = lenslab::testing::makeTestDirectory("parameter-counts");
  const std::string head =
      "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" 8 "
      "\"integer yresolution\" 8\nWorldBegin\nLightSource \"point\" \"rgb I\" [1 1 1]\n";
  std::string many = "1";
  for (int i = 0; i < 3000; ++i) many += " 1";
  const auto radius =
      writeFile(directory / "radius.pbrt",
                head + "Shape \"sphere\" \"float radius\" [" + many + "]\nWorldEnd\n");
  const std::string radiusMessages = parseAndBuild(radius);
  EXPECT_NE(radiusMessages.find("radius.pbrt:5:16: error: parameter \"float radius\" of Shape "
                                "\"sphere\" takes 1 value, but 3001 are given"),
            std::string::npos)
      << radiusMessages;
  EXPECT_NE(radiusMessages.find("(not built)"), std::string::npos) << radiusMessages;

  const auto colour = writeFile(
      directory / "colour.pbrt",
      head + "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5 0.5]\nShape \"sphere\"\nWorldEnd\n");
  const std::string colourMessages = parseAndBuild(colour);
  // A colour's count is checked as it is parsed.
  EXPECT_NE(colourMessages.find("colour.pbrt:5:18: error: \"rgb Kd\" needs r g b (three numbers), "
                                "found 4"),
            std::string::npos)
      << colourMessages;

  const auto fine = writeFile(
      directory / "fine.pbrt",
      head +
          "Material \"matte\" \"rgb Kd\" [0.5]\nShape \"trianglemesh\" \"integer indices\" "
          "[0 1 2] \"point P\" [0 0 0 1 0 0 0 1 0]\nShape \"sphere\" \"float radius\" 2\n"
          "WorldEnd\n");
  const std::string fineMessages = parseAndBuild(fine);
  EXPECT_EQ(fineMessages.find("error"), std::string::npos) << fineMessages;
  EXPECT_EQ(fineMessages.find("(not built)"), std::string::npos) << fineMessages;
}

}  // namespace
}  // namespace lenslab::render
