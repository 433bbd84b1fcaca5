#pragma once
// What every `lenslab analyze` test needs: a scratch directory, lens files written into it, and
// the command's JSON (the test fails when it exits non-zero).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {

class AnalyzeTest : public ::testing::Test {
 protected:
  explicit AnalyzeTest(const char* directory) : scratch(testing::makeTestDirectory(directory)) {}

  std::string writeFile(const std::string& name, const std::string& text) {
    const auto path = scratch / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }
  nlohmann::json analyzeJson(const std::string& arguments) {
    const auto result = testing::runProcess(lenslab("analyze --json " + arguments), scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return result.exitCode == 0 ? nlohmann::json::parse(result.out) : nlohmann::json{};
  }

  std::filesystem::path scratch;
};

}  // namespace lenslab
