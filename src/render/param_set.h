#pragma once
// The typed parameter lists of pbrt directives ("float radius" [1]), with lookups that remember
// which parameters were used so that the rest can be reported as ignored.

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "render/diagnostics.h"

namespace lenslab::render {

struct Param {
  std::string type;  // as written: float, integer, point, rgb, color, string, texture, bool, ...
  std::string name;
  std::vector<double> numbers;
  std::vector<std::string> strings;  // string, texture and bool values
  SourceLocation location;
  mutable bool used = false;
};

class ParamSet {
 public:
  void add(Param param);
  const Param* find(const std::string& name) const;

  double getFloat(const std::string& name, double fallback) const;
  int getInt(const std::string& name, int fallback) const;
  bool getBool(const std::string& name, bool fallback) const;
  std::string getString(const std::string& name, const std::string& fallback) const;
  // rgb / color / spectrum / point / normal / vector with three numbers; a single number is
  // accepted as a grey value.
  std::optional<glm::dvec3> getTriple(const std::string& name) const;
  glm::dvec3 getTriple(const std::string& name, glm::dvec3 fallback) const;
  std::vector<double> getNumbers(const std::string& name) const;
  // The name of a texture given by a "texture NAME" parameter.
  std::optional<std::string> getTextureName(const std::string& name) const;

  // Warns about each parameter nobody asked for, naming the directive.
  void warnUnused(Diagnostics& diagnostics, const std::string& what) const;
  const std::vector<Param>& items() const { return items_; }

 private:
  std::vector<Param> items_;
};

}  // namespace lenslab::render
