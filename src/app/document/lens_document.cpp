#include "app/document/lens_document.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lenslab::app {

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

double& fieldOf(optics::Surface& surface, SurfaceField field, double& scratch) {
  switch (field) {
    case SurfaceField::RadiusMm:
      return surface.radiusMm;
    case SurfaceField::ThicknessMm:
      return surface.thicknessMm;
    case SurfaceField::IndexD:
      return surface.indexD;
    case SurfaceField::ApertureDiameterMm:
      return surface.apertureDiameterMm;
    case SurfaceField::AbbeD:
    case SurfaceField::Conic:
      break;
  }
  return scratch;
}

// Why a conic or a polynomial term cannot be set on this surface to this value, if it cannot.
std::optional<std::string> profileRefusal(const optics::Surface& surface, std::size_t index,
                                          double value) {
  const std::string where = "surface " + std::to_string(index + 1);
  if (surface.isStop()) {
    return where +
           " is the aperture stop: it has no shape to make aspheric (give it a radius first)";
  }
  // The traces, the validation and the table take the terms as numbers: NaN or infinity would
  // reach a picture (a huge but finite term is a shape, flagged by validation if it is absurd).
  if (!std::isfinite(value)) return where + ": an aspheric term must be a finite number";
  return std::nullopt;
}

// "7000-14000 nm": a formula's valid range, in the nanometres the viewer speaks.
std::string formatRangeNm(const optics::CatalogGlass& glass) {
  std::ostringstream text;
  text << glass.formula.minimumUm * 1000.0 << "-" << glass.formula.maximumUm * 1000.0 << " nm";
  return text.str();
}

std::string surfaceOutOfRange(std::size_t surface, std::size_t count) {
  std::ostringstream message;
  message << "surface " << surface + 1 << " does not exist (the lens has " << count << " surfaces)";
  return message.str();
}

}  // namespace

LensDetails detailsOf(const optics::LensFile& file) {
  return {file.headerComments, file.title,    file.source, file.publishedEflMm,
          file.design,         file.lensType, file.year};
}

optics::LensFile lensFileOf(const optics::Prescription& prescription, const LensDetails& details) {
  optics::LensFile file;
  file.prescription = prescription;
  file.headerComments = details.notes;
  file.title = details.title;
  file.source = details.source;
  file.publishedEflMm = details.publishedEflMm;
  file.design = details.design;
  file.lensType = details.lensType;
  file.year = details.year;
  return file;
}

std::optional<SurfaceField> surfaceFieldFromName(const std::string& name) {
  if (name == "radius") return SurfaceField::RadiusMm;
  if (name == "thickness") return SurfaceField::ThicknessMm;
  if (name == "n" || name == "nd") return SurfaceField::IndexD;
  if (name == "abbe" || name == "vd") return SurfaceField::AbbeD;
  if (name == "aperture") return SurfaceField::ApertureDiameterMm;
  if (name == "conic" || name == "k") return SurfaceField::Conic;
  return std::nullopt;
}

const char* surfaceFieldName(SurfaceField field) {
  switch (field) {
    case SurfaceField::RadiusMm:
      return "radius";
    case SurfaceField::ThicknessMm:
      return "thickness";
    case SurfaceField::IndexD:
      return "n_d";
    case SurfaceField::AbbeD:
      return "V_d";
    case SurfaceField::ApertureDiameterMm:
      return "aperture";
    case SurfaceField::Conic:
      return "conic";
  }
  return "?";
}

std::string describe(const EditCommand& command) {
  std::ostringstream text;
  std::visit(
      Overloaded{
          [&](const SetSurfaceField& c) {
            text << "set " << surfaceFieldName(c.field) << " of surface " << c.surface + 1 << " to "
                 << c.value;
          },
          [&](const SetAsphericTerm& c) {
            text << "set A" << c.power << " of surface " << c.surface + 1 << " to " << c.value;
          },
          [&](const SetSurfaceGlass& c) {
            text << "set glass of surface " << c.surface + 1 << " to "
                 << (c.glass ? c.glass->name + " (" + c.glass->maker + ")" : std::string("none"));
          },
          [&](const MakeStop& c) { text << "make surface " << c.surface + 1 << " the stop"; },
          [&](const InsertSurface& c) { text << "insert a surface at " << c.before + 1; },
          [&](const DeleteSurface& c) { text << "delete surface " << c.surface + 1; },
          [&](const MoveSurface& c) {
            text << "move surface " << c.from + 1 << " to " << c.to + 1;
          },
          [&](const FlipLens&) { text << "flip the lens"; },
          [&](const ScaleLens& c) { text << "scale the lens by " << c.factor; },
          [&](const SetFilmDistance& c) { text << "set film distance to " << c.mm << " mm"; },
          [&](const SetStopDiameter& c) { text << "set stop diameter to " << c.mm << " mm"; },
          [&](const SetStopShape& c) { text << "set aperture to " << c.shape.spec(); },
          [&](const ReplaceLens& c) {
            text << "open " << (c.path.empty() ? std::string("a new lens") : c.path);
          },
          [&](const Undo&) { text << "undo"; },
          [&](const Redo&) { text << "redo"; },
      },
      command);
  return text.str();
}

namespace {

bool sameSurface(const optics::Surface& a, const optics::Surface& b) {
  // Bitwise-equal numbers, with NaN equal to NaN (an invalid value typed twice is no change).
  const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return same(a.radiusMm, b.radiusMm) && same(a.thicknessMm, b.thicknessMm) &&
         same(a.indexD, b.indexD) && same(a.apertureDiameterMm, b.apertureDiameterMm) &&
         a.abbeD.has_value() == b.abbeD.has_value() && (!a.abbeD || same(*a.abbeD, *b.abbeD)) &&
         a.profile == b.profile && a.glass == b.glass;
}

}  // namespace

LensDocument::LensDocument(optics::Prescription prescription, std::string path)
    : current_(std::move(prescription)), path_(std::move(path)), saved_(current_) {}

void LensDocument::markSaved(std::string path) {
  path_ = std::move(path);
  saved_ = current_;
  // Every step of this lens, since it was opened, is now of the file it was saved as, and
  // compares with what that file holds (undo after "Save as" keeps the new name, modified).
  for (std::vector<Snapshot>* steps : {&undo_, &redo_}) {
    for (Snapshot& step : *steps) {
      if (step.openedLens != openedLens_) continue;
      step.path = path_;
      step.saved = saved_;
    }
  }
}

bool LensDocument::modified() const {
  const auto& a = current_.surfaces;
  const auto& b = saved_.surfaces;
  return !std::equal(a.begin(), a.end(), b.begin(), b.end(), sameSurface) ||
         !(current_.stopShape == saved_.stopShape);
}

std::optional<std::string> LensDocument::apply(const EditCommand& command,
                                               const std::string& mergeKey) {
  if (std::holds_alternative<Undo>(command)) {
    return undo() ? std::nullopt : std::optional<std::string>("nothing to undo");
  }
  if (std::holds_alternative<Redo>(command)) {
    return redo() ? std::nullopt : std::optional<std::string>("nothing to redo");
  }
  if (const auto* replace = std::get_if<ReplaceLens>(&command);
      replace != nullptr && replace->startsSession && undo_.empty() && redo_.empty()) {
    current_ = replace->prescription;
    path_ = replace->path;
    details_ = replace->details;
    saved_ = current_;
    lastMergeKey_.clear();
    ++generation_;
    return std::nullopt;
  }
  optics::Prescription next = current_;
  LensDetails nextDetails = details_;
  std::string nextPath = path_;
  std::vector<optics::Surface>& surfaces = next.surfaces;
  const std::size_t count = surfaces.size();
  std::optional<std::string> refusal;
  std::visit(
      Overloaded{
          [&](const SetSurfaceField& c) {
            if (c.surface >= count) return void(refusal = surfaceOutOfRange(c.surface, count));
            optics::Surface& surface = surfaces[c.surface];
            // A typed n_d or V_d makes a catalogue glass a model glass of the numbers: the name
            // would otherwise contradict them (validation refuses that).
            if (c.field == SurfaceField::IndexD || c.field == SurfaceField::AbbeD)
              optics::setCatalogGlass(surface, nullptr);
            if (c.field == SurfaceField::AbbeD) {
              surface.abbeD = std::isnan(c.value) ? std::nullopt : std::optional(c.value);
              return;
            }
            if (c.field == SurfaceField::Conic) {
              if ((refusal = profileRefusal(surface, c.surface, c.value))) return;
              return surface.profile.setConic(c.value);
            }
            double scratch = 0;
            fieldOf(surface, c.field, scratch) = c.value;
            // A radius of 0 makes the surface the stop, a hole of no shape.
            if (surface.isStop()) surface.profile = {};
          },
          [&](const SetAsphericTerm& c) {
            if (c.surface >= count) return void(refusal = surfaceOutOfRange(c.surface, count));
            if (c.power < optics::AsphericProfile::kMinPower ||
                c.power > optics::AsphericProfile::kMaxPower) {
              return void(refusal = "there is no term A" + std::to_string(c.power) +
                                    " (the powers are 2 to 20)");
            }
            optics::Surface& surface = surfaces[c.surface];
            if ((refusal = profileRefusal(surface, c.surface, c.value))) return;
            surface.profile.setCoefficient(c.power, c.value);
          },
          [&](const SetSurfaceGlass& c) {
            if (c.surface >= count) return void(refusal = surfaceOutOfRange(c.surface, count));
            const std::string where = "surface " + std::to_string(c.surface + 1);
            if (!c.glass) return void(refusal = where + ": no glass given");
            if (surfaces[c.surface].isStop())
              return void(refusal = where + " is the aperture stop: air follows it, not glass");
            // An infrared material's formula does not reach the d line: it has no n_d to trace
            // the visible with, and the lens must not take a made-up one.
            if (!c.glass->nd || !c.glass->vd)
              return void(refusal = where + ": glass " + c.glass->name + " (" + c.glass->maker +
                                    ") has no index in the visible (its formula covers " +
                                    formatRangeNm(*c.glass) + ")");
            optics::setCatalogGlass(surfaces[c.surface], c.glass);
          },
          [&](const MakeStop& c) {
            if (c.surface >= count) return void(refusal = surfaceOutOfRange(c.surface, count));
            surfaces[c.surface].radiusMm = 0.0;
            surfaces[c.surface].profile = {};  // the stop is a hole, of no shape
            surfaces[c.surface].indexD = 1.0;
            surfaces[c.surface].abbeD.reset();
            surfaces[c.surface].glass = nullptr;
          },
          [&](const InsertSurface& c) {
            if (c.before > count) return void(refusal = surfaceOutOfRange(c.before, count));
            surfaces.insert(surfaces.begin() + static_cast<std::ptrdiff_t>(c.before), c.surface);
          },
          [&](const DeleteSurface& c) {
            if (c.surface >= count) return void(refusal = surfaceOutOfRange(c.surface, count));
            if (count == 1) return void(refusal = std::string("cannot delete the only surface"));
            surfaces.erase(surfaces.begin() + static_cast<std::ptrdiff_t>(c.surface));
          },
          [&](const MoveSurface& c) {
            if (c.from >= count) return void(refusal = surfaceOutOfRange(c.from, count));
            if (c.to >= count) return void(refusal = surfaceOutOfRange(c.to, count));
            const optics::Surface moving = surfaces[c.from];
            surfaces.erase(surfaces.begin() + static_cast<std::ptrdiff_t>(c.from));
            surfaces.insert(surfaces.begin() + static_cast<std::ptrdiff_t>(c.to), moving);
          },
          [&](const FlipLens&) { next = flipped(next); },
          [&](const ScaleLens& c) {
            if (!(c.factor > 0) || !std::isfinite(c.factor)) {
              return void(refusal = std::string("the scale factor must be positive"));
            }
            next = scaled(next, c.factor);
          },
          [&](const SetFilmDistance& c) {
            if (count == 0) return void(refusal = std::string("the lens has no surfaces"));
            surfaces.back().thicknessMm = c.mm;
          },
          [&](const SetStopDiameter& c) {
            const auto stop = std::find_if(surfaces.begin(), surfaces.end(),
                                           [](const optics::Surface& s) { return s.isStop(); });
            if (stop == surfaces.end()) return void(refusal = std::string("the lens has no stop"));
            stop->apertureDiameterMm = c.mm;
          },
          [&](const SetStopShape& c) { next.stopShape = c.shape; },
          [&](const ReplaceLens& c) {
            next = c.prescription;
            nextPath = c.path;
            nextDetails = c.details;
          },
          [](const Undo&) {},  // handled above
          [](const Redo&) {},
      },
      command);
  if (refusal) return refusal;

  const bool merges = !mergeKey.empty() && mergeKey == lastMergeKey_ && !undo_.empty();
  if (!merges) {
    undo_.push_back(snapshot());
    if (undo_.size() > kMaxUndoSteps) undo_.erase(undo_.begin());
  }
  lastMergeKey_ = mergeKey;
  redo_.clear();
  current_ = std::move(next);
  path_ = std::move(nextPath);
  details_ = std::move(nextDetails);
  // A lens just opened is unmodified, and a lens of its own for the steps that follow.
  if (std::holds_alternative<ReplaceLens>(command)) {
    saved_ = current_;
    openedLens_ = ++lensesOpened_;
  }
  ++generation_;
  return std::nullopt;
}

void LensDocument::restore(Snapshot&& from) {
  current_ = std::move(from.prescription);
  path_ = std::move(from.path);
  details_ = std::move(from.details);
  saved_ = std::move(from.saved);
  openedLens_ = from.openedLens;
  lastMergeKey_.clear();
  ++generation_;
}

bool LensDocument::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(snapshot());
  Snapshot step = std::move(undo_.back());
  undo_.pop_back();
  restore(std::move(step));
  return true;
}

bool LensDocument::redo() {
  if (redo_.empty()) return false;
  undo_.push_back(snapshot());
  Snapshot step = std::move(redo_.back());
  redo_.pop_back();
  restore(std::move(step));
  return true;
}

optics::AsphericProfile mirroredProfile(const optics::AsphericProfile& profile) {
  // Turned front to back the surface is z -> -z, so its sag S(r) becomes -S(r). The conic term
  // c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) is odd in c (the root sees only c^2): negating c
  // negates it with k unchanged. Each polynomial term A_i r^i must change sign itself.
  optics::AsphericProfile result = profile;
  for (int power = optics::AsphericProfile::kMinPower; power <= optics::AsphericProfile::kMaxPower;
       ++power) {
    result.setCoefficient(power, -profile.coefficient(power));
  }
  return result;
}

optics::AsphericProfile scaledProfile(const optics::AsphericProfile& profile, double factor) {
  // The scaled surface is the old one magnified: S'(s r) = s S(r). With c' = c / s the conic
  // term satisfies this for the same k; A'_i (s r)^i = s A_i r^i needs A'_i = A_i s^(1 - i).
  optics::AsphericProfile result = profile;
  for (int power = optics::AsphericProfile::kMinPower; power <= optics::AsphericProfile::kMaxPower;
       ++power) {
    result.setCoefficient(power, profile.coefficient(power) * std::pow(factor, 1 - power));
  }
  return result;
}

optics::Prescription flipped(const optics::Prescription& lens) {
  // Reversing the order swaps which medium follows each surface and the sign of every radius
  // (a centre of curvature toward the film is now toward the object). The gap after new surface
  // j is the gap before old surface n-1-j. The object side is taken to be air; the film distance
  // stays where it was, so the user refocuses after flipping.
  const std::vector<optics::Surface>& old = lens.surfaces;
  const std::size_t n = old.size();
  optics::Prescription result;
  result.surfaces.resize(n);
  // Seen from the other side the iris is mirrored left to right.
  result.stopShape = lens.stopShape.mirroredLeftToRight();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = n - 1 - j;
    optics::Surface& surface = result.surfaces[j];
    surface = old[i];
    // The stop (0) and a flat surface (inf) have no side to turn: they stay 0 and inf, not the
    // -0 and -inf the table and the saved file would show.
    surface.radiusMm =
        old[i].isStop() || old[i].isFlat() ? std::abs(old[i].radiusMm) : -old[i].radiusMm;
    surface.profile = mirroredProfile(old[i].profile);
    if (i > 0) {
      surface.thicknessMm = old[i - 1].thicknessMm;
      surface.indexD = old[i - 1].indexD;
      surface.abbeD = old[i - 1].abbeD;
      surface.glass = old[i - 1].glass;
    } else {
      surface.thicknessMm = n > 0 ? old[n - 1].thicknessMm : 0.0;
      surface.indexD = 1.0;
      surface.abbeD.reset();
      surface.glass = nullptr;
    }
  }
  return result;
}

optics::Prescription scaled(const optics::Prescription& lens, double factor) {
  optics::Prescription result = lens;
  for (optics::Surface& surface : result.surfaces) {
    surface.radiusMm *= factor;
    surface.thicknessMm *= factor;
    surface.apertureDiameterMm *= factor;
    surface.profile = scaledProfile(surface.profile, factor);
  }
  return result;
}

}  // namespace lenslab::app
