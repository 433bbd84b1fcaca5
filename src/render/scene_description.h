#pragma once
// What a pbrt scene file says, resolved into plain data: transforms applied to the directives
// they belong to, meshes read and checked, but nothing built yet (see scene.h for that).

#include <filesystem>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "render/param_set.h"

namespace lenslab::render {

struct CameraDescription {
  std::string type = "perspective";
  // As written; the parser reads it into the fields below (kept for the unused-parameter report).
  ParamSet params;
  // pbrt's camera transform: the CTM when the Camera directive was read (world -> camera).
  glm::dmat4 cameraFromWorld{1.0};
  SourceLocation location;
  // Lens file named by specfile (course, pbrt-v2) or lensfile (pbrt-v3), resolved against the
  // scene file's folder; empty for other cameras.
  std::filesystem::path lensPath;
  // true for the course's pbrt-v2 parameters (specfile ...): its camera space is in mm.
  bool courseParameters = false;

  // "perspective": full field of view across the shorter image side, thin-lens radius and focal
  // distance in scene units (no focal distance given: focused at infinity).
  double fovDegrees = 90.0;
  double lensRadius = 0.0;
  std::optional<double> focalDistance;
  // "realistic": the stop diameter (0: the lens file's own), the course camera's film distance
  // and film diagonal, pbrt-v3's focus distance in scene units.
  double apertureDiameterMm = 0.0;
  double filmDistanceMm = 0.0;
  std::optional<double> filmDiagonalMm;
  double focusDistance = 10.0;
  // "realistic": pbrt-v4's "string aperture": a built-in name (square, pentagon, star, gaussian)
  // as written, or an image file resolved against the scene file's folder; empty without one.
  std::string apertureName;
  std::filesystem::path aperturePath;  // set for an image file
  SourceLocation apertureLocation;
};

struct FilmDescription {
  int xResolution = 640;
  int yResolution = 480;
  double diagonalMm = 35.0;
  std::string filename;
  // pbrt's Film "scale": pixel values are multiplied by it. A scene that gives it sets its own
  // exposure (log2(scale) stops): the viewer's auto exposure is off for it.
  std::optional<double> scale;
};

enum class IntegratorKind { Path, DirectLighting };

struct IntegratorDescription {
  IntegratorKind kind = IntegratorKind::Path;
  int maxDepth = 5;
  bool explicitlyNamed = false;
};

struct TextureDescription {
  std::string name;
  std::string valueType;  // "float" or "color"/"spectrum"
  std::string className;  // constant, scale, checkerboard, imagemap
  ParamSet params;
  std::filesystem::path imagePath;  // imagemap only, resolved
  SourceLocation location;
};

struct MaterialDescription {
  std::string type = "matte";
  ParamSet params;
  SourceLocation location;
};

struct AreaLightDescription {
  glm::dvec3 radiance{1.0};
  bool twoSided = false;
  int samples = 1;
};

// A triangle mesh after reading and checking: positions already in the shape's space.
struct MeshData {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // empty or one per position
  std::vector<glm::dvec2> uvs;      // empty or one per position
  std::vector<unsigned> indices;    // three per triangle
};

struct ShapeDescription {
  std::string type;  // sphere, disk, cone, cylinder, trianglemesh (plymesh becomes one)
  ParamSet params;
  MeshData mesh;
  glm::dmat4 worldFromObject{1.0};  // within an ObjectBegin block: relative to the instance
  int materialIndex = 0;
  std::optional<AreaLightDescription> areaLight;
  bool reverseOrientation = false;
  SourceLocation location;
};

struct LightDescription {
  std::string type;  // point, spot, distant, infinite
  ParamSet params;
  glm::dmat4 worldFromLight{1.0};
  std::filesystem::path mapPath;  // infinite with mapname
  SourceLocation location;
};

struct ObjectDescription {
  std::string name;
  std::vector<ShapeDescription> shapes;
};

struct InstanceDescription {
  int objectIndex = 0;
  glm::dmat4 worldFromInstance{1.0};
};

struct SceneDescription {
  std::filesystem::path sourcePath;
  // The file used pbrt-v2 forms (SurfaceIntegrator, "area" lights, the course camera): some
  // defaults follow pbrt-v2 then.
  bool pbrtV2 = false;
  CameraDescription camera;
  FilmDescription film;
  int pixelSamples = 16;
  IntegratorDescription integrator;
  std::vector<TextureDescription> textures;
  std::vector<MaterialDescription> materials;  // index 0 is the default matte
  std::vector<ShapeDescription> shapes;
  std::vector<LightDescription> lights;
  std::vector<ObjectDescription> objects;
  std::vector<InstanceDescription> instances;
  // The parameters of directives the parser applies itself (Film, Sampler, Integrator,
  // PixelFilter, AreaLightSource), kept for the unused-parameter report.
  std::vector<ParamSet> parsedParams;
};

}  // namespace lenslab::render
