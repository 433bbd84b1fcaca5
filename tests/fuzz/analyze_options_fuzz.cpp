// libFuzzer target: `lenslab analyze`'s option parsing (cli/analyze_options.h) on arbitrary
// command lines: one argument per line of the input, after "lenslab analyze". It parses as the
// command does (CLI11 with the project's validators, then the checks across options) and stops
// before reading a lens. Beyond not crashing, it holds the checks to their promise: arguments
// that pass them are finite and in range, so no NaN or absurd size reaches an analysis or the
// JSON.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli/analyze_options.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  std::vector<std::string> words{"lenslab", "analyze"};
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) words.push_back(line);
  if (words.size() > 64) return 0;  // a command line, not a file: longer ones add nothing
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());

  CLI::App app{"lenslab", "lenslab"};
  CLI::App* analyze = app.add_subcommand("analyze", "analyze");
  cli::AnalyzeArguments arguments;
  const cli::AnalyzeOptions options = cli::addAnalyzeOptions(*analyze, arguments);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& error) {
    std::ostringstream out, err;
    app.exit(error, out, err);  // as cli.cpp reports it, without the noise
    return 0;
  }
  const std::optional<cli::AnalyzeRequest> request =
      cli::checkAnalyzeArguments(arguments, options.objectDistance->count() > 0);
  if (!request) return 0;

  fuzz::check(!request->reports.empty(), "an accepted command runs some analysis");
  fuzz::check(arguments.points >= 2 && arguments.points <= 4096, "--points is in 2..4096");
  fuzz::check(std::isfinite(arguments.filmDiagonalMm) && arguments.filmDiagonalMm > 0,
              "--film-diagonal is positive and finite");
  fuzz::check(std::isfinite(arguments.wavelengthNm) && arguments.wavelengthNm >= 350 &&
                  arguments.wavelengthNm <= 1000,
              "--wavelength is in 350..1000 nm");
  fuzz::check(std::isfinite(arguments.stopDiameterMm) && arguments.stopDiameterMm >= 0,
              "--stop-diameter is finite and not negative");
  fuzz::check(std::isfinite(arguments.filmDistanceMm) && arguments.filmDistanceMm >= 0,
              "--film-distance is finite and not negative");
  fuzz::check(!arguments.fieldFractions.empty(), "there is a field");
  for (double fraction : arguments.fieldFractions)
    fuzz::check(fraction >= 0 && fraction <= 1, "every field is in 0..1");
  if (request->objectDistanceMm)
    fuzz::check(std::isfinite(*request->objectDistanceMm) && *request->objectDistanceMm > 0,
                "a finite object distance is positive");
  return 0;
}
