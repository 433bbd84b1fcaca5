// Issue 40's glass edits in the viewer's document and the glass map's arithmetic: a typed name
// found in the bundled catalogues (tests/support/bundled_glass.h) becomes one undoable edit whose
// n_d and V_d are the maker's listed ones; what cannot be a lens's glass is refused with the lens
// kept; the map's reversed V_d axis puts larger Abbe numbers left.

#include <gtest/gtest.h>

#include <cmath>

#include "app/analysis/glass_map.h"
#include "app/document/glass_choice.h"
#include "app/document/lens_document.h"
#include "app/plot/plot_layout.h"
#include "optics/glass/glass_catalog_loader.h"
#include "support/bundled_glass.h"

namespace lenslab::app {
namespace {

optics::Prescription glassEditSinglet() {
  optics::Prescription lens;
  lens.surfaces = {{40.0, 5.0, 1.6, 58.0, 20.0},
                   {0.0, 2.0, 1.0, std::nullopt, 15.0},
                   {-120.0, 45.0, 1.0, std::nullopt, 20.0}};
  return lens;
}

TEST(GlassChoice, FindsNamesWithoutCaseOrHyphensAndAMakerAsTheLastWord) {
  const GlassChoice bk7 = chooseGlass("  nbk7 ");
  ASSERT_TRUE(bk7.glass) << bk7.error;
  EXPECT_EQ(bk7.glass->name, "N-BK7");
  EXPECT_EQ(bk7.glass->maker, "SCHOTT");
  EXPECT_TRUE(bk7.note.empty());
  // SCHOTT lists N-BK7 at n_d 1.5168, V_d 64.17 (schott.csv's nd_cat, vd_cat).
  EXPECT_NEAR(*bk7.glass->nd, 1.5168, 1e-5);
  EXPECT_NEAR(*bk7.glass->vd, 64.17, 0.01);

  const GlassChoice f5 = chooseGlass("F5");
  ASSERT_TRUE(f5.glass);
  EXPECT_EQ(f5.glass->maker, "SCHOTT");
  EXPECT_EQ(f5.note, "F5 is in SCHOTT, CDGM, HIKARI; using SCHOTT's");
  const GlassChoice cdgm = chooseGlass("F5 cdgm");
  ASSERT_TRUE(cdgm.glass) << cdgm.error;
  EXPECT_EQ(cdgm.glass->maker, "CDGM");
  EXPECT_TRUE(cdgm.note.empty());
  EXPECT_EQ(chooseGlass("f5", "Hikari").glass->maker, "HIKARI");

  const GlassChoice unknown = chooseGlass("NBK8");
  EXPECT_FALSE(unknown.glass);
  EXPECT_NE(unknown.error.find("\"NBK8\""), std::string::npos) << unknown.error;
  EXPECT_NE(unknown.error.find("N-BK7"), std::string::npos) << unknown.error;
  EXPECT_FALSE(chooseGlass("   ").glass);
}

TEST(SetSurfaceGlass, IsOneUndoStepAndTypingAnIndexMakesAModelGlassAgain) {
  LensDocument document(glassEditSinglet());
  const GlassChoice choice = chooseGlass("N-SF6");
  ASSERT_TRUE(choice.glass);
  ASSERT_FALSE(document.apply(SetSurfaceGlass{0, choice.glass}));
  const optics::Surface& front = document.prescription().surfaces[0];
  EXPECT_EQ(front.glass, choice.glass);
  EXPECT_NEAR(front.indexD, 1.80518, 1e-5);  // SCHOTT's listed n_d
  EXPECT_NEAR(*front.abbeD, 25.36, 0.01);
  EXPECT_TRUE(document.modified());
  ASSERT_TRUE(document.undo());
  EXPECT_EQ(document.prescription().surfaces[0].glass, nullptr);
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[0].indexD, 1.6);
  ASSERT_TRUE(document.redo());
  ASSERT_FALSE(document.apply(SetSurfaceField{0, SurfaceField::IndexD, 1.7}));
  EXPECT_EQ(document.prescription().surfaces[0].glass, nullptr);
  EXPECT_NEAR(*document.prescription().surfaces[0].abbeD, 25.36, 0.01);
}

TEST(SetSurfaceGlass, RefusesTheStopNoGlassAnInfraredOneAndAMissingSurface) {
  LensDocument document(glassEditSinglet());
  const auto generation = document.generation();
  const GlassChoice bk7 = chooseGlass("N-BK7");
  const auto refusal = [&](const EditCommand& command) {
    const auto why = document.apply(command);
    return why.value_or("(applied)");
  };
  EXPECT_EQ(refusal(SetSurfaceGlass{1, bk7.glass}),
            "surface 2 is the aperture stop: air follows it, not glass");
  EXPECT_EQ(refusal(SetSurfaceGlass{0, nullptr}), "surface 1: no glass given");
  EXPECT_EQ(refusal(SetSurfaceGlass{3, bk7.glass}),
            "surface 4 does not exist (the lens has 3 surfaces)");
  // Germanium's formula covers the infrared only: no n_d to trace the visible with.
  const GlassChoice germanium = chooseGlass("Ge");
  ASSERT_TRUE(germanium.glass) << germanium.error;
  ASSERT_FALSE(germanium.glass->nd);
  EXPECT_NE(refusal(SetSurfaceGlass{0, germanium.glass}).find("has no index in the visible"),
            std::string::npos);
  EXPECT_EQ(document.generation(), generation);
  EXPECT_FALSE(document.canUndo());
}

TEST(GlassMap, ReversedAxisPutsLargerAbbeNumbersLeft) {
  const GlassMap map(optics::defaultGlassCatalog().catalog);
  const PlotSpec spec = map.plot({});
  const PlotFrame frame = layoutPlot(spec, {0, 0, 800, 500}, 13.0f,
                                     [](const std::string& text) { return 7.0f * text.size(); });
  EXPECT_TRUE(frame.xReversed);
  EXPECT_FLOAT_EQ(frame.toScreenX(kGlassMapVdLeft), frame.area.x);
  EXPECT_FLOAT_EQ(frame.toScreenX(kGlassMapVdRight), frame.area.right());
  EXPECT_LT(frame.toScreenX(90.0), frame.toScreenX(30.0));
  EXPECT_NEAR(frame.fromScreenX(frame.toScreenX(64.17)), 64.17, 1e-4);
  // Every glass with an n_d is on it but diamond, above the axes; hiding a maker takes its own.
  EXPECT_EQ(map.outside(), std::vector<std::string>{"diamond"});
  EXPECT_EQ(map.shownCount({}), map.points().size());
  std::size_t ohara = 0;
  for (const auto& point : map.points()) ohara += point.glass->maker == "OHARA";
  EXPECT_EQ(ohara, 410u);
  EXPECT_EQ(map.shownCount({"OHARA"}), map.points().size() - ohara);
  // The nearest shown point to N-BK7's own place is a glass at that place (several makers have
  // a BK7); hidden makers are passed over.
  const auto toScreen = [&](double vd, double nd) {
    return std::pair{frame.toScreenX(vd), frame.toScreenY(nd)};
  };
  const auto [x, y] = toScreen(64.167, 1.5168);
  const auto found = map.nearest(x, y, 3.0f, {}, toScreen);
  ASSERT_TRUE(found);
  EXPECT_NEAR(map.points()[*found].nd, 1.5168, 0.002);
  std::set<std::string> all(map.makers().begin(), map.makers().end());
  EXPECT_FALSE(map.nearest(x, y, 3.0f, all, toScreen));
}

}  // namespace
}  // namespace lenslab::app
