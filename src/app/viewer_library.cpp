// The library browser's script commands (automation/script.h: library ...): the same state the
// Library panel's widgets change (panels/library_panel.cpp), and opening a lens as a double-click
// on its card does.

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "app/automation/script_words.h"
#include "app/library/library_browser.h"
#include "app/panels/panels.h"
#include "app/viewer_session.h"

namespace lenslab::app {

namespace {

std::string joinedFrom(const std::vector<std::string>& words, std::size_t first) {
  std::string text;
  for (std::size_t i = first; i < words.size(); ++i) text += (i > first ? " " : "") + words[i];
  return text;
}

}  // namespace

std::optional<std::string> Viewer::library(const std::vector<std::string>& a) {
  LibraryBrowserState& library = state_.library;
  if (a[0] == "open") {
    const std::filesystem::path folder =
        a.size() > 1 ? std::filesystem::path(a[1]) : bundledLibraryFolder();
    if (folder.empty()) return std::string("there is no bundled lenses/ folder");
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
      return "there is no folder " + folder.string();
    showLibraryBrowser(state_, std::filesystem::absolute(folder, error));
    return std::nullopt;
  }
  if (a[0] == "reload") {
    if (!library.catalogue) return std::string("the library browser is not open");
    showLibraryBrowser(state_, library.folder, /*reload=*/true);
    return std::nullopt;
  }
  if (a[0] == "search") {
    const std::string text = joinedFrom(a, 1);
    if (text.size() >= sizeof library.searchText) return "the search '" + text + "' is too long";
    std::strcpy(library.searchText, text.c_str());
    library.filter.search = text;
    return std::nullopt;
  }
  // filter ...: the parser checked the words.
  const std::string& what = a[1];
  const bool any = a.size() == 3 && a[2] == "any";
  if (what == "clear") {
    library.searchText[0] = '\0';
    library.eflRange = library.yearRange = false;
    library.filter = {};
  } else if (what == "type") {
    library.filter.type = any ? std::string() : joinedFrom(a, 2);
  } else if (what == "aspheric") {
    library.filter.aspheric = *asphericChoiceFromWord(a[2]);
  } else if (what == "efl") {
    library.eflRange = !any;
    if (!any) {
      library.eflFromMm = *script_words::parseNumber(a[2]);
      library.eflToMm = *script_words::parseNumber(a[3]);
    }
  } else if (what == "year") {
    library.yearRange = !any;
    if (!any) {
      library.yearFrom = static_cast<int>(*script_words::parseInteger(a[2]));
      library.yearTo = static_cast<int>(*script_words::parseInteger(a[3]));
    }
  }
  return std::nullopt;
}

ScriptHost::LibraryProgress Viewer::libraryProgress() const {
  const LibraryBrowserState& library = state_.library;
  if (!library.catalogue) return {false, false};
  return {library.catalogue->snapshot()->listed, library.thumbnailsShownMs.has_value()};
}

ScriptHost::Issued Viewer::openLibraryLens(const std::string& name) {
  const auto entry = findShownLibraryEntry(state_.library, name);
  if (!entry) {
    std::string shown;
    const ShownLibrary listed = shownLibraryEntries(state_.library);
    for (const std::size_t i : listed.indices)
      shown += (shown.empty() ? "" : ", ") + listed.snapshot->entries[i].fileName;
    return {"the library shows no lens named '" + name +
            "' (it shows: " + (shown.empty() ? std::string("none") : shown) + ")"};
  }
  if (!entry->usable()) return {entry->fileName + " cannot be opened: " + entry->error};
  state_.library.selectedPath = entry->path.string();
  // As the card's double-click: File > Open's path (focused for the scene, one undo step).
  Issued issued = openLensFile(entry->path.string());
  if (!issued.error) rememberRecentFile(entry->path.string());
  return issued;
}

}  // namespace lenslab::app
