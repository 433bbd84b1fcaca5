#include "app/document/lens_document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "optics/lens_system.h"

namespace lenslab::app {
namespace {

optics::Prescription triplet() {
  optics::Prescription lens;
  lens.surfaces = {{40.0, 5.0, 1.6, 58.0, 30.0},
                   {-200.0, 6.0, 1.0, std::nullopt, 30.0},
                   {0.0, 4.0, 1.0, std::nullopt, 20.0},
                   {-35.0, 2.0, 1.62, 36.0, 24.0},
                   {35.0, 45.0, 1.0, std::nullopt, 24.0}};
  return lens;
}

TEST(LensDocument, EditUndoRedo) {
  LensDocument document(triplet());
  const auto start = document.generation();
  ASSERT_FALSE(document.apply(SetSurfaceField{0, SurfaceField::RadiusMm, 42.0}));
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[0].radiusMm, 42.0);
  EXPECT_GT(document.generation(), start);
  ASSERT_TRUE(document.undo());
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[0].radiusMm, 40.0);
  ASSERT_TRUE(document.redo());
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[0].radiusMm, 42.0);
  EXPECT_FALSE(document.redo());
}

// A catalogue glass is the medium after its row: flipping carries it with the medium, and typing
// an n_d or V_d makes it a model glass of the numbers (the name would contradict them).
TEST(LensDocument, ACatalogueGlassMovesWithItsMediumAndATypedIndexReplacesIt) {
  auto glass = std::make_shared<optics::CatalogGlass>();
  glass->name = "N-BK7";
  glass->maker = "SCHOTT";
  glass->nd = 1.5168;
  glass->vd = 64.17;
  optics::Prescription lens = triplet();
  optics::setCatalogGlass(lens.surfaces[3], glass);  // the rear element's glass
  const optics::Prescription flippedLens = flipped(lens);
  // Row 3's medium lies between rows 3 and 4; flipped, between rows 0 and 1: row 0's medium.
  EXPECT_EQ(flippedLens.surfaces[0].glass, glass);
  for (std::size_t i = 1; i < flippedLens.surfaces.size(); ++i)
    EXPECT_FALSE(flippedLens.surfaces[i].glass) << i;
  EXPECT_EQ(flipped(flippedLens).surfaces[3].glass, glass);

  LensDocument document(lens);
  ASSERT_FALSE(document.apply(SetSurfaceField{3, SurfaceField::IndexD, 1.52}));
  EXPECT_FALSE(document.prescription().surfaces[3].glass);
  EXPECT_EQ(document.prescription().surfaces[3].indexD, 1.52);
  EXPECT_EQ(document.prescription().surfaces[3].abbeD, 64.17);  // the glass's V_d, kept
  EXPECT_TRUE(optics::validate(document.prescription()).empty());
  ASSERT_TRUE(document.undo());
  EXPECT_EQ(document.prescription().surfaces[3].glass, glass);
}

TEST(LensDocument, DragStepsWithOneMergeKeyAreOneUndoStep) {
  LensDocument document(triplet());
  for (double film : {44.0, 43.0, 42.0}) document.apply(SetFilmDistance{film}, "film-drag");
  document.endMerge();
  EXPECT_DOUBLE_EQ(document.prescription().surfaces.back().thicknessMm, 42.0);
  ASSERT_TRUE(document.undo());
  EXPECT_DOUBLE_EQ(document.prescription().surfaces.back().thicknessMm, 45.0);
  EXPECT_FALSE(document.canUndo());
}

TEST(LensDocument, RefusesMissingSurfacesWithoutChangingAnything) {
  LensDocument document(triplet());
  const auto generation = document.generation();
  const auto refusal = document.apply(SetSurfaceField{9, SurfaceField::RadiusMm, 1.0});
  ASSERT_TRUE(refusal.has_value());
  EXPECT_NE(refusal->find("surface 10"), std::string::npos);
  EXPECT_EQ(document.generation(), generation);
  EXPECT_FALSE(document.canUndo());
}

TEST(LensDocument, InvalidValuesAreHeldForValidationToFlag) {
  LensDocument document(triplet());
  EXPECT_FALSE(document.apply(SetSurfaceField{1, SurfaceField::ThicknessMm, -3.0}));
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[1].thicknessMm, -3.0);
}

TEST(LensDocument, InsertDeleteMove) {
  LensDocument document(triplet());
  document.apply(InsertSurface{1, {100.0, 1.0, 1.5, std::nullopt, 10.0}});
  EXPECT_EQ(document.prescription().surfaces.size(), 6u);
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[1].radiusMm, 100.0);
  document.apply(MoveSurface{1, 4});
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[4].radiusMm, 100.0);
  document.apply(DeleteSurface{4});
  EXPECT_EQ(document.prescription().surfaces.size(), 5u);
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[4].radiusMm, 35.0);
}

TEST(LensDocument, AbbeNumberCanBeCleared) {
  LensDocument document(triplet());
  document.apply(SetSurfaceField{0, SurfaceField::AbbeD, std::nan("")});
  EXPECT_FALSE(document.prescription().surfaces[0].abbeD.has_value());
}

TEST(Flip, ReversesSurfacesNegatesRadiiAndMovesMedia) {
  const optics::Prescription lens = triplet();
  const optics::Prescription flippedLens = flipped(lens);
  ASSERT_EQ(flippedLens.surfaces.size(), 5u);
  // New first surface is old last, radius negated, followed by the glass that preceded it.
  EXPECT_DOUBLE_EQ(flippedLens.surfaces[0].radiusMm, -35.0);
  EXPECT_DOUBLE_EQ(flippedLens.surfaces[0].indexD, 1.62);
  EXPECT_DOUBLE_EQ(flippedLens.surfaces[0].thicknessMm, 2.0);
  EXPECT_TRUE(flippedLens.surfaces[2].isStop());
  // The new last surface (old first) faces the film through air at the old film distance.
  EXPECT_DOUBLE_EQ(flippedLens.surfaces[4].radiusMm, -40.0);
  EXPECT_DOUBLE_EQ(flippedLens.surfaces[4].indexD, 1.0);
  EXPECT_DOUBLE_EQ(flippedLens.surfaces[4].thicknessMm, 45.0);
  // Flipping twice restores the glass layout (film distance aside, which is kept).
  const optics::Prescription twice = flipped(flippedLens);
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    EXPECT_DOUBLE_EQ(twice.surfaces[i].radiusMm, lens.surfaces[i].radiusMm);
    EXPECT_DOUBLE_EQ(twice.surfaces[i].indexD, lens.surfaces[i].indexD);
    EXPECT_DOUBLE_EQ(twice.surfaces[i].thicknessMm, lens.surfaces[i].thicknessMm);
  }
}

TEST(Flip, KeepsTheStopAndFlatSurfacesUnsigned) {
  optics::Prescription lens = triplet();
  lens.surfaces[3].radiusMm = optics::kFlatRadius;
  const optics::Prescription flippedLens = flipped(lens);
  // Old surfaces 2 (the stop) and 3 (flat) become 2 and 1.
  EXPECT_EQ(flippedLens.surfaces[2].radiusMm, 0.0);
  EXPECT_FALSE(std::signbit(flippedLens.surfaces[2].radiusMm));      // not -0, shown as "-0"
  EXPECT_EQ(flippedLens.surfaces[1].radiusMm, optics::kFlatRadius);  // not -inf
}

TEST(Scale, ScalesEveryLength) {
  const optics::Prescription doubled = scaled(triplet(), 2.0);
  EXPECT_DOUBLE_EQ(doubled.surfaces[0].radiusMm, 80.0);
  EXPECT_DOUBLE_EQ(doubled.surfaces[4].thicknessMm, 90.0);
  EXPECT_DOUBLE_EQ(doubled.surfaces[2].apertureDiameterMm, 40.0);
  EXPECT_DOUBLE_EQ(doubled.surfaces[0].indexD, 1.6);
}

TEST(LensDocument, IsModifiedUntilSavedOrUndoneBackToTheSavedLens) {
  LensDocument document(triplet(), "triplet.dat");
  EXPECT_FALSE(document.modified());
  ASSERT_FALSE(document.apply(ScaleLens{1.5}));
  EXPECT_TRUE(document.modified());
  ASSERT_TRUE(document.undo());
  EXPECT_FALSE(document.modified());
  ASSERT_FALSE(document.apply(SetFilmDistance{50.0}));
  document.markSaved("elsewhere.dat");
  EXPECT_FALSE(document.modified());
  EXPECT_EQ(document.path(), "elsewhere.dat");
  ASSERT_TRUE(document.undo());  // back to before the save: differs from the saved lens
  EXPECT_TRUE(document.modified());
  // Opening a lens gives an unmodified document.
  ASSERT_FALSE(document.apply(ReplaceLens{triplet(), "other.dat"}));
  EXPECT_FALSE(document.modified());
}

// Opening a lens is one undo step: undoing it brings back the lens before, as that lens's own
// file had it (unmodified), not compared with the file opened after it; redo opens the second
// again, unmodified too. An edit of the first still shows as modified after the round trip.
TEST(LensDocument, UndoingAnOpenComparesTheEarlierLensWithItsOwnFile) {
  LensDocument document(triplet(), "triplet.dat");
  optics::Prescription other = triplet();
  other.surfaces[0].radiusMm = 55.0;
  ASSERT_FALSE(document.apply(ReplaceLens{other, "other.dat"}));
  EXPECT_FALSE(document.modified());
  ASSERT_TRUE(document.undo());
  EXPECT_EQ(document.path(), "triplet.dat");
  EXPECT_FALSE(document.modified());
  ASSERT_TRUE(document.redo());
  EXPECT_EQ(document.path(), "other.dat");
  EXPECT_FALSE(document.modified());
  ASSERT_TRUE(document.undo());
  ASSERT_FALSE(document.apply(SetFilmDistance{50.0}));
  ASSERT_FALSE(document.apply(ReplaceLens{other, "other.dat"}));
  ASSERT_TRUE(document.undo());
  EXPECT_TRUE(document.modified());  // the triplet with its film moved
  ASSERT_TRUE(document.undo());
  EXPECT_FALSE(document.modified());
}

// "Save as" renames the lens's earlier steps too: undoing an edit made before it keeps the new
// name and compares with what that file now holds. The steps of a lens opened before are left
// with their own file.
TEST(LensDocument, SavingAsRenamesTheStepsOfThatLensOnly) {
  LensDocument document(triplet(), "first.dat");
  optics::Prescription other = triplet();
  other.surfaces[0].radiusMm = 55.0;
  ASSERT_FALSE(document.apply(ReplaceLens{other, "other.dat"}));
  ASSERT_FALSE(document.apply(SetFilmDistance{50.0}));
  ASSERT_FALSE(document.apply(SetFilmDistance{60.0}));
  document.markSaved("renamed.dat");
  ASSERT_TRUE(document.undo());
  EXPECT_EQ(document.path(), "renamed.dat");
  EXPECT_TRUE(document.modified());  // film at 50, the file has 60
  ASSERT_TRUE(document.undo());
  ASSERT_TRUE(document.undo());  // before opening other.dat
  EXPECT_EQ(document.path(), "first.dat");
  EXPECT_FALSE(document.modified());
}

}  // namespace
}  // namespace lenslab::app
