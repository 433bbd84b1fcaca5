#include "cli/info_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/json_numbers.h"
#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "optics/analysis/chromatic.h"
#include "optics/axial_beam_area.h"
#include "optics/field.h"
#include "optics/focus.h"
#include "optics/lens_file_formats.h"
#include "optics/limiting_aperture.h"
#include "optics/unvignetted_field.h"

namespace lenslab::cli {

namespace {

// What --wavelength accepts, and so the design wavelengths info traces at.
constexpr double kInfoMinWavelengthNm = 200.0;
constexpr double kInfoMaxWavelengthNm = 2000.0;

struct InfoArguments {
  std::string lensPath;
  bool json = false;
  double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm;  // when --wavelength is given
  bool wavelengthGiven = false;
  double filmDiagonalMm = 43.27;  // 36 x 24 mm full frame
  CommandWavelength used;         // the one traced at, and why (lens_loading.h)
};

// JSON has no infinity; such values are null.
// Focal lengths and distances of an afocal lens (zero power) are infinite: null, not the 0 that
// FirstOrderData holds for them.
nlohmann::json focal(const optics::FirstOrderData& fo, double value) {
  return fo.afocal ? nlohmann::json(nullptr) : finiteOrNull(value);
}

nlohmann::json pupilJson(const optics::PupilData& pupil, const char* reference) {
  return {
      {"diameter_mm", finiteOrNull(pupil.diameterMm)},
      {"position_mm", pupil.atInfinity ? nlohmann::json(nullptr) : finiteOrNull(pupil.positionMm)},
      {"position_from", reference},
      {"z_mm", pupil.atInfinity ? nlohmann::json(nullptr) : finiteOrNull(pupil.zMm)},
      {"at_infinity", pupil.atInfinity}};
}

// What limits the axial beam from infinity, the unvignetted field and whether the lens forms an
// image: computed once, printed as text or JSON.
struct BeamFigures {
  optics::LimitingAperture limit;
  std::optional<double> unvignettedFieldDeg;
  optics::InfinityImage image;
  // With a shaped stop (blades, an image): the light it admits, as a circle's f-number.
  std::optional<optics::AxialBeamArea> shapedBeam;
};

BeamFigures beamFigures(const optics::LensSystem& lens) {
  BeamFigures figures{optics::findLimitingAperture(lens, std::numeric_limits<double>::infinity()),
                      optics::unvignettedFieldOfViewDeg(lens), optics::infinityImage(lens),
                      std::nullopt};
  if (!lens.stopShape().isCircle()) figures.shapedBeam = optics::axialBeamAreaFromInfinity(lens);
  return figures;
}

// "before the iris" / "after the iris" / "the iris".
std::string whereAgainstIris(int surface, std::size_t stopIndex) {
  if (surface == static_cast<int>(stopIndex)) return "the iris";
  return surface < static_cast<int>(stopIndex) ? "before the iris" : "after the iris";
}

// The profile beyond the vertex curvature: the conic constant, and each nonzero polynomial term
// by its power ({"4": -2e-06}); {} for a sphere.
nlohmann::json asphericCoefficientsJson(const optics::AsphericProfile& profile) {
  nlohmann::json terms = nlohmann::json::object();
  for (int power = optics::AsphericProfile::kMinPower; power <= profile.highestPower(); ++power) {
    if (profile.coefficient(power) != 0.0)
      terms[std::to_string(power)] = finiteOrNull(profile.coefficient(power));
  }
  return terms;
}

nlohmann::json toJson(const optics::LoadedLens& loaded, const InfoArguments& arguments) {
  const optics::LensSystem& lens = *loaded.system;
  const optics::FirstOrderData& fo = lens.firstOrder();
  const auto realField = optics::realFieldOfViewDeg(lens, arguments.filmDiagonalMm);
  const BeamFigures beam = beamFigures(lens);
  const int limiting = beam.limit.limitingSurface();
  nlohmann::json surfaces = nlohmann::json::array();
  for (std::size_t i = 0; i < lens.prescription().surfaces.size(); ++i) {
    const optics::Surface& s = lens.prescription().surfaces[i];
    surfaces.push_back(
        {{"surface", i + 1},
         {"radius_mm", s.isFlat() ? nlohmann::json(nullptr) : finiteOrNull(s.radiusMm)},
         {"flat", s.isFlat()},
         {"stop", s.isStop()},
         {"thickness_mm", s.thicknessMm},
         {"n_d", s.mediumIndexD()},
         {"abbe_d", s.abbeD ? nlohmann::json(*s.abbeD) : nlohmann::json(nullptr)},
         // The catalogue glass by name and maker; null for a model glass (n_d, abbe_d) or air.
         {"glass", s.glass ? nlohmann::json(s.glass->name) : nlohmann::json(nullptr)},
         {"glass_maker", s.glass ? nlohmann::json(s.glass->maker) : nlohmann::json(nullptr)},
         {"conic", finiteOrNull(s.profile.conic())},
         {"aspheric_coefficients", asphericCoefficientsJson(s.profile)},
         {"n", lens.surfaces()[i].indexRear},
         {"aperture_diameter_mm", s.apertureDiameterMm},
         {"vertex_z_mm", lens.surfaces()[i].vertexZMm}});
  }
  std::string colourWhyNot;
  const std::optional<double> colourShift =
      optics::chromaticFocalShiftFromInfinityMm(lens, &colourWhyNot);
  nlohmann::json out = {
      {"lens", arguments.lensPath},
      {"wavelength_nm", lens.wavelengthNm()},
      // Where it came from: "option" (--wavelength), "design" (the file's primary design
      // wavelength) or "default" (the d line).
      {"wavelength_from", arguments.used.from},
      {"afocal", fo.afocal},
      {"efl_mm", focal(fo, fo.eflMm)},
      {"bfl_mm", focal(fo, fo.bflMm)},
      {"ffl_mm", focal(fo, fo.fflMm)},
      {"front_principal_plane_mm", focal(fo, fo.frontPrincipalPlaneMm)},
      {"rear_principal_plane_mm", focal(fo, fo.rearPrincipalPlaneMm)},
      // EFL / the paraxial beam from infinity that passes every clear aperture (the iris's
      // entrance pupil, or less when a rim limits the beam first: limiting_aperture.h).
      {"f_number", beam.limit.paraxial ? focal(fo, beam.limit.paraxial->workingFNumber)
                                       : focal(fo, fo.fNumber)},
      // The stop's shape as the lens file writes it, and for a shape other than the circle the
      // f-number of the circular beam that passes as much light (axial_beam_area.h); null for
      // the circle, whose f_number above already says it.
      {"stop_shape", lens.stopShape().spec()},
      {"f_number_by_area",
       beam.shapedBeam ? focal(fo, beam.shapedBeam->fNumberByArea) : nlohmann::json(nullptr)},
      {"passing_beam_area_mm2",
       beam.shapedBeam ? finiteOrNull(beam.shapedBeam->areaMm2) : nlohmann::json(nullptr)},
      {"total_track_mm", fo.totalTrackMm},
      {"lens_length_mm", fo.lensLengthMm},
      {"film_distance_mm", lens.filmDistanceMm()},
      // F minus C (mm, along the light), null without V_d: the chromatic focal shift.
      {"chromatic_focal_shift_mm",
       colourShift ? nlohmann::json(*colourShift) : nlohmann::json(nullptr)},
      {"entrance_pupil", pupilJson(fo.entrancePupil, "front_vertex")},
      {"exit_pupil", pupilJson(fo.exitPupil, "rear_vertex")},
      {"stop_surface", lens.stopIndex() + 1},  // counted from 1, as "surface" above
      {"stop_diameter_mm", lens.stopDiameterMm()},
      {"film_diagonal_mm", arguments.filmDiagonalMm},
      {"field_of_view_deg", focal(fo, fo.fieldOfViewDeg(arguments.filmDiagonalMm))},
      {"field_of_view_real_deg", realField ? nlohmann::json(*realField) : nlohmann::json(nullptr)},
      // What limits the axial beam from infinity (limiting_aperture.h): the surface counted from
      // 1; the working f-number 1 / (2 n' sin u') of the widest real ray that passes; the paraxial
      // figures from the smallest semi-aperture / marginal-height ratio.
      {"limiting_aperture_surface",
       limiting >= 0 ? nlohmann::json(limiting + 1) : nlohmann::json(nullptr)},
      {"limiting_aperture_is_stop", limiting >= 0
                                        ? nlohmann::json(beam.limit.limitedByStop(lens.stopIndex()))
                                        : nlohmann::json(nullptr)},
      {"working_f_number",
       beam.limit.real ? finiteOrNull(beam.limit.real->workingFNumber) : nlohmann::json(nullptr)},
      {"working_f_number_definition",
       "real rays: 1 / (2 n' sin u') of the widest axial ray from infinity that passes"},
      {"passing_beam_diameter_mm", beam.limit.real
                                       ? finiteOrNull(2.0 * beam.limit.real->entranceHeightMm)
                                       : nlohmann::json(nullptr)},
      {"paraxial_limiting_surface", beam.limit.paraxial
                                        ? nlohmann::json(beam.limit.paraxial->surfaceIndex + 1)
                                        : nlohmann::json(nullptr)},
      {"paraxial_limited_entrance_pupil_diameter_mm",
       beam.limit.paraxial ? finiteOrNull(beam.limit.paraxial->entrancePupilDiameterMm)
                           : nlohmann::json(nullptr)},
      {"unvignetted_field_of_view_deg", beam.unvignettedFieldDeg
                                            ? finiteOrNull(*beam.unvignettedFieldDeg)
                                            : nlohmann::json(nullptr)},
      {"forms_real_image", beam.image.ok()},
      {"no_image_reason",
       beam.image.ok() ? nlohmann::json(nullptr) : nlohmann::json(beam.image.whyNot)},
      {"surfaces", surfaces}};
  // What the file says of the lens (a .lens file's title, source and published focal length),
  // only when it says it.
  if (!loaded.file.title.empty()) out["title"] = loaded.file.title;
  if (!loaded.file.source.empty()) out["source"] = loaded.file.source;
  if (loaded.file.publishedEflMm)
    out["published_efl_mm"] = finiteOrNull(*loaded.file.publishedEflMm);
  if (!loaded.file.lensType.empty()) out["type"] = loaded.file.lensType;
  if (loaded.file.year) out["year"] = *loaded.file.year;
  return out;
}

void printBeam(const optics::LensSystem& lens, const BeamFigures& beam) {
  const int limiting = beam.limit.limitingSurface();
  if (beam.limit.real && limiting >= 0) {
    const optics::RealAxialBeam& real = *beam.limit.real;
    if (beam.limit.limitedByStop(lens.stopIndex()))
      std::printf("the iris (surface %zu) limits the axial beam: working f/%.2f\n",
                  lens.stopIndex() + 1, real.workingFNumber);
    else
      std::printf("surface %d limits the axial beam %s: working f/%.2f\n", limiting + 1,
                  whereAgainstIris(limiting, lens.stopIndex()).c_str(), real.workingFNumber);
    std::printf(
        "%-34s %12.4f mm across (real rays from infinity; the next is stopped by "
        "surface %d)\n",
        "  widest passing axial beam", 2.0 * real.entranceHeightMm, limiting + 1);
    std::printf("%-34s %12.4f (real rays: 1 / (2 n' sin u') of that beam's edge ray)\n",
                "  working f-number", real.workingFNumber);
  }
  if (beam.limit.paraxial) {
    const optics::ParaxialAxialLimit& paraxial = *beam.limit.paraxial;
    std::printf(
        "%-34s %12.4f mm (paraxial: surface %zu has the smallest semi-aperture / "
        "marginal height)\n",
        "  limited entrance pupil", paraxial.entrancePupilDiameterMm, paraxial.surfaceIndex + 1);
  }
  if (beam.unvignettedFieldDeg)
    std::printf(
        "%-34s %12.4f deg (from infinity: no ray the limiting aperture admits is blocked)\n",
        "field of view, unvignetted", *beam.unvignettedFieldDeg);
  else
    std::printf("%-34s %12s (no axial beam passes)\n", "field of view, unvignetted", "-");
}

void printText(const optics::LoadedLens& loaded, const InfoArguments& arguments) {
  const optics::LensSystem& lens = *loaded.system;
  if (!loaded.file.title.empty()) std::printf("%s\n", loaded.file.title.c_str());
  if (!loaded.file.source.empty()) std::printf("source: %s\n", loaded.file.source.c_str());
  if (!loaded.file.lensType.empty() || loaded.file.year) {
    std::string kind = loaded.file.lensType;
    if (loaded.file.year) kind += (kind.empty() ? "" : ", ") + std::to_string(*loaded.file.year);
    std::printf("type: %s\n", kind.c_str());
  }
  const optics::FirstOrderData& fo = lens.firstOrder();
  const BeamFigures beam = beamFigures(lens);
  auto line = [](const char* label, double value, const char* unit) {
    std::printf("%-34s %12.4f %s\n", label, value, unit);
  };
  // Values that are infinite for an afocal lens.
  auto focalLine = [&](const char* label, double value, const char* unit) {
    if (fo.afocal)
      std::printf("%-34s %12s\n", label, "afocal (infinite)");
    else
      line(label, value, unit);
  };
  std::printf("%s: %zu surfaces, stop is surface %zu (counted from 1), at %.2f nm %s\n",
              arguments.lensPath.c_str(), lens.prescription().surfaces.size(), lens.stopIndex() + 1,
              lens.wavelengthNm(), arguments.used.describe().c_str());
  if (fo.afocal) std::printf("afocal: zero power, no focal lengths\n");
  // Said first, in focus's words: the paraxial figures below mean little for such a lens.
  if (!beam.image.ok()) std::printf("%s\n", beam.image.whyNot.c_str());
  focalLine("effective focal length (EFL)", fo.eflMm, "mm");
  if (loaded.file.publishedEflMm)
    line("published focal length", *loaded.file.publishedEflMm, "mm (as the source prints it)");
  focalLine("back focal length (BFL)", fo.bflMm, "mm from the rear vertex");
  focalLine("front focal length (FFL)", fo.fflMm, "mm in front of the front vertex");
  focalLine("front principal plane", fo.frontPrincipalPlaneMm, "mm from the front vertex");
  focalLine("rear principal plane", fo.rearPrincipalPlaneMm, "mm from the rear vertex");
  if (beam.limit.paraxial)
    focalLine("f-number (infinity)", beam.limit.paraxial->workingFNumber,
              "(paraxial: EFL / limited entrance pupil, below)");
  else
    focalLine("f-number (infinity)", fo.fNumber, "(paraxial: EFL / entrance pupil)");
  if (beam.shapedBeam) {
    char area[64];
    std::snprintf(area, sizeof area, "%.2f", beam.shapedBeam->areaMm2);
    // Appended piece by piece: GCC 12 flags operator+ chains with a false -Wrestrict.
    std::string why = "(a circle passing the light of the stop's ";
    why += lens.stopShape().spec();
    why += ": a ";
    why += area;
    why += " mm2 beam from infinity)";
    focalLine("f-number by area", beam.shapedBeam->fNumberByArea, why.c_str());
  }
  line("entrance pupil diameter", fo.entrancePupil.diameterMm, "mm (the iris's image)");
  line("entrance pupil position", fo.entrancePupil.positionMm, "mm from the front vertex");
  line("exit pupil diameter", fo.exitPupil.diameterMm, "mm");
  line("exit pupil position", fo.exitPupil.positionMm, "mm from the rear vertex");
  line("lens length", fo.lensLengthMm, "mm (front to rear vertex)");
  line("film distance", lens.filmDistanceMm(), "mm (rear vertex to film)");
  line("total track", fo.totalTrackMm, "mm (front vertex to film)");
  std::string colourWhyNot;
  if (const auto shift = optics::chromaticFocalShiftFromInfinityMm(lens, &colourWhyNot))
    line("chromatic focal shift (F - C)", *shift,
         "mm (paraxial, from infinity; negative: blue focuses nearer the lens)");
  else
    std::printf("%-34s %12s (%s)\n", "chromatic focal shift (F - C)", "-", colourWhyNot.c_str());
  if (fo.afocal)
    std::printf("%-34s %12s (afocal: no image on the film)\n", "field of view", "-");
  else
    std::printf("%-34s %12.4f deg (paraxial, %.2f mm film diagonal)\n", "field of view",
                fo.fieldOfViewDeg(arguments.filmDiagonalMm), arguments.filmDiagonalMm);
  if (const auto real = optics::realFieldOfViewDeg(lens, arguments.filmDiagonalMm))
    std::printf("%-34s %12.4f deg (chief ray)\n", "field of view, real", *real);
  else
    std::printf("%-34s %12s (no chief ray reaches the film corner)\n", "field of view, real", "-");
  printBeam(lens, beam);
  std::printf("(positions are positive toward the film)\n");
}

}  // namespace

void addInfoCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<InfoArguments>();
  CLI::App* info = app.add_subcommand("info", "Print a lens's first-order (paraxial) data");
  info->add_option("LENS", arguments->lensPath,
                   "Lens file (" + optics::lensFileExtensionsText() + ")")
      ->required();
  info->add_flag("--json", arguments->json, "Print JSON instead of text");
  CLI::Option* wavelength =
      info->add_option("--wavelength", arguments->wavelengthNm,
                       "Wavelength in nm (default: the lens's primary design wavelength when its "
                       "file states one, else 587.56, the d line)")
          ->check(FiniteNumberBetween(kInfoMinWavelengthNm, kInfoMaxWavelengthNm, "nm"));
  info->add_option("--film-diagonal", arguments->filmDiagonalMm,
                   "Film diagonal in mm for the field of view (default 43.27, full frame)")
      ->check(PositiveFiniteNumber());
  info->callback([arguments, wavelength, &run] {
    arguments->wavelengthGiven = wavelength->count() > 0;
    run = [arguments] {
      const optics::LoadedLens loaded = loadLensAtWavelengthOrReport(
          arguments->lensPath, "info",
          arguments->wavelengthGiven ? std::optional<double>(arguments->wavelengthNm)
                                     : std::nullopt,
          {kInfoMinWavelengthNm, kInfoMaxWavelengthNm}, arguments->used);
      if (!loaded.ok()) return 1;
      if (arguments->json)
        std::cout << toJson(loaded, *arguments).dump(2) << "\n";
      else
        printText(loaded, *arguments);
      return 0;
    };
  });
}

}  // namespace lenslab::cli
