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
#include <utility>
#include <vector>

#include "common/diagnostics.h"
#include "optics/design_conditions.h"
#include "optics/prescription.h"

namespace lenslab::optics {

// Zoom lenses, the most complex camera lenses, have some 60 surfaces; a file of thousands is not a
// lens, and every analysis traces each ray through every surface. Every lens format's limit.
inline constexpr std::size_t kMaxLensFileSurfaces = 256;

struct LensFile {
  Prescription prescription;
  // Comment lines before the first row, without the leading '#' and one following space; in a
  // .lens file (native_lens_file.h), its `note` lines.
  std::vector<std::string> headerComments;
  // What a .lens file says of its lens (a .dat has no place for them): its title, the
  // publication its prescription comes from, and the focal length printed there (mm).
  std::string title;
  std::string source;
  std::optional<double> publishedEflMm;
  // The kind of design (`double-Gauss`, `telephoto`, `fisheye`, ...) and the year of the source
  // (a patent's filing or publication year, as the file says), for the library browser.
  std::string lensType;
  std::optional<int> year;
  // The wavelengths, fields and aperture the lens was designed for, when the file states them.
  DesignConditions design;
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
// Reads a lens file in any format lenslab knows: OpticStudio's .zmx (import/zemax_file.h), a
// CODE V sequence (.seq, import/codev_file.h) and a patent's numerical example saved as text (.txt,
// import/patent_table.h), by their extensions in any case; lenslab's own .lens
// (native_lens_file.h), told by its version line or its extension; and otherwise pbrt's .dat.
LensFileResult readLensFile(const std::filesystem::path& path);

// The text without a leading UTF-8 byte-order mark (some Windows editors write one; it is not
// part of the first line).
std::string_view withoutByteOrderMark(std::string_view text);

// Reads an aperture spec (aperture_shape.h's parseApertureSpec) into `shape`, loading an image
// relative to the lens file's folder. Returns the 1-based column and message of a malformed spec
// (an error); an image that cannot be used is a warning in `diagnostics` and leaves the shape as
// it was. `firstColumn` is the 1-based column where `spec` starts on its line.
std::optional<std::pair<int, std::string>> readApertureSpec(std::string_view spec,
                                                            const std::string& fileName,
                                                            ApertureShape& shape,
                                                            Diagnostics& diagnostics, int line,
                                                            int firstColumn);

// Text that parseLensText reads back to the identical prescription (shortest round-trip number
// formatting).
std::string formatLensText(const Prescription& prescription,
                           const std::vector<std::string>& headerComments = {});
// Why pbrt's .dat cannot hold this prescription ("surface 3 has a conic or aspheric terms, ..."),
// naming the first surface that does not fit; empty when it can.
std::string whyNotDat(const Prescription& prescription);
// Writes atomically in the format the extension names: .lens (native_lens_file.h) or else .dat.
// Returns false and sets `error` when the file cannot be written, when .dat cannot hold the
// lens (whyNotDat), or when the extension is a format lenslab only reads (.zmx, .seq, .txt:
// lens_file_formats.h); nothing is written then.
bool writeLensFile(const std::filesystem::path& path, const LensFile& lens, std::string* error);
bool writeLensFile(const std::filesystem::path& path, const Prescription& prescription,
                   const std::vector<std::string>& headerComments, std::string* error);

}  // namespace lenslab::optics
