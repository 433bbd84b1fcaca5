// The lens a CODE V sequence gives (codev_reader.h): lenslab's surfaces from the file's, in
// millimetres, with the stop, the film distance, the title, notes and design conditions.
#include "optics/import/codev_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "optics/import/stop_on_surface.h"

namespace lenslab::optics::codev {

LensFile SeqReader::finish(std::vector<std::string> comments) {
  LensFile lens;
  lens.headerComments = std::move(comments);
  lens.title = title_;
  const std::size_t first = 1;
  const std::size_t end = haveImage_ ? surfaces_.size() - 1 : surfaces_.size();
  if (end <= first) return lens;

  // Radius or curvature mode where no RDM said: CODE V's default is radii, but hand-written
  // sequences (ray-optics' tests) give curvatures without an RDM line. Values all below 1 in
  // magnitude are curvatures (radii under 1 mm for every surface are no camera lens).
  bool anyUnset = false, allSmall = true;
  int firstUnsetLine = 0;
  for (std::size_t i = first; i < end; ++i)
    if (surfaces_[i].mode == SeqValueMode::Unset) {
      if (!anyUnset) firstUnsetLine = surfaces_[i].line;
      anyUnset = true;
      allSmall = allSmall && std::abs(surfaces_[i].value) < 1.0;
    }
  if (anyUnset) {
    const SeqValueMode guess = allSmall ? SeqValueMode::Curvature : SeqValueMode::Radius;
    for (std::size_t i = first; i < end; ++i)
      if (surfaces_[i].mode == SeqValueMode::Unset) surfaces_[i].mode = guess;
    noteAt(firstUnsetLine,
           allSmall ? "no RDM command: the S values are read as curvatures (RDM N), since all are "
                      "below 1 in magnitude (CODE V's own default is radii)"
                    : "no RDM command: the S values are read as radii (CODE V's default, RDM Y)");
  }

  const double s = unitMm_;
  SeqMedium before;  // air in front of the lens
  std::optional<std::size_t> convertedStop;
  for (std::size_t i = first; i < end; ++i) {
    const SeqSurface& read = surfaces_[i];
    Surface row;
    double radius = kFlatRadius;
    if (read.value != 0.0)
      radius = read.mode == SeqValueMode::Radius ? read.value * s : s / read.value;
    if (std::isfinite(radius) && std::abs(radius) > kMaxLengthMm) {
      noteAt(read.line, "radius " + seqNumberText(radius) + " mm is beyond lenslab's limit of " +
                            seqNumberText(kMaxLengthMm) + " mm: read as flat");
      radius = kFlatRadius;
    }
    row.radiusMm = radius;
    row.thicknessMm = read.thickness * s;
    if (read.medium.kind == SeqMedium::Kind::Model) {
      row.indexD = read.medium.nd;
      row.abbeD = read.medium.vd;
    } else if (read.medium.kind == SeqMedium::Kind::Catalog) {
      setCatalogGlass(row, read.medium.glass);
    }
    row.apertureDiameterMm = read.semiAperture ? 2.0 * *read.semiAperture * s : 0.0;
    row.profile.setConic(read.conic);
    for (int power = 4; power <= AsphericProfile::kMaxPower; power += 2)
      if (const double a = read.coefficients[static_cast<std::size_t>(power)]; a != 0.0)
        row.profile.setCoefficient(power, a * std::pow(s, 1.0 - power));
    if (!read.typed && read.coefficientLine != 0)
      noteAt(read.coefficientLine,
             "conic or aspheric terms on a surface not declared CON or ASP: read as an asphere");
    // A flat surface with the same medium on both sides is no surface at all: as the stop, it
    // is lenslab's stop row itself.
    if (stop_ && *stop_ == i && !std::isfinite(radius) && row.profile.isSphere() &&
        read.medium == before) {
      row.radiusMm = 0.0;
      convertedStop = lens.prescription.surfaces.size();
    }
    before = read.medium;
    lens.prescription.surfaces.push_back(row);
    lens.rowLines.push_back(read.line);
  }
  Surface& last = lens.prescription.surfaces.back();
  last.thicknessMm += imageDefocus_ * s;
  if (haveImage_ && imageDefocus_ != 0.0)
    noteAt(imageLine_, "the image surface's thickness (" + seqNumberText(imageDefocus_ * s) +
                           " mm, a defocus) is added to the last surface's: the film is " +
                           seqNumberText(last.thicknessMm) + " mm behind it");

  const SeqSurface& object = surfaces_.front();
  if (object.line != 0 && !object.infiniteThickness)
    noteAt(object.line, "the object is " + seqNumberText(object.thickness * s) +
                            " mm in front (SO); lenslab keeps the lens, not its object distance");

  if (!convertedStop) {
    std::size_t carrier = 0;  // CODE V's default stop is surface 1
    if (stop_) {
      carrier = *stop_ - first;
    } else {
      noteAt(surfaces_[first].line, "no STO: the stop is surface 1 (CODE V's default)");
    }
    const bool flatDummy = carrier == 0 && !std::isfinite(lens.prescription.surfaces[0].radiusMm) &&
                           lens.prescription.surfaces[0].profile.isSphere() &&
                           surfaces_[first].medium == SeqMedium{};
    if (flatDummy) {
      lens.prescription.surfaces[0].radiusMm = 0.0;
    } else {
      const double diameter = lens.prescription.surfaces[carrier].apertureDiameterMm;
      insertStopAtSurface(lens, carrier, diameter);
    }
  }

  // The design conditions, in millimetres.
  DesignConditions& design = lens.design;
  if (aperture_) {
    design.aperture = *aperture_;
    if (aperture_->kind == ApertureKind::EntrancePupilDiameterMm) design.aperture->value *= s;
  }
  if (!wavelengths_.empty()) {
    design.wavelengths.nanometres = wavelengths_;
    if (reference_ > static_cast<int>(wavelengths_.size())) {
      diagnostics_.error({fileName_, referenceWord_->line, referenceWord_->column},
                         "REF " + std::to_string(reference_) + ": there are only " +
                             std::to_string(wavelengths_.size()) + " wavelengths (WL, line " +
                             std::to_string(wavelengthWord_.line) + ")");
    } else if (reference_ == 0 && wavelengths_.size() > 1) {
      note(wavelengthWord_, "no REF: the first wavelength is the reference");
    }
    design.wavelengths.primaryIndex = reference_ > 0 ? reference_ - 1 : 0;
  }
  if (fieldFamily_ >= 0) {
    static constexpr FieldKind kKinds[] = {FieldKind::ObjectAngleDeg, FieldKind::ObjectHeightMm,
                                           FieldKind::ParaxialImageHeightMm,
                                           FieldKind::RealImageHeightMm};
    const FieldSet& set = fields_[static_cast<std::size_t>(fieldFamily_)];
    design.fields.kind = kKinds[fieldFamily_];
    const double scale = fieldFamily_ == 0 ? 1.0 : s;
    const bool anyX = std::any_of(set.x.begin(), set.x.end(), [](double x) { return x != 0.0; });
    std::vector<double> values = set.y;
    if (anyX) {
      if (!set.y.empty() && set.y.size() != set.x.size()) {
        diagnostics_.error({fileName_, set.xWord.line, set.xWord.column},
                           "the x fields (" + std::to_string(set.x.size()) +
                               ") and the y fields (" + std::to_string(set.y.size()) +
                               ") are not as many");
      } else {
        values.resize(set.x.size(), 0.0);
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::hypot(set.x[i], values[i]);
        note(set.xWord,
             "fields off the y axis: lenslab's lens is round, so each field is its "
             "distance from the axis");
      }
    }
    for (double& value : values) value *= scale;
    design.fields.values = std::move(values);
  }
  if (vignetting_) {
    const bool anyUnsized =
        std::any_of(lens.prescription.surfaces.begin(), lens.prescription.surfaces.end(),
                    [](const Surface& row) { return !(row.apertureDiameterMm > 0.0); });
    if (anyUnsized)
      note(*vignetting_,
           "vignetting factors are not read: surfaces without CIR are sized to pass the whole "
           "beam of every field");
  }
  return lens;
}

}  // namespace lenslab::optics::codev
