#pragma once
// Edit > Paste lens table... (Ctrl+Shift+V): a patent's numerical example pasted as text
// (optics/import/patent_table.h). The window shows what the reader understood (the rows, the
// aspheric data, the header values, each column's meaning with a combo to change it, and every
// problem at its line), re-reading the text whenever it or a column's meaning changes; Open
// opens the lens as File > Open does. It only records what the user asks; the viewer opens the
// lens (Viewer::openPastedTable).

#include <optional>
#include <string>
#include <vector>

#include "optics/import/patent_table.h"

namespace lenslab::app {

struct PasteTableState {
  bool open = false;
  std::string text;
  // The name the text's errors give (the file a script read it from, or "pasted table").
  std::string sourceName = "pasted table";
  // A meaning per column chosen in the combos (nullopt: the heading's).
  std::vector<std::optional<optics::PatentColumn>> overrides;
  // The text as read, kept until the text or a meaning changes.
  std::optional<optics::PatentTableResult> read;
  bool openRequested = false;  // the Open button; the viewer consumes it
};

// Shows the window with `text` (the clipboard's, or a script's file), read afresh.
void showPasteTable(PasteTableState& state, std::string text, std::string sourceName);
// Reads the text again with the overrides, when it has not been read since they changed.
const optics::PatentTableResult& pastedTableRead(PasteTableState& state);

struct ViewerState;
void drawPasteTableDialog(ViewerState& state);

}  // namespace lenslab::app
