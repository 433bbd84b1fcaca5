#include "render/ply_reader.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <vector>

namespace lenslab::render {

namespace {

enum class PlyFormat { Ascii, BinaryLittle, BinaryBig };

struct PlyProperty {
  std::string name;
  std::string type;       // scalar type, or the item type of a list
  std::string countType;  // non-empty for lists
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  // of its header line
};

int typeSize(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 0;
}

std::string formatValue(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == std::trunc(value) && std::abs(value) < 1e18) {
    return std::to_string(static_cast<long long>(value));
  }
  std::ostringstream text;
  text << value;
  return text.str();
}

// Where problems are reported: in the PLY file where it has lines (the header and ASCII data),
// otherwise where the scene names the file, with the file's path in front of the message.
struct ProblemPlaces {
  std::string file;
  SourceLocation includedAt;

  Diagnostic atLine(int line, int column, std::string message) const {
    return {Severity::Error, {file, line, column}, std::move(message)};
  }
  Diagnostic outside(const std::string& message) const {
    return {Severity::Error, includedAt, file + ": " + message};
  }
};

// Reads the values of the data section one at a time, in either encoding, knowing where each
// came from for messages.
class PlyValueReader {
 public:
  PlyValueReader(const std::string& data, std::size_t start, int startLine, PlyFormat format,
                 const ProblemPlaces& places)
      : data_(data),
        position_(start),
        line_(startLine),
        lineStart_(start),
        format_(format),
        places_(places) {}

  // false at the end of the data, or (ASCII) on a token that is not a number: see problem().
  bool read(const std::string& type, double& value) {
    if (format_ == PlyFormat::Ascii) return readAscii(value);
    valueOffset_ = position_;
    const auto size = static_cast<std::size_t>(typeSize(type));
    if (data_.size() - position_ < size) {
      problem_ = "the data ends early (byte " + std::to_string(position_) + ")";
      return false;
    }
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + position_, size);
    position_ += size;
    const bool fileIsLittle = format_ == PlyFormat::BinaryLittle;
    if (fileIsLittle != (std::endian::native == std::endian::little)) {
      for (std::size_t i = 0; i < size / 2; ++i) std::swap(bytes[i], bytes[size - 1 - i]);
    }
    if (type == "char" || type == "int8")
      value = static_cast<std::int8_t>(bytes[0]);
    else if (type == "uchar" || type == "uint8")
      value = bytes[0];
    else if (type == "short" || type == "int16")
      value = load<std::int16_t>(bytes);
    else if (type == "ushort" || type == "uint16")
      value = load<std::uint16_t>(bytes);
    else if (type == "int" || type == "int32")
      value = load<std::int32_t>(bytes);
    else if (type == "uint" || type == "uint32")
      value = load<std::uint32_t>(bytes);
    else if (type == "float" || type == "float32")
      value = load<float>(bytes);
    else
      value = load<double>(bytes);
    return true;
  }

  std::size_t remainingBytes() const { return data_.size() - position_; }
  const std::string& problem() const { return problem_; }

  // Where the last value read (or the failed read) is.
  Diagnostic at(const std::string& message) const {
    if (format_ == PlyFormat::Ascii) return places_.atLine(valueLine_, valueColumn_, message);
    return places_.outside(message + " (byte " + std::to_string(valueOffset_) + ")");
  }

 private:
  template <typename T>
  static T load(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  bool readAscii(double& value) {
    while (position_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[position_]))) {
      if (data_[position_] == '\n') {
        ++line_;
        lineStart_ = position_ + 1;
      }
      ++position_;
    }
    valueLine_ = line_;
    valueColumn_ = static_cast<int>(position_ - lineStart_) + 1;
    if (position_ >= data_.size()) {
      problem_ = "the data ends early";
      return false;
    }
    const std::size_t start = position_;
    while (position_ < data_.size() &&
           !std::isspace(static_cast<unsigned char>(data_[position_]))) {
      ++position_;
    }
    const char* begin = data_.data() + start + (data_[start] == '+' ? 1 : 0);
    const char* end = data_.data() + position_;
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (stop != end || (error != std::errc() && error != std::errc::result_out_of_range)) {
      problem_ = "expected a number, found '" + data_.substr(start, position_ - start) + "'";
      return false;
    }
    if (error == std::errc::result_out_of_range) {
      // from_chars leaves the value alone: too large is infinite, too small is zero.
      const std::string text = data_.substr(start, position_ - start);
      const bool negativeExponent =
          text.find("e-") != std::string::npos || text.find("E-") != std::string::npos;
      value = negativeExponent
                  ? 0.0
                  : (text[0] == '-' ? -1.0 : 1.0) * std::numeric_limits<double>::infinity();
    }
    return true;
  }

  const std::string& data_;
  std::size_t position_;
  int line_;
  std::size_t lineStart_ = 0;
  PlyFormat format_;
  const ProblemPlaces& places_;
  int valueLine_ = 0, valueColumn_ = 0;
  std::size_t valueOffset_ = 0;
  std::string problem_;
};

// The least number of bytes one item of `element` can take: a bound on how many items the rest
// of the file can hold.
std::size_t minimumItemBytes(const PlyElement& element, PlyFormat format) {
  std::size_t bytes = 0;
  for (const PlyProperty& property : element.properties) {
    // ASCII: at least one character and one separator per value; a list at least its count.
    bytes += format == PlyFormat::Ascii
                 ? 2
                 : static_cast<std::size_t>(
                       typeSize(property.countType.empty() ? property.type : property.countType));
  }
  return bytes;
}

bool isFaceIndexList(const PlyElement& element, const PlyProperty& property) {
  return element.name == "face" &&
         (property.name == "vertex_indices" || property.name == "vertex_index");
}

std::optional<Diagnostic> readMesh(const std::string& data, MeshData& mesh,
                                   const ProblemPlaces& places) {
  std::size_t position = 0;
  int lineNumber = 0;
  auto nextLine = [&](std::string& line) {
    if (position >= data.size()) return false;
    std::size_t end = data.find('\n', position);
    if (end == std::string::npos) end = data.size();
    line = data.substr(position, end - position);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    position = std::min(data.size(), end + 1);
    ++lineNumber;
    return true;
  };
  std::string line;
  if (!nextLine(line) || line.rfind("ply", 0) != 0) {
    return places.atLine(1, 1, "not a PLY file (no 'ply' magic)");
  }
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  for (;;) {
    if (!nextLine(line)) return places.atLine(lineNumber, 1, "the PLY header has no end_header");
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string name;
      words >> name;
      if (name == "ascii")
        format = PlyFormat::Ascii;
      else if (name == "binary_little_endian")
        format = PlyFormat::BinaryLittle;
      else if (name == "binary_big_endian")
        format = PlyFormat::BinaryBig;
      else
        return places.atLine(lineNumber, 1, "unknown PLY format '" + name + "'");
    } else if (keyword == "element") {
      PlyElement element;
      std::string count;
      words >> element.name >> count;
      element.line = lineNumber;
      long long value = -1;
      const auto [stop, error] = std::from_chars(count.data(), count.data() + count.size(), value);
      if (error != std::errc() || stop != count.data() + count.size() || value < 0) {
        return places.atLine(
            lineNumber, 1, "element \"" + element.name + "\" has an invalid count '" + count + "'");
      }
      element.count = static_cast<std::uint64_t>(value);
      elements.push_back(element);
    } else if (keyword == "property") {
      if (elements.empty()) return places.atLine(lineNumber, 1, "PLY property before any element");
      PlyProperty property;
      std::string type;
      words >> type;
      if (type == "list") {
        words >> property.countType >> property.type;
      } else {
        property.type = type;
      }
      words >> property.name;
      if (typeSize(property.type) == 0 ||
          (!property.countType.empty() && typeSize(property.countType) == 0)) {
        return places.atLine(lineNumber, 1, "unknown PLY property type in '" + line + "'");
      }
      elements.back().properties.push_back(property);
    }
  }

  PlyValueReader reader(data, position, lineNumber + 1, format, places);
  std::optional<std::uint64_t> vertexCount;
  for (const PlyElement& element : elements) {
    const std::size_t minimum = minimumItemBytes(element, format);
    // + 1: the last ASCII value of a file needs no separator after it.
    if (minimum > 0 && element.count > (reader.remainingBytes() + 1) / minimum) {
      return places.atLine(element.line, 1,
                           "element \"" + element.name + "\" declares " +
                               std::to_string(element.count) + " items, more than the " +
                               std::to_string(reader.remainingBytes()) +
                               " bytes of data after the header can hold");
    }
    // Items without properties take no bytes, so no size bounds their count: a billion of them
    // once kept the reader looping (and a vertex element growing) for minutes (found by
    // tests/fuzz/ply_fuzz.cpp).
    if (element.properties.empty() && element.count > 0) {
      return places.atLine(element.line, 1,
                           "element \"" + element.name + "\" declares " +
                               std::to_string(element.count) + " items but no properties");
    }
    const bool isVertex = element.name == "vertex";
    for (std::uint64_t item = 0; item < element.count; ++item) {
      glm::dvec3 position3{0.0}, normal{0.0};
      glm::dvec2 uv{0.0};
      bool hasNormal = false, hasUv = false;
      for (const PlyProperty& property : element.properties) {
        if (!property.countType.empty()) {
          double countValue = 0;
          if (!reader.read(property.countType, countValue)) return reader.at(reader.problem());
          const std::string what = element.name + " " + std::to_string(item);
          if (countValue < 0 || countValue != std::trunc(countValue) ||
              !std::isfinite(countValue)) {
            return reader.at(what + ": the " + property.name + " list has a count of " +
                             formatValue(countValue));
          }
          const std::size_t itemBytes =
              format == PlyFormat::Ascii ? 1 : static_cast<std::size_t>(typeSize(property.type));
          if (countValue > static_cast<double>(reader.remainingBytes() / itemBytes)) {
            return reader.at(what + ": the " + property.name + " list has a count of " +
                             formatValue(countValue) + ", more than the rest of the file holds");
          }
          const auto count = static_cast<std::size_t>(countValue);
          std::vector<unsigned> polygon(count);
          const bool faceIndices = isFaceIndexList(element, property);
          for (std::size_t k = 0; k < count; ++k) {
            double value = 0;
            if (!reader.read(property.type, value)) return reader.at(reader.problem());
            if (!faceIndices) continue;
            if (!std::isfinite(value) || value != std::trunc(value) || value < 0 ||
                value > std::numeric_limits<unsigned>::max()) {
              return reader.at(what + ": vertex index " + formatValue(value) +
                               " is not a valid index");
            }
            if (vertexCount && value >= static_cast<double>(*vertexCount)) {
              return reader.at(what + ": vertex index " + formatValue(value) +
                               " is out of range (" + std::to_string(*vertexCount) + " vertices)");
            }
            polygon[k] = static_cast<unsigned>(value);
          }
          if (faceIndices) {
            for (std::size_t k = 2; k < count; ++k) {
              mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k - 1], polygon[k]});
            }
          }
          continue;
        }
        double value = 0;
        if (!reader.read(property.type, value)) return reader.at(reader.problem());
        if (!isVertex) continue;
        const std::string& name = property.name;
        if ((name == "x" || name == "y" || name == "z") && !std::isfinite(value)) {
          return reader.at("vertex " + std::to_string(item) + " is not finite (" + name + " is " +
                           formatValue(value) + ")");
        }
        if (name == "x")
          position3.x = value;
        else if (name == "y")
          position3.y = value;
        else if (name == "z")
          position3.z = value;
        else if (name == "nx")
          normal.x = value, hasNormal = true;
        else if (name == "ny")
          normal.y = value;
        else if (name == "nz")
          normal.z = value;
        else if (name == "u" || name == "s" || name == "texture_u" || name == "texture_s") {
          uv.x = value, hasUv = true;
        } else if (name == "v" || name == "t" || name == "texture_v" || name == "texture_t") {
          uv.y = value;
        }
      }
      if (isVertex) {
        mesh.positions.push_back(position3);
        if (hasNormal) mesh.normals.push_back(normal);
        if (hasUv) mesh.uvs.push_back(uv);
      }
    }
    if (isVertex) vertexCount = element.count;
  }
  // Faces read before the vertex element, or in a file without one, could not be checked as they
  // were read (found by tests/fuzz/ply_fuzz.cpp: a misspelt "element vertex" let indices 0 1 2
  // through with no vertex at all).
  for (unsigned index : mesh.indices) {
    if (index >= mesh.positions.size()) {
      return places.outside("vertex index " + std::to_string(index) + " is out of range (" +
                            std::to_string(mesh.positions.size()) + " vertices)");
    }
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) mesh.normals.clear();
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) mesh.uvs.clear();
  return std::nullopt;
}

}  // namespace

bool readPlyMeshData(const std::string& data, const std::string& fileName, MeshData& mesh,
                     const SourceLocation& includedAt, Diagnostics& diagnostics) {
  const std::optional<Diagnostic> problem = readMesh(data, mesh, {fileName, includedAt});
  if (problem) diagnostics.add(*problem);
  return !problem;
}

}  // namespace lenslab::render
