// libFuzzer target: a patent's numerical example as text (optics/import/patent_table.h). Beyond
// not crashing, it holds the reader to its header: every problem is an error at a place; what it
// understood (the rows, aspheric data and header values the paste window shows) is finite
// numbers; a table it accepts builds a LensSystem, has a line for every surface, finite design
// conditions, and its lens written as lenslab's .lens reads back to the identical prescription.
// The first byte, when it is a digit 1..5, also overrides the first column's meaning (the paste
// window's combo), so that re-reading with a user's choice is fuzzed too.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "imported_lens_checks.h"
#include "optics/import/patent_table.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"
#include "optics/prescription.h"

namespace {

bool finiteOrAbsent(const std::optional<double>& value) { return !value || std::isfinite(*value); }

void checkUnderstood(const lenslab::optics::PatentTable& table) {
  using lenslab::fuzz::check;
  for (const auto& row : table.rows) {
    check(std::isfinite(row.radiusMm) || row.radiusMm == lenslab::optics::kFlatRadius,
          "a row's radius is finite, or flat (kFlatRadius)");
    check(
        finiteOrAbsent(row.thicknessMm) && finiteOrAbsent(row.indexD) && finiteOrAbsent(row.abbeD),
        "a row's d, n_d and V_d are finite");
  }
  for (const auto& asphere : table.aspheres) {
    check(std::isfinite(asphere.conic), "a conic constant is finite");
    for (const auto& [power, coefficient] : asphere.terms)
      check(std::isfinite(coefficient), "an aspheric coefficient is finite");
  }
  for (const auto* value :
       {&table.header.focalLengthMm, &table.header.fNumber, &table.header.halfFieldDeg,
        &table.header.imageHeightMm, &table.header.backFocusMm})
    check(!*value || std::isfinite((*value)->value), "a header value is finite");
  check(finiteOrAbsent(table.filmDistanceMm), "the film distance is finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::optional<optics::PatentColumn>> overrides;
  if (!text.empty() && text.front() >= '1' && text.front() <= '5') {
    overrides.push_back(optics::kPatentColumns[text.front() - '1']);
    text.remove_prefix(1);
  }
  const optics::PatentTableResult result = optics::readPatentTable(text, "input.txt", overrides);
  fuzz::checkDiagnostics(result.lens.diagnostics, result.lens.ok());
  checkUnderstood(result.table);
  if (!result.lens.ok()) return 0;

  const optics::LensFile& lens = *result.lens.lens;
  fuzz::check(lens.prescription.stopIndex().has_value(), "an accepted table has one stop");
  fuzz::checkImportedLens(lens);
  return 0;
}
