#pragma once
// A built, immutable scene: Embree BVHs (triangle meshes as Embree triangles, quadrics as user
// geometry with exact intersection, object instances as Embree instances), materials,
// textures and lights. Safe to share between threads once built. A scene of few primitives
// answers ray queries without the BVH (FlatPrimitives), with the same results.

#include <embree3/rtcore.h>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

#include "render/analytic_shape.h"
#include "render/flat_primitives.h"
#include "render/light.h"
#include "render/light_selection.h"
#include "render/material.h"
#include "render/texture.h"

namespace lenslab::render {

struct SurfaceHit {
  float t = 0.0f;
  glm::vec3 point{0.0f};
  glm::vec3 geometricNormal{0.0f};  // unit; outward (orientation as pbrt defines it)
  glm::vec3 shadingNormal{0.0f};    // unit; on the same side as geometricNormal
  glm::vec2 uv{0.0f};
  int material = 0;
  int light = -1;               // index into lights() when the surface emits
  float uvPerWorldUnit = 0.0f;  // how fast (u, v) changes along the surface (meshes with uv)
};

// One Embree geometry's own data, indexed by its geomID in its RTCScene.
struct GeometryRecord {
  enum class Kind { Mesh, Quadric, Instance } kind = Kind::Mesh;
  int material = 0;
  int light = -1;
  // Mesh
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<unsigned> indices;
  // Per triangle, computed once at build: the unit geometric normal (xyz, before flipNormal)
  // and the mean texture-space rate per world unit (w; 0 without uvs). Shading a hit then reads
  // 16 bytes instead of three vertices, a cross product, two square roots and two divisions.
  std::vector<glm::vec4> triangleFrames;
  bool flipNormal = false;
  // Quadric
  PlacedQuadric quadric;
  bool quadricNeedsUv = true;  // false when the material ignores (u, v)
  // Instance
  int object = -1;
  glm::mat4 worldFromInstance{1.0f};
  glm::mat3 normalToWorld{1.0f};
  float instanceDeterminant = 1.0f;  // |det| of worldFromInstance's linear part
};

// A shadow ray: does anything lie on origin + t * direction for t in (0, tMax)?
struct ShadowRay {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  float tMax = 0.0f;
};

class Scene {
 public:
  Scene();
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // Nearest hit along origin + t * direction for t in (0, tMax).
  bool intersect(glm::vec3 origin, glm::vec3 direction, float tMax, SurfaceHit& hit) const;
  // Whether anything blocks the segment (0, tMax).
  bool occluded(glm::vec3 origin, glm::vec3 direction, float tMax) const;
  // The same for many rays: blocked[i] = 1 when ray i is blocked. Traced as Embree packets of 8
  // where the CPU supports them, which costs far less per ray than one at a time (shadow rays
  // from one shading point toward one light travel together); one at a time without the BVH.
  void occluded(const ShadowRay* rays, std::size_t count, std::uint8_t* blocked) const;

  const std::vector<Light>& lights() const { return lights_; }
  const std::vector<int>& infiniteLights() const { return infiniteLights_; }
  // How the path tracer picks the light it samples at a bounce.
  const LightSelection& lightSelection() const { return lightSelection_; }
  const Material& material(int index) const { return materials_[static_cast<std::size_t>(index)]; }
  const TextureSet& textures() const { return textures_; }
  float radius() const { return radius_; }
  glm::vec3 center() const { return center_; }
  // Object instances built as copies of their shapes in the top-level scene (see
  // SceneBuilder: small objects), and those kept as Embree instances.
  std::size_t flattenedInstances() const { return flattenedInstances_; }
  std::size_t embreeInstances() const { return embreeInstances_; }
  // Whether ray queries test the few primitives directly (FlatPrimitives) instead of Embree.
  bool queriesWithoutBvh() const { return !flat_.empty(); }

 private:
  friend class SceneBuilder;

  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  bool packets8_ = false;  // Embree traces 8-ray packets natively on this CPU
  std::vector<GeometryRecord> topRecords_;
  FlatPrimitives flat_;  // empty unless the scene is small enough (SceneBuilder decides)
  std::vector<RTCScene> objectScenes_;
  std::vector<std::vector<GeometryRecord>> objectRecords_;
  std::vector<Material> materials_;
  TextureSet textures_;
  std::vector<Light> lights_;
  std::vector<int> infiniteLights_;
  LightSelection lightSelection_;
  glm::vec3 center_{0.0f};
  float radius_ = 1.0f;
  std::size_t flattenedInstances_ = 0, embreeInstances_ = 0;
};

}  // namespace lenslab::render
