// libFuzzer target: the viewer script (app/automation/script.h) on arbitrary text: the parser,
// then the runner over what it accepted, against a host that does nothing but check what it is
// asked. Beyond not crashing, it holds the script to its promises: each error is at the line and
// column of what is wrong, each command keeps the column of every argument, the commands it
// accepts, written out again one per line, are accepted again as the same commands, and the
// runner hands the viewer only values the parser vouched for (surface numbers from 1, finite
// numbers in their ranges) without a hang.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <variant>

#include "app/automation/script.h"
#include "fuzz_check.h"

namespace {

using namespace lenslab;

// Surface numbers count from 1 in a script; an index past this came from 0 or a wrap.
constexpr std::size_t kMaxSurfaceIndex = 1u << 30;

bool finite(double value) { return std::isfinite(value); }

// The viewer's side of a script, reduced to checks: every request succeeds at once, nothing is
// read or written.
class CheckingHost : public app::ScriptHost {
 public:
  Issued loadLens(const std::string&, bool) override { return {std::nullopt, ++tickets_}; }
  app::CommandTicket issue(const app::EditCommand& command) override {
    std::visit(
        [](const auto& edit) {
          using Edit = std::decay_t<decltype(edit)>;
          if constexpr (std::is_same_v<Edit, app::SetSurfaceField>) {
            fuzz::check(edit.surface < kMaxSurfaceIndex, "set surface names a surface from 1");
            fuzz::check(finite(edit.value) || std::isnan(edit.value) ||
                            edit.field == app::SurfaceField::RadiusMm,
                        "only a radius may be infinite");
          } else if constexpr (std::is_same_v<Edit, app::MakeStop>) {
            fuzz::check(edit.surface < kMaxSurfaceIndex, "make-stop names a surface from 1");
          } else if constexpr (std::is_same_v<Edit, app::SetFilmDistance> ||
                               std::is_same_v<Edit, app::SetStopDiameter>) {
            fuzz::check(finite(edit.mm), "a length is finite");
          }
        },
        command);
    return ++tickets_;
  }
  std::optional<std::string> commandOutcome(app::CommandTicket) const override { return ""; }
  void startLoadingScene(const std::string&) override {}
  std::optional<std::string> sceneLoadOutcome() const override { return ""; }
  std::optional<std::string> saveLens(const std::string&) override { return std::nullopt; }
  void setExposure(double stops) override { fuzz::check(finite(stops), "exposure is finite"); }
  void setPinholeCamera(bool) override {}
  std::optional<std::string> saveWindowScreenshot(const std::string&) override {
    return std::nullopt;
  }
  std::optional<std::string> saveRender(const std::string&) override { return std::nullopt; }
  std::optional<std::string> saveCrossSection(const std::string&) override { return std::nullopt; }
  std::optional<std::string> dumpUi(const std::string&) override { return std::nullopt; }
  std::optional<int> previewSpp() const override { return 1 << 30; }
  void quit(int) override {}
  void reportError(const std::string&) override {}
  void zoomCrossSection(double factor) override {
    fuzz::check(finite(factor) && factor > 0, "a zoom factor is positive and finite");
  }
  void centreCrossSection(double zMm, double yMm) override {
    fuzz::check(finite(zMm) && finite(yMm), "a centre is finite");
  }
  std::optional<std::string> startExportRender(const std::string&, int width, int height,
                                               int samplesPerPixel) override {
    fuzz::check(width >= 0 && height >= 0 && width <= 16384 && height <= 16384,
                "an export's size is 0 (the film's) or 1..16384");
    fuzz::check(samplesPerPixel >= 1 && samplesPerPixel <= (1 << 20), "an export's spp");
    return std::nullopt;
  }
  ExportOutcome exportRenderOutcome() const override { return {}; }
  std::optional<std::string> cancelExportRender() override { return std::nullopt; }
  void setFilmPoint(std::optional<double> heightMm) override {
    fuzz::check(!heightMm || (finite(*heightMm) && *heightMm >= 0), "a film point is >= 0");
  }
  void setFieldFractions(const std::vector<double>& fractions) override {
    fuzz::check(!fractions.empty() && fractions.size() <= 8, "one to eight fields");
    for (double fraction : fractions)
      fuzz::check(fraction >= 0 && fraction <= 1, "fields are fractions from 0 to 1");
  }
  void setLayout(double lensTable, double preview, double log) override {
    for (double share : {lensTable, preview, log})
      fuzz::check(share > 0 && share < 1, "layout shares are fractions");
  }

 private:
  app::CommandTicket tickets_ = 0;
};

// Enough frames for every wait the seeds hold; a script that waits longer (wait-frames 1e9,
// wait-until-file) is cut off here rather than hanging the fuzzer.
constexpr int kMaxFrames = 2000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const app::ParsedScript script = app::parseScript(text, "fuzz.script");
  fuzz::checkDiagnostics(script.diagnostics, script.diagnostics.empty());
  for (const Diagnostic& diagnostic : script.diagnostics.all())
    fuzz::check(diagnostic.location.line >= 1 && diagnostic.location.column >= 1,
                "a script error is at a line and column");

  std::string written;
  for (const app::ScriptCommand& command : script.commands) {
    fuzz::check(!command.verb.empty() && command.line >= 1, "a command has a verb and a line");
    fuzz::check(command.argumentColumns.size() == command.arguments.size(),
                "every argument has its column");
    for (int column : command.argumentColumns) fuzz::check(column >= 2, "arguments follow a verb");
    written += command.verb;
    for (const std::string& argument : command.arguments) written += " " + argument;
    written += "\n";
  }
  const app::ParsedScript again = app::parseScript(written, "written.script");
  fuzz::check(again.diagnostics.empty(), "accepted commands are accepted again");
  fuzz::check(again.commands.size() == script.commands.size(), "as many commands again");
  for (std::size_t i = 0; i < again.commands.size(); ++i)
    fuzz::check(again.commands[i].verb == script.commands[i].verb &&
                    again.commands[i].arguments == script.commands[i].arguments,
                "the same commands again");

  // The runner never touches the disk through this host except where a command names a file
  // itself: wait-until-file asks whether it exists, set aperture image reads it.
  CheckingHost host;
  app::ScriptRunner runner(script.commands);
  for (int frame = 0; frame < kMaxFrames && runner.step(host); ++frame) {
  }
  return 0;
}
