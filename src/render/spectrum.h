#pragma once
// pbrt's spectral parameter values ("spectrum", "blackbody", "xyz") turned into the linear sRGB
// triples the renderer works with.

#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lenslab::render {

// The CIE 1931 2-degree colour-matching functions (x̄, ȳ, z̄) at a wavelength in nm, from the
// multi-lobe piecewise-Gaussian fit of Wyman, Sloan and Shirley, "Simple Analytic
// Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2), 2013, eq. 2 / table 1.
glm::dvec3 cieColourMatching(double wavelengthNm);

// CIE XYZ to linear sRGB (IEC 61966-2-1 primaries, D65 white).
glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz);

// A spectrum given as (wavelength in nm, value) pairs, increasing in wavelength, taken as
// piecewise linear and constant beyond its ends, integrated against the colour-matching
// functions over 360-830 nm. The result is white-balanced to an equal-energy white, as a
// reflectance is: a constant spectrum c gives exactly (c, c, c).
// Returns nothing, with a reason in `whyNot`, when the pairs are malformed.
std::optional<glm::dvec3> sampledSpectrumToRgb(std::span<const double> wavelengthValuePairs,
                                               std::string* whyNot = nullptr);

// A blackbody at `kelvin`, normalised to 1 at its peak wavelength (Wien's law), as pbrt-v3's
// "blackbody" [T scale] is before the scale; same white balance as sampledSpectrumToRgb.
glm::dvec3 blackbodyToRgb(double kelvin);

// The RGB value of a named spectrum: pbrt's metal names "metal-Au-eta", "metal-Au-k" (also Ag, Cu,
// Al), or the file names pbrt-v3's scenes use for them ("spds/metals/Au.eta.spd"); nothing for
// other names.
std::optional<glm::dvec3> namedSpectrumRgb(const std::string& name);

// The (wavelength, value) pairs of a pbrt-v3 .spd file: numbers separated by white space, '#'
// to the end of a line is a comment. Nothing, with a reason in `whyNot`, if it cannot be read.
std::optional<std::vector<double>> readSpectrumFile(const std::filesystem::path& path,
                                                    std::string* whyNot);
// The same for the file's text already read; `fileName` names it in `whyNot`.
std::optional<std::vector<double>> parseSpectrumText(const std::string& text,
                                                     const std::string& fileName,
                                                     std::string* whyNot);

}  // namespace lenslab::render
