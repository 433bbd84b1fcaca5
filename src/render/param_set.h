#pragma once
// The typed parameter lists of pbrt directives ("float radius" [1]), with lookups that remember
// which parameters were used, so that the rest can be reported as ignored
// (see unused_parameters.h), and marks for parameters that are read but not honoured, with what
// is done instead.

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"

namespace lenslab::render {

struct Param {
  std::string type;  // as written: float, integer, point, rgb, color, spectrum, string, ...
  std::string name;
  std::vector<double> numbers;       // spectra already converted to linear sRGB triples
  std::vector<std::string> strings;  // string, texture and bool values
  SourceLocation location;
  mutable bool used = false;
  // How many values the reader that used it takes (1 for a float, 3 for a colour; 0: any number,
  // a list): a parameter given more is an error (3 million numbers for a sphere's radius).
  mutable std::size_t takesValues = 0;
  mutable bool readAsList = false;  // some reader took all its values (getNumbers): no limit
  // Non-empty when a consumer read the parameter but cannot honour it: what it does instead.
  mutable std::string substitute;
};

class ParamSet {
 public:
  void add(Param param);
  // Marks the parameter as used.
  const Param* find(const std::string& name) const;

  double getFloat(const std::string& name, double fallback) const;
  // The first value as an int; the fallback when absent or not a representable whole number.
  int getInt(const std::string& name, int fallback) const;
  // The first value, which must be a whole number in [min, max]: otherwise reports an error at
  // the parameter and returns nothing. The fallback when absent.
  std::optional<int> getInt(const std::string& name, int fallback, int min, int max,
                            Diagnostics& diagnostics) const;
  bool getBool(const std::string& name, bool fallback) const;
  std::string getString(const std::string& name, const std::string& fallback) const;
  // rgb / color / spectrum / point / normal / vector with three numbers; a single number is
  // accepted as a grey value.
  std::optional<glm::dvec3> getTriple(const std::string& name) const;
  glm::dvec3 getTriple(const std::string& name, glm::dvec3 fallback) const;
  std::vector<double> getNumbers(const std::string& name) const;
  // The name of a texture given by a "texture NAME" parameter.
  std::optional<std::string> getTextureName(const std::string& name) const;

  // Marks a parameter, if present, as read but not supported: the unused-parameter report says
  // "... is not supported; <instead>".
  void unsupported(const std::string& name, const std::string& instead) const;

  // What the report calls the directive the parameters belong to, e.g. `Film "image"`.
  std::string owner;
  // One warning per parameter nobody asked for, and per parameter marked unsupported; an error
  // per parameter given more values than its reader takes.
  void reportUnused(Diagnostics& diagnostics) const;
  const std::vector<Param>& items() const { return items_; }

 private:
  std::vector<Param> items_;
};

}  // namespace lenslab::render
