#pragma once
// OpticStudio (Zemax) sequential lens files, .zmx (issue 41). What is read, what is refused and
// what is ignored is listed in docs/file-formats.md; in short:
// - the encodings OpticStudio and other programs write (import/text_encoding.h);
// - UNIT MM, CM, IN or METER: lengths become millimetres (a curvature divides by the unit's size
//   s, an even-asphere coefficient of r^2i multiplies by s^(1-2i), a wavelength stays in µm);
// - SURF blocks of TYPE STANDARD (or none) and EVENASPH: CURV, CONI, PARM 1..8 (the r^2..r^16
//   terms), DISZ, DIAM (a semi-diameter) or a CLAP circular aperture, STOP, GLAS;
// - glasses from the catalogues in the GCAT order, ___BLANK model glasses (n_d, V_d on the line);
// - NAME, NOTE, WAVM/PWAV, FTYP/XFLN/YFLN and ENPD/FNUM/FLOA as the title, notes and design
//   conditions (design_conditions.h).
// SURF 0 is the object: its DISZ is the object distance, which lenslab does not model (a finite
// one is a note). The last SURF is the image: the DISZ before it is the film distance. What
// lenslab cannot model (mirrors, coordinate breaks, tilts and decentres, obscurations, other
// surface types, non-sequential files) is refused at its line, naming what it is.

#include <filesystem>
#include <string>
#include <string_view>

#include "optics/lens_file.h"

namespace lenslab::optics {

// Parses .zmx text already decoded to UTF-8; `fileName` is only used in messages.
LensFileResult parseZemaxText(std::string_view text, const std::string& fileName);
// Decodes the file's bytes (decodeText) and parses them; a Latin-1 guess is a note, an
// undecodable file an error at the place decoding stopped.
LensFileResult parseZemaxBytes(std::string_view bytes, const std::string& fileName);

// .zmx in any case.
bool hasZemaxExtension(const std::filesystem::path& path);

}  // namespace lenslab::optics
