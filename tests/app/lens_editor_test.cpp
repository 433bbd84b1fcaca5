#include "app/document/lens_editor.h"

#include <gtest/gtest.h>

namespace lenslab::app {
namespace {

optics::Prescription singlet(double frontRadiusMm = 50.0) {
  optics::Prescription lens;
  lens.surfaces = {{frontRadiusMm, 5.0, 1.5, 60.0, 20.0},
                   {0.0, 3.0, 1.0, std::nullopt, 12.0},
                   {-50.0, 45.0, 1.0, std::nullopt, 20.0}};
  return lens;
}

// An editor opened on `lens` the way the viewer opens its first lens: nothing to undo.
LensEditor openedOn(const optics::Prescription& lens) {
  LensEditor editor;
  editor.issue(
      ReplaceLens{lens, "singlet.dat",
                  LensDetails{{"# a comment"}, "A singlet", "Nowhere, 1900", 50.0, {}, {}, {}},
                  /*startsSession=*/true});
  editor.applyQueued();
  return editor;
}

TEST(LensEditor, CommandsWaitForApplyQueuedAndApplyInOrder) {
  LensEditor editor = openedOn(singlet());
  const auto generation = editor.generation();
  const CommandTicket first = editor.issue(SetFilmDistance{40.0});
  const CommandTicket second = editor.issue(SetFilmDistance{41.0});
  // Issued, not applied: the document and its generation are as they were.
  EXPECT_TRUE(editor.hasQueued());
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces.back().thicknessMm, 45.0);
  EXPECT_EQ(editor.generation(), generation);
  EXPECT_FALSE(editor.outcome(first).has_value());

  const std::vector<AppliedCommand> applied = editor.applyQueued();
  ASSERT_EQ(applied.size(), 2u);
  EXPECT_EQ(applied[0].issued.ticket, first);
  EXPECT_EQ(applied[1].issued.ticket, second);
  EXPECT_FALSE(editor.hasQueued());
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces.back().thicknessMm, 41.0);  // the later one
  EXPECT_EQ(editor.generation(), generation + 2);  // one generation per applied command
  EXPECT_EQ(editor.outcome(first), "");
  EXPECT_EQ(editor.outcome(second), "");
}

TEST(LensEditor, ARefusedCommandSaysWhyAndChangesNothing) {
  LensEditor editor = openedOn(singlet());
  const auto generation = editor.generation();
  const CommandTicket ticket = editor.issue(DeleteSurface{7}, {}, CommandSource::Script);
  const std::vector<AppliedCommand> applied = editor.applyQueued();
  ASSERT_EQ(applied.size(), 1u);
  EXPECT_EQ(applied[0].issued.source, CommandSource::Script);
  ASSERT_TRUE(applied[0].refusal.has_value());
  EXPECT_EQ(editor.outcome(ticket), "surface 8 does not exist (the lens has 3 surfaces)");
  EXPECT_EQ(editor.generation(), generation);
  EXPECT_EQ(editor.prescription().surfaces.size(), 3u);
}

TEST(LensEditor, UndoAndRedoAreCommandsToo) {
  LensEditor editor = openedOn(singlet());
  EXPECT_FALSE(editor.canUndo());  // the session's first lens is no undo step
  const CommandTicket nothing = editor.issue(Undo{});
  editor.applyQueued();
  EXPECT_EQ(editor.outcome(nothing), "nothing to undo");

  editor.issue(SetSurfaceField{0, SurfaceField::RadiusMm, 42.0});
  editor.issue(Undo{});
  editor.applyQueued();
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces[0].radiusMm, 50.0);
  editor.issue(Redo{});
  editor.applyQueued();
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces[0].radiusMm, 42.0);
}

TEST(LensEditor, ADragUndoesInOneStepAndItsReleaseEndsTheStep) {
  LensEditor editor = openedOn(singlet());
  // Two frames of one drag, then the release (queued behind the drag's last edit), then a
  // second drag with the same key: two undo steps, not one.
  editor.issue(SetFilmDistance{46.0}, "drag-film");
  editor.applyQueued();
  editor.issue(SetFilmDistance{47.0}, "drag-film");
  editor.endMerge();
  editor.applyQueued();
  editor.issue(SetFilmDistance{50.0}, "drag-film");
  editor.applyQueued();
  editor.issue(Undo{});
  editor.applyQueued();
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces.back().thicknessMm, 47.0);
  editor.issue(Undo{});
  editor.applyQueued();
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces.back().thicknessMm, 45.0);
  EXPECT_FALSE(editor.canUndo());
}

TEST(LensEditor, ALensThatStartsTheSessionIsAnUndoStepOnceTheLensWasEdited) {
  LensEditor editor = openedOn(singlet());
  EXPECT_EQ(editor.path(), "singlet.dat");
  EXPECT_EQ(editor.document().details().notes, std::vector<std::string>{"# a comment"});
  EXPECT_FALSE(editor.modified());
  // The scene's lens arrives after the user edited: an ordinary replacement, undone whole,
  // what the file says of the lens (notes, title, source, ...) and path included.
  editor.issue(SetSurfaceField{0, SurfaceField::RadiusMm, 60.0});
  editor.issue(ReplaceLens{singlet(70.0), "scene.dat", {}, /*startsSession=*/true});
  editor.applyQueued();
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces[0].radiusMm, 70.0);
  EXPECT_TRUE(editor.document().details().empty());
  editor.issue(Undo{});
  editor.applyQueued();
  EXPECT_DOUBLE_EQ(editor.prescription().surfaces[0].radiusMm, 60.0);
  EXPECT_EQ(editor.path(), "singlet.dat");
  EXPECT_EQ(editor.document().details().notes, std::vector<std::string>{"# a comment"});
  EXPECT_EQ(editor.document().details().title, "A singlet");
  EXPECT_EQ(editor.document().details().source, "Nowhere, 1900");
  EXPECT_EQ(editor.document().details().publishedEflMm, 50.0);
}

}  // namespace
}  // namespace lenslab::app
