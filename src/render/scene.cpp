#include "render/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace lenslab::render {

Scene::Scene() = default;

Scene::~Scene() {
  for (RTCScene scene : objectScenes_) rtcReleaseScene(scene);
  if (top_) rtcReleaseScene(top_);
  if (device_) rtcReleaseDevice(device_);
}

namespace {

void fillShadingFromRecord(const GeometryRecord& record, const RTCHit& embreeHit, SurfaceHit& hit) {
  hit.material = record.material;
  hit.light = record.light;
  if (record.kind == GeometryRecord::Kind::Mesh) {
    const unsigned* tri = &record.indices[3 * embreeHit.primID];
    const glm::vec4 frame = record.triangleFrames[embreeHit.primID];
    const float b1 = embreeHit.u, b2 = embreeHit.v, b0 = 1.0f - b1 - b2;
    glm::vec3 n(frame);
    if (!record.normals.empty()) {
      glm::vec3 ns =
          b0 * record.normals[tri[0]] + b1 * record.normals[tri[1]] + b2 * record.normals[tri[2]];
      const float length = glm::length(ns);
      ns = length > 0.0f ? ns * (1.0f / length) : n;
      // pbrt orients the geometric normal by the shading normal when a mesh has normals.
      if (glm::dot(n, ns) < 0.0f) n = -n;
      hit.shadingNormal = ns;
    } else {
      if (record.flipNormal) n = -n;
      hit.shadingNormal = n;
    }
    hit.geometricNormal = n;
    if (!record.uvs.empty()) {
      hit.uv = b0 * record.uvs[tri[0]] + b1 * record.uvs[tri[1]] + b2 * record.uvs[tri[2]];
      hit.uvPerWorldUnit = frame.w;
    } else {
      // pbrt's default parametrisation: (0,0), (1,0), (1,1) at the three vertices.
      hit.uv = glm::vec2(b1 + b2, b2);
    }
  } else {
    // The quadric's intersect callback left the parent-space normal in Ng and (u, v).
    glm::vec3 n = glm::normalize(glm::vec3(embreeHit.Ng_x, embreeHit.Ng_y, embreeHit.Ng_z));
    if (record.quadric.flipNormal) n = -n;
    hit.geometricNormal = n;
    hit.shadingNormal = n;
    hit.uv = glm::vec2(embreeHit.u, embreeHit.v);
  }
}

RTCRayHit makeRayHit(glm::vec3 origin, glm::vec3 direction, float tMax) {
  RTCRayHit rayHit;
  rayHit.ray.org_x = origin.x;
  rayHit.ray.org_y = origin.y;
  rayHit.ray.org_z = origin.z;
  rayHit.ray.dir_x = direction.x;
  rayHit.ray.dir_y = direction.y;
  rayHit.ray.dir_z = direction.z;
  rayHit.ray.tnear = 0.0f;
  rayHit.ray.tfar = tMax;
  rayHit.ray.time = 0.0f;
  rayHit.ray.mask = 0xFFFFFFFFu;
  rayHit.ray.id = 0;
  rayHit.ray.flags = 0;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rayHit;
}

}  // namespace

bool Scene::intersect(glm::vec3 origin, glm::vec3 direction, float tMax, SurfaceHit& hit) const {
  if (!flat_.empty()) {
    FlatHit flatHit;
    if (!flat_.intersect(topRecords_, origin, direction, tMax, flatHit)) return false;
    hit.t = flatHit.t;
    hit.point = origin + hit.t * direction;
    RTCHit asEmbree;
    asEmbree.Ng_x = flatHit.normal.x;
    asEmbree.Ng_y = flatHit.normal.y;
    asEmbree.Ng_z = flatHit.normal.z;
    asEmbree.u = flatHit.u;
    asEmbree.v = flatHit.v;
    asEmbree.primID = flatHit.primitive;
    asEmbree.geomID = flatHit.record;
    fillShadingFromRecord(topRecords_[flatHit.record], asEmbree, hit);
    return true;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit = makeRayHit(origin, direction, tMax);
  rtcIntersect1(top_, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = rayHit.ray.tfar;
  hit.point = origin + hit.t * direction;
  const unsigned instance = rayHit.hit.instID[0];
  if (instance == RTC_INVALID_GEOMETRY_ID) {
    fillShadingFromRecord(topRecords_[rayHit.hit.geomID], rayHit.hit, hit);
  } else {
    const GeometryRecord& instanceRecord = topRecords_[instance];
    fillShadingFromRecord(
        objectRecords_[static_cast<std::size_t>(instanceRecord.object)][rayHit.hit.geomID],
        rayHit.hit, hit);
    const glm::vec3 normal = instanceRecord.normalToWorld * hit.geometricNormal;
    if (hit.uvPerWorldUnit > 0.0f) {
      // A triangle's world area is |det| |normalToWorld n| times its area in the object's space
      // (n its unit normal there): the texture rate per world unit, as a top-level copy of the
      // mesh would have it, is the object-space rate over the square root of that.
      hit.uvPerWorldUnit /= std::sqrt(instanceRecord.instanceDeterminant * glm::length(normal));
    }
    hit.geometricNormal = glm::normalize(normal);
    hit.shadingNormal = glm::normalize(instanceRecord.normalToWorld * hit.shadingNormal);
    hit.light = -1;  // emitters inside instances are not lights (a warning said so)
  }
  return true;
}

void Scene::occluded(const ShadowRay* rays, std::size_t count, std::uint8_t* blocked) const {
  if (!packets8_ || !flat_.empty()) {
    for (std::size_t i = 0; i < count; ++i) {
      blocked[i] = occluded(rays[i].origin, rays[i].direction, rays[i].tMax) ? 1 : 0;
    }
    return;
  }
  for (std::size_t first = 0; first < count; first += 8) {
    const std::size_t n = std::min<std::size_t>(8, count - first);
    if (n == 1) {  // a lone ray: the packet's set-up would cost more than it saves
      blocked[first] = occluded(rays[first].origin, rays[first].direction, rays[first].tMax);
      continue;
    }
    alignas(32) int valid[8];
    alignas(32) RTCRay8 packet;
    for (std::size_t k = 0; k < 8; ++k) {
      const ShadowRay& ray = rays[first + std::min(k, n - 1)];
      valid[k] = k < n ? -1 : 0;
      packet.org_x[k] = ray.origin.x;
      packet.org_y[k] = ray.origin.y;
      packet.org_z[k] = ray.origin.z;
      packet.dir_x[k] = ray.direction.x;
      packet.dir_y[k] = ray.direction.y;
      packet.dir_z[k] = ray.direction.z;
      packet.tnear[k] = 0.0f;
      packet.tfar[k] = ray.tMax;
      packet.time[k] = 0.0f;
      packet.mask[k] = 0xFFFFFFFFu;
      packet.id[k] = static_cast<unsigned>(k);
      packet.flags[k] = 0;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded8(valid, top_, &context, &packet);
    for (std::size_t k = 0; k < n; ++k) blocked[first + k] = packet.tfar[k] < 0.0f ? 1 : 0;
  }
}

bool Scene::occluded(glm::vec3 origin, glm::vec3 direction, float tMax) const {
  if (!flat_.empty()) return flat_.occluded(topRecords_, origin, direction, tMax);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = makeRayHit(origin, direction, tMax).ray;
  rtcOccluded1(top_, &context, &ray);
  return ray.tfar < 0.0f;
}

}  // namespace lenslab::render
