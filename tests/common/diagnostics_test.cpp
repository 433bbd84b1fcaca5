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

namespace lenslab {
namespace {

// Hostile input (issue 24): a 10-million-digit number quoted in an error becomes its first 40
// characters and its length, not 10 MB of error text; short tokens, paths and the apostrophes
// of English words are left alone.
TEST(Diagnostics, LongQuotedTokensAreShortenedWithTheirLength) {
  const std::string digits = "1" + std::string(10'000'000, '5');
  Diagnostics collected;
  collected.error({"scene.pbrt", 7, 32}, "malformed number '" + digits + "' (expected a number)");
  const std::string& message = collected.all().front().message;
  EXPECT_EQ(message, "malformed number '" + digits.substr(0, 40) +
                         "...' (10000001 characters) (expected a number)");
  // An unclosed quote (the token runs to the end) is shortened too.
  EXPECT_EQ(abbreviateMessage("unknown directive '" + std::string(100, 'x')),
            "unknown directive '" + std::string(40, 'x') + "... (100 characters)");
  // Left alone: a token of 64 characters, possessives, a long message without quotes.
  const std::string token64(64, 'a');
  const std::string plain = "the lens's rim at surface 3 is wider than the file's 'inf' radius '" +
                            token64 + "' by far, don't you think";
  EXPECT_EQ(abbreviateMessage(plain), plain);
  // A path is kept whole up to 1024 characters; past that it is shortened too.
  const std::string longPath = "/" + std::string(200, 'd') + "/scene.pbrt";
  const std::string missing = "cannot open '" + longPath + "'";
  EXPECT_EQ(abbreviateMessage(missing), missing);
  const std::string hugePath = "/" + std::string(2000, 'd');
  EXPECT_EQ(abbreviateMessage("cannot open '" + hugePath + "'"),
            "cannot open '" + hugePath.substr(0, 40) + "...' (2001 characters)");
  // Past 4096 characters a message is cut, with its length.
  const std::string words(5000, 'w');
  const std::string cut = abbreviateMessage(words);
  EXPECT_EQ(cut, words.substr(0, 4096) + "... (message cut: 5000 characters)");
}

// A scene's names are quoted with double quotes ("shape \"sphere\""): a 10 MB name is shortened
// like a 10 MB number.
TEST(Diagnostics, LongDoubleQuotedTokensAreShortenedToo) {
  const std::string name(10'000'000, 's');
  EXPECT_EQ(
      abbreviateMessage("unknown shape \"" + name + "\"; it is left out"),
      "unknown shape \"" + name.substr(0, 40) + "...\" (10000000 characters); it is left out");
  // A single quote inside a double-quoted token does not end it, nor the other way round.
  const std::string mixed = "parameter \"it's fine\" and 'say \"x\"'";
  EXPECT_EQ(abbreviateMessage(mixed + std::string(100, ' ')), mixed + std::string(100, ' '));
}

// A file with a problem on every one of a million lines: the first kMaxDiagnostics are listed,
// then one note; every error still counts.
TEST(Diagnostics, KeepsTheFirstProblemsAndANoteThatMoreFollow) {
  Diagnostics collected;
  for (int line = 1; line <= 1000; ++line) collected.error({"lens.dat", line, 1}, "bad row");
  ASSERT_EQ(collected.all().size(), kMaxDiagnostics + 1);
  EXPECT_EQ(collected.all()[kMaxDiagnostics - 1].location.line, static_cast<int>(kMaxDiagnostics));
  EXPECT_EQ(collected.all().back().severity, Severity::Note);
  EXPECT_NE(collected.all().back().message.find("only the first 50 are listed"), std::string::npos);
  EXPECT_TRUE(collected.hasErrors());
  EXPECT_LT(collected.formatAll().size(), 4096u);
}

}  // namespace
}  // namespace lenslab
