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

}  // namespace lenslab::cli
