// The viewer script's parser: reads a script's lines into commands and checks each command's
// shape (its verb, argument count and argument values) before any runs, so that a bad script
// fails at its file:line:column without touching the viewer. No GL: the fuzz target
// (tests/fuzz/script_fuzz.cpp) links it alone.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>

#include "app/analysis/analysis_plot_ids.h"
#include "app/analysis/field_fractions.h"
#include "app/automation/script.h"
#include "app/automation/script_words.h"
#include "app/render_export.h"
#include "optics/aperture_shape.h"

namespace lenslab::app {

using script_words::asphericTermPower;
using script_words::parseInteger;
using script_words::parseNumber;
using script_words::parseProfileValue;
using script_words::parseSurfaceValue;

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
      {"paste-lens-table", {1, 1}},
      {"paste-lens-table-column", {2, 2}},
      {"paste-lens-table-open", {0, 0}},
      {"show-panel", {1, 1}},
      {"asphere-editor", {1, 1}},
      {"glass-map", {1, 3}},  // open | close | maker M on|off
      {"pin-reference", {0, 0}},
      {"unpin-reference", {0, 0}},
      {"export-plot", {2, 2}},
      {"export-cross-section", {1, 4}},
      // Pictures for slides (issue 20).
      {"export-render", {3, 3}},
      {"start-export-render", {3, 3}},
      {"wait-export", {0, 0}},
      {"cancel-export", {0, 0}},
      {"reset-stats", {0, 0}},  // issue 21: measure a drag alone (bench/viewer-drag.sh)
      // Hardening (issue 24): COUNT random lens edits at 200 a second from SEED, and undoing
      // every step there is.
      {"edit-storm", {2, 2}},
      {"undo-all", {0, 0}},
      // The library browser (issue 42): library open|reload|wait|search|filter|select ...
      {"library", {1, 32}},
  };
  return table;
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

// "set NAME WORD" with WORD one of `words`: nothing, or "expected: set NAME w1|w2|...".
std::optional<Diagnostic> expectOneOf(const ScriptCommand& command,
                                      std::initializer_list<std::string_view> words) {
  const auto& a = command.arguments;
  if (a.size() == 2 && std::find(words.begin(), words.end(), a[1]) != words.end()) {
    return std::nullopt;
  }
  std::string choices;
  for (const std::string_view word : words) {
    if (!choices.empty()) choices += '|';
    choices += word;
  }
  return problemAt(command, 0, "expected: set " + a[0] + " " + choices);
}

// Checks a "set" command's shape; returns an error naming the offending argument.
std::optional<Diagnostic> checkSet(const ScriptCommand& command) {
  const auto& a = command.arguments;
  const auto numberAt = [&](std::size_t i) -> std::optional<Diagnostic> {
    if (i >= a.size()) return problemAt(command, a.size() - 1, "expected a value after it");
    if (!parseNumber(a[i])) return problemAt(command, i, "'" + a[i] + "' is not a number");
    return std::nullopt;
  };
  if (a[0] == "surface" && a.size() >= 3 && a[2] == "glass") {
    // set surface N glass NAME [maker M]: the name is looked up when the command runs (an
    // unknown one fails the script there, with the nearest names).
    if (a.size() != 4 && !(a.size() == 6 && a[4] == "maker"))
      return problemAt(command, 0, "expected: set surface N glass NAME [maker M]");
    const auto index = parseInteger(a[1]);
    if (!index || *index < 1)
      return problemAt(command, 1, "'" + a[1] + "' is not a surface number (1, 2, ...)");
    return std::nullopt;
  }
  if (a[0] == "surface") {
    if (a.size() != 4) {
      return problemAt(command, 0, "expected: set surface N FIELD VALUE");
    }
    const auto index = parseInteger(a[1]);
    if (!index || *index < 1)
      return problemAt(command, 1, "'" + a[1] + "' is not a surface number (1, 2, ...)");
    // An aspheric term, "a4": its power must be one the profile has, its value a finite number.
    if (const auto power = asphericTermPower(a[2])) {
      if (*power < optics::AsphericProfile::kMinPower ||
          *power > optics::AsphericProfile::kMaxPower) {
        return problemAt(command, 2,
                         "there is no aspheric term '" + a[2] + "' (expected a2 to a20)");
      }
      if (!parseProfileValue(a[3])) {
        return problemAt(command, 3, "'" + a[3] + "' is not a finite number");
      }
      return std::nullopt;
    }
    const auto field = surfaceFieldFromName(a[2]);
    if (!field) {
      return problemAt(command, 2,
                       "unknown field '" + a[2] +
                           "' (expected radius, thickness, n, abbe, aperture, conic, glass or a2 "
                           "to a20)");
    }
    if (*field == SurfaceField::Conic && !parseProfileValue(a[3])) {
      return problemAt(command, 3, "'" + a[3] + "' is not a finite number");
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
  if (a[0] == "camera") return expectOneOf(command, {"lens", "pinhole"});
  if (a[0] == "blocked-rays") return expectOneOf(command, {"show", "hide"});
  if (a[0] == "film-point") {
    if (a.size() != 2 || (a[1] != "off" && !(parseNumber(a[1]) && *parseNumber(a[1]) >= 0))) {
      return problemAt(command, 0, "expected: set film-point MM|off (MM from the axis, >= 0)");
    }
    return std::nullopt;
  }
  if (a[0] == "keep-film-distance") return expectOneOf(command, {"on", "off"});
  if (a[0] == "fields") {
    if (a.size() != 2) return problemAt(command, 0, "expected: set fields F,F,... (e.g. 0,0.7,1)");
    std::string why;
    if (!parseFieldFractions(a[1], &why)) return problemAt(command, 1, why);
    return std::nullopt;
  }
  if (a[0] == "auto-exposure" || a[0] == "colour-fans") return expectOneOf(command, {"on", "off"});
  if (a[0] == "bottom-area") return expectOneOf(command, {"maximised", "restored"});
  if (a[0] == "mtf-range") return expectOneOf(command, {"cutoff", "400", "200", "100"});
  // The vignetting teaching's switches (issue 21): the render's cos^4 weighting and rims
  // (render/falloff_toggles.h), and the heat map over the preview.
  if (a[0] == "cos4" || a[0] == "rims" || a[0] == "vignetting-overlay") {
    return expectOneOf(command, {"on", "off"});
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
          "blocked-rays, layout, keep-film-distance, auto-exposure, film-point, cos4, rims, "
          "vignetting-overlay, colour-fans, spectral, fields, bottom-area or mtf-range)");
}

// library open [FOLDER] | reload | wait | search [WORDS] | select NAME | filter type TYPE|any |
// filter efl MIN MAX|any | filter year FROM TO|any | filter aspheric yes|no|any | filter clear.
std::optional<Diagnostic> checkLibrary(const ScriptCommand& command) {
  const auto& a = command.arguments;
  const std::size_t count = a.size();
  if (a[0] == "open") {
    if (count > 2) return problemAt(command, 2, "expected: library open [FOLDER]");
    return std::nullopt;
  }
  if (a[0] == "reload" || a[0] == "wait") {
    if (count > 1) return problemAt(command, 1, "'library " + a[0] + "' takes no more words");
    return std::nullopt;
  }
  if (a[0] == "search") return std::nullopt;
  if (a[0] == "select") {
    if (count < 2) return problemAt(command, 0, "expected: library select NAME");
    return std::nullopt;
  }
  if (a[0] != "filter") {
    return problemAt(command, 0,
                     "unknown library command '" + a[0] +
                         "' (expected open, reload, wait, search, filter or select)");
  }
  const std::string what = count > 1 ? a[1] : "";
  if (what == "clear" && count == 2) return std::nullopt;
  if (what == "type" && count >= 3) return std::nullopt;
  if (what == "aspheric" && count == 3 && (a[2] == "yes" || a[2] == "no" || a[2] == "any"))
    return std::nullopt;
  if ((what == "efl" || what == "year") && count == 3 && a[2] == "any") return std::nullopt;
  if (what == "efl" || what == "year") {
    if (count != 4) {
      return problemAt(command, 1,
                       "expected: library filter " + what +
                           (what == "efl" ? " MIN MAX (mm) or any" : " FROM TO or any"));
    }
    for (std::size_t i = 2; i < 4; ++i) {
      const bool good =
          what == "efl" ? parseNumber(a[i]).has_value() : parseInteger(a[i]).has_value();
      if (!good) {
        return problemAt(command, i,
                         "'" + a[i] + "' is not " + (what == "efl" ? "a number (mm)" : "a year"));
      }
    }
    return std::nullopt;
  }
  return problemAt(command, count > 1 ? 1 : 0,
                   "expected: library filter type TYPE|any, efl MIN MAX|any, year FROM TO|any, "
                   "aspheric yes|no|any or clear");
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
  if (command.verb == "library") return checkLibrary(command);
  if (command.verb == "asphere-editor" && command.arguments[0] != "close") {
    const auto surface = parseInteger(command.arguments[0]);
    if (!surface || *surface < 1) {
      return problemAt(
          command, 0,
          "'" + command.arguments[0] + "' is not a surface number (1, 2, ...) or close");
    }
  }
  if (command.verb == "glass-map") {
    const auto& a = command.arguments;
    const bool openOrClose = count == 1 && (a[0] == "open" || a[0] == "close");
    const bool filter = count == 3 && a[0] == "maker" && (a[2] == "on" || a[2] == "off");
    if (!openOrClose && !filter)
      return problemAt(command, 0, "expected: glass-map open|close, or glass-map maker M on|off");
  }
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
  if (command.verb == "paste-lens-table-column") {
    const auto column = parseInteger(command.arguments[0]);
    if (!column || *column < 1)
      return problemAt(command, 0,
                       "'" + command.arguments[0] + "' is not a column number (from 1)");
    if (!script_words::patentColumnFromWord(command.arguments[1]))
      return problemAt(command, 1,
                       "'" + command.arguments[1] +
                           "' is not a column meaning (surface, r, d, nd, vd or ignored)");
  }
  if (command.verb == "open-dialog") {
    static const char* const kKinds[] = {
        "open-lens",     "open-scene",         "save-lens",           "save-render",
        "export-render", "save-cross-section", "export-cross-section"};
    const auto plotId = plotIdOfSaveDialog(command.arguments[0]);
    const bool knownPlot = plotId && isAnalysisPlotId(*plotId);
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
  // Surfaces count from 1, as in the lens table: make-stop 0 once reached the viewer as surface
  // SIZE_MAX, refused as "surface 0 does not exist" (found by tests/fuzz/script_fuzz.cpp).
  if (command.verb == "make-stop") {
    const auto surface = parseInteger(command.arguments[0]);
    if (!surface || *surface < 1)
      return problemAt(command, 0,
                       "'" + command.arguments[0] + "' is not a surface number (1, 2, ...)");
  }
  if (command.verb == "wait-seconds") {
    const auto seconds = parseNumber(command.arguments[0]);
    // Longer waits would meet the runner's wait limit; a script repeats the command for more.
    if (!seconds || *seconds <= 0 || *seconds > 60) {
      return problemAt(command, 0,
                       "'" + command.arguments[0] + "' is not a number of seconds in (0, 60]");
    }
  }
  const bool countArgument = command.verb == "wait-frames" || command.verb == "wait-spp" ||
                             command.verb == "quit" || command.verb == "edit-storm";
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
    // A carriage return separates words like a space: a CRLF file's lines end in one. Only that
    // one used to be dropped, so "screenshot a.png\r\r" wrote a file named "a.png\r", not the
    // one the line shows (found by tests/fuzz/script_fuzz.cpp).
    constexpr const char* kSpace = " \t\r";
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    ScriptCommand command;
    command.file = fileName;
    command.line = lineNumber;
    std::size_t position = 0;
    while (true) {
      position = line.find_first_not_of(kSpace, position);
      if (position == std::string::npos) break;
      const std::size_t end = line.find_first_of(kSpace, position);
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

}  // namespace lenslab::app
