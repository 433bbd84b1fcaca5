#pragma once
// Lens files in pbrt's format: one surface per row, "radius thickness n aperture-diameter", front
// to rear, `#` starts a comment. lenslab also reads and writes an optional fifth column, V_d, and
// `inf` as the radius of a flat refracting surface. Radius 0 is the aperture stop, n 0 means air.
//
// The stop's shape (aperture_shape.h) is a comment line, which pbrt ignores:
//   # lenslab aperture: blades 6 curvature 0.5 rotation 15   (3..32 blades; curvature 0 straight
//                                                             to 1 round, default 0; rotation of
//                                                             the first corner from +x, degrees)
//   # lenslab aperture: image iris.png                        (a square image, white = open,
//                                                             relative to the lens file's folder)
//   # lenslab aperture: circle                                (the default; not written)
// anywhere in the file (the writer puts it after the header comments). A malformed line is an
// error at its file:line:column; an image that is missing, unreadable, not square or all black
// is a warning there, and the stop stays a circle.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostics.h"
#include "optics/prescription.h"

namespace lenslab::optics {

struct LensFile {
  Prescription prescription;
  // Comment lines before the first row, without the leading '#' and one following space.
  std::vector<std::string> headerComments;
  // Line number (1-based) of each surface row, for error messages that point at a row.
  std::vector<int> rowLines;
  // The line of a surface's row (a 0-based index, as ValidationError::surface counts); the first
  // row's for the lens as a whole (-1) or an index the file has no row for; 0 without rows.
  int lineOfSurface(int surface) const;
};

struct LensFileResult {
  std::optional<LensFile> lens;  // set only when the whole file is valid
  // The errors, at their file:line:column (none on success); also warnings (an aperture image
  // that cannot be used) on success.
  Diagnostics diagnostics;
  bool ok() const { return lens.has_value(); }
};

// Parses lens file text; `fileName` is only used in the error messages. The prescription is
// checked with validate() as well, so a successful result always builds a LensSystem.
LensFileResult parseLensText(std::string_view text, const std::string& fileName);
LensFileResult readLensFile(const std::filesystem::path& path);

// Text that parseLensText reads back to the identical prescription (shortest round-trip number
// formatting).
std::string formatLensText(const Prescription& prescription,
                           const std::vector<std::string>& headerComments = {});
// Returns false and sets `error` when the file cannot be written.
bool writeLensFile(const std::filesystem::path& path, const Prescription& prescription,
                   const std::vector<std::string>& headerComments, std::string* error);

}  // namespace lenslab::optics
