#pragma once
// A comma-separated table as the glass catalogues use it (RFC 4180): one header line naming the
// columns, then one record per line; a field may be quoted ("a, b", with "" for a quote). Every
// record must have as many fields as the header. Errors say where, as `file:line:column: what`,
// so that a malformed row is reported, never skipped.

#include <string>
#include <string_view>
#include <vector>

namespace lenslab::optics {

struct CsvField {
  std::string text;
  int column = 1;  // 1-based, in characters, where the field starts
};

struct CsvRecord {
  int line = 0;  // 1-based
  std::vector<CsvField> fields;
};

struct CsvTable {
  std::vector<std::string> header;
  std::vector<CsvRecord> records;
  std::vector<std::string> errors;  // "file:line:column: what"; the table is unusable if any

  // The header's column named `name`, or -1.
  int columnIndex(std::string_view name) const;
};

// `fileLabel` names the source in the messages (a path, or a file name).
CsvTable parseCsv(std::string_view text, const std::string& fileLabel);

// "file:line:column: what".
std::string csvLocation(const std::string& fileLabel, int line, int column, std::string_view what);

}  // namespace lenslab::optics
