#include "common/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace lenslab {

namespace {

// Beside the target, so the rename stays on one filesystem; the process id keeps two writers of
// the same path from sharing a temporary.
std::filesystem::path temporaryFor(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += ".tmp-lenslab-" + std::to_string(::getpid());
  return temporary;
}

}  // namespace

std::string writeThroughTemporary(
    const std::filesystem::path& path,
    const std::function<std::string(const std::filesystem::path& temporary)>& write) {
  const std::filesystem::path temporary = temporaryFor(path);
  std::error_code ignored;
  if (const std::string error = write(temporary); !error.empty()) {
    std::filesystem::remove(temporary, ignored);
    return "cannot write " + path.string() + ": " + error;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, ignored);
    return "cannot write " + path.string() + ": " + error.message();
  }
  return {};
}

std::string checkWritable(const std::filesystem::path& path) {
  const std::string prefix = "cannot write " + path.string() + ": ";
  const std::filesystem::path directory =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code error;
  if (!std::filesystem::exists(directory, error))
    return prefix + "the directory " + directory.string() + " does not exist";
  if (!std::filesystem::is_directory(directory, error))
    return prefix + directory.string() + " is not a directory";
  if (std::filesystem::is_directory(path, error)) return prefix + "it is a directory";
  // The very temporary the write will use: the same name length, directory permissions and
  // filesystem (root passes every permission check, but not a read-only filesystem's).
  const std::filesystem::path temporary = temporaryFor(path);
  errno = 0;
  std::ofstream probe(temporary, std::ios::binary | std::ios::trunc);
  if (!probe) return prefix + std::strerror(errno != 0 ? errno : EACCES);
  probe.close();
  std::filesystem::remove(temporary, error);
  return {};
}

std::string writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
  return writeThroughTemporary(path, [&](const std::filesystem::path& temporary) -> std::string {
    std::ofstream output(temporary, std::ios::binary | std::ios::trunc);
    if (!output) return std::strerror(errno != 0 ? errno : EACCES);
    errno = 0;
    output.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    output.close();  // flushes the buffer: a full disk or a file-size limit shows up here
    if (output.fail()) return errno != 0 ? std::strerror(errno) : "write failed";
    return {};
  });
}

}  // namespace lenslab
