#include "optics/lens_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace lenslab::optics {
namespace {

class LensLoader : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("lenslab-test-lens-loader-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  // Writes a lens file whose rows start on line 3, after two comment lines, so that a row's line
  // is not its surface number.
  std::string writeLens(const std::string& name, const std::string& rows) {
    const std::filesystem::path path = directory_ / name;
    std::ofstream(path, std::ios::binary) << "# a test lens\n# from nowhere\n" << rows;
    return path.string();
  }

 private:
  std::filesystem::path directory_;
};

// A biconvex singlet (V_d 60) and the stop behind it.
constexpr const char* kSingletRows =
    "50 5 1.5 20 60\n"
    "-50 2 1 20\n"
    "0 40 0 10\n";

TEST_F(LensLoader, BuildsAGoodFileAndKeepsWhatItRead) {
  const LoadedLens lens = loadLens(writeLens("good.dat", kSingletRows), 486.13);
  ASSERT_TRUE(lens.ok()) << lens.diagnostics.formatAll();
  EXPECT_TRUE(lens.diagnostics.empty());
  EXPECT_EQ(lens.system->wavelengthNm(), 486.13);
  ASSERT_EQ(lens.system->prescription().surfaces.size(), 3u);
  EXPECT_EQ(lens.system->prescription().surfaces[1].radiusMm, -50.0);
  EXPECT_EQ(lens.file.prescription.surfaces.size(), 3u);
  EXPECT_EQ(lens.file.prescription.surfaces[0].abbeD, 60.0);
  EXPECT_EQ(lens.file.headerComments, (std::vector<std::string>{"a test lens", "from nowhere"}));
  EXPECT_EQ(lens.file.rowLines, (std::vector<int>{3, 4, 5}));
  // A biconvex singlet in air: thin-lens estimate 1 / f = (n - 1)(2 / R) gives f = 50 mm; the
  // 5 mm thickness lengthens it a little.
  EXPECT_GT(lens.system->firstOrder().eflMm, 50.0);
  EXPECT_LT(lens.system->firstOrder().eflMm, 52.0);
}

TEST_F(LensLoader, ReportsASyntaxErrorAtItsLineAndColumn) {
  const std::string path = writeLens("syntax.dat", "50 5 1.5 20\n-50 2 zz 20\n0 40 0 10\n");
  const LoadedLens lens = loadLens(path);
  EXPECT_FALSE(lens.ok());
  EXPECT_EQ(lens.system, nullptr);
  EXPECT_TRUE(lens.file.prescription.surfaces.empty());
  EXPECT_EQ(lens.diagnostics.formatAll(),
            path + ":4:7: error: 'zz' is not a number (expected the refractive index)\n");
}

TEST_F(LensLoader, ReportsAMissingFile) {
  const std::string path = (std::filesystem::temp_directory_path() / "no-such-lens.dat").string();
  const LoadedLens lens = loadLens(path);
  EXPECT_FALSE(lens.ok());
  EXPECT_EQ(lens.diagnostics.formatAll(), path + ":1:1: error: no such file\n");
}

TEST_F(LensLoader, ReportsALensThatCannotBeBuiltAtTheFailingRow) {
  // Every number is well formed, but the second surface crosses the first: reported at the
  // second row (line 4), naming surface 2 as the lens table counts.
  const std::string path = writeLens("crossing.dat", "12 1 1.5 20\n-12 5 1 20\n0 40 0 10\n");
  const LoadedLens lens = loadLens(path);
  EXPECT_FALSE(lens.ok());
  ASSERT_EQ(lens.diagnostics.all().size(), 1u) << lens.diagnostics.formatAll();
  const std::string reported = lens.diagnostics.all().front().format();
  EXPECT_EQ(
      reported.rfind(path + ":4:1: error: surface 2: crosses the previous surface (surface 1)", 0),
      0u)
      << reported;
}

TEST_F(LensLoader, ReportsABuildErrorOfTheWholeLensAtItsFirstRow) {
  // The file is valid; only the wavelength it is built at is not. That is the lens as a whole,
  // reported at its first row, and the file as read is still there.
  const std::string path = writeLens("good.dat", kSingletRows);
  const LoadedLens lens = loadLens(path, 0.0);
  EXPECT_FALSE(lens.ok());
  EXPECT_EQ(lens.file.prescription.surfaces.size(), 3u);
  EXPECT_EQ(lens.diagnostics.formatAll(),
            path + ":3:1: error: wavelength must be a positive number of nanometres\n");
}

}  // namespace
}  // namespace lenslab::optics
