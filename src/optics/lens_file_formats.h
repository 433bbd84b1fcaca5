#pragma once
// The lens file formats lenslab reads, by extension: the one list every door takes its extensions
// from (File > Open's filter, drag and drop, recent files, the Library menu, the command line and
// a scene's "string lensfile", which all read through readLensFile). A format that lenslab reads
// but cannot write (an import: .zmx, .seq, a patent's table) is never overwritten in that format:
// the viewer saves such a lens as .lens, and writeLensFile refuses the extension.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace lenslab::optics {

struct LensFileFormat {
  const char* extension;  // lower case, with the dot: ".zmx"
  const char* name;       // for messages: "OpticStudio .zmx"
  bool writable;          // writeLensFile can write it
};

// Every format, lenslab's own first (the default for saving).
std::span<const LensFileFormat> lensFileFormats();
// Their extensions, in that order: {".lens", ".dat", ".zmx", ".seq", ".txt"}.
std::vector<std::string> lensFileExtensions();
// For help texts and messages: ".lens, .dat, .zmx, .seq or .txt".
std::string lensFileExtensionsText();
// The format a path's extension names, in any case ("LENS2.ZMX"); null for any other.
const LensFileFormat* lensFileFormatOf(const std::filesystem::path& path);
// A lens file lenslab reads (lensFileFormatOf is not null).
bool hasLensFileExtension(const std::filesystem::path& path);

}  // namespace lenslab::optics
