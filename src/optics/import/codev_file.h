#pragma once
// CODE V sequence files (.seq): the commands CODE V writes to save a lens (`RDM;LEN`, `SO`, `S`,
// `SI`, `GO` ...), read into a LensFile. docs/file-formats.md lists what is read, what is refused
// and what is ignored.
//
// Syntax: commands are separated by ';' or line ends, '!' starts a comment, '&' at the end of a
// line continues the command on the next one, words are case-insensitive, and text in quotes
// ('...' or "...") is one word. A closing GO ends the lens; commands after it are not read.
//
// What changes the optics and lenslab cannot hold (mirrors, decentres and tilts, diffractive
// surfaces, private glasses, any command lenslab does not know) is refused at its line. What does
// not (variables, solves and pickups whose values are written, display settings) is ignored, with
// a note where a user should know.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "optics/lens_file.h"

namespace lenslab::optics {

// True for a .seq extension, in any case.
bool hasCodeVExtension(const std::filesystem::path& path);

// Reads a CODE V sequence; `fileName` is only used in the messages. Surfaces without a CIR carry
// no clear aperture until finishImportedLens sizes them from the lens's design conditions.
LensFileResult parseCodeVText(std::string_view text, const std::string& fileName);

// The lens as the sequence gives it, before finishImportedLens: surfaces without a CIR still have
// diameter 0, and nothing is validated. Empty when the text has errors (in `diagnostics`, with
// the notes and warnings). parseCodeVText is this and finishImportedLens.
std::optional<LensFile> readCodeVLens(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics);

}  // namespace lenslab::optics
