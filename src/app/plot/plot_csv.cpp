#include "app/plot/plot_csv.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "common/atomic_file.h"

namespace lenslab::app {

namespace {

// Quotes a field when it holds a comma, a quote or a line break (RFC 4180).
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted(1, '"');
  for (char c : text) {
    if (c == '"') quoted.push_back('"');
    quoted.push_back(c);
  }
  quoted.push_back('"');
  return quoted;
}

std::string number(double value) {
  if (!std::isfinite(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

std::string plotCsv(const PlotSpec& spec) {
  // Rows go by the independent variable: x, or y for series along y.
  const bool alongY = spec.seriesAlongY;
  std::string csv = field(alongY ? spec.y.label : spec.x.label);
  for (const PlotSeries& series : spec.series) {
    csv.push_back(',');
    csv += field(series.name);
  }
  csv += "\n";
  // Rows by x (or y), in ascending order; each series fills its own column.
  std::map<double, std::vector<std::string>> rows;
  for (std::size_t s = 0; s < spec.series.size(); ++s) {
    const PlotSeries& series = spec.series[s];
    const std::vector<double>& keys = alongY ? series.y : series.x;
    const std::vector<double>& values = alongY ? series.x : series.y;
    for (std::size_t i = 0; i < std::min(keys.size(), values.size()); ++i) {
      if (!std::isfinite(keys[i])) continue;
      auto& row = rows[keys[i]];
      row.resize(spec.series.size());
      row[s] = number(values[i]);
    }
  }
  for (const auto& [x, cells] : rows) {
    csv += number(x);
    for (const std::string& cell : cells) {
      csv.push_back(',');
      csv += cell;
    }
    csv += "\n";
  }
  return csv;
}

std::string writePlotCsv(const std::filesystem::path& path, const PlotSpec& spec) {
  return writeFileAtomically(path, plotCsv(spec));
}

}  // namespace lenslab::app
