#include "render/flat_primitives.h"

#include <immintrin.h>

// GCC 12's AVX-512 intrinsics start from _mm512_undefined_* values, which -Wmaybe-uninitialized
// reports in every caller (GCC bug 105593, fixed in GCC 13).
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>

#include "render/scene.h"

namespace lenslab::render {

namespace {

// A box is entered when its entry distance is at most its exit distance. Both are rounded (two
// roundings each, relative error below 2^-23), so the exit is stretched by 2^-20 of itself: a
// ray that grazes a box is kept, and the exact test decides.
constexpr float kExitSlack = 1.0f + 1.0f / (1 << 20);

// 1 / d per axis, with |d| kept at least 1e-20 so that (bound - origin) / d stays finite: a
// direction along a box face then gives +-huge instead of 0 * inf = NaN.
glm::vec3 safeInverse(glm::vec3 direction) {
  // One SSE division for the three axes (SSE is part of x86-64).
  const __m128 d = _mm_setr_ps(direction.x, direction.y, direction.z, 1.0f);
  const __m128 signBit = _mm_set1_ps(-0.0f);
  const __m128 magnitude = _mm_max_ps(_mm_andnot_ps(signBit, d), _mm_set1_ps(1e-20f));
  const __m128 inverse =
      _mm_div_ps(_mm_set1_ps(1.0f), _mm_or_ps(magnitude, _mm_and_ps(signBit, d)));
  alignas(16) float lanes[4];
  _mm_store_ps(lanes, inverse);
  return {lanes[0], lanes[1], lanes[2]};
}

// The boxes' six bounds, each an array of `padded` floats: lower x, y, z, then upper x, y, z.
struct BoxArrays {
  const float* bounds;
  std::size_t padded;  // a multiple of 16
  const float* lower(int axis) const { return bounds + axis * padded; }
  const float* upper(int axis) const { return bounds + (3 + axis) * padded; }
};

std::uint64_t boxesEnteredPortable(const BoxArrays& boxes, glm::vec3 origin, glm::vec3 inverse,
                                   float tMax, float* entry) {
  std::uint64_t entered = 0;
  for (std::size_t i = 0; i < boxes.padded; ++i) {
    float near = 0.0f, far = tMax;
    for (int axis = 0; axis < 3; ++axis) {
      const float t0 = (boxes.lower(axis)[i] - origin[axis]) * inverse[axis];
      const float t1 = (boxes.upper(axis)[i] - origin[axis]) * inverse[axis];
      near = std::max(near, std::min(t0, t1));
      far = std::min(far, std::max(t0, t1));
    }
    entry[i] = near;
    if (near <= far * kExitSlack) entered |= std::uint64_t{1} << i;
  }
  return entered;
}

// The same, eight boxes at a time.
__attribute__((target("avx2"))) std::uint64_t boxesEnteredAvx2(const BoxArrays& boxes,
                                                               glm::vec3 origin, glm::vec3 inverse,
                                                               float tMax, float* entry) {
  const __m256 slack = _mm256_set1_ps(kExitSlack);
  std::uint64_t entered = 0;
  for (std::size_t first = 0; first < boxes.padded; first += 8) {
    __m256 near = _mm256_setzero_ps(), far = _mm256_set1_ps(tMax);
    for (int axis = 0; axis < 3; ++axis) {
      const __m256 o = _mm256_set1_ps(origin[axis]);
      const __m256 inv = _mm256_set1_ps(inverse[axis]);
      const __m256 t0 =
          _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(boxes.lower(axis) + first), o), inv);
      const __m256 t1 =
          _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(boxes.upper(axis) + first), o), inv);
      near = _mm256_max_ps(near, _mm256_min_ps(t0, t1));
      far = _mm256_min_ps(far, _mm256_max_ps(t0, t1));
    }
    _mm256_storeu_ps(entry + first, near);
    const __m256 in = _mm256_cmp_ps(near, _mm256_mul_ps(far, slack), _CMP_LE_OQ);
    entered |= static_cast<std::uint64_t>(_mm256_movemask_ps(in)) << first;
  }
  return entered;
}

// The same, sixteen boxes at a time: the default scene's 22 primitives take two steps, not three.
__attribute__((target("avx512f"))) std::uint64_t boxesEnteredAvx512(const BoxArrays& boxes,
                                                                    glm::vec3 origin,
                                                                    glm::vec3 inverse, float tMax,
                                                                    float* entry) {
  const __m512 slack = _mm512_set1_ps(kExitSlack);
  std::uint64_t entered = 0;
  for (std::size_t first = 0; first < boxes.padded; first += 16) {
    __m512 near = _mm512_setzero_ps(), far = _mm512_set1_ps(tMax);
    for (int axis = 0; axis < 3; ++axis) {
      const __m512 o = _mm512_set1_ps(origin[axis]);
      const __m512 inv = _mm512_set1_ps(inverse[axis]);
      const __m512 t0 =
          _mm512_mul_ps(_mm512_sub_ps(_mm512_loadu_ps(boxes.lower(axis) + first), o), inv);
      const __m512 t1 =
          _mm512_mul_ps(_mm512_sub_ps(_mm512_loadu_ps(boxes.upper(axis) + first), o), inv);
      near = _mm512_max_ps(near, _mm512_min_ps(t0, t1));
      far = _mm512_min_ps(far, _mm512_max_ps(t0, t1));
    }
    _mm512_storeu_ps(entry + first, near);
    const __mmask16 in = _mm512_cmp_ps_mask(near, _mm512_mul_ps(far, slack), _CMP_LE_OQ);
    entered |= static_cast<std::uint64_t>(in) << first;
  }
  return entered;
}

using BoxTest = std::uint64_t (*)(const BoxArrays&, glm::vec3, glm::vec3, float, float*);

std::atomic<FlatPrimitives::BoxTestKind> boxTestKind{FlatPrimitives::BoxTestKind::Fastest};

BoxTest boxTest() {
  static const BoxTest fastest = __builtin_cpu_supports("avx512f") ? boxesEnteredAvx512
                                 : __builtin_cpu_supports("avx2")  ? boxesEnteredAvx2
                                                                   : boxesEnteredPortable;
  switch (boxTestKind.load(std::memory_order_relaxed)) {
    case FlatPrimitives::BoxTestKind::Fastest:
      return fastest;
    case FlatPrimitives::BoxTestKind::Avx2:
      return boxesEnteredAvx2;
    case FlatPrimitives::BoxTestKind::Portable:
      return boxesEnteredPortable;
  }
  return fastest;
}

// Moller-Trumbore: the hit's t in (0, tMax) and barycentrics (u, v) of vertices 1 and 2.
bool intersectTriangle(glm::vec3 vertex0, glm::vec3 edge1, glm::vec3 edge2, glm::vec3 origin,
                       glm::vec3 direction, float tMax, float& t, float& u, float& v) {
  const glm::vec3 p = glm::cross(direction, edge2);
  const float determinant = glm::dot(edge1, p);
  if (determinant == 0.0f) return false;  // parallel to the plane
  const float inverse = 1.0f / determinant;
  const glm::vec3 s = origin - vertex0;
  u = glm::dot(s, p) * inverse;
  if (!(u >= 0.0f && u <= 1.0f)) return false;
  const glm::vec3 q = glm::cross(s, edge1);
  v = glm::dot(direction, q) * inverse;
  if (!(v >= 0.0f && u + v <= 1.0f)) return false;
  t = glm::dot(edge2, q) * inverse;
  return t > 0.0f && t < tMax;
}

}  // namespace

bool FlatPrimitives::useBoxTest(BoxTestKind kind) {
  if (kind == BoxTestKind::Avx2 && !__builtin_cpu_supports("avx2")) return false;
  boxTestKind.store(kind);
  return true;
}

bool FlatPrimitives::build(const std::vector<GeometryRecord>& records, std::size_t limit) {
  primitives_.clear();
  bounds_.clear();
  padded_ = 0;
  limit = std::min(limit, kMaxPrimitives);
  std::size_t count = 0;
  for (const GeometryRecord& record : records) {
    if (record.kind == GeometryRecord::Kind::Instance) return false;
    count += record.kind == GeometryRecord::Kind::Mesh ? record.indices.size() / 3 : 1;
  }
  if (count == 0 || count > limit) return false;
  // Padded to whole groups of sixteen with NaN boxes, which boxesEntered masks off.
  padded_ = (count + 15) / 16 * 16;
  bounds_.assign(6 * padded_, std::nanf(""));
  const auto addBox = [this](glm::dvec3 lower, glm::dvec3 upper) {
    const std::size_t i = primitives_.size() - 1;
    for (int axis = 0; axis < 3; ++axis) {
      bounds_[axis * padded_ + i] = static_cast<float>(lower[axis]);
      bounds_[(3 + axis) * padded_ + i] = static_cast<float>(upper[axis]);
    }
  };
  for (std::size_t r = 0; r < records.size(); ++r) {
    const GeometryRecord& record = records[r];
    if (record.kind == GeometryRecord::Kind::Quadric) {
      Primitive primitive;
      primitive.record = static_cast<unsigned>(r);
      primitives_.push_back(primitive);
      glm::dvec3 lower, upper;
      record.quadric.parentBounds(lower, upper);
      addBox(lower, upper);
      continue;
    }
    for (std::size_t t = 0; t + 2 < record.indices.size(); t += 3) {
      Primitive primitive;
      primitive.record = static_cast<unsigned>(r);
      primitive.triangle = static_cast<unsigned>(t / 3);
      primitive.isTriangle = true;
      const glm::vec3 p0 = record.positions[record.indices[t]];
      const glm::vec3 p1 = record.positions[record.indices[t + 1]];
      const glm::vec3 p2 = record.positions[record.indices[t + 2]];
      primitive.vertex0 = p0;
      primitive.edge1 = p1 - p0;
      primitive.edge2 = p2 - p0;
      primitives_.push_back(primitive);
      glm::dvec3 lower = glm::min(glm::dvec3(p0), glm::min(glm::dvec3(p1), glm::dvec3(p2)));
      glm::dvec3 upper = glm::max(glm::dvec3(p0), glm::max(glm::dvec3(p1), glm::dvec3(p2)));
      padForFloatRounding(lower, upper);  // as quadric boxes are
      addBox(lower, upper);
    }
  }
  return true;
}

std::uint64_t FlatPrimitives::boxesEntered(glm::vec3 origin, glm::vec3 direction, float tMax,
                                           float* entry) const {
  const std::uint64_t entered =
      boxTest()({bounds_.data(), padded_}, origin, safeInverse(direction), tMax, entry);
  // The NaN boxes of the padding fail the SIMD comparisons, but std::min and std::max skip a
  // NaN: mask them off.
  const std::size_t count = primitives_.size();
  return count == 64 ? entered : entered & ((std::uint64_t{1} << count) - 1);
}

bool FlatPrimitives::hits(const std::vector<GeometryRecord>& records, const Primitive& primitive,
                          glm::vec3 origin, glm::vec3 direction, float tMax, FlatHit* hit) const {
  if (primitive.isTriangle) {
    float t, u, v;
    if (!intersectTriangle(primitive.vertex0, primitive.edge1, primitive.edge2, origin, direction,
                           tMax, t, u, v)) {
      return false;
    }
    if (hit) *hit = {primitive.record, primitive.triangle, t, u, v, glm::vec3(0.0f)};
    return true;
  }
  const GeometryRecord& record = records[primitive.record];
  const auto quadricHit = record.quadric.intersect(glm::dvec3(origin), glm::dvec3(direction), 0.0,
                                                   tMax, hit && record.quadricNeedsUv);
  if (!quadricHit) return false;
  if (hit) {
    *hit = {primitive.record,
            0,
            static_cast<float>(quadricHit->t),
            static_cast<float>(quadricHit->uv.x),
            static_cast<float>(quadricHit->uv.y),
            glm::vec3(quadricHit->normal)};
  }
  return true;
}

bool FlatPrimitives::intersect(const std::vector<GeometryRecord>& records, glm::vec3 origin,
                               glm::vec3 direction, float tMax, FlatHit& hit) const {
  float entry[kMaxPrimitives];
  std::uint64_t entered = boxesEntered(origin, direction, tMax, entry);
  bool found = false;
  while (entered != 0) {
    const int i = __builtin_ctzll(entered);
    entered &= entered - 1;
    // A box entered beyond the nearest hit so far holds no nearer hit.
    if (entry[i] > tMax * kExitSlack) continue;
    if (hits(records, primitives_[static_cast<std::size_t>(i)], origin, direction, tMax, &hit)) {
      tMax = hit.t;
      found = true;
    }
  }
  return found;
}

bool FlatPrimitives::occluded(const std::vector<GeometryRecord>& records, glm::vec3 origin,
                              glm::vec3 direction, float tMax) const {
  float entry[kMaxPrimitives];
  std::uint64_t entered = boxesEntered(origin, direction, tMax, entry);
  while (entered != 0) {
    const int i = __builtin_ctzll(entered);
    entered &= entered - 1;
    if (hits(records, primitives_[static_cast<std::size_t>(i)], origin, direction, tMax, nullptr)) {
      return true;
    }
  }
  return false;
}

}  // namespace lenslab::render
