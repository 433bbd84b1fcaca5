#pragma once
// Reading the CSV files the viewer's plots export (plot/plot_csv.h): a header row, then numbers
// (an empty cell, a blocked ray or a missing value, reads as NaN), optionally after a first
// column of names (a bar chart's categories).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lenslab::testing {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::string> names;  // the first column, when it holds names
  std::vector<std::vector<double>> rows;
};

inline CsvTable readCsvTable(const std::filesystem::path& path, bool firstColumnIsNames = false) {
  CsvTable table;
  std::ifstream in(path);
  std::string line;
  auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::stringstream stream(text);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    return cells;
  };
  if (std::getline(in, line)) table.header = split(line);
  while (std::getline(in, line)) {
    const auto cells = split(line);
    if (cells.empty()) continue;
    std::size_t first = 0;
    if (firstColumnIsNames) table.names.push_back(cells[first++]);
    std::vector<double> row;
    for (std::size_t i = first; i < cells.size(); ++i)
      row.push_back(cells[i].empty() ? NAN : std::stod(cells[i]));
    table.rows.push_back(row);
  }
  return table;
}

}  // namespace lenslab::testing
