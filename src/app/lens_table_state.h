#pragma once
// The lens table's own UI state: which row is selected, which cell is being typed into.

#include <string>
#include <vector>

namespace lenslab::app {

// A validation problem as the table shows it: the row (0-based surface, -1 for the whole lens).
struct LensProblem {
  int surface = -1;
  std::string message;
};

struct LensTableState {
  int selectedRow = -1;
  // The cell being edited ("3/radius") and its text. ImGui keeps the text of the active field
  // itself; this copy is what is committed when the field loses focus or Enter is pressed.
  std::string editingCell;
  char editText[64] = {};
  double scaleTargetEflMm = 50.0;
  // Cells drawn last frame whose value did not fit even cut to its whole number (the table
  // scrolls sideways so that none is cut off; dump-ui reports it for the layout tests), and
  // those shown cut, with the cut mark (drawing/value_text.h).
  int cellsCutOff = 0;
  int cellsShortened = 0;
  // The asphere editor (dialogs/asphere_editor.cpp): the surface it edits (0-based; -1 closed),
  // and the term being typed into (0 the conic, else the power) with its text.
  int asphereEditorRow = -1;
  int asphereEditingTerm = -1;
  char asphereEditText[64] = {};
};

}  // namespace lenslab::app
