#pragma once
// Runs a shell command from a test and captures its exit code, stdout and stderr.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lenslab::testing {

struct ProcessResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline std::string readWholeFile(const std::filesystem::path& path) {
  std::ifstream input(path, std::ios::binary);
  std::ostringstream text;
  text << input.rdbuf();
  return text.str();
}

// A fresh, empty directory for one test's files.
inline std::filesystem::path makeTestDirectory(const std::string& name) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() /
      ("lenslab-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

inline ProcessResult runProcess(const std::string& command,
                                const std::filesystem::path& scratchDirectory) {
  const auto out = scratchDirectory / "stdout.txt";
  const auto err = scratchDirectory / "stderr.txt";
  const std::string full = command + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(full.c_str());
  ProcessResult result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = readWholeFile(out);
  result.err = readWholeFile(err);
  return result;
}

}  // namespace lenslab::testing
