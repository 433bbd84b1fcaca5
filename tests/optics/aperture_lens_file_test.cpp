// The lens file's aperture line (lens_file.h): read, written back, and refused or warned about at
// its file:line:column.

#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <filesystem>
#include <fstream>

#include "test_lenses.h"

namespace lenslab::optics {
namespace {

const char* kRows =
    "50 5 1.5 20\n"
    "0 5 0 10\n"
    "-50 40 1 20\n";

TEST(ApertureLensFile, ReadsBladesAndWritesThemBack) {
  const std::string text =
      std::string("# a lens\n# lenslab aperture: blades 6 curvature 0.5 rotation 15\n") + kRows;
  const auto r = parseLensText(text, "t.dat");
  ASSERT_TRUE(r.ok()) << r.diagnostics.formatAll();
  const ApertureShape& shape = r.lens->prescription.stopShape;
  EXPECT_EQ(shape.kind, ApertureShape::Kind::Blades);
  EXPECT_EQ(shape.bladeCount, 6);
  EXPECT_EQ(shape.curvature, 0.5);
  EXPECT_EQ(shape.rotationDeg, 15.0);
  // The line is the shape's, not a header comment to repeat.
  ASSERT_EQ(r.lens->headerComments.size(), 1u);
  const std::string written = formatLensText(r.lens->prescription, r.lens->headerComments);
  EXPECT_NE(written.find("# lenslab aperture: blades 6 curvature 0.5 rotation 15\n"),
            std::string::npos)
      << written;
  const auto again = parseLensText(written, "t.dat");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again.lens->prescription.stopShape, shape);
  EXPECT_EQ(formatLensText(again.lens->prescription, again.lens->headerComments), written);
  // A circle writes no line.
  Prescription round = r.lens->prescription;
  round.stopShape = ApertureShape{};
  EXPECT_EQ(formatLensText(round).find("lenslab aperture"), std::string::npos);
}

TEST(ApertureLensFile, BadValuesAreErrorsAtLineAndColumn) {
  struct Bad {
    const char* line;
    const char* where;
    const char* says;
  };
  for (const Bad& bad : {
           Bad{"# lenslab aperture: blades 2\n", "t.dat:2:28:", "blade count 2 is out of range"},
           Bad{"# lenslab aperture: blades 40\n", "t.dat:2:28:", "blade count 40 is out of range"},
           Bad{"#  lenslab aperture:  blades 6 curvature 1.5\n", "t.dat:2:42:", "curvature 1.5"},
           Bad{"# lenslab aperture: round\n", "t.dat:2:21:", "unknown aperture 'round'"},
       }) {
    const auto r = parseLensText(std::string("# x\n") + bad.line + kRows, "t.dat");
    EXPECT_FALSE(r.ok()) << bad.line;
    ASSERT_FALSE(r.diagnostics.empty());
    const std::string message = r.diagnostics.all().front().format();
    EXPECT_EQ(message.rfind(bad.where, 0), 0u) << message;
    EXPECT_NE(message.find(bad.says), std::string::npos) << message;
  }
}

TEST(ApertureLensFile, AnImageBesideTheLensIsLoadedAndAMissingOneKeepsTheCircle) {
  const auto dir = std::filesystem::temp_directory_path() / "lenslab-aperture-lens-file";
  std::filesystem::create_directories(dir);
  std::vector<unsigned char> grey(16 * 16, 255);
  ASSERT_NE(stbi_write_png((dir / "iris.png").c_str(), 16, 16, 1, grey.data(), 16), 0);
  {
    std::ofstream(dir / "good.dat") << "# lenslab aperture: image iris.png\n" << kRows;
    std::ofstream(dir / "missing.dat") << "# x\n# lenslab aperture: image gone.png\n" << kRows;
  }
  const auto good = readLensFile(dir / "good.dat");
  ASSERT_TRUE(good.ok()) << good.diagnostics.formatAll();
  EXPECT_TRUE(good.diagnostics.empty());
  const ApertureShape& shape = good.lens->prescription.stopShape;
  ASSERT_EQ(shape.kind, ApertureShape::Kind::Image);
  ASSERT_TRUE(shape.mask);
  EXPECT_EQ(shape.mask->sizePx, 16);
  EXPECT_NE(formatLensText(good.lens->prescription).find("# lenslab aperture: image iris.png\n"),
            std::string::npos);

  const auto missing = readLensFile(dir / "missing.dat");
  ASSERT_TRUE(missing.ok());  // a warning: the lens is still usable, with the circle
  EXPECT_TRUE(missing.lens->prescription.stopShape.isCircle());
  ASSERT_EQ(missing.diagnostics.all().size(), 1u);
  const Diagnostic& warning = missing.diagnostics.all().front();
  EXPECT_EQ(warning.severity, Severity::Warning);
  EXPECT_EQ(warning.location.line, 2);
  EXPECT_EQ(warning.location.column, 27);
  EXPECT_NE(warning.message.find("not found; the circular stop is kept"), std::string::npos)
      << warning.message;
  std::filesystem::remove_all(dir);
}

TEST(ApertureLensFile, AMirroredImageIsReadMirroredAndWrittenBackAsMirrored) {
  // A flipped lens saves its image iris as "image-mirrored": the file's picture seen from behind.
  const auto dir = std::filesystem::temp_directory_path() / "lenslab-aperture-mirrored";
  std::filesystem::create_directories(dir);
  // Open where column < 5 or row < 3: no left-right symmetry.
  std::vector<unsigned char> pixels(16 * 16, 0);
  for (int row = 0; row < 16; ++row)
    for (int col = 0; col < 16; ++col)
      if (col < 5 || row < 3) pixels[row * 16 + col] = 255;
  ASSERT_NE(stbi_write_png((dir / "iris.png").c_str(), 16, 16, 1, pixels.data(), 16), 0);
  std::ofstream(dir / "turned.dat") << "# lenslab aperture: image-mirrored iris.png\n" << kRows;
  const auto read = readLensFile(dir / "turned.dat");
  ASSERT_TRUE(read.ok()) << read.diagnostics.formatAll();
  const ApertureShape& shape = read.lens->prescription.stopShape;
  ASSERT_EQ(shape.kind, ApertureShape::Kind::Image);
  EXPECT_TRUE(shape.mirrored);
  ASSERT_TRUE(shape.mask);
  ASSERT_EQ(shape.mask->sizePx, 16);
  for (int row = 0; row < 16; ++row)
    for (int col = 0; col < 16; ++col)
      EXPECT_EQ(shape.mask->open[row * 16 + col], pixels[row * 16 + (15 - col)] ? 1 : 0)
          << row << ", " << col;
  EXPECT_NE(
      formatLensText(read.lens->prescription).find("# lenslab aperture: image-mirrored iris.png\n"),
      std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ApertureLensFile, PbrtsBuiltInMasksReadBackByName) {
  // A lens opened from a scene with "string aperture" "star" or "gaussian" saves the mask's
  // name; with no file of that name beside the lens, the built-in mask is used again.
  const auto dir = std::filesystem::temp_directory_path() / "lenslab-aperture-builtin";
  std::filesystem::create_directories(dir);
  for (const char* name : {"star", "gaussian"}) {
    SCOPED_TRACE(name);
    std::ofstream(dir / "lens.dat") << "# lenslab aperture: image-mirrored " << name << "\n"
                                    << kRows;
    const auto read = readLensFile(dir / "lens.dat");
    ASSERT_TRUE(read.ok()) << read.diagnostics.formatAll();
    EXPECT_TRUE(read.diagnostics.empty()) << read.diagnostics.formatAll();
    const ApertureShape& shape = read.lens->prescription.stopShape;
    ASSERT_EQ(shape.kind, ApertureShape::Kind::Image);
    ASSERT_TRUE(shape.mask);
    EXPECT_TRUE(shape.mirrored);
    const auto builtin = builtinPbrtAperture(name);
    EXPECT_EQ(shape.mask->open, mirroredMask(*builtin->mask)->open);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lenslab::optics
