// The CODE V reader's commands (codev_reader.h): numbers and surface qualifiers, surface lines
// and their data, fields, and every command CODE V writes (read, refused or ignored).
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

namespace lenslab::optics::codev {

std::string seqNumberText(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

int seqCoefficientPower(std::string_view name) {
  static constexpr std::string_view kLetters = "ABCDEFGHJ";
  if (name.size() != 1) return 0;
  const std::size_t at = kLetters.find(name.front());
  return at == std::string_view::npos ? 0 : 4 + 2 * static_cast<int>(at);
}

std::string seqCommandName(std::string_view word) {
  std::string name = upperCase(word);
  if (name == "TITLE") return "TIT";
  if (name == "STOP") return "STO";
  return name;
}

bool seqIsSurfaceQualifier(std::string_view upper) {
  if (upper == "SO" || upper == "SI") return true;
  if (upper.size() < 2 || upper.front() != 'S') return false;
  return std::all_of(upper.begin() + 1, upper.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::optional<double> SeqReader::number(const SeqWord& word, const std::string& what,
                                        bool allowInfinity) {
  std::string_view body = word.text;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  double value = 0.0;
  const char* end = body.data() + body.size();
  const auto [stop, problem] = std::from_chars(body.data(), end, value);
  if (problem == std::errc::result_out_of_range) {
    error(word, "number '" + word.text + "' is out of range (" + what + ")");
    return std::nullopt;
  }
  if (word.quoted || body.empty() || problem != std::errc() || stop != end || std::isnan(value)) {
    error(word, "'" + word.text + "' is not a number (expected " + what + ")");
    return std::nullopt;
  }
  if (std::isinf(value) && !allowInfinity) {
    error(word, "infinity is not allowed here (" + what + ")");
    return std::nullopt;
  }
  return value;
}

std::optional<double> SeqReader::positive(const SeqCommand& words, const std::string& what) {
  if (words.size() != 2) {
    error(words.size() < 2 ? words[0] : words[2],
          upperCase(words[0].text) + " takes one number (" + what + ")");
    return std::nullopt;
  }
  const std::optional<double> value = number(words[1], what);
  if (value && !(*value > 0.0 && *value <= kMaxLengthMm)) {
    error(words[1], what + " " + words[1].text + " must be above 0 and at most " +
                        seqNumberText(kMaxLengthMm));
    return std::nullopt;
  }
  return value;
}

std::vector<double> SeqReader::numbers(const SeqCommand& words, std::size_t first,
                                       const std::string& what) {
  std::vector<double> values;
  for (std::size_t i = first; i < words.size(); ++i) {
    const std::optional<double> value = number(words[i], what);
    if (!value) return {};
    if (std::abs(*value) > kMaxLengthMm) {
      error(words[i], what + " " + words[i].text + " is beyond any real lens");
      return {};
    }
    values.push_back(*value);
  }
  return values;
}

SeqSurface* SeqReader::target(const SeqCommand& words, std::size_t& dataStart,
                              std::vector<std::string>* qualifiers) {
  SeqSurface* surface = &surfaces_.back();
  dataStart = 1;
  for (; dataStart < words.size(); ++dataStart) {
    const SeqWord& word = words[dataStart];
    const std::string upper = upperCase(word.text);
    if (word.quoted || upper.empty() || !std::isalpha(static_cast<unsigned char>(upper.front())))
      break;  // data from here on
    if (seqIsSurfaceQualifier(upper)) {
      std::size_t index = 0;
      if (upper == "SO") {
        index = 0;
      } else if (upper == "SI") {
        index = haveImage_ ? surfaces_.size() - 1 : surfaces_.size();
      } else {
        const auto [stop, problem] =
            std::from_chars(upper.data() + 1, upper.data() + upper.size(), index);
        if (problem != std::errc()) index = surfaces_.size();
      }
      if (index >= surfaces_.size() ||
          (upper != "SI" && haveImage_ && index == surfaces_.size() - 1)) {
        error(word, "no surface " + word.text + " has been read yet");
        return nullptr;
      }
      surface = &surfaces_[index];
    } else if (qualifiers) {
      qualifiers->push_back(upper);
    } else {
      break;
    }
  }
  return surface;
}

void SeqReader::surfaceLine(const SeqCommand& words, const std::string& name) {
  const SeqWord& at = words[0];
  if (haveImage_) {
    error(at, name + " after SI: the image surface (SI) is the last surface");
    return;
  }
  SeqSurface read;
  read.line = at.line;
  read.mode = mode_;
  readSurfaceData(words, name, read);  // what it cannot read is an error; the surface still counts
  if (name == "SO") {
    surfaces_[0] = read;
    return;
  }
  if (name == "SI") {
    haveImage_ = true;
    imageLine_ = at.line;
    imageDefocus_ = read.thickness;
    if (read.value != 0.0) error(words[1], "a curved image surface (SI); lenslab's film is flat");
  }
  surfaces_.push_back(read);
}

void SeqReader::readSurfaceData(const SeqCommand& words, const std::string& name,
                                SeqSurface& read) {
  const std::size_t limit = name == "S" ? 4 : name == "SO" ? 3 : 2;
  if (words.size() > limit + 1) {
    error(words[limit + 1], name + " takes " +
                                (name == "S" ? std::string("a radius (or curvature), a thickness "
                                                           "and a glass")
                                             : std::string("a radius (or curvature) and a "
                                                           "thickness")));
    return;
  }
  if (words.size() > 1) {
    // Radius mode: 'inf' is a flat surface too (Optiland writes it).
    const std::optional<double> value =
        number(words[1], "a radius or curvature", mode_ != SeqValueMode::Curvature);
    if (!value) return;
    read.value = std::isinf(*value) ? 0.0 : *value;
  }
  if (words.size() > 2) {
    const std::optional<double> thickness = number(words[2], "a thickness", true);
    if (!thickness) return;
    if (std::abs(*thickness) >= kSeqInfiniteThickness) {
      if (name != "SO" || *thickness < 0.0) {
        error(words[2], "thickness " + words[2].text +
                            " is infinite (1e10 or more): only the object (SO) may be at infinity");
        return;
      }
      read.infiniteThickness = true;
    } else {
      read.thickness = *thickness;
    }
  }
  if (words.size() > 3) {
    if (upperCase(words[3].text) == "REFL" && !words[3].quoted) {
      refuse(words[3], "a mirror");
      return;
    }
    if (name == "SO") {
      error(words[3],
            "an object in glass " + words[3].text + ": lenslab's lenses are in air in front");
      return;
    }
    const std::optional<SeqMedium> medium = this->medium(words[3]);
    if (!medium) return;
    read.medium = *medium;
  }
  if (words.size() > 4) {
    const std::string mode = upperCase(words[4].text);
    if (mode == "REFL")
      refuse(words[4], "a mirror");
    else if (mode != "REFR")
      error(words[4], "'" + words[4].text + "' after the glass (expected REFR or REFL)");
  }
}

void SeqReader::field(const SeqCommand& words, const std::string& name) {
  static constexpr std::array<std::string_view, 4> kFamilies = {"AN", "OB", "IM", "RI"};
  const int family = static_cast<int>(
      std::find(kFamilies.begin(), kFamilies.end(), std::string_view(name).substr(1)) -
      kFamilies.begin());
  const std::vector<double> values = numbers(words, 1, "a field");
  if (values.empty()) {
    if (words.size() < 2) error(words[0], name + " needs one value per field");
    return;
  }
  FieldSet& set = fields_[static_cast<std::size_t>(family)];
  (name.front() == 'X' ? set.x : set.y) = values;
  (name.front() == 'X' ? set.xWord : set.yWord) = words[0];
  fieldFamily_ = family;
}

bool SeqReader::command(const SeqCommand& words) {
  const SeqWord& at = words[0];
  const std::string name = seqCommandName(at.text);
  if (inPrivateCatalog_) {
    if (name == "END" && !at.quoted) inPrivateCatalog_ = false;
    return true;
  }
  if (at.quoted) {
    error(at, "a quoted text where a command was expected");
    return true;
  }
  if (name == "GO") return false;
  if (name == "S" || name == "SO" || name == "SI") {
    // The S surfaces are surfaces_[1...]; one row is kept for a stop lenslab may insert.
    if (name == "S" && surfaces_.size() >= kMaxLensFileSurfaces) {
      error(at, "too many surfaces: a lens file holds at most " +
                    std::to_string(kMaxLensFileSurfaces) + " rows, the stop's among them");
      return false;
    }
    surfaceLine(words, name);
    return true;
  }
  if (name == "RDM") {
    const std::string value = words.size() > 1 ? upperCase(words[1].text) : "Y";
    if (words.size() > 2 || (value != "Y" && value != "YES" && value != "N" && value != "NO")) {
      error(words.size() > 2 ? words[2] : words[1], "RDM takes Y (radii) or N (curvatures)");
      return true;
    }
    mode_ = value.front() == 'Y' ? SeqValueMode::Radius : SeqValueMode::Curvature;
    return true;
  }
  if (name == "DIM") {
    const std::string value = words.size() == 2 ? upperCase(words[1].text) : "";
    if (value == "M" || value == "MM") {
      unitMm_ = 1.0;
    } else if (value == "C" || value == "CM") {
      unitMm_ = 10.0;
    } else if (value == "I" || value == "IN") {
      unitMm_ = 25.4;
    } else {
      error(words.size() > 1 ? words[1] : at,
            "DIM takes M, C or I (millimetres, centimetres, "
            "inches)");
    }
    return true;
  }
  if (name == "TIT") {
    std::string title;
    for (std::size_t i = 1; i < words.size(); ++i) title += (i > 1 ? " " : "") + words[i].text;
    bool changed = false;
    title_ = seqValidUtf8(title, &changed);
    if (changed) warning(at, "the title is not valid UTF-8; its stray bytes are shown as '?'");
    return true;
  }
  if (name == "EPD" || name == "FNO") {
    if (const std::optional<double> value =
            positive(words, name == "EPD" ? "the entrance pupil diameter" : "the f-number"))
      aperture_ = DesignAperture{
          name == "EPD" ? ApertureKind::EntrancePupilDiameterMm : ApertureKind::ImageFNumber,
          *value};
    return true;
  }
  if (name == "NA" || name == "NAO") {
    warning(at, name +
                    " (a numerical aperture) is not read: lenslab's design aperture is an EPD or "
                    "an FNO, and surfaces without CIR are sized from that");
    return true;
  }
  if (name == "WL") {
    std::vector<double> values = numbers(words, 1, "a wavelength (nm)");
    if (values.empty()) {
      if (words.size() < 2) error(at, "WL needs at least one wavelength (nm)");
      return true;
    }
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!(values[i] > 0.0)) {
        error(words[i + 1], "wavelength " + words[i + 1].text + " nm must be positive");
        return true;
      }
    wavelengths_ = std::move(values);
    wavelengthWord_ = at;
    return true;
  }
  if (name == "REF") {
    int value = 0;
    const std::string_view text = words.size() == 2 ? std::string_view(words[1].text) : "";
    const auto [stop, problem] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || problem != std::errc() || stop != text.data() + text.size() || value < 1) {
      error(words.size() > 1 ? words[1] : at, "REF takes a wavelength number (1, 2, ...)");
      return true;
    }
    reference_ = value;
    referenceWord_ = words[1];
    return true;
  }
  if (name.size() == 3 && (name[0] == 'X' || name[0] == 'Y') &&
      (name.substr(1) == "AN" || name.substr(1) == "OB" || name.substr(1) == "IM" ||
       name.substr(1) == "RI")) {
    field(words, name);
    return true;
  }
  if (name == "VUX" || name == "VLX" || name == "VUY" || name == "VLY") {
    for (std::size_t i = 1; i < words.size(); ++i) {
      double value = 0.0;
      const auto [stop, problem] =
          std::from_chars(words[i].text.data(), words[i].text.data() + words[i].text.size(), value);
      if (problem == std::errc() && value != 0.0 && !vignetting_) vignetting_ = at;
    }
    return true;
  }
  if (name == "TEM" || name == "PRE") {
    const std::optional<double> value = words.size() == 2 ? number(words[1], name) : std::nullopt;
    const double standard = name == "TEM" ? 20.0 : 1.0;
    if (value && *value != standard)
      note(at, name + " " + words[1].text +
                   ": the catalogue glasses' indices are at 20 C and 1 atmosphere; lenslab does "
                   "not adjust them");
    return true;
  }
  // What does not change the lens: its version line, weights, the initials, display colours,
  // polarization, variables (CCY, THC, GLC, KC, AC ...), derivative data and the labels.
  static const std::vector<std::string> kIgnored = {
      "LEN", "WTW", "WTF", "INI", "POL", "CLS", "WID", "DER", "SLB", "CCY", "CCX", "THC", "GLC",
      "KC",  "AC",  "BC",  "CC",  "DC",  "EC",  "FC",  "GC",  "HC",  "JC",  "PIM", "NBR"};
  if (std::find(kIgnored.begin(), kIgnored.end(), name) != kIgnored.end()) return true;
  if (name == "PIK") {
    if (!noted_[1])
      note(at, "PIK (pickups) not read: the values they pick up are written on the surfaces");
    noted_[1] = true;
    return true;
  }
  if (name == "PRV") {
    refuse(at, "a private glass catalogue (PRV ... END)");
    inPrivateCatalog_ = true;
    return true;
  }
  if (name == "REFL") {
    refuse(at, "a mirror");
    return true;
  }
  if (name == "RMD") {
    const std::string mode = words.size() > 1 ? upperCase(words.back().text) : "";
    if (mode == "REFL")
      refuse(at, "a mirror (RMD REFL)");
    else if (mode != "REFR")
      error(at, "RMD takes REFR or REFL");
    return true;
  }
  if (name == "XDE" || name == "YDE" || name == "ZDE" || name == "ADE" || name == "BDE" ||
      name == "CDE") {
    std::size_t dataStart = 1;
    if (!target(words, dataStart)) return true;
    bool nonzero = dataStart >= words.size();
    for (std::size_t i = dataStart; i < words.size(); ++i) {
      const std::optional<double> value = number(words[i], "a decentre or tilt");
      if (!value) return true;
      nonzero = nonzero || *value != 0.0;
    }
    if (nonzero)
      refuse(at, name[0] <= 'C' ? "a tilt (lenslab's surfaces are perpendicular to one axis)"
                                : "a decentre (lenslab's surfaces share one axis)");
    return true;
  }
  if (name == "DAR" || name == "BEN" || name == "REV" || name == "RET" || name == "DEC") {
    refuse(at, "a decentre or tilt of a surface (lenslab's surfaces share one axis)");
    return true;
  }
  if (name == "DIF" || name == "HOE" || name == "HOR" || name == "HWL" || name == "HCT" ||
      name == "HCO" || name == "HCC" || name == "GRT" || name == "GRO" || name == "GRS") {
    refuse(at, "a diffractive surface");
    return true;
  }
  if (name == "REX" || name == "REY" || name == "ELX" || name == "ELY") {
    refuse(at, "a rectangular or elliptical aperture (lenslab's clear apertures are circles)");
    return true;
  }

  // Commands on a surface: the last one read, or the one an S qualifier names.
  std::size_t dataStart = 1;
  std::vector<std::string> qualifiers;
  SeqSurface* surface = target(words, dataStart, &qualifiers);
  if (!surface) return true;
  const bool isObject = surface == &surfaces_.front();
  const bool isImage = haveImage_ && surface == &surfaces_.back();
  const std::size_t index = static_cast<std::size_t>(surface - surfaces_.data());
  const auto oneNumber = [&](const std::string& what) -> std::optional<double> {
    if (words.size() != dataStart + 1) {
      error(words.size() > dataStart + 1 ? words[dataStart + 1] : at,
            name + " takes one number (" + what + ")");
      return std::nullopt;
    }
    return number(words[dataStart], what);
  };
  if (name == "STO") {
    if (isObject || isImage) {
      error(at, std::string("the stop on the ") + (isObject ? "object" : "image") + " surface");
    } else if (stop_ && *stop_ != index) {
      error(at, "a second STO (the first is on line " + std::to_string(stopWord_.line) +
                    "); a lens has one stop");
    } else {
      stop_ = index;
      stopWord_ = at;
    }
    return true;
  }
  if (name == "CIR") {
    for (const std::string& qualifier : qualifiers) {
      if (qualifier == "OBS" || qualifier == "HOL") {
        refuse(at, qualifier == "OBS" ? "a central obscuration" : "a hole in a surface");
        return true;
      }
      if (qualifier == "EDG") {
        if (!noted_[3])
          note(at,
               "CIR EDG (the mechanical edge) is not a clear aperture: surfaces without "
               "CIR are sized from the design aperture and fields");
        noted_[3] = true;
        return true;
      }
      error(at, "CIR " + qualifier + " is not read (expected CIR with a semi-aperture)");
      return true;
    }
    const std::optional<double> value = oneNumber("a semi-aperture");
    if (!value) return true;
    if (!(*value > 0.0 && *value <= kMaxApertureDiameterMm / 2)) {
      error(words[dataStart], "semi-aperture " + words[dataStart].text +
                                  " must be above 0 and at most " +
                                  seqNumberText(kMaxApertureDiameterMm / 2));
      return true;
    }
    if (!isObject && !isImage) surface->semiAperture = *value;  // the image's is its size
    return true;
  }
  if (name == "SPH" || name == "CON" || name == "ASP") {
    if (isObject || isImage) {
      error(at, name + " on the " + (isObject ? "object" : "image") + " surface");
      return true;
    }
    surface->typed = name != "SPH";
    if (name == "SPH") {
      surface->conic = 0.0;
      surface->coefficients.fill(0.0);
    }
    return true;
  }
  if (name == "K" || seqCoefficientPower(name) != 0) {
    if (isObject || isImage) {
      error(at, name + " on the " + std::string(isObject ? "object" : "image") + " surface");
      return true;
    }
    const std::optional<double> value =
        oneNumber(name == "K" ? "the conic constant" : "an aspheric coefficient");
    if (!value) return true;
    if (name == "K")
      surface->conic = *value;
    else
      surface->coefficients[static_cast<std::size_t>(seqCoefficientPower(name))] = *value;
    if (surface->coefficientLine == 0 && *value != 0.0) surface->coefficientLine = at.line;
    return true;
  }
  if (name == "CUF") {
    const std::optional<double> value = oneNumber("CUF");
    if (value && *value != 0.0) refuse(at, "a CUF term");
    return true;
  }
  if (name == "THI" || name == "RDY" || name == "CUY") {
    if (!qualifiers.empty()) {
      // A solve (THI HMY 0, PIM ...): the value it found is the one written on the S line.
      if (!noted_[0])
        note(at, name + " " + qualifiers.front() +
                     " (a solve) not read: the value written on the surface is used");
      noted_[0] = true;
      return true;
    }
    const std::optional<double> value = oneNumber(name == "THI"   ? "a thickness"
                                                  : name == "RDY" ? "a radius"
                                                                  : "a curvature");
    if (!value) return true;
    if (name == "THI") {
      if (std::abs(*value) >= kSeqInfiniteThickness) {
        error(words[dataStart], "an infinite thickness is only for the object (SO)");
        return true;
      }
      surface->thickness = *value;
      surface->infiniteThickness = false;
      if (isImage) imageDefocus_ = *value;
    } else {
      surface->value = *value;
      surface->mode = name == "RDY" ? SeqValueMode::Radius : SeqValueMode::Curvature;
      if (isImage && *value != 0.0) error(at, "a curved image surface; lenslab's film is flat");
    }
    return true;
  }
  if (name == "RDX" || name == "CUX") {
    refuse(at, "an x curvature (a toroidal surface)");
    return true;
  }
  error(at, "'" + at.text +
                "' is not a CODE V command lenslab reads; it may change the lens, so the file "
                "is not opened");
  return true;
}

}  // namespace lenslab::optics::codev
