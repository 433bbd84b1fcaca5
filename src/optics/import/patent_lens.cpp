// The lens a patent table gives (patent_reader.h): the checks across rows (the film distance, one
// stop, aspheric data for marked surfaces), then lenslab's surfaces, title and design conditions.
#include "optics/import/patent_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>

#include "optics/import/imported_lens.h"
#include "optics/import/stop_on_surface.h"

namespace lenslab::optics::patent {

void PatentReader::buildLens() {
  // The checks below run also after errors in the text, so that one reading reports them all.
  if (table_.rows.empty()) {
    lens_.diagnostics = diagnostics_;
    return;
  }
  const std::vector<PatentTableRow>& rows = table_.rows;
  if (rows.size() > kMaxLensFileSurfaces)
    diagnostics_.error(
        {fileName_, rows[kMaxLensFileSurfaces].line, 1},
        "more than " + std::to_string(kMaxLensFileSurfaces) + " surfaces: this is not a lens");
  // Every row but the last needs its d; the last one's is the film distance, or the back focus.
  for (std::size_t i = 0; i + 1 < rows.size(); ++i)
    if (!rows[i].thicknessMm)
      error(lines_[rowLineIndex_[i]], rowMissingAt_[i],
            "surface " + std::to_string(rows[i].surfaceNumber) + " has no d (thickness)");
  const PatentTableRow& last = rows.back();
  // The film lies behind the last row, in its medium: a camera's image is in air. A last row
  // with a glass is a table cut short (or one row alone).
  if (last.indexD) {
    std::ostringstream message;
    message << "the last surface (" << last.surfaceNumber << ") has n_d " << *last.indexD
            << ": the film would be inside glass; a table ends with the air before the image (is "
               "it cut short?)";
    error(lines_[rowLineIndex_.back()], rowIndexAt_.back(), message.str());
  }
  if (last.thicknessMm) {
    table_.filmDistanceMm = *last.thicknessMm;
    table_.filmDistanceFrom = "the last row's d (line " + std::to_string(last.line) + ")";
  } else if (table_.header.backFocusMm) {
    table_.filmDistanceMm = table_.header.backFocusMm->value;
    table_.filmDistanceFrom =
        "the back focus (line " + std::to_string(table_.header.backFocusMm->line) + ")";
    diagnostics_.note({fileName_, last.line, 1},
                      "the last row gives no d: the film is the back focus, " +
                          std::to_string(table_.header.backFocusMm->value) + " mm, behind it");
  } else {
    error(lines_[rowLineIndex_.back()], rowMissingAt_.back(),
          "the last surface has no d and the text states no back focus: the film distance is "
          "unknown");
  }
  // One stop.
  std::optional<std::size_t> stopRow;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].stop) continue;
    if (stopRow)
      diagnostics_.error({fileName_, rows[i].line, 1},
                         "a second aperture stop (the first is on line " +
                             std::to_string(rows[*stopRow].line) + ")");
    else
      stopRow = i;
  }
  if (!stopRow)
    diagnostics_.error({fileName_, table_.headingLine > 0 ? table_.headingLine : rows[0].line, 1},
                       "the table marks no aperture stop: mark its row (Stop), STO or S");
  // The aspheric data name marked surfaces, and every marked surface has data.
  std::map<int, std::size_t> rowOfNumber;
  for (std::size_t i = 0; i < rows.size(); ++i) rowOfNumber.emplace(rows[i].surfaceNumber, i);
  std::map<std::size_t, const PatentAsphere*> asphereOfRow;
  for (const PatentAsphere& a : table_.aspheres) {
    const auto it = rowOfNumber.find(a.surfaceNumber);
    if (it == rowOfNumber.end()) {
      diagnostics_.error({fileName_, a.line, 1}, "aspheric data for surface " +
                                                     std::to_string(a.surfaceNumber) +
                                                     ", which the table does not have");
      continue;
    }
    if (!rows[it->second].aspheric) {
      diagnostics_.error({fileName_, a.line, 1},
                         "aspheric data for surface " + std::to_string(a.surfaceNumber) +
                             ", whose row (line " + std::to_string(rows[it->second].line) +
                             ") is not marked aspheric (*)");
      continue;
    }
    asphereOfRow[it->second] = &a;
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i].aspheric && !asphereOfRow.count(i))
      diagnostics_.error({fileName_, rows[i].line, 1},
                         "surface " + std::to_string(rows[i].surfaceNumber) +
                             " is marked aspheric (*) but no aspheric data name it");
  if (diagnostics_.hasErrors()) {
    lens_.diagnostics = diagnostics_;
    return;
  }

  LensFile lens;
  bool stopOnSurface = false;
  std::size_t stopSurface = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PatentTableRow& row = rows[i];
    Surface s;
    s.radiusMm = row.radiusMm;
    if (row.radiusMm == 0.0 && !row.stop) {
      s.radiusMm = kFlatRadius;
      diagnostics_.note(
          {fileName_, row.line, 1},
          "r 0 on surface " + std::to_string(row.surfaceNumber) + " is read as a flat surface");
    }
    s.thicknessMm = i + 1 == rows.size() ? *table_.filmDistanceMm : *row.thicknessMm;
    s.indexD = row.indexD.value_or(1.0);
    s.abbeD = row.abbeD;
    s.apertureDiameterMm = 0.0;  // a table gives none: derived from the design conditions
    if (const auto it = asphereOfRow.find(i); it != asphereOfRow.end()) {
      s.profile.setConic(it->second->conic);
      for (const auto& [power, value] : it->second->terms) s.profile.setCoefficient(power, value);
    }
    if (row.stop) {
      if (s.isFlat() || s.radiusMm == 0.0) {
        if (!s.profile.isSphere())
          diagnostics_.error({fileName_, row.line, 1},
                             "the stop's row has aspheric data but no curvature");
        s.radiusMm = 0.0;  // lenslab's stop row
      } else {
        stopOnSurface = true;
        stopSurface = i;
      }
    }
    lens.prescription.surfaces.push_back(s);
    lens.rowLines.push_back(row.line);
  }
  if (stopOnSurface) {
    insertStopAtSurface(lens, stopSurface, 0.0);
    diagnostics_.note({fileName_, rows[stopSurface].line, 1},
                      "the stop is on surface " + std::to_string(rows[stopSurface].surfaceNumber) +
                          ": a stop row is placed at its vertex");
  }
  // Title: the first line of text before the table.
  const int tableStart = rows.front().line;
  for (const FoldedLine& line : lines_) {
    if (line.number >= tableStart || (table_.headingLine && line.number >= table_.headingLine))
      break;
    const std::string t = patent::trimmed(line.original);
    if (t.empty()) continue;
    if (lens.title.empty())
      lens.title = t;
    else
      lens.headerComments.push_back(t);
  }
  const PatentHeader& h = table_.header;
  if (h.focalLengthMm) lens.publishedEflMm = h.focalLengthMm->value;
  if (h.fNumber)
    lens.design.aperture = DesignAperture{ApertureKind::ImageFNumber, h.fNumber->value};
  if (h.halfFieldDeg) {
    lens.design.fields.kind = FieldKind::ObjectAngleDeg;
    lens.design.fields.values = {0.0, h.halfFieldDeg->value};
  } else if (h.imageHeightMm) {
    lens.design.fields.kind = FieldKind::ParaxialImageHeightMm;
    lens.design.fields.values = {0.0, h.imageHeightMm->value};
  }
  // n_d and ν_d are d-line data, ν_d defined by F and C: the design wavelengths they imply.
  lens.design.wavelengths.nanometres = {587.5618, 486.1327, 656.2725};
  lens.design.wavelengths.primaryIndex = 0;
  // A table gives no clear apertures: finishImportedLens derives them from the design's
  // f-number and field (clear_apertures.h).
  lens_ = finishImportedLens(std::move(lens), diagnostics_, fileName_);
}

}  // namespace lenslab::optics::patent
