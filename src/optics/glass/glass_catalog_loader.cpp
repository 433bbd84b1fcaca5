#include "optics/glass/glass_catalog_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/formatted.h"
#include "common/resource_directories.h"
#include "optics/glass/csv_table.h"
#include "optics/glass/glass_names.h"

namespace lenslab::optics {

namespace {

constexpr std::size_t kMaxErrorsKept = 20;

// The columns a catalogue file must have (data/glass/README.md); they may come in any order.
constexpr const char* kColumns[] = {"name",    "group",   "formula_id", "formula", "coefficients",
                                    "lmin_um", "lmax_um", "nd",         "vd",      "nd_cat",
                                    "vd_cat",  "code",    "status",     "T_K"};

bool parseNumber(std::string_view text, double& value) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc{} && ptr == end && std::isfinite(value);
}

// Reads one record's fields by column name, collecting errors at the field's place.
class RecordReader {
 public:
  RecordReader(const CsvTable& table, const CsvRecord& record, const std::string& fileLabel,
               std::vector<std::string>& errors)
      : table_(table), record_(record), fileLabel_(fileLabel), errors_(errors) {}

  const CsvField& field(const char* column) const {
    return record_.fields[static_cast<std::size_t>(table_.columnIndex(column))];
  }
  const std::string& text(const char* column) const { return field(column).text; }

  void fail(const CsvField& at, const std::string& what, int offset = 0) {
    ok_ = false;
    errors_.push_back(csvLocation(fileLabel_, record_.line, at.column + offset, what));
  }
  void fail(const char* column, const std::string& what) { fail(field(column), what); }

  double number(const char* column) {
    double value = 0.0;
    if (!parseNumber(text(column), value)) {
      fail(column, formatted("%s \"%s\" is not a number", column, text(column).c_str()));
    }
    return value;
  }
  std::optional<double> optionalNumber(const char* column) {
    if (text(column).empty()) return std::nullopt;
    return number(column);
  }

  // The space-separated coefficients, each error at its own column.
  std::vector<double> numberList(const char* column) {
    const CsvField& at = field(column);
    std::vector<double> values;
    std::size_t i = 0;
    const std::string& s = at.text;
    while (i < s.size()) {
      if (s[i] == ' ') {
        ++i;
        continue;
      }
      const std::size_t start = i;
      while (i < s.size() && s[i] != ' ') ++i;
      double value = 0.0;
      const std::string_view word(s.data() + start, i - start);
      if (!parseNumber(word, value)) {
        fail(at, formatted("coefficient \"%s\" is not a number", std::string(word).c_str()),
             static_cast<int>(start));
      }
      values.push_back(value);
    }
    return values;
  }

  bool ok() const { return ok_; }

 private:
  const CsvTable& table_;
  const CsvRecord& record_;
  const std::string& fileLabel_;
  std::vector<std::string>& errors_;
  bool ok_ = true;
};

// A table's (wavelength, index) pairs by wavelength: two LZOS tables of the database (CTK8, OF1)
// list one pair out of place, which is unambiguous to put right. Pairs at the same wavelength
// stay, for dispersionCoefficientsProblem to refuse.
void sortTable(std::vector<double>& table) {
  if (table.size() % 2 != 0) return;
  std::vector<std::pair<double, double>> pairs;
  for (std::size_t i = 0; i < table.size(); i += 2) pairs.emplace_back(table[i], table[i + 1]);
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    table[2 * i] = pairs[i].first;
    table[2 * i + 1] = pairs[i].second;
  }
}

// n_d and V_d from the formula, when its range covers the d, F and C lines.
void computeAbbe(CatalogGlass& glass) {
  const DispersionFormula& f = glass.formula;
  if (!f.covers(kCatalogFLineNm) || !f.covers(kCatalogCLineNm)) return;
  const double nd = f.indexAtUm(kCatalogDLineNm / 1000.0);
  const double nF = f.indexAtUm(kCatalogFLineNm / 1000.0);
  const double nC = f.indexAtUm(kCatalogCLineNm / 1000.0);
  if (!std::isfinite(nd) || !std::isfinite(nF) || !std::isfinite(nC)) return;
  glass.nd = nd;
  if (nF != nC) glass.vd = (nd - 1.0) / (nF - nC);
}

std::optional<CatalogGlass> readGlass(const CsvTable& table, const CsvRecord& record,
                                      const std::string& fileLabel, const std::string& maker,
                                      std::vector<std::string>& errors) {
  RecordReader row(table, record, fileLabel, errors);
  CatalogGlass glass;
  glass.name = row.text("name");
  if (glass.name.empty()) row.fail("name", "a glass without a name");
  glass.maker = maker;
  glass.group = row.text("group");
  glass.sourceFile = fileLabel;
  glass.sourceLine = record.line;
  const auto kind = dispersionFormulaKindFromId(row.text("formula_id"));
  if (!kind) {
    row.fail("formula_id", "unknown formula id \"" + row.text("formula_id") +
                               "\" (1-9 or tab, data/glass/README.md)");
  }
  glass.formula.kind = kind.value_or(DispersionFormulaKind::Polynomial);
  glass.formula.coefficients = row.numberList("coefficients");
  glass.formula.minimumUm = row.number("lmin_um");
  glass.formula.maximumUm = row.number("lmax_um");
  if (row.ok() &&
      !(glass.formula.minimumUm > 0.0 && glass.formula.maximumUm >= glass.formula.minimumUm)) {
    row.fail("lmax_um", formatted("the range %g-%g um is empty or not positive",
                                  glass.formula.minimumUm, glass.formula.maximumUm));
  }
  if (glass.formula.kind == DispersionFormulaKind::Tabulated) sortTable(glass.formula.coefficients);
  if (row.ok()) {
    const std::string problem =
        dispersionCoefficientsProblem(glass.formula.kind, glass.formula.coefficients);
    if (!problem.empty()) row.fail("coefficients", problem);
  }
  const std::vector<double>& points = glass.formula.coefficients;
  if (row.ok() && glass.formula.kind == DispersionFormulaKind::Tabulated &&
      (glass.formula.minimumUm < points.front() ||
       glass.formula.maximumUm > points[points.size() - 2])) {
    row.fail("lmin_um", formatted("the range %g-%g um reaches beyond the table's %g-%g um",
                                  glass.formula.minimumUm, glass.formula.maximumUm, points.front(),
                                  points[points.size() - 2]));
  }
  row.optionalNumber("nd");  // checked for form only: lenslab computes its own
  row.optionalNumber("vd");
  glass.catalogNd = row.optionalNumber("nd_cat");
  glass.catalogVd = row.optionalNumber("vd_cat");
  glass.referenceTemperatureK = row.optionalNumber("T_K");
  glass.code = row.text("code");
  glass.status = row.text("status");
  if (!row.ok()) return std::nullopt;
  computeAbbe(glass);
  return glass;
}

}  // namespace

std::vector<CatalogGlass> parseGlassCsv(std::string_view text, const std::string& fileLabel,
                                        const std::string& maker,
                                        std::vector<std::string>& errors) {
  const CsvTable table = parseCsv(text, fileLabel);
  errors.insert(errors.end(), table.errors.begin(), table.errors.end());
  std::vector<CatalogGlass> glasses;
  bool columnsOk = true;
  for (const char* column : kColumns) {
    if (table.columnIndex(column) < 0 && !table.header.empty()) {
      errors.push_back(csvLocation(fileLabel, 1, 1, std::string("no column \"") + column + "\""));
      columnsOk = false;
    }
  }
  if (!columnsOk || table.header.empty()) return glasses;
  for (const CsvRecord& record : table.records) {
    if (auto glass = readGlass(table, record, fileLabel, maker, errors)) {
      glasses.push_back(std::move(*glass));
    }
  }
  return glasses;
}

GlassCatalogLoad loadGlassCatalog(const std::filesystem::path& directory) {
  GlassCatalogLoad load;
  std::error_code error;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    if (entry.path().extension() == ".csv" && entry.is_regular_file())
      files.push_back(entry.path());
  }
  if (error) {
    load.errors.push_back(directory.string() +
                          ": cannot list the glass catalogues: " + error.message());
    return load;
  }
  if (files.empty()) {
    load.errors.push_back(directory.string() + ": no glass catalogue (*.csv) there");
    return load;
  }
  std::sort(files.begin(), files.end());
  std::vector<CatalogGlass> glasses;
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) {
      load.errors.push_back(file.string() + ": cannot read it");
      continue;
    }
    auto some = parseGlassCsv(text.str(), file.filename().string(), upperCase(file.stem().string()),
                              load.errors);
    std::move(some.begin(), some.end(), std::back_inserter(glasses));
  }
  if (load.errors.size() > kMaxErrorsKept) {
    const std::size_t more = load.errors.size() - kMaxErrorsKept;
    load.errors.resize(kMaxErrorsKept);
    load.errors.push_back(formatted("... and %zu more errors", more));
  }
  if (load.errors.empty()) load.catalog = std::make_shared<const GlassCatalog>(std::move(glasses));
  return load;
}

const GlassCatalogLoad& defaultGlassCatalog() {
  // A function-local static: initialised once, by the first caller, while others wait.
  static const GlassCatalogLoad load = [] {
    // LENSLAB_GLASS_DIR names another directory of catalogues (a maker's newer files, or the
    // checkout's data/glass for a test program, which runs outside the tree the lookup knows).
    const char* override = std::getenv("LENSLAB_GLASS_DIR");
    if (override && *override) return loadGlassCatalog(override);
    const std::filesystem::path directory = findResourceDirectory("glass");
    if (directory.empty()) {
      GlassCatalogLoad missing;
      missing.errors.push_back(
          "the bundled glass catalogues (a `glass` directory beside lenslab's lenses) are not "
          "installed");
      return missing;
    }
    return loadGlassCatalog(directory);
  }();
  return load;
}

}  // namespace lenslab::optics
