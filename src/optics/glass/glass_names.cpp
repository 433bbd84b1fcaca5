#include "optics/glass/glass_names.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace lenslab::optics {

std::string glassNameKey(std::string_view name) {
  std::string key;
  key.reserve(name.size());
  for (const char c : name) {
    if (c == '-' || c == ' ' || c == '_') continue;
    key += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return key;
}

std::string upperCase(std::string_view text) {
  std::string upper(text);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return upper;
}

const std::vector<std::string>& glassMakerOrder() {
  static const std::vector<std::string> order = {
      "SCHOTT",   "OHARA", "HOYA",   "CDGM",      "HIKARI",  "SUMITA", "LZOS",
      "CRYSTRAN", "AMI",   "VITRON", "LIGHTPATH", "CORNING", "MISC"};
  return order;
}

std::size_t glassMakerRank(std::string_view maker) {
  const auto& order = glassMakerOrder();
  return static_cast<std::size_t>(std::find(order.begin(), order.end(), maker) - order.begin());
}

int editDistance(std::string_view a, std::string_view b) {
  // One row of the classic table at a time.
  std::vector<int> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace lenslab::optics
