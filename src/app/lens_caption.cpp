#include "app/lens_caption.h"

#include <filesystem>
#include <regex>
#include <string_view>
#include <vector>

#include "app/analysis/lens_figures.h"
#include "app/viewer_state.h"
#include "optics/lens_file_formats.h"
#include "optics/lens_loader.h"

namespace lenslab::app {

namespace {

std::string trimmed(std::string text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '#'; };
  while (!text.empty() && blank(text.front())) text.erase(text.begin());
  while (!text.empty() && (blank(text.back()) || text.back() == '.')) text.pop_back();
  return text;
}

}  // namespace

std::string withoutNominalFNumber(const std::string& name) {
  // " f/2" or ", f/4" (the comma before it goes too: "50 mm, f/4, in flint" keeps one comma).
  static const std::regex kFNumber(R"((,\s*|\s+|^)[fF]/\s*[0-9]+(\.[0-9]+)?)");
  return trimmed(std::regex_replace(name, kFNumber, ""));
}

LensDetails lensDetails(const ViewerState& state) {
  // Read from the file when the document has none (a scene's lens is opened without them).
  const LensDetails& details = state.lens.document().details();
  const std::string& path = state.lens.document().path();
  if (details.empty() && !path.empty()) return detailsOf(optics::loadLens(path).file);
  return details;
}

std::string lensName(const ViewerState& state) {
  return lensNameOf(lensDetails(state), state.lens.document().path());
}

std::string lensNameOf(const LensDetails& details, const std::string& path) {
  if (std::string name = withoutNominalFNumber(trimmed(details.title)); !name.empty()) return name;
  // A pbrt .dat has no title: its first header comment names the lens. The notes of a format
  // with a title (a .lens, a .zmx's NOTE: often a vendor's disclaimer) are not a name.
  const optics::LensFileFormat* format = optics::lensFileFormatOf(path);
  if (!format || std::string_view(format->extension) == ".dat") {
    for (const std::string& comment : details.notes) {
      if (std::string name = withoutNominalFNumber(trimmed(comment)); !name.empty()) return name;
    }
  }
  if (!path.empty()) return std::filesystem::path(path).stem().string();
  return "Untitled lens";
}

std::string lensSource(const ViewerState& state) { return lensDetails(state).source; }

std::string lensFNumberText(const ViewerState& state) {
  if (!state.lensSystem) return "";
  if (state.lensSystem->firstOrder().afocal) return "afocal";
  return fNumberText(*state.lensSystem);
}

std::string lensTitle(const ViewerState& state) {
  const std::string fNumber = lensFNumberText(state);
  return lensName(state) + (fNumber.empty() ? "" : " · " + fNumber);
}

}  // namespace lenslab::app
