#include "app/library/library_entry.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

#include "app/document/lens_document.h"
#include "app/lens_caption.h"
#include "optics/field.h"
#include "optics/lens_file_formats.h"
#include "optics/lens_loader.h"
#include "optics/limiting_aperture.h"
#include "optics/ray_fan.h"

namespace lenslab::app {

std::uint64_t contentHash(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::vector<std::filesystem::path> listLibraryFiles(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.is_regular_file(error) && optics::hasLensFileExtension(entry.path()))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return a.filename() < b.filename(); });
  return files;
}

int countElements(const optics::Prescription& prescription) {
  // A piece of glass starts at each surface with glass after it: a cemented doublet's three
  // surfaces are two elements (glass after the first and the second, air after the third).
  int elements = 0;
  for (const optics::Surface& surface : prescription.surfaces)
    elements += !surface.isStop() && surface.mediumIndexD() != 1.0;
  return elements;
}

int countAsphericSurfaces(const optics::Prescription& prescription) {
  int count = 0;
  for (const optics::Surface& surface : prescription.surfaces)
    count += !surface.isStop() && !surface.profile.isSphere();
  return count;
}

namespace {

// The largest magnitude among a design's field values; 0 without any.
double libraryFullFieldValue(const optics::DesignFields& fields) {
  double largest = 0.0;
  for (const double value : fields.values) largest = std::max(largest, std::abs(value));
  return largest;
}

// Half the real field of view of the chief ray landing `imageHeightMm` from the axis.
std::optional<double> libraryHalfFieldAt(const optics::LensSystem& system, double imageHeightMm) {
  const auto full = optics::realFieldOfViewDeg(system, 2.0 * imageHeightMm);
  if (!full || !std::isfinite(*full)) return std::nullopt;
  return 0.5 * *full;
}

}  // namespace

LibraryEntry readLibraryEntry(const std::filesystem::path& path,
                              std::shared_ptr<const optics::LensSystem>* system) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  optics::LoadedLens loaded = optics::loadLens(path);
  LibraryEntry entry;
  if (loaded.ok()) {
    entry = describeLibraryLens(path, loaded.file, *loaded.system);
  } else {
    entry.path = path;
    entry.fileName = entry.name = path.filename().string();
    const auto& errors = loaded.diagnostics.all();
    entry.error = errors.empty() ? path.string() + ": cannot be read" : errors.front().format();
  }
  entry.contentHash = contentHash(bytes.str());
  if (system) *system = loaded.system;
  return entry;
}

LibraryEntry describeLibraryLens(const std::filesystem::path& path, const optics::LensFile& file,
                                 const optics::LensSystem& system) {
  LibraryEntry entry;
  entry.path = path;
  entry.fileName = path.filename().string();
  entry.name = lensNameOf(detailsOf(file), path.string());
  entry.type = file.lensType;
  entry.source = file.source;
  entry.year = file.year;
  entry.elements = countElements(file.prescription);
  entry.asphericSurfaces = countAsphericSurfaces(file.prescription);
  const optics::FirstOrderData& firstOrder = system.firstOrder();
  if (firstOrder.afocal || !std::isfinite(firstOrder.eflMm)) return entry;
  entry.eflMm = firstOrder.eflMm;
  // As the first-order section's f-number (lens_figures.h): the beam that passes every rim, not
  // the iris's alone.
  const auto limit =
      optics::findParaxialAxialLimit(system, std::numeric_limits<double>::infinity());
  const double fNumber =
      limit && std::isfinite(limit->workingFNumber) ? limit->workingFNumber : firstOrder.fNumber;
  if (std::isfinite(fNumber) && fNumber > 0.0) entry.fNumber = fNumber;
  // The field the file states, else the one the lens covers on a full-frame film (or its image
  // circle, when that is smaller: a fisheye's, a phone lens's).
  const optics::DesignFields& design = file.design.fields;
  const double stated = libraryFullFieldValue(design);
  if (stated > 0.0 && design.kind == optics::FieldKind::ObjectAngleDeg) {
    entry.halfFieldDeg = stated;
    entry.halfFieldFrom = "design field";
  } else if (stated > 0.0 && (design.kind == optics::FieldKind::RealImageHeightMm ||
                              design.kind == optics::FieldKind::ParaxialImageHeightMm)) {
    entry.halfFieldDeg = libraryHalfFieldAt(system, stated);
    entry.halfFieldFrom = "design field";
  }
  const double corner = 0.5 * kLibraryFilmDiagonalMm;
  const double circle = optics::coverageImageHeightMm(system, std::nullopt);
  const bool covered = !(circle < corner) || !(circle > 0.0);
  entry.fansHalfDiagonalMm = covered ? corner : circle;
  if (!entry.halfFieldDeg) {
    entry.halfFieldDeg = libraryHalfFieldAt(system, covered ? corner : circle);
    entry.halfFieldFrom = covered ? "full-frame corner" : "image circle";
  }
  if (!entry.halfFieldDeg) entry.halfFieldFrom.clear();
  return entry;
}

}  // namespace lenslab::app
