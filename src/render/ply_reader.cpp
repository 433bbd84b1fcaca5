#include "render/ply_reader.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

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
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
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

class PlyValueReader {
 public:
  PlyValueReader(std::istream& input, PlyFormat format) : input_(input), format_(format) {}

  bool read(const std::string& type, double& value) {
    if (format_ == PlyFormat::Ascii) return static_cast<bool>(input_ >> value);
    const int size = typeSize(type);
    unsigned char bytes[8];
    if (!input_.read(reinterpret_cast<char*>(bytes), size)) return false;
    const bool fileIsLittle = format_ == PlyFormat::BinaryLittle;
    if (fileIsLittle != (std::endian::native == std::endian::little)) {
      for (int i = 0; i < size / 2; ++i) std::swap(bytes[i], bytes[size - 1 - i]);
    }
    if (type == "char" || type == "int8") value = static_cast<std::int8_t>(bytes[0]);
    else if (type == "uchar" || type == "uint8") value = bytes[0];
    else if (type == "short" || type == "int16") value = load<std::int16_t>(bytes);
    else if (type == "ushort" || type == "uint16") value = load<std::uint16_t>(bytes);
    else if (type == "int" || type == "int32") value = load<std::int32_t>(bytes);
    else if (type == "uint" || type == "uint32") value = load<std::uint32_t>(bytes);
    else if (type == "float" || type == "float32") value = load<float>(bytes);
    else value = load<double>(bytes);
    return true;
  }

 private:
  template <typename T>
  static T load(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }
  std::istream& input_;
  PlyFormat format_;
};

}  // namespace

std::optional<std::string> readPlyMesh(const std::filesystem::path& path, MeshData& mesh) {
  std::ifstream input(path, std::ios::binary);
  if (!input) return "cannot open PLY file " + path.string();
  std::string line;
  std::getline(input, line);
  if (line.rfind("ply", 0) != 0) return path.string() + " is not a PLY file (no 'ply' magic)";
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  for (;;) {
    if (!std::getline(input, line)) return path.string() + ": PLY header has no end_header";
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string name;
      words >> name;
      if (name == "ascii") format = PlyFormat::Ascii;
      else if (name == "binary_little_endian") format = PlyFormat::BinaryLittle;
      else if (name == "binary_big_endian") format = PlyFormat::BinaryBig;
      else return path.string() + ": unknown PLY format '" + name + "'";
    } else if (keyword == "element") {
      PlyElement element;
      words >> element.name >> element.count;
      elements.push_back(element);
    } else if (keyword == "property") {
      if (elements.empty()) return path.string() + ": PLY property before any element";
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
        return path.string() + ": unknown PLY property type in '" + line + "'";
      }
      elements.back().properties.push_back(property);
    }
  }

  PlyValueReader reader(input, format);
  for (const PlyElement& element : elements) {
    const bool isVertex = element.name == "vertex";
    const bool isFace = element.name == "face";
    for (std::size_t item = 0; item < element.count; ++item) {
      glm::dvec3 position{0.0}, normal{0.0};
      glm::dvec2 uv{0.0};
      bool hasNormal = false, hasUv = false;
      for (const PlyProperty& property : element.properties) {
        if (!property.countType.empty()) {
          double countValue = 0;
          if (!reader.read(property.countType, countValue)) {
            return path.string() + ": PLY data ends early";
          }
          const auto count = static_cast<std::size_t>(countValue);
          std::vector<unsigned> polygon(count);
          for (std::size_t k = 0; k < count; ++k) {
            double value = 0;
            if (!reader.read(property.type, value)) return path.string() + ": PLY data ends early";
            polygon[k] = static_cast<unsigned>(value);
          }
          if (isFace && (property.name == "vertex_indices" || property.name == "vertex_index")) {
            // A fan splits convex polygons; PLY meshes in practice hold triangles and quads.
            for (std::size_t k = 2; k < count; ++k) {
              mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k - 1], polygon[k]});
            }
          }
          continue;
        }
        double value = 0;
        if (!reader.read(property.type, value)) return path.string() + ": PLY data ends early";
        if (!isVertex) continue;
        const std::string& name = property.name;
        if (name == "x") position.x = value;
        else if (name == "y") position.y = value;
        else if (name == "z") position.z = value;
        else if (name == "nx") normal.x = value, hasNormal = true;
        else if (name == "ny") normal.y = value;
        else if (name == "nz") normal.z = value;
        else if (name == "u" || name == "s" || name == "texture_u" || name == "texture_s") {
          uv.x = value, hasUv = true;
        } else if (name == "v" || name == "t" || name == "texture_v" || name == "texture_t") {
          uv.y = value;
        }
      }
      if (isVertex) {
        mesh.positions.push_back(position);
        if (hasNormal) mesh.normals.push_back(normal);
        if (hasUv) mesh.uvs.push_back(uv);
      }
    }
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) mesh.normals.clear();
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) mesh.uvs.clear();
  return std::nullopt;
}

}  // namespace lenslab::render
