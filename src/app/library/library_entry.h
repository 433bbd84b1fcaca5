#pragma once
// What the library browser says of one lens file (Lens > Library, panels/library_panel.cpp): its
// name and design type, the figures computed from its prescription (focal length, f-number,
// field), what it is made of (elements, aspheric surfaces) and the year of its source. Read off
// the UI thread (library_catalogue.h); no ImGui or GL here, so it is unit-tested.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "optics/lens_file.h"
#include "optics/lens_system.h"

namespace lenslab::app {

// The film the browser measures a lens's field on when its file states none: the 36 x 24 mm full
// frame, as the viewer's default film.
inline constexpr double kLibraryFilmDiagonalMm = 43.27;

struct LibraryEntry {
  std::filesystem::path path;
  std::string fileName;  // "dgauss-50mm.dat"
  // The lens's name as the viewer's caption gives it (lens_caption.h: its title, a .dat's first
  // header comment, else the file's stem), without a nominal f-number.
  std::string name;
  std::string type;    // the file's design type ("double-Gauss"); "" when it states none
  std::string source;  // the publication it comes from; "" when it states none
  std::optional<int> year;
  // Computed from the prescription, at the lens's wavelength: the paraxial EFL (none for an
  // afocal lens), the paraxial f-number of the beam that passes every rim from infinity (as the
  // first-order section writes it), and the half field in degrees (halfFieldFrom says whence).
  std::optional<double> eflMm;
  std::optional<double> fNumber;
  std::optional<double> halfFieldDeg;
  std::string halfFieldFrom;  // "design field", "full-frame corner", "image circle"
  // The film half diagonal its thumbnail's fans spread over: the full frame's, or the lens's
  // image circle when that is smaller (library_thumbnail.h).
  double fansHalfDiagonalMm = 0.5 * kLibraryFilmDiagonalMm;
  int elements = 0;          // pieces of glass: surfaces with glass after them
  int asphericSurfaces = 0;  // surfaces whose profile is not a sphere (a conic or A_i terms)
  // FNV-1a of the file's bytes: the thumbnail caches key on it, so an edited file gets a new one.
  std::uint64_t contentHash = 0;
  std::string error;  // why the file cannot be used ("" when it can); its figures are then unset
  bool usable() const { return error.empty(); }
};

// FNV-1a, 64 bits: cheap (a lens file is a few kilobytes) and stable across runs and builds.
std::uint64_t contentHash(std::string_view bytes);

// The lens files of the library folder, as the Library menu lists them: every format lenslab
// reads (optics/lens_file_formats.h), sorted by file name.
std::vector<std::filesystem::path> listLibraryFiles(const std::filesystem::path& folder);

// Reads, builds and describes the lens file at `path` (its content hash included); a file that
// cannot be used gets an entry with its first error, where and what. `system`, when given, gets
// the lens as built (null for such a file), for its thumbnail.
LibraryEntry readLibraryEntry(const std::filesystem::path& path,
                              std::shared_ptr<const optics::LensSystem>* system = nullptr);

// The entry of a file read and built (`file`, `system`): what readLibraryEntry computes for it.
LibraryEntry describeLibraryLens(const std::filesystem::path& path, const optics::LensFile& file,
                                 const optics::LensSystem& system);

// The files' elements and aspheric surfaces, as the entry counts them.
int countElements(const optics::Prescription& prescription);
int countAsphericSurfaces(const optics::Prescription& prescription);

}  // namespace lenslab::app
