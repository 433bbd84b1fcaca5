#include "common/diagnostics.h"

#include <gtest/gtest.h>

namespace lenslab {
namespace {

Diagnostic diagnostic(Severity severity, SourceLocation location, std::string message) {
  Diagnostic made;
  made.severity = severity;
  made.location = std::move(location);
  made.message = std::move(message);
  return made;
}

TEST(Diagnostic, FormatsFileLineColumnSeverityAndMessage) {
  const Diagnostic error = diagnostic(Severity::Error, {"scene.pbrt", 12, 7}, "expected a number");
  EXPECT_EQ(error.format(), "scene.pbrt:12:7: error: expected a number");
  const Diagnostic warning = diagnostic(Severity::Warning, {"lens.dat", 3, 1}, "odd");
  EXPECT_EQ(warning.format(), "lens.dat:3:1: warning: odd");
  const Diagnostic note = diagnostic(Severity::Note, {"a.script", 1, 20}, "from here");
  EXPECT_EQ(note.format(), "a.script:1:20: note: from here");
}

TEST(Diagnostic, WithoutALineNamesTheFileAlone) {
  const Diagnostic whole = diagnostic(Severity::Error, {"mesh.ply", 0, 0}, "cannot open");
  EXPECT_EQ(whole.format(), "mesh.ply: error: cannot open");
}

TEST(Diagnostics, CollectsInOrderAndCountsOnlyErrorsAsErrors) {
  Diagnostics diagnostics;
  EXPECT_TRUE(diagnostics.empty());
  diagnostics.warning({"a", 1, 2}, "first");
  diagnostics.note({"a", 1, 3}, "second");
  EXPECT_FALSE(diagnostics.empty());
  EXPECT_FALSE(diagnostics.hasErrors());
  diagnostics.error({"b", 4, 5}, "third");
  EXPECT_TRUE(diagnostics.hasErrors());
  ASSERT_EQ(diagnostics.all().size(), 3u);
  EXPECT_EQ(diagnostics.all()[2].message, "third");
  EXPECT_EQ(diagnostics.formatAll(),
            "a:1:2: warning: first\n"
            "a:1:3: note: second\n"
            "b:4:5: error: third\n");
}

TEST(Diagnostics, AppendKeepsTheOrderAndTheErrors) {
  Diagnostics lens;
  lens.error({"lens.dat", 2, 1}, "surface 2: crosses the previous surface (surface 1)");
  Diagnostics scene;
  scene.warning({"scene.pbrt", 1, 1}, "unused parameter");
  EXPECT_FALSE(scene.hasErrors());
  scene.append(lens);
  EXPECT_TRUE(scene.hasErrors());
  EXPECT_EQ(scene.formatAll(),
            "scene.pbrt:1:1: warning: unused parameter\n"
            "lens.dat:2:1: error: surface 2: crosses the previous surface (surface 1)\n");
  scene.append(scene);  // a collector appended to itself doubles, and stays valid
  EXPECT_EQ(scene.all().size(), 4u);
}

}  // namespace
}  // namespace lenslab
