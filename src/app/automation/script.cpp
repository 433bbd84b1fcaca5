#include "app/automation/script.h"

#include "app/analysis/analysis_plots.h"
#include "app/analysis/analysis_setup.h"
#include "app/automation/script_words.h"
#include "app/document/aperture_image.h"
#include "app/document/glass_choice.h"
#include "app/render_export.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "optics/aperture_shape.h"

namespace lenslab::app {

using script_words::parseInteger;
using script_words::parseNumber;
using script_words::parseSurfaceValue;

void ScriptRunner::fail(ScriptHost& host, const ScriptCommand& command,
                        const std::string& message) {
  failed_ = true;
  next_ = commands_.size();
  host.reportError(Diagnostic{Severity::Error, command.at(0), message}.format());
  host.quit(1);
}

bool ScriptRunner::step(ScriptHost& host) {
  changedThisStep_ = false;
  while (next_ < commands_.size()) {
    const ScriptCommand& command = commands_[next_];
    if (!execute(command, host)) {
      // Waiting: try again next frame, unless it has waited too long.
      const auto now = std::chrono::steady_clock::now();
      if (!waitStarted_) waitStarted_ = now;
      if (now - *waitStarted_ > kWaitLimit) {
        fail(host, command,
             command.verb + ": timed out after " + std::to_string(kWaitLimit.count()) + " s");
        return false;
      }
      return true;
    }
    if (failed_) return false;
    ++next_;
    framesWaited_ = 0;
    exportStarted_ = false;
    waitStarted_.reset();
  }
  return false;
}

bool ScriptRunner::stormEdits(const ScriptCommand& command, ScriptHost& host) {
  const long count = *parseInteger(command.arguments[0]);
  const auto now = std::chrono::steady_clock::now();
  if (!storm_) {
    storm_.emplace(static_cast<std::uint64_t>(*parseInteger(command.arguments[1])));
    stormIssued_ = 0;
    stormStarted_ = now;
  }
  // As many as are due by now at the storm's rate (a frame issues several): the edits land in
  // the frames as a fast user's would, not all at once.
  const double elapsedSeconds = std::chrono::duration<double>(now - stormStarted_).count();
  const long due = std::min(count, 1 + static_cast<long>(elapsedSeconds * kStormEditsPerSecond));
  for (; stormIssued_ < due; ++stormIssued_) awaitedCommand_ = host.issue(storm_->next());
  if (stormIssued_ < count) return false;
  // Done once the last is applied; refusals (a surface that does not exist) are part of it.
  if (awaitedCommand_ && !host.commandOutcome(*awaitedCommand_)) return false;
  awaitedCommand_.reset();
  storm_.reset();
  char summary[160];
  std::snprintf(summary, sizeof summary, "edit-storm: %ld edits in %.2f s (%.0f per second)", count,
                elapsedSeconds, elapsedSeconds > 0 ? count / elapsedSeconds : 0.0);
  host.reportInfo(summary);
  return true;
}

bool ScriptRunner::undoAll(const ScriptCommand& /*command*/, ScriptHost& host) {
  // A batch of undos a frame, until one is refused: then there is nothing left to undo.
  if (!undoBatch_.empty()) {
    if (!host.commandOutcome(undoBatch_.back())) return false;  // applied with the next frame
    bool refused = false;
    for (const CommandTicket ticket : undoBatch_) {
      const std::optional<std::string> outcome = host.commandOutcome(ticket);
      if (outcome && outcome->empty()) {
        ++undone_;
      } else {
        refused = true;
      }
    }
    undoBatch_.clear();
    if (refused) {
      host.reportInfo("undo-all: undid " + std::to_string(undone_) + " steps");
      undone_ = 0;
      return true;
    }
  }
  constexpr int kUndosPerFrame = 16;
  for (int i = 0; i < kUndosPerFrame; ++i) undoBatch_.push_back(host.issue(Undo{}));
  return false;
}

bool ScriptRunner::editAndWait(const ScriptCommand& command, ScriptHost& host,
                               const EditCommand& edit) {
  if (!awaitedCommand_) awaitedCommand_ = host.issue(edit);
  return waitForCommand(command, host);
}

bool ScriptRunner::waitForCommand(const ScriptCommand& command, ScriptHost& host) {
  const std::optional<std::string> outcome = host.commandOutcome(*awaitedCommand_);
  if (!outcome) return false;  // applied with the next frame
  awaitedCommand_.reset();
  if (!outcome->empty()) fail(host, command, command.verb + ": " + *outcome);
  return true;
}

bool ScriptRunner::waitForExport(const ScriptCommand& command, ScriptHost& host,
                                 bool cancelIsFine) {
  const ScriptHost::ExportOutcome outcome = host.exportRenderOutcome();
  if (outcome.running) return false;
  if (!outcome.error.empty()) {
    fail(host, command, command.verb + ": " + outcome.error);
  } else if (outcome.cancelled && !cancelIsFine) {
    fail(host, command, command.verb + ": the export was cancelled; nothing was written");
  }
  return true;
}

bool ScriptRunner::execute(const ScriptCommand& command, ScriptHost& host) {
  const auto& a = command.arguments;
  const auto check = [&](std::optional<std::string> error) {
    if (error) fail(host, command, command.verb + ": " + *error);
    return true;
  };
  const std::string& verb = command.verb;
  const bool isCapture = verb == "screenshot" || verb == "screenshot-render" ||
                         verb == "screenshot-cross-section" || verb == "dump-ui" ||
                         verb == "export-cross-section" || verb == "check-window";
  // Let a frame show the change first, and the figures computed off the UI thread catch up.
  if (isCapture && (changedThisStep_ || !host.analysesSettled())) return false;
  const bool isWait = verb.rfind("wait-", 0) == 0;
  if (!isCapture && !isWait) changedThisStep_ = true;
  if (verb == "load-lens") {
    if (!awaitedCommand_) {
      const ScriptHost::Issued issued = host.loadLens(a[0], a.size() == 2);
      if (issued.error) return check(issued.error);
      awaitedCommand_ = issued.ticket;
    }
    return waitForCommand(command, host);
  }
  if (verb == "load-scene") {
    if (framesWaited_++ == 0) host.startLoadingScene(a[0]);
    const auto outcome = host.sceneLoadOutcome();
    if (!outcome) return false;  // still loading
    return check(outcome->empty() ? std::nullopt : outcome);
  }
  if (verb == "save-lens") return check(host.saveLens(a[0]));
  if (verb == "make-stop") {
    return editAndWait(command, host, MakeStop{static_cast<std::size_t>(*parseInteger(a[0]) - 1)});
  }
  if (verb == "flip") return editAndWait(command, host, FlipLens{});
  if (verb == "undo") return editAndWait(command, host, Undo{});
  if (verb == "edit-storm") return stormEdits(command, host);
  if (verb == "undo-all") return undoAll(command, host);
  if (verb == "redo") return editAndWait(command, host, Redo{});
  if (verb == "set") {
    if (a[0] == "surface") {
      const std::size_t surface = static_cast<std::size_t>(*parseInteger(a[1]) - 1);
      if (a[2] == "glass") {
        // Looked up once, when first run (the command then waits for its edit).
        if (!awaitedCommand_) {
          const GlassChoice choice = chooseGlass(a[3], a.size() == 6 ? a[5] : std::string());
          if (!choice.glass) {
            fail(host, command, "surface " + a[1] + ": " + choice.error);
            return true;
          }
          if (!choice.note.empty()) host.reportInfo(choice.note + " (add 'maker M' to choose)");
          return editAndWait(command, host, SetSurfaceGlass{surface, choice.glass});
        }
        return waitForCommand(command, host);
      }
      if (const auto power = script_words::asphericTermPower(a[2])) {
        return editAndWait(command, host,
                           SetAsphericTerm{surface, static_cast<int>(*power),
                                           *script_words::parseProfileValue(a[3])});
      }
      const auto field = *surfaceFieldFromName(a[2]);
      return editAndWait(command, host,
                         SetSurfaceField{surface, field, *parseSurfaceValue(field, a[3])});
    }
    if (a[0] == "film-distance") {
      return editAndWait(command, host, SetFilmDistance{*parseNumber(a[1])});
    }
    if (a[0] == "stop-diameter") {
      return editAndWait(command, host, SetStopDiameter{*parseNumber(a[1])});
    }
    if (a[0] == "aperture") {
      std::string spec;
      for (std::size_t i = 1; i < a.size(); ++i) spec += (i > 1 ? " " : "") + a[i];
      optics::ApertureShape shape = *optics::parseApertureSpec(spec).shape;
      if (shape.kind == optics::ApertureShape::Kind::Image && !awaitedCommand_) {
        std::string error;
        const auto image = loadImageAperture(shape.imageName, &error);
        if (!image) {
          // As the lens panel does: logged, and the stop keeps its shape; the script goes on.
          host.reportError(error + "; the stop keeps its shape");
          return true;
        }
        shape = shape.mirrored ? image->mirroredLeftToRight() : *image;
      }
      return editAndWait(command, host, SetStopShape{shape});
    }
    if (a[0] == "exposure") {
      host.setExposure(*parseNumber(a[1]));
      return true;
    }
    if (a[0] == "blocked-rays") {
      host.showBlockedRays(a[1] == "show");
      return true;
    }
    if (a[0] == "film-point") {
      host.setFilmPoint(a[1] == "off" ? std::nullopt : parseNumber(a[1]));
      return true;
    }
    if (a[0] == "keep-film-distance") {
      host.setKeepFilmDistance(a[1] == "on");
      return true;
    }
    if (a[0] == "fields") {
      host.setFieldFractions(*parseFieldFractions(a[1], nullptr));
      return true;
    }
    if (a[0] == "auto-exposure") {
      host.setAutoExposure(a[1] == "on");
      return true;
    }
    if (a[0] == "colour-fans") {
      host.setColourFans(a[1] == "on");
      return true;
    }
    if (a[0] == "bottom-area") {
      host.setBottomAreaMaximised(a[1] == "maximised");
      return true;
    }
    if (a[0] == "mtf-range") {
      host.setMtfRange(a[1] == "cutoff" ? 0.0 : *parseNumber(a[1]));
      return true;
    }
    if (a[0] == "cos4" || a[0] == "rims" || a[0] == "vignetting-overlay") {
      host.setVignettingSwitch(a[0], a[1] == "on");
      return true;
    }
    if (a[0] == "spectral") {
      host.setSpectralMode(*render::parseSpectralMode(a[1]));
      return true;
    }
    if (a[0] == "layout") {
      host.setLayout(*parseNumber(a[1]), *parseNumber(a[2]), *parseNumber(a[3]));
      return true;
    }
    host.setPinholeCamera(a[1] == "pinhole");
    return true;
  }
  if (verb == "zoom-cross-section") {
    host.zoomCrossSection(*parseNumber(a[0]));
    return true;
  }
  if (verb == "centre-cross-section") {
    host.centreCrossSection(*parseNumber(a[0]), *parseNumber(a[1]));
    return true;
  }
  if (verb == "drop") return check(host.drop(a[0]));
  if (verb == "show-panel") return check(host.showPanel(a[0]));
  if (verb == "asphere-editor") {
    if (a[0] == "close") return check(host.showAsphereEditor(std::nullopt));
    return check(host.showAsphereEditor(static_cast<std::size_t>(*parseInteger(a[0]) - 1)));
  }
  if (verb == "pin-reference") return check(host.pinReference());
  if (verb == "unpin-reference") return check(host.unpinReference());
  if (verb == "glass-map") {
    if (a[0] == "maker") return check(host.showGlassMaker(a[1], a[2] == "on"));
    return check(host.showGlassMap(a[0] == "open"));
  }
  if (verb == "export-plot") {
    const ScriptHost::PlotExport attempt = host.exportPlot(a[0], a[1]);
    return attempt.ready ? check(attempt.error) : false;
  }
  if (verb == "open-dialog") return check(host.openDialog(a[0]));
  if (verb == "dialog-choose") return check(host.chooseInDialog(a[0]));
  if (verb == "paste-lens-table") return check(host.pasteLensTable(a[0]));
  if (verb == "paste-lens-table-column")
    return check(host.setPastedColumn(static_cast<int>(*parseInteger(a[0])), a[1]));
  if (verb == "paste-lens-table-open") {
    if (!awaitedCommand_) {
      const ScriptHost::Issued issued = host.pressPasteTableOpen();
      if (issued.error) return check(issued.error);
      awaitedCommand_ = issued.ticket;
    }
    return waitForCommand(command, host);
  }
  if (verb == "wait-frames") {
    // Counted from this command's first frame: "wait-frames 3" lets three frames be drawn.
    return framesWaited_++ >= *parseInteger(a[0]);
  }
  if (verb == "wait-seconds") {
    // step() notes when a command first waits; the idle viewer wakes at least 4 times a second.
    if (!waitStarted_) return false;
    return std::chrono::steady_clock::now() - *waitStarted_ >=
           std::chrono::duration<double>(*parseNumber(a[0]));
  }
  if (verb == "wait-spp") {
    const auto spp = host.previewSpp();
    if (!spp) {
      fail(host, command, "wait-spp: the preview cannot render (no valid lens or scene)");
      return true;
    }
    return *spp >= *parseInteger(a[0]);
  }
  if (verb == "wait-until-file") return std::filesystem::exists(a[0]);
  // A failed load does not fail the script: the viewer logs it, as for a file the user dropped.
  if (verb == "wait-scene-load") return host.sceneLoadOutcome().has_value();
  if (verb == "export-render" || verb == "start-export-render") {
    if (!exportStarted_) {
      int width = 0, height = 0;  // 0 x 0: the scene's film
      if (a[1] != "film") std::tie(width, height) = *parseExportSize(a[1], nullptr);
      if (const auto error =
              host.startExportRender(a[0], width, height, static_cast<int>(*parseInteger(a[2])))) {
        fail(host, command, verb + ": " + *error);
        return true;
      }
      exportStarted_ = true;
      if (verb == "start-export-render") return true;
    }
    return waitForExport(command, host, /*cancelIsFine=*/false);
  }
  if (verb == "wait-export") return waitForExport(command, host, /*cancelIsFine=*/true);
  if (verb == "cancel-export") return check(host.cancelExportRender());
  if (verb == "screenshot") return check(host.saveWindowScreenshot(a[0]));
  if (verb == "screenshot-render") return check(host.saveRender(a[0]));
  if (verb == "screenshot-cross-section") return check(host.saveCrossSection(a[0]));
  if (verb == "export-cross-section") {
    if (!awaitedExport_) {
      const std::vector<std::string> options(a.begin() + 1, a.end());
      const ScriptHost::ExportStarted started =
          host.startCrossSectionExport(a[0], *parseExportArguments(options));
      if (started.error) return check(started.error);
      awaitedExport_ = started.ticket;
    }
    const std::optional<std::string> outcome = host.exportOutcome(*awaitedExport_);
    if (!outcome) return false;  // still being written
    awaitedExport_.reset();
    return check(outcome->empty() ? std::nullopt : outcome);
  }
  if (verb == "dump-ui") return check(host.dumpUi(a[0]));
  if (verb == "check-window") return check(host.checkWindow());
  if (verb == "library") {
    if (a[0] == "wait") return host.libraryProgress().finished;
    if (a[0] == "select") {
      if (!awaitedCommand_) {
        if (!host.libraryProgress().listed) return false;  // the name may be in the rest
        std::string name;
        for (std::size_t i = 1; i < a.size(); ++i) name += (i > 1 ? " " : "") + a[i];
        const ScriptHost::Issued issued = host.openLibraryLens(name);
        if (issued.error) return check(issued.error);
        awaitedCommand_ = issued.ticket;
      }
      return waitForCommand(command, host);
    }
    return check(host.library(a));
  }
  if (verb == "reset-stats") {
    host.resetStats();
    return true;
  }
  if (verb == "quit") {
    host.quit(a.empty() ? 0 : static_cast<int>(*parseInteger(a[0])));
    next_ = commands_.size();
    return true;
  }
  fail(host, command, "unknown command '" + verb + "'");
  return true;
}

}  // namespace lenslab::app
