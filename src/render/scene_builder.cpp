#include "render/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <map>

#include "render/unused_parameters.h"

namespace lenslab::render {

namespace {

// ---- Embree user-geometry callbacks for quadrics ----

void quadricBounds(const RTCBoundsFunctionArguments* args) {
  const auto* record = static_cast<const GeometryRecord*>(args->geometryUserPtr);
  glm::dvec3 lower, upper;
  record->quadric.parentBounds(lower, upper);
  args->bounds_o->lower_x = static_cast<float>(lower.x);
  args->bounds_o->lower_y = static_cast<float>(lower.y);
  args->bounds_o->lower_z = static_cast<float>(lower.z);
  args->bounds_o->upper_x = static_cast<float>(upper.x);
  args->bounds_o->upper_y = static_cast<float>(upper.y);
  args->bounds_o->upper_z = static_cast<float>(upper.z);
}

template <typename Args>
std::optional<QuadricHit> quadricHitFor(const Args* args, unsigned i, RTCRayN* ray, bool withUv) {
  const auto* record = static_cast<const GeometryRecord*>(args->geometryUserPtr);
  const unsigned n = args->N;
  const glm::dvec3 origin(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i),
                          RTCRayN_org_z(ray, n, i));
  const glm::dvec3 direction(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i),
                             RTCRayN_dir_z(ray, n, i));
  return record->quadric.intersect(origin, direction, RTCRayN_tnear(ray, n, i),
                                   RTCRayN_tfar(ray, n, i), withUv);
}

void quadricIntersect(const RTCIntersectFunctionNArguments* args) {
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
  const auto* record = static_cast<const GeometryRecord*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const auto found = quadricHitFor(args, i, ray, record->quadricNeedsUv);
    if (!found) continue;
    const glm::dvec3 normal = found->normal;
    const unsigned n = args->N;
    RTCRayN_tfar(ray, n, i) = static_cast<float>(found->t);
    RTCHitN_Ng_x(hit, n, i) = static_cast<float>(normal.x);
    RTCHitN_Ng_y(hit, n, i) = static_cast<float>(normal.y);
    RTCHitN_Ng_z(hit, n, i) = static_cast<float>(normal.z);
    RTCHitN_u(hit, n, i) = static_cast<float>(found->uv.x);
    RTCHitN_v(hit, n, i) = static_cast<float>(found->uv.y);
    RTCHitN_primID(hit, n, i) = args->primID;
    RTCHitN_geomID(hit, n, i) = args->geomID;
    RTCHitN_instID(hit, n, i, 0) = args->context->instID[0];
  }
}

void quadricOccluded(const RTCOccludedFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    if (quadricHitFor(args, i, args->ray, false)) {
      RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
    }
  }
}

glm::vec3 toFloat(glm::dvec3 v) { return glm::vec3(v); }

// Whether `placed` is a whole sphere (no z or phi cut) placed by a similarity, which sampleLight
// may sample by the cone it subtends; if so, its world centre and radius.
bool isWholeSphere(const PlacedQuadric& placed, glm::dvec3& center, double& radius) {
  const Quadric& q = placed.quadric;
  // Relative: rotations written with 7 digits, as exporters write Transform matrices, are
  // orthogonal to about 1e-6; an ellipsoid that close to a sphere is sampled as one with a bias
  // of the same order.
  constexpr double kTolerance = 1e-5;
  if (q.kind != QuadricKind::Sphere || q.zMin > -q.radius * (1.0 - kTolerance) ||
      q.zMax < q.radius * (1.0 - kTolerance) ||
      q.phiMax < glm::two_pi<double>() * (1.0 - kTolerance)) {
    return false;
  }
  // A similarity's linear part M has M^T M = s^2 I.
  const glm::dmat3 m(placed.parentFromObject);
  const glm::dmat3 gram = glm::transpose(m) * m;
  const double scale2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::abs(gram[i][j] - (i == j ? scale2 : 0.0)) > kTolerance * scale2) return false;
    }
  }
  center = glm::dvec3(placed.parentFromObject * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  radius = q.radius * std::sqrt(scale2);
  return true;
}

// GeometryRecord::triangleFrames of a mesh record whose positions, uvs and indices are set.
std::vector<glm::vec4> triangleFrames(const GeometryRecord& record) {
  std::vector<glm::vec4> frames;
  frames.reserve(record.indices.size() / 3);
  for (std::size_t t = 0; t + 2 < record.indices.size(); t += 3) {
    const unsigned* tri = &record.indices[t];
    const glm::vec3 p0 = record.positions[tri[0]];
    // The cross product's length is twice the area: it normalises the normal and gives the
    // world side of the texture-rate ratio.
    const glm::vec3 edgeCross =
        glm::cross(record.positions[tri[1]] - p0, record.positions[tri[2]] - p0);
    const float worldArea = glm::length(edgeCross);
    const glm::vec3 normal = edgeCross * (1.0f / worldArea);
    float uvPerWorldUnit = 0.0f;
    if (!record.uvs.empty()) {
      // sqrt(uv area / world area): the mean (u, v) rate per unit length.
      const glm::vec2 e1 = record.uvs[tri[1]] - record.uvs[tri[0]];
      const glm::vec2 e2 = record.uvs[tri[2]] - record.uvs[tri[0]];
      const float uvArea = std::abs(e1.x * e2.y - e1.y * e2.x);
      uvPerWorldUnit = worldArea > 0.0f ? std::sqrt(uvArea / worldArea) : 0.0f;
    }
    frames.emplace_back(normal, uvPerWorldUnit);
  }
  return frames;
}

}  // namespace

class SceneBuilder {
 public:
  SceneBuilder(const SceneDescription& description, const BuildOptions& options,
               Diagnostics& diagnostics)
      : description_(description),
        options_(options),
        diagnostics_(diagnostics),
        scene_(std::make_shared<Scene>()) {}

  std::shared_ptr<const Scene> build() {
    scene_->device_ = rtcNewDevice(nullptr);
    if (!scene_->device_) {
      diagnostics_.error({description_.sourcePath.string(), 0, 0},
                         "cannot create the Embree device");
      return nullptr;
    }
    buildTextures();
    buildMaterials();
    // Object scenes first: instances refer to them.
    for (std::size_t object = 0; object < description_.objects.size(); ++object) {
      RTCScene objectScene = rtcNewScene(scene_->device_);
      scene_->objectScenes_.push_back(objectScene);
      scene_->objectRecords_.emplace_back();
      scene_->objectRecords_.back().reserve(description_.objects[object].shapes.size());
    }
    for (std::size_t object = 0; object < description_.objects.size(); ++object) {
      for (const ShapeDescription& shape : description_.objects[object].shapes) {
        if (shape.areaLight) {
          diagnostics_.warning(shape.location,
                               "area lights inside object instances are not supported; the "
                               "shape is drawn without emission");
        }
        addShape(scene_->objectScenes_[object], scene_->objectRecords_[object], shape, false);
      }
      rtcCommitScene(scene_->objectScenes_[object]);
    }
    scene_->top_ = rtcNewScene(scene_->device_);
    const std::vector<bool> flatten = instancesToFlatten();
    std::size_t topCount = description_.shapes.size();
    for (std::size_t i = 0; i < description_.instances.size(); ++i) {
      topCount += flatten[i] ? objectOf(description_.instances[i]).shapes.size() : 1;
    }
    scene_->topRecords_.reserve(topCount);  // final: quadric records are pointed to
    for (const ShapeDescription& shape : description_.shapes) {
      addShape(scene_->top_, scene_->topRecords_, shape, true);
    }
    for (std::size_t i = 0; i < description_.instances.size(); ++i) {
      const InstanceDescription& instance = description_.instances[i];
      if (!flatten[i]) {
        addInstance(instance);
        ++scene_->embreeInstances_;
        continue;
      }
      for (ShapeDescription shape : objectOf(instance).shapes) {
        shape.worldFromObject = instance.worldFromInstance * shape.worldFromObject;
        // As inside an Embree instance: no emission (the object loop above warned).
        addShape(scene_->top_, scene_->topRecords_, shape, false, false);
      }
      ++scene_->flattenedInstances_;
    }
    rtcCommitScene(scene_->top_);
    if (scene_->embreeInstances_ == 0 && options_.flatPrimitiveLimit > 0) {
      scene_->flat_.build(scene_->topRecords_, options_.flatPrimitiveLimit);
    }
    scene_->packets8_ =
        rtcGetDeviceProperty(scene_->device_, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0;
    RTCBounds bounds;
    rtcGetSceneBounds(scene_->top_, &bounds);
    if (bounds.lower_x <= bounds.upper_x) {
      const glm::vec3 lower(bounds.lower_x, bounds.lower_y, bounds.lower_z);
      const glm::vec3 upper(bounds.upper_x, bounds.upper_y, bounds.upper_z);
      scene_->center_ = 0.5f * (lower + upper);
      scene_->radius_ = std::max(1e-3f, 0.5f * glm::length(upper - lower));
    }
    buildLights();
    scene_->lightSelection_ = LightSelection(scene_->lights_);
    // Everything that reads parameters has run (the camera's were read by the parser).
    reportUnusedParameters(description_, diagnostics_);
    if (diagnostics_.hasErrors()) return nullptr;
    return scene_;
  }

 private:
  // ---- textures ----
  std::shared_ptr<const FloatImage> loadImage(const std::filesystem::path& path, bool srgb,
                                              const SourceLocation& where) {
    const std::string key = path.string() + (srgb ? "#srgb" : "#linear");
    const auto found = images_.find(key);
    if (found != images_.end()) return found->second;
    ReadResult read = readImage(path, srgb);
    if (!read.ok) {
      diagnostics_.error(where, read.error);
      return nullptr;
    }
    auto image = std::make_shared<const FloatImage>(std::move(read.image));
    images_[key] = image;
    return image;
  }

  int textureParam(const ParamSet& params, const std::string& name, glm::vec3 fallback,
                   const SourceLocation& where) {
    if (const auto textureName = params.getTextureName(name)) {
      const auto found = textureIndex_.find(*textureName);
      if (found != textureIndex_.end()) return found->second;
      diagnostics_.warning(where, "unknown texture \"" + *textureName + "\" for \"" + name +
                                      "\"; a constant is used");
      return scene_->textures_.constant(fallback);
    }
    return scene_->textures_.constant(toFloat(params.getTriple(name, glm::dvec3(fallback))));
  }

  void buildTextures() {
    for (const TextureDescription& description : description_.textures) {
      const ParamSet& params = description.params;
      Texture texture;
      texture.uScale = static_cast<float>(params.getFloat("uscale", 1.0));
      texture.vScale = static_cast<float>(params.getFloat("vscale", 1.0));
      texture.uDelta = static_cast<float>(params.getFloat("udelta", 0.0));
      texture.vDelta = static_cast<float>(params.getFloat("vdelta", 0.0));
      if (params.getString("mapping", "uv") != "uv") {
        params.unsupported("mapping", "uv mapping is used");
      }
      if (description.className == "constant") {
        texture.value = toFloat(params.getTriple("value", glm::dvec3(1.0)));
      } else if (description.className == "scale") {
        texture.kind = TextureKind::Scale;
        texture.first = textureParam(params, "tex1", glm::vec3(1.0f), description.location);
        texture.second = textureParam(params, "tex2", glm::vec3(1.0f), description.location);
      } else if (description.className == "checkerboard") {
        texture.kind = TextureKind::Checkerboard;
        if (params.getFloat("dimension", 2.0) != 2.0) {
          params.unsupported("dimension", "the 2D checkerboard is used");
        }
        params.unsupported("aamode", "the checkerboard is point sampled (no antialiasing)");
        texture.first = textureParam(params, "tex1", glm::vec3(1.0f), description.location);
        texture.second = textureParam(params, "tex2", glm::vec3(0.0f), description.location);
      } else if (description.className == "imagemap") {
        texture.kind = TextureKind::Image;
        const std::string extension = description.imagePath.extension().string();
        // 8-bit images are sRGB-encoded unless the scene says otherwise (pbrt-v3 "gamma").
        const bool srgb = params.getBool("gamma", true);
        texture.image = loadImage(description.imagePath, srgb, description.location);
        if (!texture.image) continue;
        texture.imageScale = static_cast<float>(params.getFloat("scale", 1.0));
        texture.flipT = !description_.pbrtV2;
        texture.coarserMipLevels = buildCoarserMipLevels(*texture.image);
        if (params.getBool("invert", false)) {
          params.unsupported("invert", "the image is used as it is");
        }
        const std::string wrap = params.getString("wrap", "repeat");
        texture.clampWrap = wrap == "clamp";
        texture.blackWrap = wrap == "black";
        if (wrap != "repeat" && wrap != "clamp" && wrap != "black") {
          params.unsupported("wrap", "\"repeat\" is used");
        }
        // Lookups are trilinear (mip-mapped) where the image allows: pbrt-v3's trilinear true.
        if (!params.getBool("trilinear", true)) {
          params.unsupported("trilinear", "trilinear filtering is used instead of EWA");
        }
        params.unsupported("maxanisotropy", "isotropic trilinear filtering is used");
        if (params.getString("filter", "trilinear") != "trilinear") {
          params.unsupported("filter", "trilinear filtering is used");
        }
      }
      textureIndex_[description.name] = scene_->textures_.add(std::move(texture));
    }
  }

  // ---- materials ----
  void buildMaterials() {
    for (const MaterialDescription& description : description_.materials) {
      const ParamSet& params = description.params;
      const SourceLocation& at = description.location;
      Material material;
      if (description.type == "matte") {
        material.kind = MaterialKind::Matte;
        material.kd = textureParam(params, "Kd", glm::vec3(0.5f), at);
        if (params.getFloat("sigma", 0.0) != 0.0) {
          params.unsupported("sigma", "Lambertian reflection is used (no Oren-Nayar roughness)");
        }
      } else if (description.type == "plastic") {
        material.kind = MaterialKind::Plastic;
        material.kd = textureParam(params, "Kd", glm::vec3(0.25f), at);
        material.ks = textureParam(params, "Ks", glm::vec3(0.25f), at);
        material.roughness = textureParam(params, "roughness", glm::vec3(0.1f), at);
        material.remapRoughness = params.getBool("remaproughness", true);
      } else if (description.type == "mirror") {
        material.kind = MaterialKind::Mirror;
        material.kr = textureParam(params, "Kr", glm::vec3(0.9f), at);
      } else if (description.type == "glass") {
        material.kind = MaterialKind::Glass;
        material.kr = textureParam(params, "Kr", glm::vec3(1.0f), at);
        material.kt = textureParam(params, "Kt", glm::vec3(1.0f), at);
        material.eta = static_cast<float>(params.getFloat("index", params.getFloat("eta", 1.5)));
        for (const char* rough : {"roughness", "uroughness", "vroughness"}) {
          if (params.getFloat(rough, 0.0) != 0.0) {
            params.unsupported(rough, "smooth glass is used");
          }
        }
        params.find("remaproughness");
      } else if (description.type == "metal") {
        material.kind = MaterialKind::Metal;
        for (const char* name : {"eta", "k"}) {
          const auto value = params.getTriple(name);
          if (value) (name[0] == 'e' ? material.metalEta : material.metalK) = toFloat(*value);
          if (params.getTextureName(name)) {
            params.unsupported(name,
                               "textures are not supported here; the default (copper) is "
                               "used");
          }
        }
        const char* roughnessName = params.find("roughness") ? "roughness" : "uroughness";
        material.roughness = textureParam(params, roughnessName, glm::vec3(0.01f), at);
        if (roughnessName[0] == 'u' && params.find("vroughness") &&
            params.getFloat("vroughness", 0.01) != params.getFloat("uroughness", 0.01)) {
          params.unsupported("vroughness", "isotropic roughness (uroughness) is used");
        }
        material.remapRoughness = params.getBool("remaproughness", true);
      } else {
        material.kind = MaterialKind::None;  // "none" / "": an interface that only passes light
      }
      params.find("type");
      params.unsupported("bumpmap", "the surface is shaded without bump mapping");
      material.usesUv = materialUsesUv(material, scene_->textures_);
      scene_->materials_.push_back(material);
    }
  }

  // ---- geometry ----
  // `reportProblems` false for the copies of a flattened instance: the object's own pass
  // reported them once.
  void addShape(RTCScene target, std::vector<GeometryRecord>& records,
                const ShapeDescription& shape, bool allowEmission, bool reportProblems = true) {
    GeometryRecord record;
    record.material = shape.materialIndex;
    const ParamSet& params = shape.params;
    RTCGeometry geometry = nullptr;
    if (shape.type == "trianglemesh") {
      const glm::dmat4& m = shape.worldFromObject;
      const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m)));
      for (const glm::dvec3& p : shape.mesh.positions) {
        record.positions.push_back(toFloat(glm::dvec3(m * glm::dvec4(p, 1.0))));
      }
      for (const glm::dvec3& n : shape.mesh.normals) {
        record.normals.push_back(toFloat(glm::normalize(normalMatrix * n)));
      }
      for (const glm::dvec2& uv : shape.mesh.uvs) record.uvs.push_back(glm::vec2(uv));
      record.indices = shape.mesh.indices;
      record.flipNormal = shape.reverseOrientation != (glm::determinant(glm::dmat3(m)) < 0.0);
      if (record.indices.empty()) return;
      record.triangleFrames = triangleFrames(record);
      geometry = rtcNewGeometry(scene_->device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* vertices = static_cast<float*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                  3 * sizeof(float), record.positions.size()));
      for (std::size_t i = 0; i < record.positions.size(); ++i) {
        vertices[3 * i] = record.positions[i].x;
        vertices[3 * i + 1] = record.positions[i].y;
        vertices[3 * i + 2] = record.positions[i].z;
      }
      auto* indices = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                  3 * sizeof(unsigned), record.indices.size() / 3));
      std::copy(record.indices.begin(), record.indices.end(), indices);
    } else {
      record.kind = GeometryRecord::Kind::Quadric;
      Quadric& q = record.quadric.quadric;
      const double phiMaxDegrees = std::clamp(params.getFloat("phimax", 360.0), 0.0, 360.0);
      q.phiMax = glm::radians(phiMaxDegrees);
      q.radius = params.getFloat("radius", 1.0);
      if (shape.type == "sphere") {
        q.kind = QuadricKind::Sphere;
        q.zMin = std::clamp(params.getFloat("zmin", -q.radius), -q.radius, q.radius);
        q.zMax = std::clamp(params.getFloat("zmax", q.radius), -q.radius, q.radius);
        if (q.zMin > q.zMax) std::swap(q.zMin, q.zMax);
      } else if (shape.type == "disk") {
        q.kind = QuadricKind::Disk;
        q.height = params.getFloat("height", 0.0);
        q.innerRadius = params.getFloat("innerradius", 0.0);
      } else if (shape.type == "cylinder") {
        q.kind = QuadricKind::Cylinder;
        q.zMin = params.getFloat("zmin", -1.0);
        q.zMax = params.getFloat("zmax", 1.0);
        if (q.zMin > q.zMax) std::swap(q.zMin, q.zMax);
      } else {
        q.kind = QuadricKind::Cone;
        q.height = params.getFloat("height", 1.0);
      }
      if (!(q.radius > 0.0) || (q.kind == QuadricKind::Cone && !(q.height > 0.0))) {
        if (reportProblems) {
          diagnostics_.warning(shape.location, "degenerate " + shape.type + "; it is left out");
        }
        return;
      }
      record.quadric.place(shape.worldFromObject, shape.reverseOrientation);
      record.quadricNeedsUv = scene_->materials_[static_cast<std::size_t>(record.material)].usesUv;
      geometry = rtcNewGeometry(scene_->device_, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(geometry, 1);
    }

    if (shape.areaLight && allowEmission) record.light = addAreaLight(shape, record);
    records.push_back(std::move(record));
    GeometryRecord& stored = records.back();
    if (stored.kind == GeometryRecord::Kind::Quadric) {
      // records has its final capacity (reserved), so this pointer stays valid.
      rtcSetGeometryUserData(geometry, &stored);
      rtcSetGeometryBoundsFunction(geometry, quadricBounds, nullptr);
      rtcSetGeometryIntersectFunction(geometry, quadricIntersect);
      rtcSetGeometryOccludedFunction(geometry, quadricOccluded);
    }
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(target, geometry);
    rtcReleaseGeometry(geometry);
    if (id != records.size() - 1) {
      diagnostics_.error(shape.location, "internal: Embree geometry ids out of step");
    }
  }

  // ---- instances ----
  const ObjectDescription& objectOf(const InstanceDescription& instance) const {
    return description_.objects[static_cast<std::size_t>(instance.objectIndex)];
  }

  // Which instances become copies of their object's shapes in the top-level scene. Embree's
  // instances cost a second traversal and a transform per ray that reaches them, which for a
  // small object is most of its cost (the default scene's seven posts, a cylinder and a disk
  // each: 13% of the render time at one sample per pixel). Copies of a big object would cost
  // memory instead, so only objects of at most kFlattenPrimitives primitives are copied, and at
  // most kFlattenBudget primitives in all, in the file's order.
  static constexpr std::size_t kFlattenPrimitives = 64;
  static constexpr std::size_t kFlattenBudget = std::size_t{1} << 18;
  std::vector<bool> instancesToFlatten() const {
    std::vector<std::size_t> primitives(description_.objects.size(), 0);
    for (std::size_t o = 0; o < description_.objects.size(); ++o) {
      for (const ShapeDescription& shape : description_.objects[o].shapes) {
        primitives[o] += shape.type == "trianglemesh" ? shape.mesh.indices.size() / 3 : 1;
      }
    }
    std::vector<bool> flatten(description_.instances.size(), false);
    std::size_t spent = 0;
    for (std::size_t i = 0; i < description_.instances.size(); ++i) {
      const auto object = static_cast<std::size_t>(description_.instances[i].objectIndex);
      if (primitives[object] <= kFlattenPrimitives &&
          spent + primitives[object] <= kFlattenBudget) {
        flatten[i] = true;
        spent += primitives[object];
      }
    }
    return flatten;
  }

  void addInstance(const InstanceDescription& instance) {
    GeometryRecord record;
    record.kind = GeometryRecord::Kind::Instance;
    record.object = instance.objectIndex;
    record.worldFromInstance = glm::mat4(instance.worldFromInstance);
    record.normalToWorld =
        glm::mat3(glm::transpose(glm::inverse(glm::dmat3(instance.worldFromInstance))));
    record.instanceDeterminant =
        static_cast<float>(std::abs(glm::determinant(glm::dmat3(instance.worldFromInstance))));
    RTCGeometry geometry = rtcNewGeometry(scene_->device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(geometry,
                                 scene_->objectScenes_[static_cast<std::size_t>(record.object)]);
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR,
                            &record.worldFromInstance[0][0]);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_->top_, geometry);
    rtcReleaseGeometry(geometry);
    scene_->topRecords_.push_back(std::move(record));
  }

  // ---- lights ----
  int addAreaLight(const ShapeDescription& shape, const GeometryRecord& record) {
    auto emitter = std::make_shared<Emitter>();
    if (record.kind == GeometryRecord::Kind::Mesh) {
      float total = 0.0f;
      for (std::size_t t = 0; t < record.indices.size(); t += 3) {
        const glm::vec3 a = record.positions[record.indices[t]];
        const glm::vec3 b = record.positions[record.indices[t + 1]];
        const glm::vec3 c = record.positions[record.indices[t + 2]];
        emitter->triangles.insert(emitter->triangles.end(), {a, b, c});
        total += 0.5f * glm::length(glm::cross(b - a, c - a));
        emitter->cumulativeArea.push_back(total);
      }
      emitter->area = total;
      emitter->flipNormal = record.flipNormal;
    } else {
      emitter->isQuadric = true;
      emitter->quadric = record.quadric;
      // Area scales by |det|^(2/3) under a similarity transform.
      const double det = std::abs(glm::determinant(glm::dmat3(record.quadric.parentFromObject)));
      emitter->areaScale = std::pow(det, 2.0 / 3.0);
      emitter->area = static_cast<float>(record.quadric.quadric.area() * emitter->areaScale);
      emitter->flipNormal = record.quadric.flipNormal;
      if (record.quadric.quadric.kind == QuadricKind::Disk) {
        emitter->isDisk = true;
        emitter->disk = PlanarDisk::fromPlaced(record.quadric, emitter->flipNormal);
        emitter->area = emitter->disk.area;
      }
      emitter->isSphere =
          isWholeSphere(record.quadric, emitter->sphereCenter, emitter->sphereRadius);
    }
    Light light;
    light.kind = LightKind::Area;
    light.intensity = toFloat(shape.areaLight->radiance);
    light.twoSided = shape.areaLight->twoSided;
    light.samples = shape.areaLight->samples;
    light.emitter = std::move(emitter);
    scene_->lights_.push_back(std::move(light));
    return static_cast<int>(scene_->lights_.size()) - 1;
  }

  // The unit world direction of `from - to` in light space, or nothing (with a warning) when
  // from and to coincide.
  std::optional<glm::vec3> lightDirection(const LightDescription& description, glm::dvec3 vector) {
    const glm::dvec3 world = glm::dvec3(description.worldFromLight * glm::dvec4(vector, 0.0));
    if (!(glm::length(world) > 0.0)) {
      diagnostics_.warning(description.location, "light \"" + description.type +
                                                     "\" has \"from\" equal to \"to\" (no "
                                                     "direction); the light is left out");
      return std::nullopt;
    }
    return toFloat(glm::normalize(world));
  }

  void buildLights() {
    for (const LightDescription& description : description_.lights) {
      const ParamSet& params = description.params;
      const glm::dmat4& m = description.worldFromLight;
      const double scale = params.getFloat("scale", 1.0);
      Light light;
      if (description.type == "point" || description.type == "spot") {
        light.kind = description.type == "point" ? LightKind::Point : LightKind::Spot;
        light.intensity = toFloat(params.getTriple("I", glm::dvec3(1.0)) * scale);
        const glm::dvec3 from = params.getTriple("from", glm::dvec3(0.0));
        light.position = toFloat(glm::dvec3(m * glm::dvec4(from, 1.0)));
        if (light.kind == LightKind::Spot) {
          const glm::dvec3 to = params.getTriple("to", glm::dvec3(0.0, 0.0, 1.0));
          const auto direction = lightDirection(description, to - from);
          if (!direction) continue;
          light.direction = *direction;
          const double cone = params.getFloat("coneangle", 30.0);
          const double delta = params.getFloat("conedelta", 5.0);
          light.cosTotalWidth = static_cast<float>(std::cos(glm::radians(cone)));
          light.cosFalloffStart = static_cast<float>(std::cos(glm::radians(cone - delta)));
        }
      } else if (description.type == "distant") {
        light.kind = LightKind::Distant;
        light.intensity = toFloat(params.getTriple("L", glm::dvec3(1.0)) * scale);
        const glm::dvec3 from = params.getTriple("from", glm::dvec3(0.0));
        const glm::dvec3 to = params.getTriple("to", glm::dvec3(0.0, 0.0, 1.0));
        const auto direction = lightDirection(description, from - to);
        if (!direction) continue;
        light.direction = *direction;
      } else {
        light.kind = LightKind::Infinite;
        light.intensity = toFloat(params.getTriple("L", glm::dvec3(1.0)) * scale);
        constexpr int kMaxSamples = 4096;
        const auto v2Samples = params.getInt("samples", 1, 1, kMaxSamples, diagnostics_);
        const auto samples =
            params.getInt("nsamples", v2Samples.value_or(1), 1, kMaxSamples, diagnostics_);
        if (!samples || !v2Samples) continue;
        light.samples = *samples;
        light.lightFromWorld = glm::mat3(glm::inverse(glm::dmat3(m)));
        if (!description.mapPath.empty()) {
          params.find("mapname");
          params.find("filename");
          light.map = loadImage(description.mapPath, true, description.location);
          if (!light.map) continue;
        }
        scene_->infiniteLights_.push_back(static_cast<int>(scene_->lights_.size()));
      }
      scene_->lights_.push_back(std::move(light));
    }
  }

  const SceneDescription& description_;
  const BuildOptions options_;
  Diagnostics& diagnostics_;
  std::shared_ptr<Scene> scene_;
  std::map<std::string, int> textureIndex_;
  std::map<std::string, std::shared_ptr<const FloatImage>> images_;
};

BuildResult buildScene(const SceneDescription& description, const BuildOptions& options) {
  BuildResult result;
  SceneBuilder builder(description, options, result.diagnostics);
  result.scene = builder.build();
  return result;
}

}  // namespace lenslab::render
