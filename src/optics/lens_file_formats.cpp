#include "optics/lens_file_formats.h"

#include <algorithm>
#include <cctype>
#include <iterator>

namespace lenslab::optics {

namespace {

// Adding a format to every door is one line here (and its reader in readLensFile).
constexpr LensFileFormat kLensFileFormats[] = {
    {".lens", "lenslab .lens", true},     {".dat", "pbrt .dat", true},
    {".zmx", "OpticStudio .zmx", false},  {".seq", "CODE V .seq", false},
    {".txt", "patent table .txt", false},
};

}  // namespace

std::span<const LensFileFormat> lensFileFormats() { return kLensFileFormats; }

std::vector<std::string> lensFileExtensions() {
  std::vector<std::string> extensions;
  for (const LensFileFormat& format : kLensFileFormats) extensions.emplace_back(format.extension);
  return extensions;
}

std::string lensFileExtensionsText() {
  std::string text;
  const std::size_t count = std::size(kLensFileFormats);
  for (std::size_t i = 0; i < count; ++i)
    text += (i == 0           ? ""
             : i + 1 == count ? " or "
                              : ", ") +
            std::string(kLensFileFormats[i].extension);
  return text;
}

const LensFileFormat* lensFileFormatOf(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const LensFileFormat& format : kLensFileFormats)
    if (extension == format.extension) return &format;
  return nullptr;
}

bool hasLensFileExtension(const std::filesystem::path& path) {
  return lensFileFormatOf(path) != nullptr;
}

}  // namespace lenslab::optics
