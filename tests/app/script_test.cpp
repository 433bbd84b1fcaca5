#include "app/automation/script.h"

#include "optics/lens_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace lenslab::app {
namespace {

class FakeHost : public ScriptHost {
 public:
  Issued loadLens(const std::string& path, bool keepFileFilmDistance) override {
    calls.push_back("load-lens " + path + (keepFileFilmDistance ? " keep-film-distance" : ""));
    if (path == "broken.dat") return {std::string("broken.dat:3:7: not a number")};
    return {std::nullopt,
            lens.issue(ReplaceLens{lens.prescription(), path}, {}, CommandSource::Script)};
  }
  // A scene loads over `sceneLoadFrames` calls of sceneLoadOutcome(), as the viewer's loads
  // take frames.
  void startLoadingScene(const std::string& path) override {
    calls.push_back("load-scene " + path);
    sceneLoadPolls = 0;
    sceneError = path == "broken.pbrt" ? "broken.pbrt:2:1: unknown directive" : "";
  }
  std::optional<std::string> sceneLoadOutcome() const override {
    if (++sceneLoadPolls < sceneLoadFrames) return std::nullopt;
    return sceneError;
  }
  std::optional<std::string> saveLens(const std::string& path) override {
    calls.push_back("save-lens " + path);
    return std::nullopt;
  }
  // Like the viewer, the fake applies a script's lens commands with the next frame.
  CommandTicket issue(const EditCommand& command) override {
    calls.push_back(describe(command));
    return lens.issue(command, {}, CommandSource::Script);
  }
  std::optional<std::string> commandOutcome(CommandTicket ticket) const override {
    return lens.outcome(ticket);
  }
  void setExposure(double stops) override { exposure = stops; }
  void setPinholeCamera(bool usePinhole) override { pinhole = usePinhole; }
  std::optional<std::string> saveWindowScreenshot(const std::string& path) override {
    calls.push_back("screenshot " + path);
    return std::nullopt;
  }
  std::optional<std::string> saveRender(const std::string& path) override {
    calls.push_back("render " + path);
    return std::nullopt;
  }
  std::optional<std::string> saveCrossSection(const std::string& path) override {
    calls.push_back("cross-section " + path);
    return std::nullopt;
  }
  std::optional<std::string> dumpUi(const std::string&) override { return std::nullopt; }
  std::optional<int> previewSpp() const override { return spp; }
  void quit(int code) override { exitCode = code; }
  void reportError(const std::string& message) override { errors.push_back(message); }

  FakeHost() {
    lens.issue(ReplaceLens{optics::Prescription{{{40.0, 5.0, 1.5, std::nullopt, 20.0},
                                                 {0.0, 5.0, 1.0, std::nullopt, 10.0},
                                                 {-40.0, 40.0, 1.0, std::nullopt, 20.0}},
                                                optics::ApertureShape{}},
                           "",
                           {},
                           true});
    lens.applyQueued();
  }
  const optics::Prescription& prescription() const { return lens.prescription(); }
  // One frame of the viewer: the commands issued since the last are applied, then the script
  // takes its step.
  bool frame(ScriptRunner& runner) {
    lens.applyQueued();
    return runner.step(*this);
  }

  LensEditor lens;
  std::vector<std::string> calls, errors;
  std::optional<int> exitCode;
  std::optional<int> spp = 0;
  int sceneLoadFrames = 1;
  mutable int sceneLoadPolls = 0;
  std::string sceneError;
  double exposure = 0;
  bool pinhole = false;
  void setKeepFilmDistance(bool keep) override { keepFilmDistance = keep; }
  std::optional<bool> keepFilmDistance;
  void setFieldFractions(const std::vector<double>& fractions) override { fields = fractions; }
  std::vector<double> fields;
};

TEST(ScriptRun, SetFieldsGivesTheHostTheFractions) {
  const ParsedScript script = parseScript("set fields 0,0.5, 1\n", "t");
  // One argument: the list is a single word unless spaces split it.
  EXPECT_FALSE(script.diagnostics.empty());
  const ParsedScript joined = parseScript("set fields 0,0.5,1\n", "t");
  ASSERT_TRUE(joined.diagnostics.empty()) << joined.diagnostics.formatAll();
  FakeHost host;
  ScriptRunner runner(joined.commands);
  while (host.frame(runner)) {
  }
  EXPECT_TRUE(host.errors.empty());
  EXPECT_EQ(host.fields, (std::vector<double>{0.0, 0.5, 1.0}));
}

// edit-storm at its rate, then undo-all back to the lens the script started with: every edit the
// storm made was one undo step (refused ones, naming a surface that does not exist, made none).
TEST(ScriptRun, AnEditStormIsUndoneWholeByUndoAll) {
  const ParsedScript script = parseScript("edit-storm 100 7\nundo-all\n", "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  FakeHost host;
  // Compared as the lens file would write them: every digit of every field.
  const auto text = [&] { return optics::formatLensText(host.prescription()); };
  const std::string start = text();
  ScriptRunner runner(script.commands);
  const auto started = std::chrono::steady_clock::now();
  bool stormed = false;
  while (host.frame(runner)) {
    if (!stormed && host.calls.size() >= 100) {
      stormed = true;
      // 100 edits at 200 a second: half a second (the first at once).
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      EXPECT_GT(seconds, 0.45);
      EXPECT_LT(seconds, 1.5);
      EXPECT_NE(text(), start);
    }
  }
  EXPECT_TRUE(host.errors.empty());
  EXPECT_EQ(text(), start);
  EXPECT_FALSE(host.lens.document().canUndo());
  // Undos were issued, a batch a frame, until one was refused.
  const auto undos = std::count(host.calls.begin(), host.calls.end(), describe(Undo{}));
  EXPECT_GE(undos, 16);
}

TEST(ScriptParse, WaitSecondsTakesUpTo60Seconds) {
  for (const char* bad : {"wait-seconds 0\n", "wait-seconds 61\n", "wait-seconds soon\n"})
    EXPECT_FALSE(parseScript(bad, "t").diagnostics.empty()) << bad;
  const ParsedScript script = parseScript("wait-seconds 0.3\n", "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  FakeHost host;
  ScriptRunner runner(script.commands);
  const auto started = std::chrono::steady_clock::now();
  while (host.frame(runner)) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_GE(seconds, 0.3);
  EXPECT_LT(seconds, 2.0);
}

TEST(ScriptParse, FieldsAndPlotDialogsAreChecked) {
  const ParsedScript bad = parseScript(
      "set fields 0,1.5\nset fields 0,x\nset fields 0,0,0,0,0,0,0,0,0\n"
      "open-dialog save-nonsense-plot\n",
      "t");
  ASSERT_EQ(bad.diagnostics.all().size(), 4u) << bad.diagnostics.formatAll();
  EXPECT_NE(bad.diagnostics.all()[0].format().find("t:1:12: error: field 1.5 is not between 0"),
            std::string::npos)
      << bad.diagnostics.all()[0].format();
  EXPECT_NE(bad.diagnostics.all()[1].format().find("'x' is not a number"), std::string::npos);
  EXPECT_NE(bad.diagnostics.all()[2].format().find("at most 8 fields"), std::string::npos);
  EXPECT_NE(bad.diagnostics.all()[3].format().find("illumination"), std::string::npos)
      << bad.diagnostics.all()[3].format();
  const ParsedScript good = parseScript("open-dialog save-illumination-plot\n", "t");
  EXPECT_TRUE(good.diagnostics.empty()) << good.diagnostics.formatAll();
}

TEST(ScriptRun, KeepFilmDistanceAsALoadLensOptionAndAsASetting) {
  const ParsedScript script = parseScript(
      "load-lens a.dat keep-film-distance\n"
      "load-lens b.dat\n"
      "set keep-film-distance on\n",
      "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  FakeHost host;
  ScriptRunner runner(script.commands);
  while (host.frame(runner)) {
  }
  EXPECT_TRUE(host.errors.empty());
  EXPECT_EQ(host.calls,
            (std::vector<std::string>{"load-lens a.dat keep-film-distance", "load-lens b.dat"}));
  EXPECT_EQ(host.keepFilmDistance, true);
}

TEST(ScriptParse, KeepFilmDistanceTakesOnlyItsOwnWords) {
  const ParsedScript script = parseScript(
      "load-lens a.dat sharp\n"
      "set keep-film-distance maybe\n",
      "t.script");
  ASSERT_EQ(script.diagnostics.all().size(), 2u);
  EXPECT_EQ(
      script.diagnostics.all()[0].format().rfind("t.script:1:17: error: unknown option 'sharp'", 0),
      0u)
      << script.diagnostics.all()[0].format();
  EXPECT_EQ(script.diagnostics.all()[1].format().rfind(
                "t.script:2:5: error: expected: set keep-film-distance on|off", 0),
            0u)
      << script.diagnostics.all()[1].format();
}

// Every setting that takes one of a few words accepts each of them and nothing else; another
// word, or two, is reported at the setting's name with the words it takes.
TEST(ScriptParse, ChoiceSettingsTakeOnlyTheirWords) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> choices = {
      {"camera", {"lens", "pinhole"}},
      {"blocked-rays", {"show", "hide"}},
      {"keep-film-distance", {"on", "off"}},
      {"auto-exposure", {"on", "off"}},
      {"colour-fans", {"on", "off"}},
      {"cos4", {"on", "off"}},
      {"rims", {"on", "off"}},
      {"vignetting-overlay", {"on", "off"}}};
  for (const auto& [name, words] : choices) {
    for (const std::string& word : words) {
      const ParsedScript good = parseScript("set " + name + " " + word + "\n", "t.script");
      EXPECT_TRUE(good.diagnostics.empty())
          << name << " " << word << ": " << good.diagnostics.formatAll();
    }
    const std::string expected =
        "t.script:1:5: error: expected: set " + name + " " + words[0] + "|" + words[1];
    for (const std::string& bad :
         std::vector<std::string>{" maybe", " " + words[0] + " " + words[1]}) {
      const ParsedScript script = parseScript("set " + name + bad + "\n", "t.script");
      ASSERT_EQ(script.diagnostics.all().size(), 1u) << name << bad;
      EXPECT_EQ(script.diagnostics.all()[0].format().rfind(expected, 0), 0u)
          << script.diagnostics.all()[0].format();
    }
  }
}

// Surfaces count from 1: make-stop 0 is refused where it is written, not passed on to the viewer
// as surface SIZE_MAX (tests/fuzz/regressions/script/make-stop-0.script).
TEST(ScriptParse, MakeStopCountsSurfacesFromOne) {
  const ParsedScript script = parseScript("make-stop 0\nmake-stop 1\n", "t.script");
  ASSERT_EQ(script.diagnostics.all().size(), 1u);
  EXPECT_EQ(script.diagnostics.all()[0].format(),
            "t.script:1:11: error: '0' is not a surface number (1, 2, ...)");
  ASSERT_EQ(script.commands.size(), 1u);
  EXPECT_EQ(script.commands[0].arguments, std::vector<std::string>{"1"});
}

// A carriage return separates words wherever it is: "a.png\r\r" is the file a.png, as the viewer
// shows it (tests/fuzz/regressions/script/carriage-returns.script).
TEST(ScriptParse, CarriageReturnsSeparateWords) {
  const ParsedScript script =
      parseScript("show-panel a\r\r\nscreenshot b.png\r\n\rundo\r\n", "t.script");
  EXPECT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  ASSERT_EQ(script.commands.size(), 3u);
  EXPECT_EQ(script.commands[0].arguments, std::vector<std::string>{"a"});
  EXPECT_EQ(script.commands[1].arguments, std::vector<std::string>{"b.png"});
  EXPECT_EQ(script.commands[2].verb, "undo");
}

TEST(ScriptParse, ReportsFileLineColumnForEachBadLine) {
  const ParsedScript script = parseScript(
      "load-lens a.dat\n"
      "set surface x radius 40\n"
      "set surface 2 colour 3\n"
      "frobnicate\n"
      "set film-distance abc\n"
      "wait-spp\n",
      "t.script");
  ASSERT_EQ(script.diagnostics.all().size(), 5u);
  EXPECT_EQ(script.diagnostics.all()[0].format().rfind("t.script:2:13: error: ", 0), 0u)
      << script.diagnostics.all()[0].format();
  EXPECT_EQ(script.diagnostics.all()[1].format().rfind("t.script:3:15: error: ", 0), 0u)
      << script.diagnostics.all()[1].format();
  EXPECT_EQ(script.diagnostics.all()[2].format().rfind("t.script:4:1: error: ", 0), 0u)
      << script.diagnostics.all()[2].format();
  EXPECT_EQ(script.diagnostics.all()[3].format().rfind("t.script:5:19: error: ", 0), 0u)
      << script.diagnostics.all()[3].format();
  EXPECT_EQ(script.diagnostics.all()[4].format().rfind("t.script:6:1: error: ", 0), 0u)
      << script.diagnostics.all()[4].format();
}

TEST(ScriptRun, AppliesEditsUndoAndQuits) {
  const ParsedScript script = parseScript(
      "# comment line\r\n"
      "set surface 1 radius 35   # trailing comment\n"
      "set film-distance 37\n"
      "undo\n"
      "set exposure -1.5\n"
      "set camera pinhole\n"
      "screenshot out.png\n"
      "quit 3\n",
      "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  FakeHost host;
  ScriptRunner runner(script.commands);
  // Each edit waits for the frame that applies it: the radius, the film distance, the undo.
  EXPECT_TRUE(host.frame(runner));
  EXPECT_EQ(host.calls, std::vector<std::string>{"set radius of surface 1 to 35"});
  EXPECT_DOUBLE_EQ(host.prescription().surfaces[0].radiusMm, 40.0);  // not applied yet
  EXPECT_TRUE(host.frame(runner));
  EXPECT_DOUBLE_EQ(host.prescription().surfaces[0].radiusMm, 35.0);
  EXPECT_TRUE(host.frame(runner));
  EXPECT_DOUBLE_EQ(host.prescription().surfaces[2].thicknessMm, 37.0);
  EXPECT_TRUE(host.frame(runner));  // the screenshot waits for a frame that shows the edits
  EXPECT_FALSE(host.frame(runner));
  EXPECT_DOUBLE_EQ(host.prescription().surfaces[0].radiusMm, 35.0);
  EXPECT_DOUBLE_EQ(host.prescription().surfaces[2].thicknessMm, 40.0);  // undone
  EXPECT_EQ(host.calls.back(), "screenshot out.png");
  EXPECT_DOUBLE_EQ(host.exposure, -1.5);
  EXPECT_TRUE(host.pinhole);
  EXPECT_EQ(host.exitCode, 3);
  EXPECT_FALSE(runner.failed());
}

TEST(ScriptRun, WaitsForFramesAndSamplesWithoutBlocking) {
  const ParsedScript script = parseScript("wait-frames 2\nwait-spp 4\nquit\n", "t");
  FakeHost host;
  ScriptRunner runner(script.commands);
  EXPECT_TRUE(runner.step(host));  // frame 1
  EXPECT_TRUE(runner.step(host));  // frame 2
  EXPECT_TRUE(runner.step(host));  // frames done; now waiting for samples
  host.spp = 2;
  EXPECT_TRUE(runner.step(host));
  EXPECT_FALSE(host.exitCode.has_value());
  host.spp = 4;
  EXPECT_FALSE(runner.step(host));
  EXPECT_EQ(host.exitCode, 0);
}

TEST(ScriptRun, FailsOnTheFirstErrorWithItsLocation) {
  const ParsedScript script =
      parseScript("load-lens broken.dat\nscreenshot never.png\n", "s.script");
  FakeHost host;
  ScriptRunner runner(script.commands);
  EXPECT_FALSE(runner.step(host));
  EXPECT_TRUE(runner.failed());
  EXPECT_EQ(host.exitCode, 1);
  ASSERT_EQ(host.errors.size(), 1u);
  EXPECT_EQ(host.errors[0].rfind("s.script:1:11: error: load-lens: ", 0), 0u) << host.errors[0];
  EXPECT_NE(host.errors[0].find("broken.dat:3:7"), std::string::npos);
  for (const auto& call : host.calls) EXPECT_EQ(call.find("screenshot"), std::string::npos);
}

TEST(ScriptRun, LoadSceneWaitsForTheSceneAndFailsWithItsError) {
  const ParsedScript script = parseScript(
      "load-scene a.pbrt\nscreenshot a.png\nload-scene broken.pbrt\nscreenshot never.png\n",
      "s.script");
  FakeHost host;
  host.sceneLoadFrames = 3;
  ScriptRunner runner(script.commands);
  EXPECT_TRUE(runner.step(host));  // loading: started once, nothing after it yet
  EXPECT_TRUE(runner.step(host));
  EXPECT_EQ(host.calls, std::vector<std::string>{"load-scene a.pbrt"});
  int steps = 2;
  while (runner.step(host) && steps < 20) ++steps;
  // a.pbrt opened: its screenshot; then broken.pbrt failed, and the script stopped there.
  EXPECT_EQ(host.calls, (std::vector<std::string>{"load-scene a.pbrt", "screenshot a.png",
                                                  "load-scene broken.pbrt"}));
  EXPECT_EQ(host.exitCode, 1);
  ASSERT_EQ(host.errors.size(), 1u);
  EXPECT_NE(host.errors[0].find("s.script:3:"), std::string::npos) << host.errors[0];
  EXPECT_NE(host.errors[0].find("broken.pbrt:2:1"), std::string::npos) << host.errors[0];
}

TEST(ScriptRun, EditOfAMissingSurfaceFails) {
  const ParsedScript script = parseScript("set surface 9 radius 1\nundo\n", "t");
  FakeHost host;
  ScriptRunner runner(script.commands);
  EXPECT_TRUE(host.frame(runner));  // issued, and waiting for its frame
  EXPECT_FALSE(runner.failed());
  EXPECT_FALSE(host.frame(runner));
  EXPECT_TRUE(runner.failed());
  ASSERT_EQ(host.errors.size(), 1u);
  EXPECT_NE(host.errors[0].find("t:1:5: error: set: surface 9 does not exist"), std::string::npos)
      << host.errors[0];
}

TEST(ScriptRun, UndoWithNothingToUndoFails) {
  const ParsedScript script = parseScript("undo\n", "t");
  FakeHost host;
  ScriptRunner runner(script.commands);
  while (host.frame(runner)) {
  }
  ASSERT_EQ(host.errors.size(), 1u);
  EXPECT_EQ(host.errors[0], "t:1:1: error: undo: nothing to undo");
}

// inf is a flat surface's radius, as the table and the lens file write it; it means nothing as a
// thickness or a film distance, so there it stays "not a number".
TEST(ScriptRun, RadiusInfMakesAFlatSurface) {
  const ParsedScript script = parseScript("set surface 1 radius inf\n", "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  FakeHost host;
  ScriptRunner runner(script.commands);
  while (host.frame(runner)) {
  }
  EXPECT_FALSE(runner.failed()) << (host.errors.empty() ? "" : host.errors[0]);
  EXPECT_TRUE(std::isinf(host.prescription().surfaces[0].radiusMm));

  for (const char* text :
       {"set surface 1 thickness inf\n", "set film-distance inf\n", "set surface 1 radius nan\n"}) {
    const ParsedScript rejected = parseScript(text, "t");
    ASSERT_EQ(rejected.diagnostics.all().size(), 1u) << text;
    EXPECT_NE(rejected.diagnostics.formatAll().find("is not a number"), std::string::npos)
        << rejected.diagnostics.formatAll();
  }
}

// Issue 40: a conic and an aspheric term, each one undo step, as the table's cells are.
TEST(ScriptRun, ConicAndAsphericTermsAreSetAndUndoneOneAtATime) {
  const ParsedScript script = parseScript(
      "set surface 1 conic -0.5\nset surface 1 a4 -2e-6\nset surface 1 a3 1.5e-5\nundo\n", "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  FakeHost host;
  ScriptRunner runner(script.commands);
  while (host.frame(runner)) {
  }
  EXPECT_FALSE(runner.failed()) << (host.errors.empty() ? "" : host.errors[0]);
  EXPECT_EQ(host.calls, (std::vector<std::string>{"set conic of surface 1 to -0.5",
                                                  "set A4 of surface 1 to -2e-06",
                                                  "set A3 of surface 1 to 1.5e-05", "undo"}));
  const optics::AsphericProfile& profile = host.prescription().surfaces[0].profile;
  EXPECT_DOUBLE_EQ(profile.conic(), -0.5);
  EXPECT_DOUBLE_EQ(profile.coefficient(4), -2e-6);
  EXPECT_EQ(profile.coefficient(3), 0.0);  // undone
  EXPECT_EQ(profile.highestPower(), 4);
}

TEST(ScriptParse, BadAsphericTermsAreErrorsAtTheirLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"set surface 1 a1 1e-3\n",
       "t:1:15: error: there is no aspheric term 'a1' (expected a2 to a20)"},
      {"set surface 1 a21 1e-3\n", "t:1:15: error: there is no aspheric term 'a21'"},
      {"set surface 1 a4 nan\n", "t:1:18: error: 'nan' is not a finite number"},
      {"set surface 1 a4 none\n", "t:1:18: error: 'none' is not a finite number"},
      {"set surface 1 conic none\n", "t:1:21: error: 'none' is not a finite number"},
      {"set surface 1 conic inf\n", "t:1:21: error: 'inf' is not a finite number"},
      {"set surface 1 ax 1\n", "t:1:15: error: unknown field 'ax'"},
  };
  for (const auto& [text, expected] : cases) {
    const ParsedScript parsed = parseScript(text, "t");
    ASSERT_EQ(parsed.diagnostics.all().size(), 1u) << text;
    EXPECT_NE(parsed.diagnostics.formatAll().find(expected), std::string::npos)
        << parsed.diagnostics.formatAll();
  }
}

// The stop is a hole: no shape to make aspheric. A surface that does not exist has none either.
// Both fail the script at their line, when the document refuses them.
TEST(ScriptRun, AsphericTermsOnTheStopOrOnNoSurfaceFailAtTheirLine) {
  for (const auto& [text, expected] :
       {std::pair<const char*, const char*>{
            "make-stop 2\nset surface 2 a4 1e-6\n",
            "t:2:5: error: set: surface 2 is the aperture stop: it has no shape to make aspheric"},
        {"make-stop 2\nset surface 2 conic -1\n",
         "t:2:5: error: set: surface 2 is the aperture stop"},
        {"set surface 9 a4 1e-6\n", "t:1:5: error: set: surface 9 does not exist"}}) {
    const ParsedScript script = parseScript(text, "t");
    ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
    FakeHost host;
    ScriptRunner runner(script.commands);
    while (host.frame(runner)) {
    }
    EXPECT_TRUE(runner.failed()) << text;
    ASSERT_EQ(host.errors.size(), 1u) << text;
    EXPECT_NE(host.errors[0].find(expected), std::string::npos) << host.errors[0];
  }
}

TEST(ScriptRun, AbbeNoneClearsTheAbbeNumber) {
  const ParsedScript script = parseScript("set surface 1 abbe 60\nset surface 1 abbe none\n", "t");
  ASSERT_TRUE(script.diagnostics.empty());
  FakeHost host;
  ScriptRunner runner(script.commands);
  while (host.frame(runner)) {
  }
  EXPECT_FALSE(runner.failed());
  EXPECT_FALSE(host.prescription().surfaces[0].abbeD.has_value());
}

TEST(ScriptParse, ViewerCommandsAreChecked) {
  const ParsedScript good = parseScript(
      "set blocked-rays hide\nset layout 0.25 0.4 0.2\nzoom-cross-section 1e4\n"
      "drop x.dat\nopen-dialog save-cross-section\ndialog-choose a.png\n",
      "t");
  EXPECT_TRUE(good.diagnostics.empty()) << good.diagnostics.formatAll();
  const ParsedScript bad = parseScript(
      "set blocked-rays maybe\nset layout 0.25 1.5 0.2\nzoom-cross-section -2\n"
      "open-dialog open-sesame\n",
      "t");
  ASSERT_EQ(bad.diagnostics.all().size(), 4u);
  EXPECT_EQ(bad.diagnostics.all()[1].format().rfind("t:2:17: error: ", 0), 0u)
      << bad.diagnostics.all()[1].format();
  EXPECT_EQ(bad.diagnostics.all()[2].format().rfind("t:3:20: error: ", 0), 0u)
      << bad.diagnostics.all()[2].format();
}

TEST(ScriptRun, AHostWithoutAWindowRefusesDialogs) {
  const ParsedScript script = parseScript("open-dialog open-lens\n", "t");
  FakeHost host;
  ScriptRunner runner(script.commands);
  runner.step(host);
  EXPECT_TRUE(runner.failed());
}

// Pictures for slides: export-render waits for its export (a cancel fails it), start-export-render
// does not, wait-export accepts a cancel; set auto-exposure reaches the host.
class ExportHost : public FakeHost {
 public:
  std::optional<std::string> startExportRender(const std::string& path, int width, int height,
                                               int samplesPerPixel) override {
    calls.push_back("export " + path + " " + std::to_string(width) + "x" + std::to_string(height) +
                    " " + std::to_string(samplesPerPixel));
    outcome = ExportOutcome{true, false, ""};
    return std::nullopt;
  }
  ExportOutcome exportRenderOutcome() const override { return outcome; }
  std::optional<std::string> cancelExportRender() override {
    if (!outcome.running) return std::string("there is no export rendering to cancel");
    outcome = ExportOutcome{false, true, ""};
    return std::nullopt;
  }
  void setAutoExposure(bool on) override { autoExposure = on; }
  ExportOutcome outcome{false, false, "no export was started"};
  bool autoExposure = true;
};

TEST(ScriptRun, ExportRenderWaitsUntilWrittenAndACancelFailsIt) {
  const ParsedScript script = parseScript(
      "set auto-exposure off\nexport-render a.png 640x400 16\nexport-render b.exr film 4\n", "t");
  ASSERT_TRUE(script.diagnostics.empty()) << script.diagnostics.formatAll();
  ExportHost host;
  ScriptRunner runner(script.commands);
  EXPECT_TRUE(runner.step(host));  // started; waiting
  EXPECT_FALSE(host.autoExposure);
  ASSERT_EQ(host.calls, std::vector<std::string>{"export a.png 640x400 16"});
  EXPECT_TRUE(runner.step(host));  // still rendering: not started twice
  EXPECT_EQ(host.calls.size(), 1u);
  host.outcome = {false, false, ""};  // written
  EXPECT_TRUE(runner.step(host));     // the next export (the film's size: 0x0) started
  ASSERT_EQ(host.calls.size(), 2u);
  EXPECT_EQ(host.calls[1], "export b.exr 0x0 4");
  host.outcome = {false, true, ""};  // cancelled (by a click): the script fails
  EXPECT_FALSE(runner.step(host));
  EXPECT_TRUE(runner.failed());
  ASSERT_EQ(host.errors.size(), 1u);
  EXPECT_EQ(host.errors[0].rfind("t:3:15: error: export-render: the export was cancelled", 0), 0u)
      << host.errors[0];
}

TEST(ScriptRun, StartExportRenderGoesOnAndWaitExportAcceptsACancel) {
  const ParsedScript script =
      parseScript("start-export-render a.png 64x40 1\ncancel-export\nwait-export\nquit\n", "t");
  ExportHost host;
  ScriptRunner runner(script.commands);
  EXPECT_FALSE(runner.step(host));  // started, cancelled, waited, quit: all in one frame
  EXPECT_FALSE(runner.failed());
  EXPECT_EQ(host.exitCode, 0);
}

TEST(ScriptParse, ExportCommandsAreChecked) {
  const ParsedScript bad = parseScript(
      "export-render a.png 640 16\nexport-render a.png 0x400 16\nexport-render a.png 64x40 0\n"
      "start-export-render a.png\nset auto-exposure maybe\n",
      "t");
  ASSERT_EQ(bad.diagnostics.all().size(), 5u) << bad.diagnostics.formatAll();
  EXPECT_EQ(bad.diagnostics.all()[0].format(),
            "t:1:21: error: '640' is not WIDTHxHEIGHT (e.g. 640x400) or film");
  EXPECT_EQ(bad.diagnostics.all()[1].format().rfind("t:2:21: error: '0x400': each side", 0), 0u)
      << bad.diagnostics.all()[1].format();
  EXPECT_EQ(bad.diagnostics.all()[2].format().rfind("t:3:27: error: '0' is not a sample", 0), 0u)
      << bad.diagnostics.all()[2].format();
}

}  // namespace
}  // namespace lenslab::app
