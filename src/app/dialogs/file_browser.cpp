#include "app/dialogs/file_browser.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <system_error>
#include <utility>

#include "app/platform/ui_scale.h"

namespace lenslab::app {

namespace {

void copyToBuffer(char* buffer, std::size_t size, const std::string& text) {
  std::strncpy(buffer, text.c_str(), size - 1);
  buffer[size - 1] = '\0';
}

}  // namespace

void FileBrowser::show(std::string purpose, Mode mode, std::vector<std::string> extensions,
                       const std::filesystem::path& startDirectory, std::string suggestedName) {
  visible_ = true;
  purpose_ = std::move(purpose);
  mode_ = mode;
  extensions_ = std::move(extensions);
  std::error_code error;
  directory_ = std::filesystem::is_directory(startDirectory, error)
                   ? std::filesystem::absolute(startDirectory, error)
                   : std::filesystem::current_path(error);
  copyToBuffer(nameBuffer_, sizeof nameBuffer_, suggestedName);
  option_.reset();
  readDirectory();
}

void FileBrowser::addOption(std::string label, bool* value, std::string tooltip) {
  option_ = Option{std::move(label), std::move(tooltip), value};
}

bool FileBrowser::matchesFilter(const std::filesystem::path& path) const {
  if (extensions_.empty()) return true;
  // In any case: "LENS2.ZMX" from a Windows disk is a .zmx.
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return std::find(extensions_.begin(), extensions_.end(), extension) != extensions_.end();
}

void FileBrowser::readDirectory() {
  entries_.clear();
  listingError_.clear();
  copyToBuffer(directoryBuffer_, sizeof directoryBuffer_, directory_.string());
  std::error_code error;
  std::filesystem::directory_iterator it(directory_, error);
  if (error) {
    listingError_ = "cannot list " + directory_.string() + ": " + error.message();
    return;
  }
  for (const auto& item : it) {
    const std::string name = item.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code typeError;
    const bool isDirectory = item.is_directory(typeError);
    if (!isDirectory && !matchesFilter(item.path())) continue;
    entries_.push_back({name, isDirectory});
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    if (a.isDirectory != b.isDirectory) return a.isDirectory;
    return a.name < b.name;
  });
}

void FileBrowser::submit(const std::string& name) {
  copyToBuffer(nameBuffer_, sizeof nameBuffer_, name);
  submitRequested_ = true;
}

std::optional<std::filesystem::path> FileBrowser::draw() {
  if (!visible_) return std::nullopt;
  std::optional<std::filesystem::path> chosen;
  ImGui::SetNextWindowSize(ImVec2(px(560), px(420)), ImGuiCond_Appearing);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  const std::string title = purpose_ + "###file-browser";
  if (ImGui::Begin(title.c_str(), &visible_, ImGuiWindowFlags_NoCollapse)) {
    const ImVec2 position = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    rect_ = {position.x, position.y, size.x, size.y};
    if (ImGui::Button("Up") && directory_.has_parent_path()) {
      directory_ = directory_.parent_path();
      readDirectory();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputText("##directory", directoryBuffer_, sizeof directoryBuffer_,
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
      directory_ = directoryBuffer_;
      readDirectory();
    }
    // The filter, above the name: which files the list shows.
    const float footer = ImGui::GetFrameHeightWithSpacing() * (option_ ? 3.0f : 2.0f) +
                         (extensions_.empty() ? 0.0f : ImGui::GetTextLineHeightWithSpacing());
    ImGui::BeginChild("entries", ImVec2(0, -footer), true);
    if (!listingError_.empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", listingError_.c_str());
    }
    std::optional<std::filesystem::path> enter;
    for (const Entry& entry : entries_) {
      const std::string label = entry.isDirectory ? entry.name + "/" : entry.name;
      const bool selected = !entry.isDirectory && entry.name == nameBuffer_;
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (entry.isDirectory) {
          if (ImGui::IsMouseDoubleClicked(0)) enter = directory_ / entry.name;
        } else {
          copyToBuffer(nameBuffer_, sizeof nameBuffer_, entry.name);
          if (ImGui::IsMouseDoubleClicked(0)) chosen = directory_ / entry.name;
        }
      }
    }
    ImGui::EndChild();
    if (enter) {
      directory_ = *enter;
      readDirectory();
    }
    if (!extensions_.empty()) {
      std::string shown = "Files:";
      for (const std::string& extension : extensions_) shown += " *" + extension;
      ImGui::TextDisabled("%s", shown.c_str());
    }
    ImGui::SetNextItemWidth(-px(160));
    const bool submitted = ImGui::InputText("##name", nameBuffer_, sizeof nameBuffer_,
                                            ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    const bool confirm = ImGui::Button(mode_ == Mode::Open ? "Open" : "Save", ImVec2(px(70), 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(px(70), 0))) visible_ = false;
    if (option_ && option_->value != nullptr) {
      ImGui::Checkbox(option_->label.c_str(), option_->value);
      if (ImGui::IsItemHovered() && !option_->tooltip.empty()) {
        ImGui::SetTooltip("%s", option_->tooltip.c_str());
      }
    }
    if ((submitted || confirm || std::exchange(submitRequested_, false)) &&
        nameBuffer_[0] != '\0') {
      const std::filesystem::path typed = nameBuffer_;
      chosen = typed.is_absolute() ? typed : directory_ / typed;
    }
  }
  ImGui::End();
  if (chosen) visible_ = false;
  return chosen;
}

}  // namespace lenslab::app
