#pragma once
// The lens table's own UI state: which row is selected, which cell is being typed into.

#include <string>
#include <vector>

#include "optics/glass/catalog_glass.h"

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
  // The glass cell being typed into (panels/glass_cell.cpp): its row (-1 none) and text, the
  // catalogue's completions of that text shown under it, the one Up/Down or the mouse
  // highlights (-1: the text as typed) and the one clicked (applied as the field lets go).
  int glassEditingRow = -1;
  char glassText[64] = {};
  std::vector<const optics::CatalogGlass*> glassCompletions;
  int glassHighlight = -1;
  int glassPicked = -1;
  // The last glass typed: why it was refused, or which maker's a name in several catalogues is;
  // shown under the table until the next glass is typed.
  std::string glassMessage;
  bool glassMessageIsError = false;
  int asphereEditingTerm = -1;
  char asphereEditText[64] = {};
};

}  // namespace lenslab::app
