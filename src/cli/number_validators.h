#pragma once
// CLI11 checks for numeric options. CLI11's PositiveNumber and Range let NaN through (every
// comparison with NaN is false), accept infinity, and print DBL_MAX in their messages; these
// reject both with a short message, e.g. "--film-diagonal: 'nan' is not a positive finite number".

#include <CLI/CLI.hpp>

namespace lenslab::cli {

// A positive, finite number: a length in mm, a wavelength in nm.
class PositiveFiniteNumber : public CLI::Validator {
 public:
  PositiveFiniteNumber();
};

// Any finite number, for options whose sign is free (an exposure in stops).
class FiniteNumber : public CLI::Validator {
 public:
  FiniteNumber();
};

// A finite number from min to max inclusive, in `unit` ("nm"): "'100' is not between 200 and
// 2000 nm", where CLI::Range said "Value 100 not in range 200.000000 to 2000.000000".
class FiniteNumberBetween : public CLI::Validator {
 public:
  FiniteNumberBetween(double min, double max, const std::string& unit);
};

}  // namespace lenslab::cli
