// The one policy for glass names no catalogue holds (import/glass_resolution.h), and the .zmx
// and .seq readers applying it alike.
#include "optics/import/glass_resolution.h"

#include <gtest/gtest.h>

#include <string>

#include "optics/glass/glass_catalog_loader.h"
#include "optics/import/codev_file.h"
#include "optics/import/zemax_file.h"

namespace lenslab::optics {
namespace {

const GlassCatalog& catalog() { return *defaultGlassCatalog().catalog; }

std::string successorOf(const std::string& name, const std::vector<std::string>& makers = {}) {
  const auto successor = documentedGlassSuccessor(catalog(), name, makers);
  return successor ? successor->glass->name + " " + successor->glass->maker : "none";
}

TEST(GlassResolution, OnlyTheDocumentedPairs) {
  EXPECT_EQ(successorOf("BK7"), "N-BK7 SCHOTT");  // SCHOTT's lead-free N- line
  EXPECT_EQ(successorOf("bk7"), "N-BK7 SCHOTT");
  EXPECT_EQ(successorOf("KZFS4"), "N-KZFS4 SCHOTT");
  EXPECT_EQ(successorOf("TIM2"), "S-TIM2 OHARA");  // OHARA's eco S- line
  EXPECT_EQ(successorOf("SILICA"), "fused_silica MISC");
  EXPECT_EQ(successorOf("L-TIM28_MOLD"), "L-TIM28 OHARA");
  // No successor: SCHOTT has no N-SK19, no maker an N- or S- of a made-up name, and a name that
  // is already the new one has none.
  EXPECT_EQ(successorOf("SK19"), "none");
  EXPECT_EQ(successorOf("NOSUCHGLASS"), "none");
  EXPECT_EQ(successorOf("N-NOSUCH"), "none");
  EXPECT_EQ(successorOf(""), "none");
}

TEST(GlassResolution, AMakersPairOnlyWhereTheFileAllowsThatMaker) {
  EXPECT_EQ(successorOf("BK7", {"OHARA"}), "none");
  EXPECT_EQ(successorOf("TIM2", {"SCHOTT"}), "none");
  EXPECT_EQ(successorOf("TIM2", {"SCHOTT", "OHARA"}), "S-TIM2 OHARA");
  EXPECT_EQ(successorOf("BK7", {"OHARA", "SCHOTT"}), "N-BK7 SCHOTT");
}

TEST(GlassResolution, TheWarningNamesBothGlassesAndTheSuccessorsNumbers) {
  const auto successor = documentedGlassSuccessor(catalog(), "BK7", {});
  ASSERT_TRUE(successor);
  const std::string warning = glassSubstitutionWarning("BK7", *successor);
  EXPECT_NE(warning.find("glass BK7 is in no catalogue lenslab has; substituting N-BK7 (SCHOTT, "
                         "n_d 1.516"),
            std::string::npos)
      << warning;
  EXPECT_NE(warning.find("Check the lens against its source"), std::string::npos) << warning;
}

// A singlet whose first surface's glass is `glass` (CODE V).
std::string seqSinglet(const std::string& glass) {
  return "RDM\nTIT 'singlet'\nEPD 10\nWL 587.56\nYAN 0 5\nSO 0 1e10\nS 0 0\nSTO\nS 50 5 " + glass +
         "\nS -50 45\nSI 0 0\nGO\n";
}

// The same singlet in OpticStudio's words.
std::string zmxSinglet(const std::string& glass, const std::string& gcat) {
  return "UNIT MM\nENPD 10\nGCAT " + gcat +
         "\nWAVM 1 0.58756 1\nSURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DISZ 0\nSURF 2\n  "
         "CURV 0.02\n  DISZ 5\n  GLAS " +
         glass + " 0 0 1.5 40\nSURF 3\n  CURV -0.02\n  DISZ 45\nSURF 4\n";
}

bool warnsAt(const Diagnostics& diagnostics, int line, const std::string& text) {
  for (const Diagnostic& d : diagnostics.all())
    if (d.severity == Severity::Warning && d.location.line == line &&
        d.message.find(text) != std::string::npos)
      return true;
  return false;
}

TEST(GlassResolution, ZmxAndSeqSubstituteTheSameWay) {
  // The same old names in both readers: the same successor, each a warning at the glass's line.
  const struct {
    const char* name;
    const char* successor;
  } olds[] = {{"BK7", "N-BK7"}, {"TIM2", "S-TIM2"}, {"SILICA", "fused_silica"}};
  for (const auto& [name, successor] : olds) {
    const LensFileResult seq = parseCodeVText(seqSinglet(name), "singlet.seq");
    ASSERT_TRUE(seq.ok()) << name << "\n" << seq.diagnostics.formatAll();
    const LensFileResult zmx = parseZemaxText(zmxSinglet(name, "SCHOTT OHARA MISC"), "s.zmx");
    ASSERT_TRUE(zmx.ok()) << name << "\n" << zmx.diagnostics.formatAll();
    const auto* seqGlass = seq.lens->prescription.surfaces[1].glass.get();
    const auto* zmxGlass = zmx.lens->prescription.surfaces[1].glass.get();
    ASSERT_TRUE(seqGlass && zmxGlass) << name;
    EXPECT_EQ(seqGlass->name, successor);
    EXPECT_EQ(zmxGlass->name, successor);
    const std::string said = std::string("glass ") + name + " is in no catalogue lenslab has";
    EXPECT_TRUE(warnsAt(seq.diagnostics, 9, said)) << seq.diagnostics.formatAll();
    EXPECT_TRUE(warnsAt(zmx.diagnostics, 13, said)) << zmx.diagnostics.formatAll();
  }
  // A maker's name for a glass another maker replaced: no substitution in either.
  EXPECT_FALSE(parseCodeVText(seqSinglet("TIM2_SCHOTT"), "singlet.seq").ok());
  EXPECT_FALSE(parseZemaxText(zmxSinglet("NOSUCHGLASS", "SCHOTT"), "s.zmx").ok());
}

}  // namespace
}  // namespace lenslab::optics
