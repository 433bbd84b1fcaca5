#pragma once
// lenslab's own lens format, `.lens`: human-readable text that holds everything a lens in
// lenslab has, which pbrt's .dat (lens_file.h) cannot: conics and aspheric terms, a title, the
// publication a prescription comes from. docs/file-formats.md is its reference; in short:
//
//   lenslab-lens 1                                   the version line, first
//   title Double-Gauss 50 mm f/2                     text keys take the rest of the line
//   source US 2,532,751, example 1
//   published_efl_mm 50.2
//   note Stop moved 1 mm toward the front.           repeatable, in order
//   aperture blades 6 curvature 0.5                  the stop's shape (aperture_shape.h)
//   design_wavelengths_nm 486.13 587.56 656.27 primary 587.56   the design conditions
//   design_fields angle_deg 0 14 20                  (design_conditions.h), each at most once
//   design_aperture f_number 2
//   surface radius 58.95 thickness 7.52 nd 1.67 vd 47.2 diameter 50.4
//   stop thickness 3 diameter 30
//   surface radius -25 thickness 3 glass N-BK7 maker SCHOTT diameter 20 conic -0.5 a4 -2.1e-06
//   surface radius 80 thickness 36.77 diameter 20
//
// One surface per row, front to rear; each row is `surface` or `stop`, then name-value pairs in
// any order. `radius` (inf for a flat surface), `thickness` (to the next surface; the last row's
// is the film distance) and `diameter` (the clear aperture) are required; the medium after the
// surface is a catalogue glass (`glass NAME`, with `maker` to choose among catalogues; the
// bundled catalogues, glass/glass_catalog_loader.h) or a model glass (`nd`, `vd`), and air
// without either; `conic` and `a2` ... `a20` give the profile
// (aspheric_profile.h). `#` starts a comment at the beginning of a line or after a row's pairs.
// Numbers are written in their shortest form that reads back exactly. Every problem is an error
// at its file:line:column; a file from a newer lenslab (version above 1) says so.

#include <filesystem>
#include <string>
#include <string_view>

#include "optics/lens_file.h"

namespace lenslab::optics {

inline constexpr std::string_view kNativeLensVersionKey = "lenslab-lens";
inline constexpr int kNativeLensVersion = 1;

// The extension is .lens (any case).
bool hasNativeLensExtension(const std::filesystem::path& path);
// The text is a .lens file: its first line that is not blank or a comment starts with the
// version key, or (for a file that lacks it, so that it gets the .lens reader's message) the
// path has the .lens extension.
bool isNativeLensText(std::string_view text, const std::filesystem::path& path);

// Parses .lens text; `fileName` is used in the messages. Validated as parseLensText is.
LensFileResult parseNativeLensText(std::string_view text, const std::string& fileName);
// Text that parseNativeLensText reads back to an identical LensFile (prescription, title,
// source, published focal length, notes, design conditions).
std::string formatNativeLensText(const LensFile& lens);

}  // namespace lenslab::optics
