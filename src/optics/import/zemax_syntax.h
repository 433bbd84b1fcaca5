#pragma once
// OpticStudio .zmx syntax (zemax_file.h): a line's words and their columns, keywords without
// case, numbers as OpticStudio writes them, and the lens units.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lenslab::optics::zmx {

struct ZmxWord {
  std::string_view text;
  int column = 0;  // 1-based, in bytes
};

struct ZmxLine {
  int number = 0;
  std::string_view text;
  bool indented = false;
  std::vector<ZmxWord> words;
};

// The words of a line (separated by blanks), with their columns.
std::vector<ZmxWord> zmxWords(std::string_view text);

// The text after the first word (NAME's and NOTE's text), without the blanks around it.
std::string_view zmxRestAfter(std::string_view text, const ZmxWord& word);

// ASCII upper case: keywords are read in any case.
std::string zmxUpper(std::string_view text);

// A number as OpticStudio writes it ("1.5E+1", "-1.", "0"); empty when it is not one or is not
// finite.
std::optional<double> zmxNumber(std::string_view text);

// The length of one lens unit in millimetres.
std::optional<double> zmxUnitMm(std::string_view unit);

}  // namespace lenslab::optics::zmx
