// The installed lenslab, as a user gets it: `cmake --install` of this build tree into a temporary
// prefix, and the .deb that CPack makes from it, unpacked with dpkg-deb. Each is run from a
// directory that is neither the checkout nor the build tree, so only the installed files can
// answer.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "support/run_process.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

// Single-quoted for the shell. (Built with append: GCC 12 warns, wrongly, of overlapping copies in
// "'" + string + "'".)
std::string quoted(const fs::path& path) {
  std::string text = "'";
  text.append(path.string()).append("'");
  return text;
}

// Every regular file under `root`, relative to it.
std::set<std::string> filesUnder(const fs::path& root) {
  std::set<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.is_regular_file()) files.insert(fs::relative(entry.path(), root).string());
  }
  return files;
}

// The number on the "effective focal length (EFL)" line of `lenslab info`'s report; NaN without
// one.
double eflMm(const std::string& report) {
  const std::string label = "effective focal length (EFL)";
  const std::size_t at = report.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(report.c_str() + at + label.size(), nullptr);
}

// The width and height in a PNG's IHDR chunk (big-endian, bytes 16-23).
std::array<int, 2> pngSize(const fs::path& path) {
  const std::string bytes = testing::readWholeFile(path);
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {0, 0};
  auto word = [&](std::size_t at) {
    int value = 0;
    for (std::size_t i = 0; i < 4; ++i)
      value = value * 256 + static_cast<unsigned char>(bytes[at + i]);
    return value;
  };
  return {word(16), word(20)};
}

// One install into a temporary prefix, shared by the tests of the installed tree.
class InstalledTree : public ::testing::Test {
 protected:
  static fs::path prefix;
  static testing::ProcessResult install;

  static void SetUpTestSuite() {
    const fs::path directory = testing::makeTestDirectory("install");
    prefix = directory / "prefix";
    install = testing::runProcess(std::string(CMAKE_COMMAND) + " --install " +
                                      quoted(LENSLAB_BUILD_DIR) + " --prefix " + quoted(prefix),
                                  directory);
  }
  void SetUp() override { ASSERT_EQ(install.exitCode, 0) << install.out << install.err; }

  fs::path scratch = testing::makeTestDirectory("installed-run");
  fs::path installedLenslab() const { return prefix / "bin" / "lenslab"; }
  fs::path data() const { return prefix / "share" / "lenslab"; }
  // Runs `command` from the scratch directory.
  testing::ProcessResult runHere(const std::string& command) {
    return testing::runProcess("cd " + quoted(scratch) + " && " + command, scratch);
  }
  // Runs the installed viewer under Xvfb from the scratch directory with `arguments` until its
  // first preview sample, and returns its dump-ui (discarded when it failed).
  nlohmann::json runViewer(const std::string& arguments) {
    std::ofstream(scratch / "commands.script") << "wait-spp 1\ndump-ui ui.json\nquit\n";
    fs::remove(scratch / "ui.json");
    const auto result = runHere(quoted(fs::path(LENSLAB_SOURCE_DIR) / "tests/app/with-xvfb") + " " +
                                quoted(installedLenslab()) +
                                " --size 800x500 --script commands.script " + arguments);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    std::ifstream file(scratch / "ui.json");
    return nlohmann::json::parse(file, nullptr, false);
  }
};

fs::path InstalledTree::prefix;
testing::ProcessResult InstalledTree::install;

TEST_F(InstalledTree, HoldsTheBinaryTheDataAndTheDesktopFilesAndNothingElse) {
  std::set<std::string> expected = {"bin/lenslab", "share/applications/lenslab.desktop",
                                    "share/icons/hicolor/scalable/apps/lenslab.svg",
                                    "share/icons/hicolor/256x256/apps/lenslab.png"};
  // Each bundled directory of the checkout and its installed name (the glass catalogues are
  // data/glass in the checkout).
  for (const auto& [checkout, installed] : {std::pair<std::string, std::string>{"lenses", "lenses"},
                                            {"scenes", "scenes"},
                                            {"data/glass", "glass"}}) {
    for (const auto& entry : fs::directory_iterator(fs::path(LENSLAB_SOURCE_DIR) / checkout)) {
      expected.insert("share/lenslab/" + installed + "/" + entry.path().filename().string());
    }
  }
  EXPECT_EQ(filesUnder(prefix), expected);  // no test or benchmark executable
  EXPECT_EQ(pngSize(prefix / "share/icons/hicolor/256x256/apps/lenslab.png"),
            (std::array<int, 2>{256, 256}));
}

TEST_F(InstalledTree, InfoReadsAnInstalledLens) {
  const auto result = runHere(quoted(installedLenslab()) + " info " +
                              quoted(data() / "lenses" / "dgauss-50mm.dat"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // pbrt-v3's dgauss.dat, which the file reproduces: f = 50.36 mm.
  EXPECT_NEAR(eflMm(result.out), 50.36, 0.01) << result.out;
}

// The default scene names its lens as ../lenses/dgauss-50mm.dat: installed, that is the installed
// lens. The picture is the same as the checkout's scene gives through the build tree's binary.
TEST_F(InstalledTree, TheInstalledDefaultSceneRendersAsTheCheckoutsDoes) {
  const std::string settings = " --resolution 48x32 --spp 2 --threads 1 --quiet --out ";
  const auto installed =
      runHere(quoted(installedLenslab()) + " render " + quoted(data() / "scenes" / "default.pbrt") +
              settings + "installed.png");
  ASSERT_EQ(installed.exitCode, 0) << installed.err;
  const auto built = runHere(quoted(fs::path(LENSLAB_BUILD_DIR) / "lenslab") + " render " +
                             quoted(fs::path(LENSLAB_SOURCE_DIR) / "scenes" / "default.pbrt") +
                             settings + "built.png");
  ASSERT_EQ(built.exitCode, 0) << built.err;
  const std::string picture = testing::readWholeFile(scratch / "installed.png");
  EXPECT_GT(picture.size(), 100u);
  EXPECT_EQ(picture, testing::readWholeFile(scratch / "built.png"));
}

// The viewer's own lookup (src/common/resource_directories.cpp): started with no --lens or
// --scene from an unrelated directory, it opens the installed default lens and scene.
TEST_F(InstalledTree, TheViewerOpensTheInstalledDefaultLensAndScene) {
  const auto dump = runViewer("");
  ASSERT_FALSE(dump.is_discarded());
  const fs::path canonicalData = fs::canonical(data());
  EXPECT_EQ(dump["state"]["scene_path"].get<std::string>(),
            (canonicalData / "scenes" / "default.pbrt").string());
  EXPECT_EQ(fs::weakly_canonical(dump["state"]["lens_path"].get<std::string>()),
            canonicalData / "lenses" / "dgauss-50mm.dat");
}

// The desktop entry's Exec=lenslab %f: a file manager passes the file alone, a lens or a scene.
TEST_F(InstalledTree, TheViewerOpensALensOrSceneGivenAsTheDesktopEntryDoes) {
  const fs::path lens = data() / "lenses" / "wide-22mm.dat";
  const auto withLens = runViewer(quoted(lens));
  ASSERT_FALSE(withLens.is_discarded());
  EXPECT_EQ(fs::weakly_canonical(withLens["state"]["lens_path"].get<std::string>()),
            fs::canonical(lens));  // kept when the default scene brings its own

  // A scene of the user's, beside the lens it names.
  fs::create_directories(scratch / "mine" / "scenes");
  fs::create_directories(scratch / "mine" / "lenses");
  fs::copy_file(data() / "scenes" / "default.pbrt", scratch / "mine" / "scenes" / "chart.pbrt");
  fs::copy_file(data() / "lenses" / "dgauss-50mm.dat",
                scratch / "mine" / "lenses" / "dgauss-50mm.dat");
  const auto withScene = runViewer("mine/scenes/chart.pbrt");
  ASSERT_FALSE(withScene.is_discarded());
  EXPECT_EQ(withScene["state"]["scene_path"], "mine/scenes/chart.pbrt");  // as given
  EXPECT_EQ(withScene["state"]["scene_loading"], "");
  // The viewer ran in the scratch directory: relative paths are relative to it.
  const fs::path sceneLens = withScene["state"]["lens_path"].get<std::string>();
  EXPECT_EQ(fs::weakly_canonical(scratch / sceneLens),
            fs::canonical(scratch / "mine" / "lenses" / "dgauss-50mm.dat"));
}

TEST_F(InstalledTree, TheDesktopFileIsValidAndNamesTheInstalledIcon) {
  const fs::path desktop = prefix / "share" / "applications" / "lenslab.desktop";
  const auto result = runHere("desktop-file-validate " + quoted(desktop));
  ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
  // Hints (several main categories, as asked for) are fine; errors and warnings are not.
  const std::string report = result.out + result.err;
  EXPECT_EQ(report.find("error:"), std::string::npos) << report;
  EXPECT_EQ(report.find("warning:"), std::string::npos) << report;
  const std::string entry = testing::readWholeFile(desktop);
  EXPECT_NE(entry.find("\nExec=lenslab %f\n"), std::string::npos);
  EXPECT_NE(entry.find("\nIcon=lenslab\n"), std::string::npos);
  EXPECT_NE(entry.find("\nCategories=Graphics;Science;Education;\n"), std::string::npos);
}

// The .deb CPack makes from this build tree (packaging/CMakeLists.txt), unpacked without
// installing it: its /usr tree works from wherever it lands.
TEST(Deb, UnpackedItRunsAndFindsItsLens) {
  const fs::path directory = testing::makeTestDirectory("deb");
  const auto packed =
      testing::runProcess(std::string(CPACK_COMMAND) + " --config " +
                              quoted(fs::path(LENSLAB_BUILD_DIR) / "CPackConfig.cmake") +
                              " -G DEB -B " + quoted(directory / "out"),
                          directory);
  ASSERT_EQ(packed.exitCode, 0) << packed.out << packed.err;
  fs::path deb;
  for (const auto& entry : fs::directory_iterator(directory / "out")) {
    if (entry.path().extension() == ".deb") deb = entry.path();
  }
  ASSERT_FALSE(deb.empty()) << packed.out;
  EXPECT_EQ(deb.filename().string().rfind("lenslab_" LENSLAB_VERSION "_", 0), 0u) << deb;

  const auto fields = testing::runProcess(
      "dpkg-deb -f " + quoted(deb) + " Package Version Section Depends", directory);
  ASSERT_EQ(fields.exitCode, 0) << fields.err;
  EXPECT_NE(fields.out.find("Package: lenslab\n"), std::string::npos) << fields.out;
  EXPECT_NE(fields.out.find("Version: " LENSLAB_VERSION "\n"), std::string::npos) << fields.out;
  EXPECT_NE(fields.out.find("Section: graphics\n"), std::string::npos) << fields.out;
  // dpkg-shlibdeps found the runtime libraries the binary links.
  for (const char* library : {"libglfw3", "libembree3", "libtbb"}) {
    EXPECT_NE(fields.out.find(library), std::string::npos) << fields.out;
  }

  const fs::path root = directory / "root";
  const auto extracted =
      testing::runProcess("dpkg-deb -x " + quoted(deb) + " " + quoted(root), directory);
  ASSERT_EQ(extracted.exitCode, 0) << extracted.err;
  const fs::path elsewhere = directory / "elsewhere";
  fs::create_directories(elsewhere);
  const auto info =
      testing::runProcess("cd " + quoted(elsewhere) + " && " + quoted(root / "usr/bin/lenslab") +
                              " info " + quoted(root / "usr/share/lenslab/lenses/dgauss-50mm.dat"),
                          directory);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NEAR(eflMm(info.out), 50.36, 0.01) << info.out;
  EXPECT_TRUE(fs::is_regular_file(root / "usr/share/applications/lenslab.desktop"));
  EXPECT_TRUE(fs::is_regular_file(root / "usr/share/lenslab/scenes/default.pbrt"));
}

}  // namespace
}  // namespace lenslab
