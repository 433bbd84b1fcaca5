#include "app/plot/plot_csv.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "app/plot/plot_scale.h"
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

std::string csvNumber(double value) {
  if (!std::isfinite(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// A scatter cannot share rows by x (two rays may land at one x): one point a row.
std::string pointsCsv(const PlotSpec& spec) {
  std::string csv = "series," + field(spec.x.label) + "," + field(spec.y.label) + "\n";
  for (const PlotSeries& series : spec.series)
    for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()); ++i) {
      if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) continue;
      csv +=
          field(series.name) + "," + csvNumber(series.x[i]) + "," + csvNumber(series.y[i]) + "\n";
    }
  return csv;
}

}  // namespace

std::string plotCsv(const PlotSpec& spec) {
  for (const PlotSeries& series : spec.series)
    if (series.points) return pointsCsv(spec);
  if (spec.equalAspect) {
    // A picture (a grid's lines) is points, not a function: one row per point, numbered by
    // polyline within its series.
    std::string csv = "series,polyline," + field(spec.x.label) + "," + field(spec.y.label) + "\n";
    for (const PlotSeries& series : spec.series) {
      if (series.guide) continue;
      int polyline = 0;
      for (const auto& [begin, end] : finiteRuns(series)) {
        for (std::size_t i = begin; i < end; ++i)
          csv += field(series.name) + "," + std::to_string(polyline) + "," +
                 csvNumber(series.x[i]) + "," + csvNumber(series.y[i]) + "\n";
        ++polyline;
      }
    }
    return csv;
  }
  // Rows go by the independent variable: x, or y for series along y.
  const bool alongY = spec.seriesAlongY;
  std::string csv = field(alongY ? spec.y.label : spec.x.label);
  // Guides are not data.
  std::vector<const PlotSeries*> data;
  for (const PlotSeries& series : spec.series)
    if (!series.guide) data.push_back(&series);
  for (const PlotSeries* series : data) {
    csv.push_back(',');
    csv += field(series->name);
  }
  csv += "\n";
  // Rows by x (or y), in ascending order; each series fills its own column.
  std::map<double, std::vector<std::string>> rows;
  for (std::size_t s = 0; s < data.size(); ++s) {
    const PlotSeries& series = *data[s];
    const std::vector<double>& keys = alongY ? series.y : series.x;
    const std::vector<double>& values = alongY ? series.x : series.y;
    for (std::size_t i = 0; i < std::min(keys.size(), values.size()); ++i) {
      if (!std::isfinite(keys[i])) continue;
      auto& row = rows[keys[i]];
      row.resize(data.size());
      row[s] = csvNumber(values[i]);
    }
  }
  for (const auto& [x, cells] : rows) {
    // A categorical axis names its rows ("1", "2", ..., "total") rather than numbering them.
    const long index = std::lround(x);
    if (!spec.categories.empty() && index >= 0 &&
        index < static_cast<long>(spec.categories.size()) && x == static_cast<double>(index))
      csv += field(spec.categories[static_cast<std::size_t>(index)]);
    else
      csv += csvNumber(x);
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
