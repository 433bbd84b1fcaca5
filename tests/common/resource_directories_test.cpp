#include "common/resource_directories.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/run_process.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

// A fake machine: a checkout with its build tree, an install moved to another prefix, and the
// prefix the build was configured for. Each test creates only the directories it needs.
struct FakeTrees {
  fs::path root;
  fs::path source() const { return root / "checkout"; }
  fs::path build() const { return root / "checkout" / "build"; }
  fs::path movedPrefix() const { return root / "opt" / "lenslab"; }
  fs::path configuredData() const { return root / "usr" / "local" / "share" / "lenslab"; }

  ResourceSearchPlaces places(const fs::path& executableDirectory) const {
    return {executableDirectory, build(), source(), "../share/lenslab", configuredData()};
  }
};

FakeTrees makeTrees(const std::string& name) {
  return FakeTrees{fs::canonical(testing::makeTestDirectory("resources-" + name))};
}

fs::path makeDirectory(const fs::path& path) {
  fs::create_directories(path);
  return path;
}

TEST(ResourceDirectories, TheBuildTreeUsesTheCheckout) {
  const FakeTrees trees = makeTrees("build");
  makeDirectory(trees.build());
  const fs::path lenses = makeDirectory(trees.source() / "lenses");
  makeDirectory(trees.configuredData() / "lenses");  // an older install must not win
  EXPECT_EQ(findResourceDirectory("lenses", trees.places(trees.build())), lenses);
}

TEST(ResourceDirectories, TheGlassCataloguesAreUnderDataInTheCheckoutAndBesideLensesInstalled) {
  const FakeTrees trees = makeTrees("glass");
  makeDirectory(trees.build());
  makeDirectory(trees.source() / "glass");  // not where the checkout keeps them
  const fs::path checkout = makeDirectory(trees.source() / "data" / "glass");
  EXPECT_EQ(findResourceDirectory("glass", trees.places(trees.build())), checkout);
  const fs::path bin = makeDirectory(trees.movedPrefix() / "bin");
  const fs::path installed = makeDirectory(trees.movedPrefix() / "share" / "lenslab" / "glass");
  EXPECT_EQ(findResourceDirectory("glass", trees.places(bin)), installed);
}

TEST(ResourceDirectories, AnInstallUnderAnotherPrefixUsesItsOwnShareDirectory) {
  const FakeTrees trees = makeTrees("moved");
  const fs::path bin = makeDirectory(trees.movedPrefix() / "bin");
  const fs::path scenes = makeDirectory(trees.movedPrefix() / "share" / "lenslab" / "scenes");
  // Both the checkout and the configured prefix have scenes too: neither is this install's.
  makeDirectory(trees.source() / "scenes");
  makeDirectory(trees.configuredData() / "scenes");
  EXPECT_EQ(findResourceDirectory("scenes", trees.places(bin)), scenes);
}

TEST(ResourceDirectories, ADirectoryBesideTheExecutableComesFirst) {
  const FakeTrees trees = makeTrees("beside");
  const fs::path bin = makeDirectory(trees.movedPrefix() / "bin");
  const fs::path beside = makeDirectory(bin / "lenses");
  makeDirectory(trees.movedPrefix() / "share" / "lenslab" / "lenses");
  EXPECT_EQ(findResourceDirectory("lenses", trees.places(bin)), beside);
}

TEST(ResourceDirectories, TheConfiguredPrefixIsTheLastResort) {
  const FakeTrees trees = makeTrees("configured");
  const fs::path bin = makeDirectory(trees.root / "somewhere" / "bin");
  const fs::path lenses = makeDirectory(trees.configuredData() / "lenses");
  EXPECT_EQ(findResourceDirectory("lenses", trees.places(bin)), lenses);
  // Without the executable's directory (no /proc), the configured prefix still answers.
  EXPECT_EQ(findResourceDirectory("lenses", trees.places({})), lenses);
}

TEST(ResourceDirectories, AFileWithTheNameIsNotADirectoryAndNothingFoundIsEmpty) {
  const FakeTrees trees = makeTrees("none");
  const fs::path bin = makeDirectory(trees.movedPrefix() / "bin");
  std::ofstream(bin / "lenses") << "not a directory";
  EXPECT_EQ(findResourceDirectory("lenses", trees.places(bin)), fs::path());
}

TEST(ResourceDirectories, CandidatesInLookupOrder) {
  const FakeTrees trees = makeTrees("order");
  makeDirectory(trees.build());
  const auto inBuild = resourceCandidates("scenes", trees.places(trees.build()));
  ASSERT_EQ(inBuild.size(), 4u);
  EXPECT_EQ(inBuild[0], trees.build() / "scenes");
  EXPECT_EQ(inBuild[1], trees.source() / "scenes");
  EXPECT_EQ(inBuild[2], trees.build() / "../share/lenslab" / "scenes");
  EXPECT_EQ(inBuild[3], trees.configuredData() / "scenes");
  // Outside the build tree the checkout is not a candidate.
  const fs::path bin = makeDirectory(trees.movedPrefix() / "bin");
  const auto installed = resourceCandidates("scenes", trees.places(bin));
  ASSERT_EQ(installed.size(), 3u);
  EXPECT_EQ(installed[1], bin / "../share/lenslab" / "scenes");
}

// The running test binary's own places come from this build's CMake configuration.
TEST(ResourceDirectories, ThisBuildFindsTheCheckoutFromTheBuildTree) {
  ResourceSearchPlaces places = resourceSearchPlaces();
  EXPECT_EQ(places.sourceDirectory, fs::path(LENSLAB_SOURCE_DIR));
  EXPECT_EQ(places.dataDirectoryFromExecutable, fs::path("../share/lenslab"));
  EXPECT_EQ(places.installDataDirectory.filename(), "lenslab");
  // As the lenslab binary at the top of the build tree sees it.
  places.executableDirectory = places.buildDirectory;
  EXPECT_EQ(findResourceDirectory("lenses", places),
            fs::canonical(fs::path(LENSLAB_SOURCE_DIR) / "lenses"));
}

}  // namespace
}  // namespace lenslab
