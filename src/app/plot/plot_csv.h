#pragma once
// A plot's numbers as CSV: a header with the x axis's label and each series' name, then one row
// per x. Series that share their x values share rows; a series without a value at some x leaves
// its cell empty. Values are written with 9 significant digits.

#include <filesystem>
#include <string>

#include "app/plot/plot_spec.h"

namespace lenslab::app {

std::string plotCsv(const PlotSpec& spec);

// Atomic (temporary file + rename). Returns an error message naming the path, or "".
std::string writePlotCsv(const std::filesystem::path& path, const PlotSpec& spec);

}  // namespace lenslab::app
