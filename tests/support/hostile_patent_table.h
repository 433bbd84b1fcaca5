#pragma once
// A valid patent table (f/4, a stop row on line 5, an aspheric surface 1) with one line replaced
// or text appended: the base of the patent reader's hostile cases, in its unit tests and in the
// CLI's (tests/hostile).

#include <cstddef>
#include <string>
#include <vector>

namespace lenslab::testing {

// `row` in place of line `replaced` (1-based; 0 replaces none) and `extra` appended.
inline std::string hostilePatentTable(int replaced = 0, const std::string& row = "",
                                      const std::string& extra = "") {
  std::vector<std::string> lines = {"f = 52.1  Fno 4.0  2ω 20",
                                    "Surface r d nd vd",
                                    "1* 50 5 1.5168 64.2",
                                    "2 -200 2",
                                    "3(Stop) INF 3",
                                    "4 -80 40",
                                    "",
                                    "Aspheric coefficients",
                                    "Surface 1: K = -0.5 A4 = 1.0E-07 A6 = 2.0E-11"};
  if (replaced > 0) lines[static_cast<std::size_t>(replaced - 1)] = row;
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text + extra;
}

}  // namespace lenslab::testing
