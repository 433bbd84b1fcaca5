#include "app/automation/script.h"

#include "app/analysis/analysis_plots.h"
#include "app/analysis/analysis_setup.h"
#include "app/document/aperture_image.h"

#include "app/render_export.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "optics/aperture_shape.h"

namespace lenslab::app {

namespace {

struct VerbShape {
  std::size_t minArguments, maxArguments;
};

// Argument counts per verb; "set" is checked further by its own rules below.
const std::map<std::string, VerbShape>& verbs() {
  static const std::map<std::string, VerbShape> table = {
      {"load-lens", {1, 2}},
      {"load-scene", {1, 1}},
      {"save-lens", {1, 1}},
      {"set", {2, 8}},  // set aperture blades N curvature C rotation D: 7
      {"make-stop", {1, 1}},
      {"flip", {0, 0}},
      {"undo", {0, 0}},
      {"redo", {0, 0}},
      {"wait-frames", {1, 1}},
      {"wait-seconds", {1, 1}},
      {"wait-spp", {1, 1}},
      {"wait-until-file", {1, 1}},
      {"wait-scene-load", {0, 0}},
      {"screenshot", {1, 1}},
      {"screenshot-render", {1, 1}},
      {"screenshot-cross-section", {1, 1}},
      {"dump-ui", {1, 1}},
      {"check-window", {0, 0}},
      {"quit", {0, 1}},
      {"zoom-cross-section", {1, 1}},
      {"centre-cross-section", {2, 2}},
      {"drop", {1, 1}},
      {"open-dialog", {1, 1}},
      {"dialog-choose", {1, 1}},
      {"show-panel", {1, 1}},
      {"export-plot", {2, 2}},
      {"export-cross-section", {1, 4}},
      // Pictures for slides (issue 20).
      {"export-render", {3, 3}},
      {"start-export-render", {3, 3}},
      {"wait-export", {0, 0}},
      {"cancel-export", {0, 0}},
      {"reset-stats", {0, 0}},
      // Hardening (issue 24): COUNT random lens edits at kStormEditsPerSecond, SEED; and undoing
      // every step there is.
      {"edit-storm", {2, 2}},
      {"undo-all", {0, 0}},  // issue 21: measure a drag alone (bench/viewer-drag.sh)
  };
  return table;
}

std::optional<double> parseNumber(const std::string& text) {
  if (text == "none") return std::nan("");
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

// A surface field's value: a number, or for a radius also inf (a flat surface, as the table and
// the lens file write it). No other setting has a meaning for infinity.
std::optional<double> parseSurfaceValue(SurfaceField field, const std::string& text) {
  if (field == SurfaceField::RadiusMm && (text == "inf" || text == "-inf")) {
    return std::numeric_limits<double>::infinity();
  }
  return parseNumber(text);
}

std::optional<long> parseInteger(const std::string& text) {
  long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty()) return std::nullopt;
  return value;
}

}  // namespace

std::optional<CrossSectionExportRequest> parseExportArguments(
    const std::vector<std::string>& arguments, std::size_t* badArgument) {
  CrossSectionExportRequest request;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    const std::size_t times = argument.find('x');
    bool good = true;
    if (argument == "light" || argument == "dark") {
      good = !request.dark;
      request.dark = argument == "dark";
    } else if (times != std::string::npos) {
      const auto width = parseInteger(argument.substr(0, times));
      const auto height = parseInteger(argument.substr(times + 1));
      good = !request.widthPx && width && height && *width > 0 && *height > 0 && *width <= 100000 &&
             *height <= 100000;
      if (good) {
        request.widthPx = static_cast<int>(*width);
        request.heightPx = static_cast<int>(*height);
      }
    } else {
      const auto dpi = parseNumber(argument);
      good = !request.dotsPerInch && dpi && *dpi > 0;
      if (good) request.dotsPerInch = *dpi;
    }
    if (!good) {
      if (badArgument != nullptr) *badArgument = i;
      return std::nullopt;
    }
  }
  return request;
}

namespace {

// Where problemAt reports a problem with the command as a whole: column 1 of its line.
constexpr std::size_t kLineStart = std::numeric_limits<std::size_t>::max();

Diagnostic problemAt(const ScriptCommand& command, std::size_t argument, std::string message) {
  return {Severity::Error, command.at(argument), std::move(message)};
}

// Checks a "set" command's shape; returns an error naming the offending argument.
std::optional<Diagnostic> checkSet(const ScriptCommand& command) {
  const auto& a = command.arguments;
  const auto numberAt = [&](std::size_t i) -> std::optional<Diagnostic> {
    if (i >= a.size()) return problemAt(command, a.size() - 1, "expected a value after it");
    if (!parseNumber(a[i])) return problemAt(command, i, "'" + a[i] + "' is not a number");
    return std::nullopt;
  };
  if (a[0] == "surface") {
    if (a.size() != 4) {
      return problemAt(command, 0, "expected: set surface N FIELD VALUE");
    }
    const auto index = parseInteger(a[1]);
    if (!index || *index < 1)
      return problemAt(command, 1, "'" + a[1] + "' is not a surface number (1, 2, ...)");
    const auto field = surfaceFieldFromName(a[2]);
    if (!field) {
      return problemAt(
          command, 2,
          "unknown field '" + a[2] + "' (expected radius, thickness, n, abbe or aperture)");
    }
    if (!parseSurfaceValue(*field, a[3])) {
      const char* expected = *field == SurfaceField::RadiusMm ? " (or inf for a flat surface)" : "";
      return problemAt(command, 3, "'" + a[3] + "' is not a number" + expected);
    }
    return std::nullopt;
  }
  if (a[0] == "film-distance" || a[0] == "stop-diameter" || a[0] == "exposure") {
    if (a.size() != 2) return problemAt(command, 0, "expected: set " + a[0] + " VALUE");
    return numberAt(1);
  }
  if (a[0] == "aperture") {
    // The stop's shape in the lens file's words (optics/aperture_shape.h); an image's file is
    // read when the command runs (a bad one is logged and the stop keeps its shape).
    std::string spec;
    std::vector<std::size_t> starts;
    for (std::size_t i = 1; i < a.size(); ++i) {
      if (i > 1) spec += ' ';
      starts.push_back(spec.size());
      spec += a[i];
    }
    const optics::ApertureSpecResult parsed = optics::parseApertureSpec(spec);
    if (parsed.shape) return std::nullopt;
    std::size_t argument = 1;
    for (std::size_t i = 0; i < starts.size(); ++i)
      if (static_cast<int>(starts[i]) <= parsed.column) argument = i + 1;
    return problemAt(command, argument,
                     parsed.error +
                         "; expected: set aperture circle | blades N [curvature C] [rotation D] "
                         "| image FILE");
  }
  if (a[0] == "camera") {
    if (a.size() != 2 || (a[1] != "lens" && a[1] != "pinhole")) {
      return problemAt(command, 0, "expected: set camera lens|pinhole");
    }
    return std::nullopt;
  }
  if (a[0] == "blocked-rays") {
    if (a.size() != 2 || (a[1] != "show" && a[1] != "hide")) {
      return problemAt(command, 0, "expected: set blocked-rays show|hide");
    }
    return std::nullopt;
  }
  if (a[0] == "film-point") {
    if (a.size() != 2 || (a[1] != "off" && !(parseNumber(a[1]) && *parseNumber(a[1]) >= 0))) {
      return problemAt(command, 0, "expected: set film-point MM|off (MM from the axis, >= 0)");
    }
    return std::nullopt;
  }
  if (a[0] == "keep-film-distance") {
    if (a.size() != 2 || (a[1] != "on" && a[1] != "off")) {
      return problemAt(command, 0, "expected: set keep-film-distance on|off");
    }
    return std::nullopt;
  }
  if (a[0] == "fields") {
    if (a.size() != 2) return problemAt(command, 0, "expected: set fields F,F,... (e.g. 0,0.7,1)");
    std::string why;
    if (!parseFieldFractions(a[1], &why)) return problemAt(command, 1, why);
    return std::nullopt;
  }
  if (a[0] == "auto-exposure" || a[0] == "colour-fans") {
    if (a.size() != 2 || (a[1] != "on" && a[1] != "off")) {
      return problemAt(command, 0, "expected: set " + a[0] + " on|off");
    }
    return std::nullopt;
  }
  // The vignetting teaching's switches (issue 21): the render's cos^4 weighting and rims
  // (render/falloff_toggles.h), and the heat map over the preview.
  if (a[0] == "cos4" || a[0] == "rims" || a[0] == "vignetting-overlay") {
    if (a.size() != 2 || (a[1] != "on" && a[1] != "off")) {
      return problemAt(command, 0, "expected: set " + a[0] + " on|off");
    }
    return std::nullopt;
  }
  if (a[0] == "spectral") {
    if (a.size() != 2 || !render::parseSpectralMode(a[1])) {
      return problemAt(command, 0, "expected: set spectral on|off|auto");
    }
    return std::nullopt;
  }
  if (a[0] == "layout") {
    if (a.size() != 4) return problemAt(command, 0, "expected: set layout LENS PREVIEW LOG");
    for (std::size_t i = 1; i < 4; ++i) {
      const auto value = parseNumber(a[i]);
      if (!value || !(*value > 0 && *value < 1)) {
        return problemAt(command, i, "'" + a[i] + "' is not a fraction between 0 and 1");
      }
    }
    return std::nullopt;
  }
  return problemAt(
      command, 0,
      "unknown setting '" + a[0] +
          "' (expected surface, film-distance, stop-diameter, aperture, exposure, camera, "
          "blocked-rays, "
          "layout, keep-film-distance, auto-exposure, film-point, cos4, rims, "
          "vignetting-overlay, colour-fans, spectral or fields)");
}

std::optional<Diagnostic> checkShape(const ScriptCommand& command) {
  const auto shape = verbs().find(command.verb);
  if (shape == verbs().end()) {
    return problemAt(command, kLineStart, "unknown command '" + command.verb + "'");
  }
  const std::size_t count = command.arguments.size();
  if (count < shape->second.minArguments || count > shape->second.maxArguments) {
    std::ostringstream message;
    message << "'" << command.verb << "' takes ";
    if (shape->second.minArguments == shape->second.maxArguments) {
      message << shape->second.minArguments;
    } else {
      message << shape->second.minArguments << " to " << shape->second.maxArguments;
    }
    message << " argument(s), got " << count;
    return problemAt(command, kLineStart, message.str());
  }
  if (command.verb == "set") return checkSet(command);
  if (command.verb == "load-lens" && count == 2 && command.arguments[1] != "keep-film-distance") {
    return problemAt(command, 1,
                     "unknown option '" + command.arguments[1] + "' (expected keep-film-distance)");
  }
  if (command.verb == "export-render" || command.verb == "start-export-render") {
    std::string error;
    if (command.arguments[1] != "film" && !parseExportSize(command.arguments[1], &error)) {
      return problemAt(command, 1, error + " or film");
    }
    const auto spp = parseInteger(command.arguments[2]);
    if (!spp || *spp < 1 || *spp > (1 << 20)) {
      return problemAt(command, 2,
                       "'" + command.arguments[2] + "' is not a sample count from 1 to 1048576");
    }
  }
  if (command.verb == "zoom-cross-section") {
    const auto factor = parseNumber(command.arguments[0]);
    if (!factor || !(*factor > 0)) {
      return problemAt(command, 0, "'" + command.arguments[0] + "' is not a positive number");
    }
  }
  if (command.verb == "centre-cross-section") {
    for (std::size_t i = 0; i < 2; ++i) {
      if (!parseNumber(command.arguments[i])) {
        return problemAt(command, i, "'" + command.arguments[i] + "' is not a number (mm)");
      }
    }
  }
  if (command.verb == "export-cross-section") {
    const std::vector<std::string> options(command.arguments.begin() + 1, command.arguments.end());
    std::size_t bad = 0;
    if (!parseExportArguments(options, &bad)) {
      return problemAt(command, bad + 1,
                       "'" + options[bad] +
                           "' is not a size (1600x900), a DPI (300) or a theme (light or dark), "
                           "or repeats one");
    }
    const std::string extension = std::filesystem::path(command.arguments[0]).extension();
    if (extension != ".png" && extension != ".svg") {
      return problemAt(command, 0, "'" + command.arguments[0] + "' does not end in .png or .svg");
    }
  }
  if (command.verb == "open-dialog") {
    static const char* const kKinds[] = {
        "open-lens",     "open-scene",         "save-lens",           "save-render",
        "export-render", "save-cross-section", "export-cross-section"};
    const auto plotId = plotIdOfSaveDialog(command.arguments[0]);
    const bool knownPlot = plotId && findAnalysisPlot(*plotId);
    if (!knownPlot &&
        std::find(std::begin(kKinds), std::end(kKinds), command.arguments[0]) == std::end(kKinds)) {
      return problemAt(
          command, 0,
          "unknown dialog '" + command.arguments[0] +
              "' (expected open-lens, open-scene, save-lens, save-render, "
              "export-render, save-cross-section, export-cross-section or save-ID-plot "
              "for a plot: " +
              analysisPlotIds() + ")");
    }
  }
  if (command.verb == "wait-seconds") {
    const auto seconds = parseNumber(command.arguments[0]);
    // Longer waits would meet kWaitLimit; a script repeats the command for more.
    if (!seconds || *seconds <= 0 || *seconds > 60) {
      return problemAt(command, 0,
                       "'" + command.arguments[0] + "' is not a number of seconds in (0, 60]");
    }
  }
  const bool countArgument = command.verb == "wait-frames" || command.verb == "wait-spp" ||
                             command.verb == "make-stop" || command.verb == "quit" ||
                             command.verb == "edit-storm";
  if (countArgument && count == 1) {
    const auto value = parseInteger(command.arguments[0]);
    if (!value || *value < 0) {
      return problemAt(command, 0, "'" + command.arguments[0] + "' is not a non-negative integer");
    }
  }
  return std::nullopt;
}

}  // namespace

SourceLocation ScriptCommand::at(std::size_t argument) const {
  const int column = argument < argumentColumns.size() ? argumentColumns[argument] : 1;
  return {file, line, column};
}

ParsedScript parseScript(const std::string& text, const std::string& fileName) {
  ParsedScript script;
  std::istringstream lines(text);
  std::string line;
  for (int lineNumber = 1; std::getline(lines, line); ++lineNumber) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    ScriptCommand command;
    command.file = fileName;
    command.line = lineNumber;
    std::size_t position = 0;
    while (true) {
      position = line.find_first_not_of(" \t", position);
      if (position == std::string::npos) break;
      const std::size_t end = line.find_first_of(" \t", position);
      std::string word = line.substr(position, end - position);
      if (command.verb.empty()) {
        command.verb = std::move(word);
      } else {
        command.arguments.push_back(std::move(word));
        command.argumentColumns.push_back(static_cast<int>(position) + 1);
      }
      if (end == std::string::npos) break;
      position = end;
    }
    if (command.verb.empty()) continue;
    if (std::optional<Diagnostic> problem = checkShape(command)) {
      script.diagnostics.add(std::move(*problem));
    } else {
      script.commands.push_back(std::move(command));
    }
  }
  return script;
}

ParsedScript readScriptFile(const std::filesystem::path& path) {
  std::ifstream input(path, std::ios::binary);
  if (!input) {
    ParsedScript script;
    script.diagnostics.error({path.string(), 1, 1}, "cannot open the script");
    return script;
  }
  std::ostringstream text;
  text << input.rdbuf();
  return parseScript(text.str(), path.string());
}

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
      const auto field = *surfaceFieldFromName(a[2]);
      const std::size_t surface = static_cast<std::size_t>(*parseInteger(a[1]) - 1);
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
        shape = *image;
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
  if (verb == "export-plot") {
    const ScriptHost::PlotExport attempt = host.exportPlot(a[0], a[1]);
    return attempt.ready ? check(attempt.error) : false;
  }
  if (verb == "open-dialog") return check(host.openDialog(a[0]));
  if (verb == "dialog-choose") return check(host.chooseInDialog(a[0]));
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
