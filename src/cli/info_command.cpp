#include "cli/info_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "optics/field.h"

namespace lenslab::cli {

namespace {

struct InfoArguments {
  std::string lensPath;
  bool json = false;
  double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm;
  double filmDiagonalMm = 43.27;  // 36 x 24 mm full frame
};

// JSON has no infinity; such values are null.
nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

// Focal lengths and distances of an afocal lens (zero power) are infinite: null, not the 0 that
// FirstOrderData holds for them.
nlohmann::json focal(const optics::FirstOrderData& fo, double value) {
  return fo.afocal ? nlohmann::json(nullptr) : number(value);
}

nlohmann::json pupilJson(const optics::PupilData& pupil, const char* reference) {
  return {{"diameter_mm", number(pupil.diameterMm)},
          {"position_mm", pupil.atInfinity ? nlohmann::json(nullptr) : number(pupil.positionMm)},
          {"position_from", reference},
          {"z_mm", pupil.atInfinity ? nlohmann::json(nullptr) : number(pupil.zMm)},
          {"at_infinity", pupil.atInfinity}};
}

nlohmann::json toJson(const optics::LensSystem& lens, const InfoArguments& arguments) {
  const optics::FirstOrderData& fo = lens.firstOrder();
  const auto realField = optics::realFieldOfViewDeg(lens, arguments.filmDiagonalMm);
  nlohmann::json surfaces = nlohmann::json::array();
  for (std::size_t i = 0; i < lens.prescription().surfaces.size(); ++i) {
    const optics::Surface& s = lens.prescription().surfaces[i];
    surfaces.push_back({{"surface", i + 1},
                        {"radius_mm", s.isFlat() ? nlohmann::json(nullptr) : number(s.radiusMm)},
                        {"flat", s.isFlat()},
                        {"stop", s.isStop()},
                        {"thickness_mm", s.thicknessMm},
                        {"n_d", s.mediumIndexD()},
                        {"abbe_d", s.abbeD ? nlohmann::json(*s.abbeD) : nlohmann::json(nullptr)},
                        {"n", lens.surfaces()[i].indexRear},
                        {"aperture_diameter_mm", s.apertureDiameterMm},
                        {"vertex_z_mm", lens.surfaces()[i].vertexZMm}});
  }
  return {
      {"lens", arguments.lensPath},
      {"wavelength_nm", lens.wavelengthNm()},
      {"afocal", fo.afocal},
      {"efl_mm", focal(fo, fo.eflMm)},
      {"bfl_mm", focal(fo, fo.bflMm)},
      {"ffl_mm", focal(fo, fo.fflMm)},
      {"front_principal_plane_mm", focal(fo, fo.frontPrincipalPlaneMm)},
      {"rear_principal_plane_mm", focal(fo, fo.rearPrincipalPlaneMm)},
      {"f_number", focal(fo, fo.fNumber)},
      {"total_track_mm", fo.totalTrackMm},
      {"lens_length_mm", fo.lensLengthMm},
      {"film_distance_mm", lens.filmDistanceMm()},
      {"entrance_pupil", pupilJson(fo.entrancePupil, "front_vertex")},
      {"exit_pupil", pupilJson(fo.exitPupil, "rear_vertex")},
      {"stop_surface", lens.stopIndex() + 1},  // counted from 1, as "surface" above
      {"stop_diameter_mm", lens.stopDiameterMm()},
      {"film_diagonal_mm", arguments.filmDiagonalMm},
      {"field_of_view_deg", focal(fo, fo.fieldOfViewDeg(arguments.filmDiagonalMm))},
      {"field_of_view_real_deg", realField ? nlohmann::json(*realField) : nlohmann::json(nullptr)},
      {"surfaces", surfaces}};
}

void printText(const optics::LensSystem& lens, const InfoArguments& arguments) {
  const optics::FirstOrderData& fo = lens.firstOrder();
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
  std::printf("%s: %zu surfaces, stop is surface %zu (counted from 1), at %.2f nm\n",
              arguments.lensPath.c_str(), lens.prescription().surfaces.size(), lens.stopIndex() + 1,
              lens.wavelengthNm());
  if (fo.afocal) std::printf("afocal: zero power, no focal lengths\n");
  focalLine("effective focal length (EFL)", fo.eflMm, "mm");
  focalLine("back focal length (BFL)", fo.bflMm, "mm from the rear vertex");
  focalLine("front focal length (FFL)", fo.fflMm, "mm in front of the front vertex");
  focalLine("front principal plane", fo.frontPrincipalPlaneMm, "mm from the front vertex");
  focalLine("rear principal plane", fo.rearPrincipalPlaneMm, "mm from the rear vertex");
  focalLine("f-number (infinity)", fo.fNumber, "");
  line("entrance pupil diameter", fo.entrancePupil.diameterMm, "mm");
  line("entrance pupil position", fo.entrancePupil.positionMm, "mm from the front vertex");
  line("exit pupil diameter", fo.exitPupil.diameterMm, "mm");
  line("exit pupil position", fo.exitPupil.positionMm, "mm from the rear vertex");
  line("lens length", fo.lensLengthMm, "mm (front to rear vertex)");
  line("film distance", lens.filmDistanceMm(), "mm (rear vertex to film)");
  line("total track", fo.totalTrackMm, "mm (front vertex to film)");
  if (fo.afocal)
    std::printf("%-34s %12s (afocal: no image on the film)\n", "field of view", "-");
  else
    std::printf("%-34s %12.4f deg (paraxial, %.2f mm film diagonal)\n", "field of view",
                fo.fieldOfViewDeg(arguments.filmDiagonalMm), arguments.filmDiagonalMm);
  if (const auto real = optics::realFieldOfViewDeg(lens, arguments.filmDiagonalMm))
    std::printf("%-34s %12.4f deg (chief ray)\n", "field of view, real", *real);
  else
    std::printf("%-34s %12s (no chief ray reaches the film corner)\n", "field of view, real", "-");
  std::printf("(positions are positive toward the film)\n");
}

}  // namespace

void addInfoCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<InfoArguments>();
  CLI::App* info = app.add_subcommand("info", "Print a lens's first-order (paraxial) data");
  info->add_option("LENS", arguments->lensPath, "Lens file (.dat, pbrt format)")->required();
  info->add_flag("--json", arguments->json, "Print JSON instead of text");
  info->add_option("--wavelength", arguments->wavelengthNm, "Wavelength in nm (default 587.56)")
      ->check(FiniteNumberBetween(200.0, 2000.0, "nm"));
  info->add_option("--film-diagonal", arguments->filmDiagonalMm,
                   "Film diagonal in mm for the field of view (default 43.27, full frame)")
      ->check(PositiveFiniteNumber());
  info->callback([arguments, &run] {
    run = [arguments] {
      const auto lens = loadLensOrReport(arguments->lensPath, "info", arguments->wavelengthNm);
      if (!lens) return 1;
      if (arguments->json)
        std::cout << toJson(*lens, *arguments).dump(2) << "\n";
      else
        printText(*lens, *arguments);
      return 0;
    };
  });
}

}  // namespace lenslab::cli
