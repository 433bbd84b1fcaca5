#include "render/spectrum.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace lenslab::render {

namespace {

constexpr double kFirstNm = 360.0;
constexpr double kLastNm = 830.0;
constexpr double kStepNm = 1.0;

// One lobe of the fit: a Gaussian with a different width on each side of its mean.
double lobe(double wavelengthNm, double weight, double meanNm, double sigmaBelowNm,
            double sigmaAboveNm) {
  const double t = (wavelengthNm - meanNm) / (wavelengthNm < meanNm ? sigmaBelowNm : sigmaAboveNm);
  return weight * std::exp(-0.5 * t * t);
}

// Value of a piecewise-linear spectrum at a wavelength, constant beyond the end points.
double spectrumAt(std::span<const double> pairs, double wavelengthNm) {
  const std::size_t count = pairs.size() / 2;
  if (wavelengthNm <= pairs[0]) return pairs[1];
  if (wavelengthNm >= pairs[2 * (count - 1)]) return pairs[2 * (count - 1) + 1];
  std::size_t i = 0;
  while (pairs[2 * (i + 1)] < wavelengthNm) ++i;
  const double x0 = pairs[2 * i], x1 = pairs[2 * (i + 1)];
  const double f = (wavelengthNm - x0) / (x1 - x0);
  return (1.0 - f) * pairs[2 * i + 1] + f * pairs[2 * (i + 1) + 1];
}

// sRGB of the equal-energy white (the XYZ of a constant 1, normalised by the integral of ȳ).
template <typename Spectrum>
glm::dvec3 unbalancedRgb(Spectrum&& spectrum) {
  glm::dvec3 xyz(0.0);
  double yIntegral = 0.0;
  for (double nm = kFirstNm; nm <= kLastNm; nm += kStepNm) {
    const glm::dvec3 matching = cieColourMatching(nm);
    xyz += spectrum(nm) * matching;
    yIntegral += matching.y;
  }
  return xyzToLinearSrgb(xyz / yIntegral);
}

glm::dvec3 balanced(glm::dvec3 rgb) {
  static const glm::dvec3 white = unbalancedRgb([](double) { return 1.0; });
  return rgb / white;
}

// Optical constants (wavelength nm, eta, k) of metals at room temperature, from the tables of
// P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", Phys. Rev. B 6,
// 4370 (1972) for Au, Ag and Cu, and A. D. Rakić, "Algorithm for the determination of intrinsic
// optical constants of metal films: application to aluminum", Appl. Opt. 34, 4755 (1995) for Al;
// as tabulated by the refractiveindex.info database (public domain), visible range only.
struct MetalTable {
  const char* symbol;
  std::vector<double> nmEtaK;
};

const std::vector<MetalTable>& metals() {
  static const std::vector<MetalTable> tables = {
      {"Au", {354.2, 1.50,  1.866, 367.9, 1.48,  1.895, 381.5, 1.46,  1.933, 397.4, 1.47,
              1.952, 413.3, 1.46,  1.958, 430.5, 1.45,  1.948, 450.9, 1.38,  1.914, 471.4,
              1.31,  1.849, 495.9, 1.04,  1.833, 520.9, 0.62,  2.081, 548.6, 0.43,  2.455,
              582.1, 0.29,  2.863, 616.8, 0.21,  3.272, 659.5, 0.14,  3.697, 704.5, 0.13,
              4.103, 756.0, 0.14,  4.542, 821.1, 0.16,  5.083, 892.0, 0.17,  5.663}},
      {"Ag", {354.2, 0.10,  1.419, 367.9, 0.07,  1.657, 381.5, 0.05,  1.864, 397.4, 0.05,
              2.070, 413.3, 0.05,  2.275, 430.5, 0.04,  2.462, 450.9, 0.04,  2.657, 471.4,
              0.05,  2.869, 495.9, 0.05,  3.093, 520.9, 0.05,  3.324, 548.6, 0.06,  3.586,
              582.1, 0.05,  3.858, 616.8, 0.06,  4.152, 659.5, 0.05,  4.483, 704.5, 0.04,
              4.838, 756.0, 0.03,  5.242, 821.1, 0.04,  5.727, 892.0, 0.04,  6.312}},
      {"Cu", {354.2, 1.37,  1.916, 367.9, 1.36,  1.975, 381.5, 1.33,  2.045, 397.4, 1.32,
              2.116, 413.3, 1.28,  2.207, 430.5, 1.25,  2.305, 450.9, 1.24,  2.397, 471.4,
              1.25,  2.483, 495.9, 1.22,  2.564, 520.9, 1.18,  2.608, 548.6, 1.02,  2.577,
              582.1, 0.70,  2.704, 616.8, 0.30,  3.205, 659.5, 0.22,  3.747, 704.5, 0.21,
              4.205, 756.0, 0.24,  4.665, 821.1, 0.26,  5.180, 892.0, 0.30,  5.768}},
      {"Al",
       {310.0,  0.2800, 3.7081, 326.3,  0.3147, 3.9165, 364.7,  0.3988, 4.3957, 413.3,  0.5214,
        5.0008, 442.8,  0.6079, 5.3676, 476.9,  0.7278, 5.7781, 516.6,  0.8734, 6.2418, 563.6,
        1.0728, 6.7839, 619.9,  1.3660, 7.4052, 652.3,  1.5724, 7.7354, 688.8,  1.8301, 8.0601,
        729.3,  2.1606, 8.3565, 774.9,  2.6154, 8.4914, 794.8,  2.7675, 8.3866, 815.7,  2.7668,
        8.2573, 837.7,  2.6945, 8.1878, 885.6,  2.2802, 8.1134}},
  };
  return tables;
}

glm::dvec3 metalRgb(const MetalTable& table, bool wantK) {
  std::vector<double> pairs;
  for (std::size_t i = 0; i + 2 < table.nmEtaK.size(); i += 3) {
    pairs.push_back(table.nmEtaK[i]);
    pairs.push_back(table.nmEtaK[i + (wantK ? 2 : 1)]);
  }
  return *sampledSpectrumToRgb(pairs);
}

}  // namespace

glm::dvec3 cieColourMatching(double nm) {
  // Table 1 of Wyman, Sloan and Shirley (2013): weight, mean, and the widths below and above
  // the mean, all in nm.
  const double x = lobe(nm, 1.056, 599.8, 37.9, 31.0) + lobe(nm, 0.362, 442.0, 16.0, 26.7) -
                   lobe(nm, 0.065, 501.1, 20.4, 26.2);
  const double y = lobe(nm, 0.821, 568.8, 46.9, 40.5) + lobe(nm, 0.286, 530.9, 16.3, 31.1);
  const double z = lobe(nm, 1.217, 437.0, 11.8, 36.0) + lobe(nm, 0.681, 459.0, 26.0, 13.8);
  return {x, y, z};
}

glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz) {
  return {3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
          -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
          0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z};
}

std::optional<glm::dvec3> sampledSpectrumToRgb(std::span<const double> pairs, std::string* whyNot) {
  auto fail = [&](const std::string& reason) -> std::optional<glm::dvec3> {
    if (whyNot) *whyNot = reason;
    return std::nullopt;
  };
  if (pairs.size() < 2 || pairs.size() % 2 != 0) {
    return fail("a sampled spectrum needs (wavelength, value) pairs, found " +
                std::to_string(pairs.size()) + " numbers");
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!std::isfinite(pairs[i])) return fail("a sampled spectrum has a non-finite number");
  }
  for (std::size_t i = 2; i < pairs.size(); i += 2) {
    if (!(pairs[i] > pairs[i - 2])) {
      return fail("sampled spectrum wavelengths must increase (" + std::to_string(pairs[i - 2]) +
                  " then " + std::to_string(pairs[i]) + ")");
    }
  }
  return balanced(unbalancedRgb([&](double nm) { return spectrumAt(pairs, nm); }));
}

glm::dvec3 blackbodyToRgb(double kelvin) {
  constexpr double h = 6.62607015e-34;     // Planck, J s
  constexpr double c = 299792458.0;        // m/s
  constexpr double k = 1.380649e-23;       // Boltzmann, J/K
  constexpr double wien = 2.897771955e-3;  // m K
  auto planck = [&](double metres) {
    return 2.0 * h * c * c / std::pow(metres, 5) / std::expm1(h * c / (metres * k * kelvin));
  };
  const double peak = planck(wien / kelvin);
  return balanced(unbalancedRgb([&](double nm) { return planck(nm * 1e-9) / peak; }));
}

std::optional<glm::dvec3> namedSpectrumRgb(const std::string& name) {
  for (const MetalTable& table : metals()) {
    const std::string symbol = table.symbol;
    for (const bool wantK : {false, true}) {
      const std::string suffix = wantK ? "k" : "eta";
      const std::string fileName = symbol + "." + suffix + ".spd";
      const bool endsWithFileName =
          name.size() >= fileName.size() &&
          name.compare(name.size() - fileName.size(), fileName.size(), fileName) == 0 &&
          (name.size() == fileName.size() || name[name.size() - fileName.size() - 1] == '/');
      if (name == "metal-" + symbol + "-" + suffix || endsWithFileName) {
        return metalRgb(table, wantK);
      }
    }
  }
  return std::nullopt;
}

std::optional<std::vector<double>> readSpectrumFile(const std::filesystem::path& path,
                                                    std::string* whyNot) {
  std::ifstream input(path, std::ios::binary);
  if (!input) {
    if (whyNot) *whyNot = "cannot open spectrum file " + path.string();
    return std::nullopt;
  }
  std::ostringstream text;
  text << input.rdbuf();
  return parseSpectrumText(text.str(), path.string(), whyNot);
}

std::optional<std::vector<double>> parseSpectrumText(const std::string& text,
                                                     const std::string& fileName,
                                                     std::string* whyNot) {
  std::istringstream input(text);
  std::vector<double> numbers;
  std::string line;
  int lineNumber = 0;
  while (std::getline(input, line)) {
    ++lineNumber;
    const std::size_t comment = line.find('#');
    if (comment != std::string::npos) line.resize(comment);
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      double value = 0.0;
      const auto [stop, error] = std::from_chars(word.data(), word.data() + word.size(), value);
      if (error != std::errc() || stop != word.data() + word.size()) {
        if (whyNot) {
          *whyNot =
              fileName + ":" + std::to_string(lineNumber) + ": '" + word + "' is not a number";
        }
        return std::nullopt;
      }
      numbers.push_back(value);
    }
  }
  return numbers;
}

}  // namespace lenslab::render
