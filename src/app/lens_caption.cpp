#include "app/lens_caption.h"

#include <filesystem>
#include <regex>
#include <vector>

#include "app/analysis/lens_figures.h"
#include "app/viewer_state.h"
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

std::string lensName(const ViewerState& state) {
  // Read from the file when the document has no comments (a scene's lens is opened without).
  std::vector<std::string> comments = state.lens.document().headerComments();
  const std::string& path = state.lens.document().path();
  if (comments.empty() && !path.empty()) comments = optics::loadLens(path).file.headerComments;
  for (const std::string& comment : comments) {
    if (std::string name = withoutNominalFNumber(trimmed(comment)); !name.empty()) return name;
  }
  if (!path.empty()) return std::filesystem::path(path).stem().string();
  return "Untitled lens";
}

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
