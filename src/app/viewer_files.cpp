#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "app/analysis/analysis_plots.h"
#include "app/automation/script_words.h"
#include "app/drawing/svg_export.h"
#include "app/platform/screenshot.h"
#include "app/platform/ui_scale.h"
#include "app/resources.h"
#include "app/viewer_session.h"
#include "optics/lens_file.h"
#include "optics/lens_file_formats.h"
#include "optics/lens_loader.h"
#include "render/camera_factory.h"
#include "render/image_io.h"
#include "render/uniform_field.h"

namespace lenslab::app {

namespace {

// Reads part of the back buffer: a window-coordinate rectangle scaled to framebuffer pixels.
FramebufferImage cropToRect(const FramebufferImage& image, const Rect& rect, float scale) {
  FramebufferImage crop;
  const int x0 = std::clamp(static_cast<int>(rect.x * scale), 0, image.width);
  const int y0 = std::clamp(static_cast<int>(rect.y * scale), 0, image.height);
  const int x1 = std::clamp(static_cast<int>(rect.right() * scale), x0, image.width);
  const int y1 = std::clamp(static_cast<int>(rect.bottom() * scale), y0, image.height);
  crop.width = x1 - x0;
  crop.height = y1 - y0;
  crop.rgba.reserve(static_cast<std::size_t>(crop.width) * crop.height * 4);
  for (int y = y0; y < y1; ++y) {
    const auto row = image.rgba.begin() + (static_cast<std::size_t>(y) * image.width + x0) * 4;
    crop.rgba.insert(crop.rgba.end(), row, row + static_cast<std::ptrdiff_t>(crop.width) * 4);
  }
  return crop;
}

}  // namespace

void Viewer::askForPath(const FileRequest& request) {
  using Kind = FileRequest::Kind;
  const std::filesystem::path lenses = findResourceDirectory("lenses");
  const std::filesystem::path scenes = findResourceDirectory("scenes");
  const std::filesystem::path here = std::filesystem::current_path();
  browserPurpose_ = request;
  switch (request.kind) {
    case Kind::Open:
    case Kind::OpenLens:
      // Every format lenslab reads (optics/lens_file_formats.h), as every other door.
      fileBrowser_.show("Open lens", FileBrowser::Mode::Open, optics::lensFileExtensions(), lenses);
      fileBrowser_.addOption(kKeepFilmDistanceLabel, &state_.settings.keepLensFilmDistance,
                             kKeepFilmDistanceTooltip);
      break;
    case Kind::OpenScene:
      fileBrowser_.show("Open scene", FileBrowser::Mode::Open, {".pbrt"}, scenes);
      break;
    case Kind::SaveLens: {
      // lenslab's own format holds everything (aspheric terms too); .dat only spheres and
      // model glasses (optics::whyNotDat says what does not fit). The name proposed is the
      // lens's own as .lens: an imported lens (.zmx, .seq, .txt) is never written over in its
      // foreign format (writeLensFile refuses it).
      const std::filesystem::path opened = state_.lens.path();
      const std::string stem = opened.empty() ? std::string("lens") : opened.stem().string();
      fileBrowser_.show("Save lens as", FileBrowser::Mode::Save, {".lens", ".dat"}, here,
                        render::nonClobberingPath(here, stem, ".lens").filename());
      break;
    }
    case Kind::SaveRender:
      fileBrowser_.show("Save render as (.png or .exr)", FileBrowser::Mode::Save, {".png", ".exr"},
                        here, render::nonClobberingPath(here, "lenslab-render", ".png").filename());
      break;
    case Kind::ExportRenderPath:
      fileBrowser_.show("Export render as (.png, .exr or .pfm)", FileBrowser::Mode::Save,
                        {".png", ".exr", ".pfm"}, here,
                        render::nonClobberingPath(here, "lenslab-export", ".png").filename());
      break;
    case Kind::SavePlot: {
      const AnalysisPlotSource* plot = findAnalysisPlot(request.plotId);
      if (!plot) break;
      fileBrowser_.show(
          "Save the " + std::string(plot->title) + " plot as (.svg, .png or .csv)",
          FileBrowser::Mode::Save, {".svg", ".png", ".csv"}, here,
          render::nonClobberingPath(here, "lenslab-" + std::string(plot->id), ".svg").filename());
      break;
    }
    case Kind::SaveCrossSection: {
      // The export dialog's format gives the suggested name; typing the other extension works.
      const char* extension = state_.crossSectionExport.svg ? ".svg" : ".png";
      fileBrowser_.show(
          "Export cross-section as (.png or .svg)", FileBrowser::Mode::Save, {".png", ".svg"}, here,
          render::nonClobberingPath(here, "lenslab-cross-section", extension).filename());
      break;
    }
  }
}

std::optional<std::string> Viewer::openDialog(const std::string& kind) {
  using Kind = FileRequest::Kind;
  if (kind == "export-render") {  // the Export render window, not a file browser
    state_.exportDialog.openRequested = true;
    return std::nullopt;
  }
  static const std::pair<const char*, Kind> kKinds[] = {
      {"open-lens", Kind::OpenLens},
      {"open-scene", Kind::OpenScene},
      {"save-lens", Kind::SaveLens},
      {"save-render", Kind::SaveRender},
      {"save-cross-section", Kind::SaveCrossSection}};
  if (kind == "export-cross-section") {  // the settings dialog, as File > Export cross-section...
    state_.showExportCrossSection = true;
    return std::nullopt;
  }
  for (const auto& [name, value] : kKinds) {
    if (kind == name) {
      askForPath({value, {}});
      return std::nullopt;
    }
  }
  // save-ID-plot: an analysis panel's plot.
  if (const auto id = plotIdOfSaveDialog(kind)) {
    if (!findAnalysisPlot(*id)) return "there is no plot '" + *id + "' (" + analysisPlotIds() + ")";
    askForPath({Kind::SavePlot, {}, *id});
    return std::nullopt;
  }
  return "unknown dialog '" + kind + "'";
}

std::optional<std::string> Viewer::chooseInDialog(const std::string& name) {
  if (!fileBrowser_.visible()) return "there is no file browser open to choose " + name;
  fileBrowser_.submit(name);
  return std::nullopt;
}

// Requests from the menus, the browser, drops and the recent-files list: what the user opened
// goes to the recent files (the defaults loaded at start do not), a scene once it has loaded.
std::optional<std::string> Viewer::perform(const FileRequest& request) {
  using Kind = FileRequest::Kind;
  const std::string& path = request.path;
  const auto remember = [&](std::optional<std::string> error) {
    if (!error) rememberRecentFile(path);
    return error;
  };
  switch (request.kind) {
    case Kind::Open:
      if (std::filesystem::path(path).extension() == ".pbrt") {
        startLoadingScene(path, SceneOrigin::User);
        return std::nullopt;
      }
      return remember(openLensFile(path).error);
    case Kind::OpenLens:
      return remember(openLensFile(path).error);
    case Kind::OpenScene:
      // Loads off the UI thread; it becomes a recent file once open (finishSceneLoad).
      startLoadingScene(path, SceneOrigin::User);
      return std::nullopt;
    case Kind::SaveLens:
      return remember(saveLens(path));
    case Kind::SaveRender:
      return saveRender(path);
    case Kind::ExportRenderPath:
      state_.exportDialog.path = path;
      return std::nullopt;
    case Kind::SavePlot: {
      // Computed off the UI thread: written when the plot for the current lens is ready (the
      // panel that asked is showing it, so it normally is).
      const PlotExport attempt = exportPlot(request.plotId, path);
      if (!attempt.ready)
        return "the " + request.plotId + " plot is still being computed; try again";
      return attempt.error;
    }
    case Kind::SaveCrossSection:
      // Drawn off screen at the export dialog's settings: the browser is in no frame of it.
      return exportCrossSectionAs(path, state_.crossSectionExport);
  }
  return std::nullopt;
}

std::string Viewer::saveWindowScreenshotToDefault() {
  const std::filesystem::path path =
      render::nonClobberingPath(std::filesystem::current_path(), "lenslab-window", ".png");
  if (const auto error = saveWindowScreenshot(path.string())) return *error;
  return {};
}

ScriptHost::Issued Viewer::openLensFile(const std::string& path, bool startsSession,
                                        bool keepFilmDistance) {
  return openLoadedLens(optics::loadLens(path), path, path, startsSession, keepFilmDistance);
}

ScriptHost::Issued Viewer::openPastedTable() {
  PasteTableState& paste = state_.pasteTable;
  const optics::PatentTableResult& read = pastedTableRead(paste);
  optics::LoadedLens loaded;
  loaded.diagnostics = read.lens.diagnostics;
  if (read.lens.ok()) {
    loaded.file = *read.lens.lens;
    optics::BuildResult built = optics::LensSystem::build(loaded.file.prescription);
    for (const optics::ValidationError& error : built.errors)
      loaded.diagnostics.error({paste.sourceName, loaded.file.lineOfSurface(error.surface), 1},
                               error.toString());
    loaded.system = std::move(built.system);
  }
  ScriptHost::Issued issued = openLoadedLens(std::move(loaded), "", paste.sourceName, false, false);
  if (!issued.error) paste.open = false;
  return issued;
}

std::optional<std::string> Viewer::pasteLensTable(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot read " + path;
  std::stringstream text;
  text << in.rdbuf();
  showPasteTable(state_.pasteTable, text.str(), path);
  return std::nullopt;
}

std::optional<std::string> Viewer::setPastedColumn(int column, const std::string& meaning) {
  PasteTableState& paste = state_.pasteTable;
  if (!paste.open) return "the Paste lens table window is not open";
  const std::size_t columns = pastedTableRead(paste).table.columns.size();
  if (column < 1 || static_cast<std::size_t>(column) > columns)
    return "the table has " + std::to_string(columns) + " columns, not " + std::to_string(column);
  const auto m = script_words::patentColumnFromWord(meaning);
  if (!m) return "unknown column meaning '" + meaning + "'";
  if (paste.overrides.size() < columns) paste.overrides.resize(columns);
  paste.overrides[static_cast<std::size_t>(column - 1)] = *m;
  paste.read.reset();
  return std::nullopt;
}

ScriptHost::Issued Viewer::openLoadedLens(optics::LoadedLens loaded, const std::string& path,
                                          const std::string& name, bool startsSession,
                                          bool keepFilmDistance) {
  if (!loaded.ok()) {
    // The current lens stays; every problem goes to the log with its file:line:column.
    std::string message = "cannot open lens " + name + ":";
    for (const Diagnostic& diagnostic : loaded.diagnostics.all()) {
      message += "\n  " + diagnostic.format();
    }
    return {message};
  }
  // Focused as a camera would be, in the one command that opens it: one undo step.
  // With all the file says of the lens (title, notes, source, design conditions), to save back.
  LensDetails details = detailsOf(loaded.file);
  ReplaceLens opening{std::move(loaded.file.prescription), path, std::move(details), startsSession};
  const OpeningFocus focus = focusForOpening(
      *loaded.system, state_.sceneFocus, keepFilmDistance || state_.settings.keepLensFilmDistance);
  if (focus.filmDistanceMm) {
    opening.prescription.surfaces.back().thicknessMm = *focus.filmDistanceMm;
  }
  if (startsSession && keepLensOnSceneLoad && !keepFilmDistance) {
    sessionLensToFocus_ = SessionLens{opening, loaded.system};
  }
  const double openedFilmDistanceMm = opening.prescription.surfaces.back().thicknessMm;
  const CommandTicket ticket = state_.lens.issue(std::move(opening));
  if (!startsSession && !sceneLoadOutcome_) {
    lensOpenedWhileSceneLoads_ = {ticket, loaded.system, openedFilmDistanceMm,
                                  keepFilmDistance || state_.settings.keepLensFilmDistance};
  }
  state_.log.info("Opened lens " + name);
  // What the lens file could not honour (an aperture image: the stop stays a circle).
  for (const Diagnostic& diagnostic : loaded.diagnostics.all()) {
    if (diagnostic.severity == Severity::Note)
      state_.log.info(diagnostic.format());
    else
      state_.log.warning(diagnostic.format());
  }
  if (!focus.message.empty()) state_.log.info(focus.message);
  return {std::nullopt, ticket};
}

void Viewer::focusSessionLens() {
  std::optional<SessionLens> session = std::exchange(sessionLensToFocus_, std::nullopt);
  // Edited meanwhile: the user's edits stay. Another lens opened meanwhile (perhaps still
  // queued, so not yet undoable): that later choice stays. Kept at the file's film distance:
  // the opening already said so.
  if (!session || state_.lens.canUndo() || lensOpenedWhileSceneLoads_ ||
      state_.settings.keepLensFilmDistance)
    return;
  const OpeningFocus focus =
      focusForOpening(*session->system, state_.sceneFocus, state_.settings.keepLensFilmDistance);
  if (focus.message.empty()) return;
  state_.log.info(focus.message);
  if (!focus.filmDistanceMm) return;
  session->opening.prescription.surfaces.back().thicknessMm = *focus.filmDistanceMm;
  state_.lens.issue(std::move(session->opening));
}

void Viewer::startLoadingScene(const std::string& path, SceneOrigin origin) {
  sceneLoader_.start(path);
  sceneOrigin_ = origin;
  state_.loadingScenePath = path;
  sceneLoadOutcome_.reset();
  lensOpenedWhileSceneLoads_.reset();
}

void Viewer::focusLensOpenedWhileSceneLoaded(const LensOpenedWhileSceneLoads& opened) {
  if (opened.keepFilmDistance) return;  // at the file's film distance, as the opening said
  if (state_.lens.lastIssued() != opened.opening) {
    state_.log.info(
        "The lens was edited while the scene loaded: it is not focused again at the scene's "
        "focus distance");
    return;
  }
  // As if it had been opened over the loaded scene: focused at its focus distance, or at the
  // file's film distance where the scene gives none or the lens cannot focus there (the message
  // says which).
  const OpeningFocus focus = focusForOpening(*opened.system, state_.sceneFocus, false);
  if (!focus.message.empty()) state_.log.info(focus.message);
  const double filmMm = focus.filmDistanceMm.value_or(opened.system->filmDistanceMm());
  if (filmMm != opened.filmDistanceMm) state_.lens.issue(SetFilmDistance{filmMm});
}

void Viewer::finishSceneLoad() {
  std::optional<SceneLoader::Result> result = sceneLoader_.take();
  if (!result) return;
  state_.loadingScenePath.clear();
  const std::optional<std::string> error = openLoadedScene(result->path, result->loaded);
  sceneLoadOutcome_ = error.value_or("");
  if (error) {
    state_.log.error(*error);
    if (sceneOrigin_ == SceneOrigin::CommandLine) {
      std::fprintf(stderr, "lenslab: %s\n", error->c_str());
      quit(1);
    }
    return;
  }
  // What the user chose to open, from the command line or the menus, is a recent file.
  if (sceneOrigin_ == SceneOrigin::User || sceneOrigin_ == SceneOrigin::CommandLine) {
    rememberRecentFile(result->path);
  }
}

void Viewer::rememberRecentFile(const std::string& path) {
  std::error_code ignored;
  addRecentFile(state_.settings, std::filesystem::absolute(path, ignored).string());
}

std::optional<std::string> Viewer::openLoadedScene(const std::string& path,
                                                   const LoadedScene& loaded) {
  if (!loaded.error.empty()) return "cannot open scene " + path + ":\n" + loaded.error;
  for (const std::string& warning : loaded.warnings) state_.log.warning(warning);
  preview_.setScene(loaded);
  state_.scenePath = path;
  if (const auto focusMm = render::focusDistanceMmOf(*loaded.description)) {
    state_.sceneFocus = {focusMm, ""};
  } else {
    state_.sceneFocus = {std::nullopt, "the scene sets a film distance, not a focus distance"};
  }
  focusSessionLens();
  const render::CameraFraming framing = render::framingOf(*loaded.description);
  state_.filmDiagonalMm = framing.filmDiagonalMm;
  state_.sceneSamplesRearDisk = framing.lensSampling == render::LensSampling::RearElementDisk;
  state_.sceneIsUniformField = render::isUniformField(*loaded.description, *loaded.scene);
  state_.crossSectionNeedsFit = true;
  state_.log.info("Opened scene " + path);
  // A scene that sets its exposure (Film "scale") is shown at it, without auto exposure.
  if (const auto scale = loaded.description->film.scale) {
    state_.exposureStops = std::log2(*scale);
    state_.settings.autoExposure = false;
    char message[160];
    std::snprintf(message, sizeof message,
                  "The scene sets its exposure (Film \"scale\" %g: %+.2f EV): auto exposure off",
                  *scale, state_.exposureStops);
    state_.log.info(message);
  }
  // A scene with a realistic camera brings its lens, stop and focus, unless the user chose a
  // lens on the command line or opened one while the scene loaded. The lens is built the way
  // `lenslab render` builds it (lensOfScene).
  const std::optional<LensOpenedWhileSceneLoads> openedWhileLoading =
      std::exchange(lensOpenedWhileSceneLoads_, std::nullopt);
  if (openedWhileLoading) {
    if (loaded.description->camera.type == "realistic" && !keepLensOnSceneLoad)
      state_.log.info("Kept the lens opened while the scene loaded, not the scene's");
    focusLensOpenedWhileSceneLoaded(*openedWhileLoading);
  } else if (loaded.description->camera.type == "realistic" && !keepLensOnSceneLoad) {
    Diagnostics diagnostics;
    if (const auto sceneLens = render::lensOfScene(*loaded.description, diagnostics)) {
      const std::string lensPath = sceneLens->path.string();
      // The scene opened with brings the lens the session starts from, not an edit to undo
      // (unless the user has edited the lens while the scene loaded).
      const bool atStart =
          sceneOrigin_ == SceneOrigin::Default || sceneOrigin_ == SceneOrigin::CommandLine;
      state_.lens.issue(ReplaceLens{sceneLens->prescription, lensPath, {}, atStart});
      state_.log.info("Using the scene's lens " + lensPath + " (its stop and focus)");
    } else {
      for (const Diagnostic& diagnostic : diagnostics.all()) {
        state_.log.warning(diagnostic.format());
      }
    }
  }
  return std::nullopt;
}

std::optional<std::string> Viewer::saveLens(const std::string& path) {
  std::string error;
  if (!optics::writeLensFile(
          path, lensFileOf(state_.lens.prescription(), state_.lens.document().details()), &error)) {
    return error;
  }
  state_.lens.markSaved(path);
  state_.log.info("Saved lens to " + path);
  return std::nullopt;
}

std::optional<std::string> Viewer::saveWindowScreenshot(const std::string& path) {
  ensureDrawn();
  const render::WriteResult result =
      saveFramebufferPng(path, window_.framebufferWidth(), window_.framebufferHeight());
  if (!result.ok) return result.error;
  state_.log.info("Saved window screenshot to " + path);
  return std::nullopt;
}

std::optional<std::string> Viewer::saveRender(const std::string& path) {
  const auto snapshot = preview_.latest();
  if (!snapshot || snapshot->samplesPerPixel == 0) {
    return "cannot save " + path + ": there is no render yet";
  }
  const render::FloatImage image{snapshot->width, snapshot->height, snapshot->rgb};
  // At the exposure the preview shows (the user's, plus auto exposure's when on).
  const render::WriteResult result = render::writeImage(path, image, shownExposureStops(state_));
  if (!result.ok) return result.error;
  state_.log.info("Saved render (" + std::to_string(snapshot->samplesPerPixel) + " spp) to " +
                  path);
  return std::nullopt;
}

std::optional<std::string> Viewer::exportCrossSectionAs(const std::string& path,
                                                        const CrossSectionExportSettings& settings,
                                                        std::uint64_t* ticket) {
  auto prepared = prepareCrossSectionExport(state_, path, settings);
  if (auto* error = std::get_if<std::string>(&prepared)) return *error;
  const std::uint64_t number = nextExportTicket_++;
  if (ticket != nullptr) *ticket = number;
  exports_.push_back(
      {number, path,
       std::async(std::launch::async, [job = std::get<CrossSectionExportJob>(std::move(prepared))] {
         CrossSectionExportResult result = runCrossSectionExport(job);
         Window::wakeFromAnyThread();  // the next frame logs it
         return result;
       })});
  return std::nullopt;
}

void Viewer::finishExports() {
  for (auto running = exports_.begin(); running != exports_.end();) {
    if (running->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++running;
      continue;
    }
    const CrossSectionExportResult result = running->result.get();
    if (result.error.empty()) {
      state_.log.info("Exported cross-section to " + running->path + " (" + result.summary + ")");
    } else {
      state_.log.error(result.error);
    }
    exportOutcomes_[running->ticket] = result.error;
    running = exports_.erase(running);
  }
}

ScriptHost::ExportStarted Viewer::startCrossSectionExport(
    const std::string& path, const CrossSectionExportRequest& request) {
  CrossSectionExportSettings settings;  // the defaults, not the dialog's: scripts reproduce
  if (request.widthPx) settings.slide.widthPx = *request.widthPx;
  if (request.heightPx) settings.slide.heightPx = *request.heightPx;
  if (request.dotsPerInch) settings.dotsPerInch = *request.dotsPerInch;
  if (request.dark) settings.slide.theme = *request.dark ? SlideTheme::Dark : SlideTheme::Light;
  ExportStarted started;
  started.error = exportCrossSectionAs(path, settings, &started.ticket);
  return started;
}

std::optional<std::string> Viewer::exportOutcome(std::uint64_t ticket) const {
  const auto outcome = exportOutcomes_.find(ticket);
  if (outcome == exportOutcomes_.end()) return std::nullopt;
  return outcome->second;
}

std::optional<std::string> Viewer::saveCrossSection(const std::string& path) {
  const auto canvas = state_.uiRects.find("cross-section/canvas");
  if (canvas == state_.uiRects.end()) return std::string("the cross-section is not visible");
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".svg") {
    // What the panel shows: its drawing (lens, stop, axis, film and the ray fans), framed as the
    // panel frames it.
    const CrossSectionDrawing& drawing = crossSection(state_).drawing;
    const auto [canvasWidth, canvasHeight] = state_.crossSectionCanvasSize;
    SvgFrame frame = wholeDrawingFrame(drawing);
    if (canvasWidth > 1 && canvasHeight > 1) {
      frame.visibleMm = state_.crossSectionView.visibleBounds(canvasWidth, canvasHeight);
      // Line widths are in pixels at UI scale 1, like the panel's before px().
      frame.mmPerPixel = uiScale() / state_.crossSectionView.pixelsPerMm;
    }
    if (const std::string error = writeCrossSectionSvg(path, drawing, frame); !error.empty()) {
      return error;
    }
  } else {
    ensureDrawn();
    const float scale = static_cast<float>(window_.framebufferWidth()) /
                        static_cast<float>(std::max(1, window_.width()));
    const FramebufferImage crop =
        cropToRect(readFramebuffer(window_.framebufferWidth(), window_.framebufferHeight()),
                   canvas->second, scale);
    const render::WriteResult result =
        render::writePngRgba8(path, crop.width, crop.height, crop.rgba);
    if (!result.ok) return result.error;
  }
  state_.log.info("Saved cross-section to " + path);
  return std::nullopt;
}

}  // namespace lenslab::app
