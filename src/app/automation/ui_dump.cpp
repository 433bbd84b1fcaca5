#include "app/automation/ui_dump.h"

#include "app/lens_caption.h"
#include "common/atomic_file.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

namespace lenslab::app {

namespace {

// The wavelengths the cross-section's fans are drawn at: the lens's own, then the colour fans'
// (none when they are off or the lens has no dispersion).
std::vector<double> colourFanWavelengths(const ViewerState& state) {
  std::vector<double> wavelengths;
  if (state.rayFans.fans.empty() || state.rayFans.fans.front().atOtherWavelengths.empty())
    return wavelengths;
  wavelengths.push_back(state.rayFans.wavelengthNm);
  for (const auto& other : state.rayFans.fans.front().atOtherWavelengths)
    wavelengths.push_back(other.wavelengthNm);
  return wavelengths;
}

// The pinned reference: its title, how often its analyses were asked for (once per settings:
// never for an edit of the lens), whether they have finished, and the first-order comparison.
nlohmann::json referenceJson(const ViewerState& state) {
  if (!state.reference) return nullptr;
  const ReferenceLens& reference = *state.reference;
  const auto latest = reference.job ? reference.job->latest() : nullptr;
  nlohmann::json rows = nlohmann::json::array();
  for (const FirstOrderComparisonRow& row : reference.shownComparison)
    rows.push_back({{"name", row.name},
                    {"lens", row.lens},
                    {"reference", row.reference},
                    {"difference", row.difference}});
  return {{"title", reference.title},
          {"analysis_requests", reference.requests},
          {"computed", latest != nullptr},
          {"compute_ms", latest ? latest->computeMs : 0.0},
          {"no_image", latest ? latest->noImage : std::string()},
          {"first_order", rows}};
}

// The library browser (issue 42): its folder, what it lists with the filters as they are, which
// have their thumbnail uploaded, and how long it took to show them (ms from the request).
nlohmann::json libraryDump(const LibraryBrowserState& library) {
  const auto optionalMs = [](const std::optional<double>& ms) {
    return ms ? nlohmann::json(*ms) : nlohmann::json(nullptr);
  };
  nlohmann::json shown = nlohmann::json::array();
  const ShownLibrary listed = shownLibraryEntries(library);
  for (const std::size_t i : listed.indices) {
    const LibraryEntry& entry = listed.snapshot->entries[i];
    const auto orNull = [](const auto& value) {
      return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
    };
    shown.push_back({{"file", entry.fileName},
                     {"name", entry.name},
                     {"type", entry.type},
                     {"year", orNull(entry.year)},
                     {"efl_mm", orNull(entry.eflMm)},
                     {"f_number", orNull(entry.fNumber)},
                     {"half_field_deg", orNull(entry.halfFieldDeg)},
                     {"elements", entry.elements},
                     {"aspheric_surfaces", entry.asphericSurfaces},
                     {"error", entry.error},
                     {"thumbnail", library.thumbnails.count(entry.contentHash) > 0}});
  }
  const LibraryFilter& filter = library.filter;
  return {{"folder", library.folder.string()},
          {"files", listed.snapshot ? listed.snapshot->files : 0},
          {"listed", listed.snapshot && listed.snapshot->listed},
          {"thumbnails_from_disk", listed.snapshot ? listed.snapshot->thumbnailsFromDisk : 0},
          {"thumbnails_drawn", listed.snapshot ? listed.snapshot->thumbnailsDrawn : 0},
          {"shown", shown},
          {"selected", library.selectedPath},
          {"filter",
           {{"search", filter.search},
            {"type", filter.type},
            {"aspheric", asphericChoiceWord(filter.aspheric)},
            {"efl_mm", filter.minEflMm ? nlohmann::json({*filter.minEflMm, *filter.maxEflMm})
                                       : nlohmann::json(nullptr)},
            {"year", filter.minYear ? nlohmann::json({*filter.minYear, *filter.maxYear})
                                    : nlohmann::json(nullptr)}}},
          {"panel_shown_ms", optionalMs(library.panelShownMs)},
          {"panel_shown_after_frames", library.panelShownAfterFrames
                                           ? nlohmann::json(*library.panelShownAfterFrames)
                                           : nlohmann::json(nullptr)},
          {"read_ms", listed.snapshot ? listed.snapshot->listedAfterMs : 0.0},
          {"thumbnails_made_ms", listed.snapshot ? listed.snapshot->finishedAfterMs : 0.0},
          {"listed_ms", optionalMs(library.listedMs)},
          {"thumbnails_shown_ms", optionalMs(library.thumbnailsShownMs)}};
}

}  // namespace

std::string writeUiDump(const std::filesystem::path& path, const ViewerState& state,
                        const std::string& fileBrowserPurpose, int windowWidth, int windowHeight) {
  nlohmann::json widgets = nlohmann::json::object();
  for (const auto& [name, rect] : state.uiRects) {
    widgets[name] = {{"x", rect.x}, {"y", rect.y}, {"width", rect.width}, {"height", rect.height}};
  }
  // What tests check besides positions: the lens, its flags, the dialog, the log.
  nlohmann::json problems = nlohmann::json::array();
  for (const LensProblem& problem : state.lensProblems) {
    problems.push_back({{"surface", problem.surface + 1}, {"message", problem.message}});
  }
  nlohmann::json log = nlohmann::json::array();
  for (const LogEntry& entry : state.log.entries()) {
    log.push_back({{"level", entry.level == LogLevel::Error     ? "error"
                             : entry.level == LogLevel::Warning ? "warning"
                                                                : "info"},
                   {"text", entry.text}});
  }
  // The lens's film distance and stop, and the cross-section's view, for tests that drag them.
  const optics::Prescription& lens = state.lens.prescription();
  nlohmann::json filmDistance = nullptr, stopDiameter = nullptr;
  if (!lens.surfaces.empty()) filmDistance = lens.surfaces.back().thicknessMm;
  if (const auto stop = lens.stopIndex()) stopDiameter = lens.surfaces[*stop].apertureDiameterMm;
  const CrossSectionView& view = state.crossSectionView;
  // Edit > Paste lens table...: what the window read, as its rows and combos show it.
  nlohmann::json pasteColumns = nlohmann::json::array();
  int pasteRows = 0, pasteErrors = 0;
  if (state.pasteTable.read) {
    for (const optics::PatentTableColumn& c : state.pasteTable.read->table.columns)
      pasteColumns.push_back(
          {{"heading", c.heading}, {"meaning", optics::patentColumnLabel(c.meaning)}});
    pasteRows = static_cast<int>(state.pasteTable.read->table.rows.size());
    for (const Diagnostic& d : state.pasteTable.read->lens.diagnostics.all())
      pasteErrors += d.severity == Severity::Error;
  }
  nlohmann::json about = {
      {"lens_path", state.lens.path()},
      // As the Lens panel and the exports caption it (lens_caption.h).
      {"lens_name", lensName(state)},
      {"lens_source", lensSource(state)},
      {"lens_modified", state.lens.modified()},
      {"lens_valid", state.lensSystemIsCurrent},
      {"problems", problems},
      {"file_browser", fileBrowserPurpose},
      {"recent_files", state.settings.recentFiles},
      {"layout",
       {{"lens_table_width", state.settings.layout.lensTableWidth},
        {"preview_width", state.settings.layout.previewWidth},
        {"log_height", state.settings.layout.logHeight},
        {"plot_height", state.settings.layout.plotHeight},
        {"bottom_maximised", state.bottomAreaMaximised}}},
      {"log", log},
      {"tabs", state.settings.selectedTabs},
      {"analysis_conditions", state.analysisConditions},
      {"scene_path", state.scenePath},
      {"scene_loading", state.loadingScenePath},
      {"lens_table_cells_cut_off", state.lensTable.cellsCutOff},
      {"lens_table_cells_shortened", state.lensTable.cellsShortened},
      {"lens_panel_scroll_max_y", state.lensPanelScrollMaxY},
      {"film_distance_mm", filmDistance},
      {"film_diagonal_mm", state.filmDiagonalMm},
      {"field_fractions", state.fanSettings.fieldFractions},
      {"colour_fans", state.fanSettings.colourFans},
      {"colour_fan_wavelengths_nm", colourFanWavelengths(state)},
      {"stop_diameter_mm", stopDiameter},
      {"aperture", lens.stopShape.spec()},
      {"focus_at_text", state.focusAtShown},
      {"in_focus_text", state.inFocusText},
      {"preview",
       {{"image_width", state.preview.imageWidth},
        {"image_height", state.preview.imageHeight},
        {"samples_per_pixel", state.preview.samplesPerPixel},
        {"draft", state.preview.reducedResolution},
        {"exposure_stops", state.exposureStops},
        {"auto_exposure", state.settings.autoExposure},
        {"auto_exposure_stops", state.preview.autoExposureStops}}},
      // The pinned reference (null without one) and the first-order data beside it as shown.
      {"reference", referenceJson(state)},
      // The first-order section's beam figures as shown (empty until it has been drawn).
      {"first_order",
       {{"f_number", state.fNumberText},
        {"axial_beam", state.axialBeamText},
        {"unvignetted", state.unvignettedText},
        {"f_number_by_area", state.areaFNumberText},
        {"colour_focus", state.colourFocusText}}},
      // File > Export render...: the window's fields and the running or last export.
      {"export",
       {{"open", state.exportDialog.open},
        {"width", state.exportDialog.widthPx},
        {"height", state.exportDialog.heightPx},
        {"samples_per_pixel", state.exportDialog.samplesPerPixel},
        {"path", state.exportDialog.path},
        {"running", state.exportDialog.progress.running()},
        {"spp_done", state.exportDialog.progress.sppDone()},
        {"shown_result", state.exportDialog.shownResult}}},
      {"paste_table",
       {{"open", state.pasteTable.open},
        {"rows", pasteRows},
        {"columns", pasteColumns},
        {"errors", pasteErrors},
        {"can_open", state.pasteTable.read && state.pasteTable.read->lens.ok()}}},
      {"cross_section_view",
       {{"pixels_per_mm", view.pixelsPerMm},
        {"centre_z_mm", view.centreZMm},
        {"centre_y_mm", view.centreYMm}}},
  };
  // The film point's bundle as the cross-section shows it (surfaces from 1).
  const auto& traced = state.filmPointBundle;
  const bool tracedForCurrentLens =
      traced.lens &&
      (traced.lens == state.lensSystem || (traced.lens == state.lensWithoutRims.stopOnly &&
                                           state.lensWithoutRims.from == state.lensSystem));
  if (state.filmPointHeightMm && tracedForCurrentLens) {
    nlohmann::json blocked = nlohmann::json::array();
    for (const optics::BundleShare& share : traced.bundle.blocked)
      blocked.push_back({{"surface", share.surface + 1}, {"fraction", share.fraction}});
    about["film_point"] = {
        {"height_mm", traced.heightMm},
        {"passing", traced.bundle.passing},
        {"blocked", blocked},
        // false: traced as the render with its rims toggle off (stop only)
        {"rims", traced.lens->apertureClipping() == optics::ApertureClipping::EveryRim},
        {"rays", traced.bundle.rays.size()}};
  }
  // Each surface's medium (issue 40's glass cell and glass map): the catalogue glass and its
  // maker, or null for a model glass, with the n_d and V_d the lens traces.
  nlohmann::json media = nlohmann::json::array();
  for (const optics::Surface& surface : lens.surfaces) {
    media.push_back({{"glass", surface.glass ? nlohmann::json(surface.glass->name) : nullptr},
                     {"maker", surface.glass ? nlohmann::json(surface.glass->maker) : nullptr},
                     {"n_d", surface.indexD},
                     {"v_d", surface.abbeD ? nlohmann::json(*surface.abbeD) : nullptr}});
  }
  about["media"] = media;
  about["glass_message"] = state.lensTable.glassMessage;
  // The glass cell's completion list as shown ("N-SF6 SCHOTT"), top first.
  nlohmann::json completions = nlohmann::json::array();
  for (const optics::CatalogGlass* glass : state.lensTable.glassCompletions)
    completions.push_back(glass->name + " " + glass->maker);
  about["glass_completions"] = completions;
  about["selected_row"] = state.lensTable.selectedRow + 1;
  // The glass map's axes as drawn (widgets' glass-map/plot is the box they span), what it shows
  // and the glass under the mouse.
  about["glass_map"] = {{"open", state.glassMap.open},
                        {"v_d_left", kGlassMapVdLeft},
                        {"v_d_right", kGlassMapVdRight},
                        {"n_d_bottom", kGlassMapNdBottom},
                        {"n_d_top", kGlassMapNdTop},
                        {"points_shown", state.glassMap.pointsShown},
                        {"hidden_makers", state.glassMap.hiddenMakers},
                        {"hovered", state.glassMap.hovered},
                        {"message", state.glassMap.message}};
  // The vignetting teaching's switches (issue 21) and what the illumination plot notes.
  about["spectral"] = render::toString(state.falloff.spectral);
  about["vignetting"] = {{"cos4", state.falloff.cos4},
                         {"rims", state.falloff.rims},
                         {"overlay", state.vignettingOverlay},
                         {"render_note", state.illumination.renderNote},
                         {"uniform_field", state.sceneIsUniformField}};
  std::shared_ptr<const void> keepMeasured;
  if (const MeasuredFalloff* measured = latestMeasuredFalloff(state.measuredFalloff, keepMeasured);
      measured && state.sceneIsUniformField) {
    about["vignetting"]["measured"] = {{"spp", measured->samplesPerPixel},
                                       {"current_lens", measured->lens == state.lensSystem},
                                       {"image_height_mm", measured->imageHeightMm},
                                       {"relative", measured->relative}};
  }
  about["library"] = libraryDump(state.library);
  const nlohmann::json json = {{"window", {{"width", windowWidth}, {"height", windowHeight}}},
                               {"widgets", widgets},
                               {"state", about}};
  return writeFileAtomically(path, json.dump(2) + '\n');
}

}  // namespace lenslab::app
