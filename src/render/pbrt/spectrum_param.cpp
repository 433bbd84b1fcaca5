#include "render/pbrt/spectrum_param.h"

#include <string>
#include <vector>

#include "render/pbrt/diagnostic_text.h"
#include "render/spectrum.h"

namespace lenslab::render::pbrt {

namespace {

std::vector<double> rgbNumbers(glm::dvec3 rgb) { return {rgb.x, rgb.y, rgb.z}; }

// "spectrum" given by a name: a built-in named spectrum or a .spd file of wavelength-value pairs.
bool convertNamedSpectrum(Param& param, const std::string& what,
                          const std::filesystem::path& directory, const SceneFiles& files,
                          Diagnostics& diagnostics) {
  const std::string name = param.strings[0];
  param.strings.clear();
  if (const auto rgb = namedSpectrumRgb(name)) {
    param.numbers = rgbNumbers(*rgb);
    return true;
  }
  const std::filesystem::path given(name);
  const std::filesystem::path path = given.is_absolute() ? given : directory / given;
  std::string whyNot;
  std::optional<std::vector<double>> pairs;
  if (!files.problem(path, "spectrum file")) {
    if (const auto text = files.read(path))
      pairs = parseSpectrumText(*text, path.string(), &whyNot);
    else
      whyNot = "cannot open spectrum file " + path.string();
  }
  const auto rgb = pairs ? sampledSpectrumToRgb(*pairs, &whyNot) : std::nullopt;
  if (rgb) {
    param.numbers = rgbNumbers(*rgb);
    return true;
  }
  diagnostics.warning(param.location,
                      what + ": \"" + name + "\" is neither a known named spectrum " +
                          "(metal-Au-eta, metal-Au-k, and Ag, Cu, Al) nor a readable .spd " +
                          "file" + (whyNot.empty() ? "" : " (" + whyNot + ")") +
                          "; the default value is used");
  return false;
}

}  // namespace

std::optional<bool> convertSpectrumParam(Param& param, const std::filesystem::path& directory,
                                         const SceneFiles& files, Diagnostics& diagnostics) {
  const std::string what = "\"" + param.type + " " + param.name + "\"";
  if (param.type == "spectrum") {
    if (!param.strings.empty())
      return convertNamedSpectrum(param, what, directory, files, diagnostics);
    if (param.numbers.size() == 1) return true;  // a grey value, as for rgb
    std::string whyNot;
    const auto rgb = sampledSpectrumToRgb(param.numbers, &whyNot);
    if (!rgb) {
      diagnostics.error(param.location, what + ": " + whyNot + " (for a colour, write \"rgb " +
                                            param.name + "\" [r g b])");
      return std::nullopt;
    }
    param.numbers = rgbNumbers(*rgb);
    return true;
  }
  if (param.type == "blackbody") {
    // pbrt-v3: [temperature scale] pairs; pbrt-v4: a temperature alone.
    std::vector<double> values = param.numbers;
    if (values.size() == 1) values.push_back(1.0);
    if (values.empty() || values.size() % 2 != 0) {
      diagnostics.error(param.location, what + " needs [temperature scale] pairs, found " +
                                            std::to_string(param.numbers.size()) + " numbers");
      return std::nullopt;
    }
    param.numbers.clear();
    for (std::size_t i = 0; i < values.size(); i += 2) {
      if (!(values[i] > 0.0)) {
        diagnostics.error(param.location,
                          what + ": temperature " + formatNumber(values[i]) + " K is not positive");
        return std::nullopt;
      }
      for (double v : rgbNumbers(blackbodyToRgb(values[i]) * values[i + 1])) {
        param.numbers.push_back(v);
      }
    }
    return true;
  }
  if (param.type == "xyz") {
    if (param.numbers.empty() || param.numbers.size() % 3 != 0) {
      diagnostics.error(param.location, what + " needs X Y Z triples, found " +
                                            std::to_string(param.numbers.size()) + " numbers");
      return std::nullopt;
    }
    for (std::size_t i = 0; i < param.numbers.size(); i += 3) {
      const glm::dvec3 rgb =
          xyzToLinearSrgb(glm::dvec3(param.numbers[i], param.numbers[i + 1], param.numbers[i + 2]));
      for (int c = 0; c < 3; ++c) param.numbers[i + static_cast<std::size_t>(c)] = rgb[c];
    }
    return true;
  }
  if ((param.type == "rgb" || param.type == "color") && param.numbers.size() != 1 &&
      (param.numbers.empty() || param.numbers.size() % 3 != 0)) {
    diagnostics.error(param.location, what + " needs r g b (three numbers), found " +
                                          std::to_string(param.numbers.size()));
    return std::nullopt;
  }
  return true;
}

}  // namespace lenslab::render::pbrt
