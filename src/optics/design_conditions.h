#pragma once
// The conditions a lens was designed for, when its file states them (a .zmx's WAVM/PWAV, FTYP/YFLN
// and ENPD/FNUM; a .seq's WL/REF, XAN/YAN/YOB/YIM and EPD/FNO; a patent's f-number and field
// angle): its wavelengths, its fields and its aperture. They are the analyses' defaults for that
// lens and what a table without clear apertures derives them from (import/clear_apertures.h).
// A .dat states none of them; every member is then empty.

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace lenslab::optics {

struct DesignWavelengths {
  std::vector<double> nanometres;  // in the order the file lists them
  int primaryIndex = 0;            // into nanometres: the reference wavelength
  bool empty() const { return nanometres.empty(); }
  // The reference wavelength (an index out of range taken as the nearest end); 0 when empty.
  double primaryNm() const {
    if (nanometres.empty()) return 0.0;
    const int last = static_cast<int>(nanometres.size()) - 1;
    return nanometres[static_cast<std::size_t>(std::clamp(primaryIndex, 0, last))];
  }
};

// How a file measures its field points.
enum class FieldKind {
  ObjectAngleDeg,         // angle of the chief ray in object space (Zemax FTYP 0, CODE V XAN/YAN)
  ObjectHeightMm,         // height on a finite object (Zemax FTYP 1, CODE V YOB)
  ParaxialImageHeightMm,  // paraxial image height (Zemax FTYP 2, CODE V YIM)
  RealImageHeightMm,      // real image height (Zemax FTYP 3)
};

struct DesignFields {
  FieldKind kind = FieldKind::ObjectAngleDeg;
  // The meridional (y) field values, in the kind's unit, in the file's order; the largest
  // magnitude is the full field.
  std::vector<double> values;
  bool empty() const { return values.empty(); }
};

// How a file fixes the size of the axial beam.
enum class ApertureKind {
  EntrancePupilDiameterMm,  // Zemax ENPD, CODE V EPD
  ImageFNumber,             // paraxial working f-number at infinity, EFL / EPD (Zemax FNUM, CODE V
                            // FNO, a patent's Fno)
  StopDiameter,             // the stop's own clear aperture sets it (Zemax FLOA)
};

struct DesignAperture {
  ApertureKind kind = ApertureKind::StopDiameter;
  double value = 0.0;  // the diameter (mm) or the f-number; unused for StopDiameter
};

struct DesignConditions {
  DesignWavelengths wavelengths;
  DesignFields fields;
  std::optional<DesignAperture> aperture;
  bool empty() const { return wavelengths.empty() && fields.empty() && !aperture; }
};

}  // namespace lenslab::optics
