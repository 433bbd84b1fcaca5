// The lens a .zmx file gives (zemax_reader.h): lenslab's surfaces from the SURF blocks, in
// millimetres, with the stop, the film distance and the design conditions.
#include "optics/import/zemax_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "optics/import/stop_on_surface.h"

namespace lenslab::optics::zmx {

void ZmxReader::build() {
  if (surfaces.empty()) {
    error(1, 1,
          "no surfaces: a lens file has SURF 0 (the object), the lens's surfaces and the "
          "image surface");
    return;
  }
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].number != static_cast<int>(i)) {
      error(surfaces[i].line, 1,
            "SURF " + std::to_string(surfaces[i].number) + " where SURF " + std::to_string(i) +
                " was expected (surfaces are numbered 0, 1, 2, ... in order)");
      return;
    }
  if (surfaces.size() < 3) {
    error(surfaces.back().line, 1,
          "a lens needs at least one surface between the object (SURF 0) and the image (the last "
          "SURF)");
    return;
  }
  if (surfaces.size() - 2 > kMaxLensFileSurfaces) {
    error(surfaces[kMaxLensFileSurfaces + 1].line, 1,
          "too many surfaces: a lens file holds at most " + std::to_string(kMaxLensFileSurfaces));
    return;
  }
  const double s = unitMm;
  const ZmxSurface& object = surfaces.front();
  const ZmxSurface& image = surfaces.back();

  // The object: lenslab's lens looks at a scene, not at a plane the file fixes.
  if (object.stop) error(object.line, 1, "the object surface (SURF 0) cannot be the stop");
  if (!object.glass.empty() && zmxUpper(object.glass) != "AIR")
    error(object.glassLine, object.glassColumn,
          "the object space is glass " + object.glass +
              "; lenslab's lenses have air in front of the first surface");
  if (!object.infiniteThickness && object.thicknessLine > 0) {
    std::ostringstream message;
    message << "the object is at a finite distance, " << object.thickness * s
            << " mm in front of the first surface; lenslab keeps the film where the file has it "
               "(focused on that object) and does not record the object's distance";
    note(object.thicknessLine, 1, message.str());
  }
  if (image.stop) error(image.line, 1, "the image surface cannot be the stop");
  if (image.curvature != 0.0) {
    std::ostringstream message;
    message << "the image surface is curved (radius " << s / image.curvature
            << " mm); lenslab's film is flat, at the image surface's vertex";
    warning(image.line, 1, message.str());
  }

  std::optional<std::size_t> stopRow;
  double stopDiameterMm = 0.0;
  for (std::size_t i = 1; i + 1 < surfaces.size(); ++i) {
    const ZmxSurface& z = surfaces[i];
    Surface surface;
    if (z.curvature != 0.0) {
      const double radiusMm = s / z.curvature;
      // A curvature below 1e-6 / mm is a flat surface to far better than any lens is made.
      if (std::abs(radiusMm) > kMaxLengthMm) {
        std::ostringstream message;
        message << "SURF " << z.number << "'s radius " << radiusMm
                << " mm is taken as flat (beyond " << kMaxLengthMm << " mm)";
        note(z.line, 1, message.str());
        surface.radiusMm = kFlatRadius;
      } else {
        surface.radiusMm = radiusMm;
      }
    } else {
      surface.radiusMm = kFlatRadius;
    }
    if (z.infiniteThickness) {
      error(z.thicknessLine, 1,
            "SURF " + std::to_string(z.number) +
                " has an infinite thickness (DISZ INFINITY): only the object's may be");
      continue;
    }
    surface.thicknessMm = z.thickness * s;
    if (std::abs(surface.thicknessMm) > kMaxLengthMm) {
      std::ostringstream message;
      message << "SURF " << z.number << "'s thickness " << surface.thicknessMm
              << " mm is beyond any real lens (at most " << kMaxLengthMm << " mm)";
      error(z.thicknessLine, 1, message.str());
      continue;
    }
    const std::optional<double> semi =
        z.clearApertureRadius ? z.clearApertureRadius : z.semiDiameter;
    if (semi) {
      surface.apertureDiameterMm = 2.0 * *semi * s;
      if (!(surface.apertureDiameterMm <= kMaxApertureDiameterMm)) {
        std::ostringstream message;
        message << "SURF " << z.number << "'s diameter " << surface.apertureDiameterMm
                << " mm is beyond any real lens (at most " << kMaxApertureDiameterMm << " mm)";
        error(z.line, 1, message.str());
        continue;
      }
    }
    // A flat surface's sag is 0 whatever its conic constant: it is kept only on a curved one.
    if (z.curvature != 0.0) surface.profile.setConic(z.conic);
    if (z.type == "EVENASPH") {
      for (const auto& [index, value] : z.parameters) {
        if (index < 1 || index > 8) {
          if (value == 0.0) continue;  // an unused parameter, as other surface types write them
          error(z.parameterLines.at(index), 1,
                "EVENASPH has PARM 1 to 8 (the r^2 to r^16 terms), not PARM " +
                    std::to_string(index));
          continue;
        }
        // z = sum a_i r^2i in lens units; in mm, a_i s^(1 - 2i).
        const double coefficient = value * std::pow(s, 1.0 - 2.0 * index);
        if (!std::isfinite(coefficient)) {
          error(z.parameterLines.at(index), 1, "the coefficient overflows in millimetres");
          continue;
        }
        surface.profile.setCoefficient(2 * index, coefficient);
      }
    }
    if (!resolveGlass(z, surface)) continue;
    // A dummy surface (flat, the same medium on both sides, neither the stop nor a hard aperture)
    // bends no ray; OpticStudio files use them to mark places. Its gap joins the row before it,
    // and its semi-diameter, often 0, does not become a rim that would block the beam.
    std::vector<Surface>& rows = lens.prescription.surfaces;
    const Surface air;
    const Surface& before = rows.empty() ? air : rows.back();
    if (surface.isFlat() && !surface.profile.hasPolynomial() && !z.stop && !z.clearApertureRadius &&
        surface.indexD == before.indexD && surface.abbeD == before.abbeD &&
        surface.glass == before.glass) {
      if (!rows.empty()) rows.back().thicknessMm += surface.thicknessMm;
      note(z.line, 1,
           "SURF " + std::to_string(z.number) +
               " is a dummy surface (flat, the same medium on both sides): left out" +
               (rows.empty() ? ", the lens starts at the next surface" : ""));
      continue;
    }
    if (z.stop) {
      stopRow = lens.prescription.surfaces.size();
      stopDiameterMm = surface.apertureDiameterMm;
    }
    lens.prescription.surfaces.push_back(std::move(surface));
    lens.rowLines.push_back(z.line);
  }
  if (diagnostics.hasErrors()) return;
  if (!stopRow) {
    error(surfaces[1].line, 1,
          "no surface is the aperture stop (STOP); lenslab does not guess where it is");
    return;
  }

  // The stop: a flat surface between two equal media is lenslab's stop row itself; one that
  // refracts keeps its surface, with a stop row at its vertex.
  std::vector<Surface>& rows = lens.prescription.surfaces;
  const Surface& carrier = rows[*stopRow];
  const double indexBefore = *stopRow == 0 ? 1.0 : rows[*stopRow - 1].mediumIndexD();
  const bool sameMedium = *stopRow == 0 ? carrier.mediumIndexD() == 1.0 && !carrier.glass
                                        : carrier.mediumIndexD() == indexBefore &&
                                              carrier.glass == rows[*stopRow - 1].glass &&
                                              carrier.abbeD == rows[*stopRow - 1].abbeD;
  if (carrier.isFlat() && carrier.profile.isSphere() && sameMedium) {
    rows[*stopRow].radiusMm = 0.0;
  } else {
    insertStopAtSurface(lens, *stopRow, stopDiameterMm);
  }

  // Design conditions.
  DesignConditions& design = lens.design;
  const std::size_t waveCount =
      wavelengthCount ? static_cast<std::size_t>(*wavelengthCount) : wavelengthsUm.size();
  for (std::size_t n = 1; n <= waveCount; ++n) {
    const auto found = wavelengthsUm.find(static_cast<int>(n));
    if (found == wavelengthsUm.end()) {
      error(fieldTypeLine, 1,
            "the file has " + std::to_string(waveCount) + " wavelengths but no WAVM " +
                std::to_string(n));
      return;
    }
    if (!(found->second > 0.0) || found->second > 100.0) {
      error(wavelengthLines.at(found->first), 1,
            "wavelength " + std::to_string(found->second) + " µm is not a wavelength");
      return;
    }
    design.wavelengths.nanometres.push_back(found->second * 1000.0);
  }
  if (!design.wavelengths.empty()) {
    const int primary = primaryWavelength.value_or(1);
    if (primary < 1 || static_cast<std::size_t>(primary) > waveCount) {
      error(primaryLine, 1,
            "PWAV " + std::to_string(primary) + " is not one of the " + std::to_string(waveCount) +
                " wavelengths");
      return;
    }
    design.wavelengths.primaryIndex = primary - 1;
  }
  static const FieldKind kFieldKinds[] = {FieldKind::ObjectAngleDeg, FieldKind::ObjectHeightMm,
                                          FieldKind::ParaxialImageHeightMm,
                                          FieldKind::RealImageHeightMm};
  std::size_t fields = fieldCount ? static_cast<std::size_t>(*fieldCount) : yFields.size();
  if (!fieldCount) {
    // Without FTYP's count, the unused trailing zeros of a fixed-width line are not fields.
    while (fields > 1 && yFields[fields - 1] == 0.0 &&
           (fields > xFields.size() || xFields[fields - 1] == 0.0))
      --fields;
  }
  const std::size_t given = std::max(xFields.size(), yFields.size());
  if (fields > given) {
    note(fieldTypeLine, 1,
         "FTYP counts " + std::to_string(fields) + " fields but XFLN/YFLN give " +
             std::to_string(given) + "; reading those");
    fields = given;
  }
  if (fields > 0 && fieldType > 3) {
    note(fieldTypeLine, 1,
         "field type " + std::to_string(fieldType) +
             " (FTYP) is not one lenslab keeps (object angle, object height, paraxial or real "
             "image height); the fields are not read");
  } else if (fields > 0) {
    design.fields.kind = kFieldKinds[fieldType];
    bool radial = false;
    for (std::size_t i = 0; i < fields; ++i) {
      const double x = i < xFields.size() ? xFields[i] : 0.0;
      const double y = i < yFields.size() ? yFields[i] : 0.0;
      double value = y;
      if (x != 0.0) {
        radial = true;
        // A centred lens images every azimuth alike: the field's distance from the axis. For an
        // angle, the angle whose tangent is the tangents' length.
        constexpr double kDegree = 3.14159265358979323846 / 180.0;
        value = fieldType == 0
                    ? std::atan(std::hypot(std::tan(x * kDegree), std::tan(y * kDegree))) / kDegree
                    : std::hypot(x, y);
      }
      const double field = fieldType == 0 ? value : value * s;
      if (fieldType == 0 ? !(std::abs(field) < 90.0) : !(std::abs(field) <= kMaxLengthMm)) {
        std::ostringstream message;
        message << "field " << i + 1 << " (" << field << (fieldType == 0 ? " degrees" : " mm")
                << ") is beyond any real lens's field";
        error(fieldLine, 1, message.str());
        return;
      }
      design.fields.values.push_back(field);
    }
    if (radial)
      note(xFieldLine, 1,
           "fields off the y axis (XFLN) are read as their distance from the axis: the lens is "
           "rotationally symmetric");
  }
  if (aperture) {
    DesignAperture a = *aperture;
    if (a.kind == ApertureKind::EntrancePupilDiameterMm) a.value *= s;
    const double limit =
        a.kind == ApertureKind::EntrancePupilDiameterMm ? kMaxApertureDiameterMm : 1000.0;
    if (!(a.value <= limit)) {
      std::ostringstream message;
      message << (a.kind == ApertureKind::EntrancePupilDiameterMm ? "the entrance pupil diameter "
                                                                  : "the f-number ")
              << a.value << " is beyond any real lens (at most " << limit << ")";
      error(apertureLine, 1, message.str());
      return;
    }
    design.aperture = a;
  }
}

}  // namespace lenslab::optics::zmx
