#include "render/param_set.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace {

// A reader of one value (or of a colour's three) notes how many it takes.
const Param* takes(const Param* item, std::size_t values) {
  if (item) item->takesValues = values;
  return item;
}

}  // namespace

double ParamSet::getFloat(const std::string& name, double fallback) const {
  const Param* item = takes(find(name), 1);
  return item && !item->numbers.empty() ? item->numbers[0] : fallback;
}

namespace {

bool isInt(double value) {
  return std::isfinite(value) && value == std::trunc(value) &&
         value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max();
}

std::string formatNumber(double value) {
  std::string text = std::to_string(value);
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

}  // namespace

int ParamSet::getInt(const std::string& name, int fallback) const {
  const Param* item = takes(find(name), 1);
  if (!item || item->numbers.empty() || !isInt(item->numbers[0])) return fallback;
  return static_cast<int>(item->numbers[0]);
}

std::optional<int> ParamSet::getInt(const std::string& name, int fallback, int min, int max,
                                    Diagnostics& diagnostics) const {
  const Param* item = takes(find(name), 1);
  if (!item || item->numbers.empty()) return fallback;
  const double value = item->numbers[0];
  const std::string what = "\"" + item->type + " " + item->name + "\"";
  if (!isInt(value)) {
    diagnostics.error(item->location,
                      what + " must be a whole number, found " + formatNumber(value));
    return std::nullopt;
  }
  if (value < min || value > max) {
    diagnostics.error(item->location, what + " is " + formatNumber(value) + ", outside " +
                                          std::to_string(min) + " to " + std::to_string(max));
    return std::nullopt;
  }
  return static_cast<int>(value);
}

bool ParamSet::getBool(const std::string& name, bool fallback) const {
  const Param* item = takes(find(name), 1);
  if (!item || item->strings.empty()) return fallback;
  return item->strings[0] == "true";
}

std::string ParamSet::getString(const std::string& name, const std::string& fallback) const {
  const Param* item = takes(find(name), 1);
  return item && !item->strings.empty() ? item->strings[0] : fallback;
}

std::optional<glm::dvec3> ParamSet::getTriple(const std::string& name) const {
  const Param* item = takes(find(name), 3);
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
  if (item) item->readAsList = true;
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

void ParamSet::unsupported(const std::string& name, const std::string& instead) const {
  for (const Param& item : items_) {
    if (item.name == name) {
      item.used = true;
      item.substitute = instead;
    }
  }
}

void ParamSet::reportUnused(Diagnostics& diagnostics) const {
  for (const Param& item : items_) {
    const std::size_t given = std::max(item.numbers.size(), item.strings.size());
    // A colour may be one grey value; otherwise a reader of N values given more is an error.
    if (item.used && !item.readAsList && item.takesValues > 0 && given > item.takesValues) {
      diagnostics.error(item.location, "parameter \"" + item.type + " " + item.name + "\" of " +
                                           owner + " takes " + std::to_string(item.takesValues) +
                                           (item.takesValues == 1 ? " value" : " values") +
                                           ", but " + std::to_string(given) + " are given");
    }
    if (item.used && item.substitute.empty()) continue;
    diagnostics.warning(item.location, "parameter \"" + item.type + " " + item.name + "\" of " +
                                           owner + " is not supported; " +
                                           (item.used ? item.substitute : "ignored"));
  }
}

}  // namespace lenslab::render
