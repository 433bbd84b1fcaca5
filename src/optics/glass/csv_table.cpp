#include "optics/glass/csv_table.h"

#include "common/formatted.h"

namespace lenslab::optics {

namespace {

// Splits one line into fields, or says what is wrong with its quoting (and where).
struct SplitLine {
  std::vector<CsvField> fields;
  std::string error;
  int errorColumn = 0;
};

SplitLine splitLine(std::string_view line) {
  SplitLine result;
  std::size_t i = 0;
  while (true) {
    CsvField field;
    field.column = static_cast<int>(i) + 1;
    if (i < line.size() && line[i] == '"') {
      ++i;
      bool closed = false;
      while (i < line.size()) {
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field.text += '"';
            i += 2;
            continue;
          }
          closed = true;
          ++i;
          break;
        }
        field.text += line[i++];
      }
      if (!closed) {
        result.error = "a quoted field is not closed on its line";
        result.errorColumn = field.column;
        return result;
      }
      if (i < line.size() && line[i] != ',') {
        result.error = "text after a quoted field's closing quote";
        result.errorColumn = static_cast<int>(i) + 1;
        return result;
      }
    } else {
      while (i < line.size() && line[i] != ',') {
        if (line[i] == '"') {
          result.error = "a quote inside an unquoted field";
          result.errorColumn = static_cast<int>(i) + 1;
          return result;
        }
        field.text += line[i++];
      }
    }
    result.fields.push_back(std::move(field));
    if (i >= line.size()) return result;
    ++i;  // the comma
  }
}

}  // namespace

int CsvTable::columnIndex(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::string csvLocation(const std::string& fileLabel, int line, int column, std::string_view what) {
  return formatted("%s:%d:%d: ", fileLabel.c_str(), line, column) + std::string(what);
}

CsvTable parseCsv(std::string_view text, const std::string& fileLabel) {
  CsvTable table;
  int lineNumber = 0;
  bool haveHeader = false;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (lineNumber == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // BOM
    if (line.empty()) continue;  // blank lines carry nothing
    SplitLine split = splitLine(line);
    if (!split.error.empty()) {
      table.errors.push_back(csvLocation(fileLabel, lineNumber, split.errorColumn, split.error));
      continue;
    }
    if (!haveHeader) {
      for (CsvField& field : split.fields) table.header.push_back(std::move(field.text));
      haveHeader = true;
      continue;
    }
    if (split.fields.size() != table.header.size()) {
      const int column = split.fields.size() > table.header.size()
                             ? split.fields[table.header.size()].column
                             : static_cast<int>(line.size()) + 1;
      table.errors.push_back(csvLocation(fileLabel, lineNumber, column,
                                         formatted("%zu fields where the header has %zu",
                                                   split.fields.size(), table.header.size())));
      continue;
    }
    table.records.push_back({lineNumber, std::move(split.fields)});
  }
  if (!haveHeader) table.errors.push_back(csvLocation(fileLabel, 1, 1, "no header line"));
  return table;
}

}  // namespace lenslab::optics
