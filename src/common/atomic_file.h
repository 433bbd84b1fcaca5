#pragma once
// Writing files atomically: the data goes to a temporary file beside the target, which is renamed
// into place only when it is complete. A failed or interrupted write never leaves a partial or
// truncated file, and an earlier file at the path stays intact until the new one is whole.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace lenslab {

// Returns "" on success, else a message that names `path` and says what went wrong.
std::string writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

// For encoders that insist on writing a file themselves (stb, OpenEXR): `write` writes the
// temporary path it is given and returns "" or an error; on success the file is renamed to
// `path`, on failure the temporary is removed. Returns "" or an error naming `path`.
std::string writeThroughTemporary(
    const std::filesystem::path& path,
    const std::function<std::string(const std::filesystem::path& temporary)>& write);

// Whether a file could be written at `path` now, before the work that makes it (a long render):
// its directory exists and the temporary the write would use can be created there (and is
// removed again). "" if so, else a message that names `path` and says why not ("the directory
// renders does not exist", "Permission denied", "Read-only file system", "File name too long").
std::string checkWritable(const std::filesystem::path& path);

}  // namespace lenslab
