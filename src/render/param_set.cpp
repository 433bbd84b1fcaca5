#include "render/param_set.h"

namespace lenslab::render {

void ParamSet::add(Param param) {
  for (Param& existing : items_) {
    if (existing.name == param.name) {
      existing = std::move(param);
      return;
    }
  }
  items_.push_back(std::move(param));
}

const Param* ParamSet::find(const std::string& name) const {
  for (const Param& item : items_) {
    if (item.name == name) {
      item.used = true;
      return &item;
    }
  }
  return nullptr;
}

double ParamSet::getFloat(const std::string& name, double fallback) const {
  const Param* item = find(name);
  return item && !item->numbers.empty() ? item->numbers[0] : fallback;
}

int ParamSet::getInt(const std::string& name, int fallback) const {
  const Param* item = find(name);
  return item && !item->numbers.empty() ? static_cast<int>(item->numbers[0]) : fallback;
}

bool ParamSet::getBool(const std::string& name, bool fallback) const {
  const Param* item = find(name);
  if (!item || item->strings.empty()) return fallback;
  return item->strings[0] == "true";
}

std::string ParamSet::getString(const std::string& name, const std::string& fallback) const {
  const Param* item = find(name);
  return item && !item->strings.empty() ? item->strings[0] : fallback;
}

std::optional<glm::dvec3> ParamSet::getTriple(const std::string& name) const {
  const Param* item = find(name);
  if (!item || item->type == "texture") return std::nullopt;
  if (item->numbers.size() >= 3) {
    return glm::dvec3(item->numbers[0], item->numbers[1], item->numbers[2]);
  }
  if (item->numbers.size() == 1) return glm::dvec3(item->numbers[0]);
  return std::nullopt;
}

glm::dvec3 ParamSet::getTriple(const std::string& name, glm::dvec3 fallback) const {
  return getTriple(name).value_or(fallback);
}

std::vector<double> ParamSet::getNumbers(const std::string& name) const {
  const Param* item = find(name);
  return item ? item->numbers : std::vector<double>{};
}

std::optional<std::string> ParamSet::getTextureName(const std::string& name) const {
  for (const Param& item : items_) {
    if (item.name == name && item.type == "texture" && !item.strings.empty()) {
      item.used = true;
      return item.strings[0];
    }
  }
  return std::nullopt;
}

void ParamSet::warnUnused(Diagnostics& diagnostics, const std::string& what) const {
  for (const Param& item : items_) {
    if (!item.used) {
      diagnostics.warning(item.location, "parameter \"" + item.type + " " + item.name +
                                             "\" of " + what + " is not supported; ignored");
    }
  }
}

}  // namespace lenslab::render
