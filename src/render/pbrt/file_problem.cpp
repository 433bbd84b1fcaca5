#include "render/pbrt/file_problem.h"

#include <system_error>

namespace lenslab::render::pbrt {

std::optional<std::string> fileProblem(const std::filesystem::path& path, const std::string& what) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) {
    return what + " " + path.string() + " does not exist";
  }
  if (error) return "cannot open " + what + " " + path.string() + ": " + error.message();
  if (status.type() == std::filesystem::file_type::directory) {
    return what + " " + path.string() + " is a directory, not a file";
  }
  return std::nullopt;
}

}  // namespace lenslab::render::pbrt
