// `seidel`: the Seidel sums per surface and in total (optics/analysis/seidel.h), with their
// third-order consequences on the Gaussian image plane, so that they can be set beside real rays.

#include <cstdio>

#include "cli/analyze/reports.h"
#include "optics/analysis/seidel.h"

namespace lenslab::cli {

namespace {

nlohmann::json termsJson(const optics::SeidelTerms& t, bool chromatic) {
  nlohmann::json json{{"S1", finiteOrNull(t.s1)},
                      {"S2", finiteOrNull(t.s2)},
                      {"S3", finiteOrNull(t.s3)},
                      {"S4", finiteOrNull(t.s4)},
                      {"S5", finiteOrNull(t.s5)}};
  if (chromatic) {
    json["CL"] = finiteOrNull(t.cl);
    json["CT"] = finiteOrNull(t.ct);
  }
  return json;
}

std::string termsLine(const std::string& name, const optics::SeidelTerms& t, bool chromatic) {
  std::string line = formatted("%8s %11.6f %11.6f %11.6f %11.6f %11.6f", name.c_str(), t.s1, t.s2,
                               t.s3, t.s4, t.s5);
  if (chromatic) line += formatted(" %11.6f %11.6f", t.cl, t.ct);
  return line + "\n";
}

}  // namespace

ReportPart seidelReport(const AnalyzeContext& context) {
  std::string whyNot;
  const auto sums =
      optics::computeSeidelSums(*context.lens, context.setup.objectDistanceFromFilmMm,
                                optics::seidelFieldHeightMm(*context.lens, context.setup), &whyNot);
  if (!sums) throw AnalysisUnavailable(whyNot);
  const bool chromatic = sums->chromatic;
  nlohmann::json surfaces = nlohmann::json::array();
  for (std::size_t i = 0; i < sums->surfaces.size(); ++i) {
    nlohmann::json entry{{"surface", i + 1}};  // from 1, as `info` and the viewer count
    entry.update(termsJson(sums->surfaces[i], chromatic));
    surfaces.push_back(std::move(entry));
  }
  const optics::SeidelTransverse& tr = sums->transverse;
  nlohmann::json thirdOrder{{"spherical_transverse_mm", finiteOrNull(tr.sphericalMm)},
                            {"spherical_longitudinal_mm", finiteOrNull(tr.sphericalLongMm)},
                            {"coma_tangential_mm", finiteOrNull(tr.comaTangentialMm)},
                            {"coma_sagittal_mm", finiteOrNull(tr.comaSagittalMm)},
                            {"tangential_focus_mm", finiteOrNull(tr.tangentialFocusMm)},
                            {"sagittal_focus_mm", finiteOrNull(tr.sagittalFocusMm)},
                            {"petzval_focus_mm", finiteOrNull(tr.petzvalFocusMm)},
                            {"distortion_mm", finiteOrNull(tr.distortionMm)},
                            {"distortion_percent", finiteOrNull(tr.distortionPercent)}};
  if (chromatic) {
    thirdOrder["axial_color_transverse_mm"] = finiteOrNull(tr.axialColourMm);
    thirdOrder["axial_color_longitudinal_mm"] = finiteOrNull(tr.axialColourLongMm);
    thirdOrder["lateral_color_mm"] = finiteOrNull(tr.lateralColourMm);
  }
  ReportPart part;
  part.json = nlohmann::json{
      {"convention",
       "Welford, Aberrations of Optical Systems, ch. 7: S1 = -A^2 h D(u/n), S2 = -A Abar h "
       "D(u/n), S3 = -Abar^2 h D(u/n), S4 = -H^2 c D(1/n), S5 = (Abar/A)(S3 + S4), CL = A h "
       "D(dn/n), CT = Abar h D(dn/n) with A = n(hc + u), dn = n_F - n_C, c the paraxial "
       "curvature c_p = c0 + 2 A2 (c0 = 1/R); an aspheric surface adds 8 delta D(n) h^4 "
       "(h_bar/h)^j to S1, S2, S3, S5 (j = 0, 1, 2, 3), delta = (1 + k) c0^3/8 + A4 - c_p^3/8, "
       "odd powers left out (odd_aspheric_terms_left_out); u is the slope along the "
       "light, y toward the film point. Marginal ray to the limited entrance pupil's edge, chief "
       "ray through the stop's centre to field_height_mm on the Gaussian image. W = S1 rho^4/8 + "
       "S2 eta rho^3 cos/2 + S3 eta^2 rho^2 cos^2/2 + (S3 + S4) eta^2 rho^2/4 + S5 eta^3 rho "
       "cos/2; transverse aberration = dW/d(pupil) / (n' u')"},
      {"units", "mm (wavefront sums; heights in mm, slopes in radians)"},
      {"wavelength_nm", finiteOrNull(sums->wavelengthNm)},
      {"entrance_pupil_radius_mm", finiteOrNull(sums->entrancePupilRadiusMm)},
      {"field_height_mm", finiteOrNull(sums->fieldHeightMm)},
      {"lagrange_invariant_mm", finiteOrNull(sums->lagrangeInvariant)},
      {"image_index", finiteOrNull(sums->imageIndex)},
      {"marginal_image_slope", finiteOrNull(sums->marginalImageSlope)},
      {"gaussian_image_from_film_mm", finiteOrNull(sums->gaussianImageFromFilmMm)},
      {"surfaces", std::move(surfaces)},
      {"total", termsJson(sums->total, chromatic)},
      {"third_order", std::move(thirdOrder)}};
  // Surfaces (from 1) whose odd-power aspheric terms the sums leave out (seidel.h): empty for
  // every lens without them, so that a reader can rely on the key.
  nlohmann::json oddTerms = nlohmann::json::array();
  for (std::size_t i : sums->surfacesWithOddTerms) oddTerms.push_back(i + 1);
  (*part.json)["odd_aspheric_terms_left_out"] = std::move(oddTerms);

  part.text = formatted(
      "Welford's sums (mm); marginal ray to the %.3f mm entrance pupil radius, chief ray to a "
      "%.3f mm image\n",
      sums->entrancePupilRadiusMm, sums->fieldHeightMm);
  part.text += formatted("%8s %11s %11s %11s %11s %11s", "surface", "S1 sph", "S2 coma", "S3 astig",
                         "S4 Petzval", "S5 dist");
  part.text += chromatic ? formatted(" %11s %11s\n", "CL axial", "CT lateral")
                         : std::string("   (no V_d: no colour sums)\n");
  for (std::size_t i = 0; i < sums->surfaces.size(); ++i)
    part.text += termsLine(std::to_string(i + 1), sums->surfaces[i], chromatic);
  part.text += termsLine("total", sums->total, chromatic);
  part.text += formatted(
      "third order at the Gaussian image: spherical %.4f mm (focus %.4f mm), coma tangential "
      "%.4f mm, distortion %.3f %%\n",
      tr.sphericalMm, tr.sphericalLongMm, tr.comaTangentialMm, tr.distortionPercent);
  part.text += formatted("  tangential focus %.4f mm, sagittal %.4f mm, Petzval %.4f mm\n",
                         tr.tangentialFocusMm, tr.sagittalFocusMm, tr.petzvalFocusMm);
  if (chromatic)
    part.text += formatted("  axial colour focus (F - C) %.4f mm, lateral colour %.4f um\n",
                           tr.axialColourLongMm, 1000.0 * tr.lateralColourMm);
  if (const std::string note = optics::seidelOddTermsNote(*sums); !note.empty())
    part.text += "note: " + note + "\n";
  return part;
}

}  // namespace lenslab::cli
