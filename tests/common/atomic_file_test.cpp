#include "common/atomic_file.h"

#include <gtest/gtest.h>

#include "support/run_process.h"

namespace lenslab {
namespace {

std::size_t filesIn(const std::filesystem::path& directory) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(directory),
                                                std::filesystem::directory_iterator()));
}

TEST(AtomicFile, WritesAndReplaces) {
  const auto directory = testing::makeTestDirectory("atomic");
  const auto path = directory / "a.txt";
  ASSERT_EQ(writeFileAtomically(path, "first"), "");
  ASSERT_EQ(writeFileAtomically(path, "second, longer"), "");
  EXPECT_EQ(testing::readWholeFile(path), "second, longer");
  EXPECT_EQ(filesIn(directory), 1u);  // no temporary left behind
}

TEST(AtomicFile, AFailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const auto directory = testing::makeTestDirectory("atomic-fail");
  const auto path = directory / "a.txt";
  ASSERT_EQ(writeFileAtomically(path, "old"), "");
  const std::string error = writeThroughTemporary(path, [](const std::filesystem::path& temporary) {
    writeFileAtomically(temporary, "half written");  // the encoder got this far, then failed
    return std::string("disk full");
  });
  EXPECT_NE(error.find(path.string()), std::string::npos);
  EXPECT_NE(error.find("disk full"), std::string::npos);
  EXPECT_EQ(testing::readWholeFile(path), "old");
  EXPECT_EQ(filesIn(directory), 1u);
}

TEST(AtomicFile, UnwritableDirectoryIsAnErrorNamingThePath) {
  const std::string error = writeFileAtomically("/nonexistent-dir/a.txt", "x");
  EXPECT_NE(error.find("/nonexistent-dir/a.txt"), std::string::npos);
}

}  // namespace
}  // namespace lenslab
