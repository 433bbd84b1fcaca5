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
#include <cstring>
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

// The triangles' vertex 0 and edges, nine arrays of `padded` floats: vertex 0 x, y, z, edge 1
// x, y, z, edge 2 x, y, z. Padding lanes are all zero: a zero determinant, never hit.
struct TriangleArrays {
  const float* data;
  std::size_t padded;  // a multiple of 16
  const float* component(int index) const { return data + index * padded; }
};

// (Vectors go by reference: a vector returned by value would have a different ABI in callers
// with and without AVX, which GCC warns of.)
template <typename Lanes>
__attribute__((always_inline)) inline void loadLanes(const float* from, Lanes& lanes) {
  std::memcpy(&lanes, from, sizeof lanes);
}

// Moller-Trumbore (intersectTriangle below) on sizeof(Floats) / 4 triangles at once, with the
// same operations in the same order lane by lane, so every lane's t, u and v are those of the
// scalar test (this file is compiled without fused multiply-adds: src/render/CMakeLists.txt).
// Written with GCC's vector extensions, so that the AVX-512 and AVX2 kernels that
// inline it share one body; they compare with intrinsics (GCC 12 turns a 512-bit vector
// comparison without AVX512DQ into one scalar comparison per lane).
template <typename Floats>
__attribute__((always_inline)) inline void triangleLanes(const TriangleArrays& triangles,
                                                         std::size_t first, glm::vec3 origin,
                                                         glm::vec3 direction, Floats& determinant,
                                                         Floats& t, Floats& u, Floats& v) {
  Floats v0x, v0y, v0z, e1x, e1y, e1z, e2x, e2y, e2z;
  loadLanes(triangles.component(0) + first, v0x);
  loadLanes(triangles.component(1) + first, v0y);
  loadLanes(triangles.component(2) + first, v0z);
  loadLanes(triangles.component(3) + first, e1x);
  loadLanes(triangles.component(4) + first, e1y);
  loadLanes(triangles.component(5) + first, e1z);
  loadLanes(triangles.component(6) + first, e2x);
  loadLanes(triangles.component(7) + first, e2y);
  loadLanes(triangles.component(8) + first, e2z);
  // p = cross(direction, edge2), as glm::cross computes it.
  const Floats px = direction.y * e2z - e2y * direction.z;
  const Floats py = direction.z * e2x - e2z * direction.x;
  const Floats pz = direction.x * e2y - e2x * direction.y;
  determinant = e1x * px + e1y * py + e1z * pz;
  const Floats inverse = 1.0f / determinant;
  const Floats sx = origin.x - v0x, sy = origin.y - v0y, sz = origin.z - v0z;
  u = (sx * px + sy * py + sz * pz) * inverse;
  // q = cross(s, edge1).
  const Floats qx = sy * e1z - e1y * sz;
  const Floats qy = sz * e1x - e1z * sx;
  const Floats qz = sx * e1y - e1x * sy;
  v = (direction.x * qx + direction.y * qy + direction.z * qz) * inverse;
  t = (e2x * qx + e2y * qy + e2z * qz) * inverse;
}

// The triangles hit within (0, tMax) among the groups of sixteen whose bit is set in `groups`:
// their bits, and each one's t, u and v in the arrays (lane i at index i). The conditions are
// intersectTriangle's (a NaN fails each, as there).
__attribute__((target("avx512f"))) std::uint64_t trianglesHitAvx512(const TriangleArrays& triangles,
                                                                    unsigned groups,
                                                                    glm::vec3 origin,
                                                                    glm::vec3 direction, float tMax,
                                                                    float* t, float* u, float* v) {
  using Floats = float __attribute__((vector_size(64)));
  const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
  const __m512 far = _mm512_set1_ps(tMax);
  std::uint64_t hit = 0;
  for (; groups != 0; groups &= groups - 1) {
    const std::size_t first = 16 * static_cast<std::size_t>(__builtin_ctz(groups));
    Floats determinantLanes, tLanes, uLanes, vLanes;
    triangleLanes(triangles, first, origin, direction, determinantLanes, tLanes, uLanes, vLanes);
    __m512 determinant, laneT, laneU, laneV;
    std::memcpy(&determinant, &determinantLanes, sizeof determinant);
    std::memcpy(&laneT, &tLanes, sizeof laneT);
    std::memcpy(&laneU, &uLanes, sizeof laneU);
    std::memcpy(&laneV, &vLanes, sizeof laneV);
    _mm512_storeu_ps(t + first, laneT);
    _mm512_storeu_ps(u + first, laneU);
    _mm512_storeu_ps(v + first, laneV);
    const __mmask16 lanes =
        _mm512_cmp_ps_mask(determinant, zero, _CMP_NEQ_UQ) &
        _mm512_cmp_ps_mask(laneU, zero, _CMP_GE_OQ) & _mm512_cmp_ps_mask(laneU, one, _CMP_LE_OQ) &
        _mm512_cmp_ps_mask(laneV, zero, _CMP_GE_OQ) &
        _mm512_cmp_ps_mask(_mm512_add_ps(laneU, laneV), one, _CMP_LE_OQ) &
        _mm512_cmp_ps_mask(laneT, zero, _CMP_GT_OQ) & _mm512_cmp_ps_mask(laneT, far, _CMP_LT_OQ);
    hit |= static_cast<std::uint64_t>(lanes) << first;
  }
  return hit;
}

// The same, eight lanes at a time (two steps per group of sixteen).
__attribute__((target("avx2"))) std::uint64_t trianglesHitAvx2(const TriangleArrays& triangles,
                                                               unsigned groups, glm::vec3 origin,
                                                               glm::vec3 direction, float tMax,
                                                               float* t, float* u, float* v) {
  using Floats = float __attribute__((vector_size(32)));
  const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
  const __m256 far = _mm256_set1_ps(tMax);
  std::uint64_t hit = 0;
  for (; groups != 0; groups &= groups - 1) {
    for (std::size_t first = 16 * static_cast<std::size_t>(__builtin_ctz(groups)), end = first + 16;
         first < end; first += 8) {
      Floats determinantLanes, tLanes, uLanes, vLanes;
      triangleLanes(triangles, first, origin, direction, determinantLanes, tLanes, uLanes, vLanes);
      __m256 determinant, laneT, laneU, laneV;
      std::memcpy(&determinant, &determinantLanes, sizeof determinant);
      std::memcpy(&laneT, &tLanes, sizeof laneT);
      std::memcpy(&laneU, &uLanes, sizeof laneU);
      std::memcpy(&laneV, &vLanes, sizeof laneV);
      _mm256_storeu_ps(t + first, laneT);
      _mm256_storeu_ps(u + first, laneU);
      _mm256_storeu_ps(v + first, laneV);
      __m256 lanes = _mm256_and_ps(_mm256_cmp_ps(determinant, zero, _CMP_NEQ_UQ),
                                   _mm256_cmp_ps(laneU, zero, _CMP_GE_OQ));
      lanes = _mm256_and_ps(lanes, _mm256_cmp_ps(laneU, one, _CMP_LE_OQ));
      lanes = _mm256_and_ps(lanes, _mm256_cmp_ps(laneV, zero, _CMP_GE_OQ));
      lanes = _mm256_and_ps(lanes, _mm256_cmp_ps(_mm256_add_ps(laneU, laneV), one, _CMP_LE_OQ));
      lanes = _mm256_and_ps(lanes, _mm256_cmp_ps(laneT, zero, _CMP_GT_OQ));
      lanes = _mm256_and_ps(lanes, _mm256_cmp_ps(laneT, far, _CMP_LT_OQ));
      hit |= static_cast<std::uint64_t>(_mm256_movemask_ps(lanes)) << first;
    }
  }
  return hit;
}

using BoxTest = std::uint64_t (*)(const BoxArrays&, glm::vec3, glm::vec3, float, float*);
using TriangleTest = std::uint64_t (*)(const TriangleArrays&, unsigned, glm::vec3, glm::vec3, float,
                                       float*, float*, float*);

std::atomic<FlatPrimitives::KernelKind> kernelKind{FlatPrimitives::KernelKind::Fastest};

bool cpuHasAvx512() {
  static const bool has = __builtin_cpu_supports("avx512f");
  return has;
}
bool cpuHasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}

// The kernels to use: the kind useKernels chose, with Fastest resolved to the CPU's best. After
// this, Fastest means the AVX-512 kernels (boxTest and triangleTest below).
FlatPrimitives::KernelKind kernelsInUse() {
  FlatPrimitives::KernelKind kind = kernelKind.load(std::memory_order_relaxed);
  if (kind == FlatPrimitives::KernelKind::Fastest) {
    kind = cpuHasAvx512() ? FlatPrimitives::KernelKind::Fastest
           : cpuHasAvx2() ? FlatPrimitives::KernelKind::Avx2
                          : FlatPrimitives::KernelKind::Portable;
  }
  return kind;
}

BoxTest boxTest(FlatPrimitives::KernelKind kind) {
  switch (kind) {
    case FlatPrimitives::KernelKind::Fastest:
      return boxesEnteredAvx512;
    case FlatPrimitives::KernelKind::Avx2:
      return boxesEnteredAvx2;
    case FlatPrimitives::KernelKind::Portable:
      return boxesEnteredPortable;
  }
  return boxesEnteredPortable;
}

TriangleTest triangleTest(FlatPrimitives::KernelKind kind) {
  switch (kind) {
    case FlatPrimitives::KernelKind::Fastest:
      return trianglesHitAvx512;
    case FlatPrimitives::KernelKind::Avx2:
      return trianglesHitAvx2;
    case FlatPrimitives::KernelKind::Portable:
      return nullptr;
  }
  return nullptr;
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

bool FlatPrimitives::useKernels(KernelKind kind) {
  if (kind == KernelKind::Avx2 && !cpuHasAvx2()) return false;
  kernelKind.store(kind);
  return true;
}

bool FlatPrimitives::build(const std::vector<GeometryRecord>& records, std::size_t limit) {
  primitives_.clear();
  bounds_.clear();
  triangles_.clear();
  padded_ = 0;
  triangleBits_ = 0;
  limit = std::min(limit, kMaxPrimitives);
  std::size_t count = 0, triangleCount = 0;
  for (const GeometryRecord& record : records) {
    if (record.kind == GeometryRecord::Kind::Instance) return false;
    if (record.kind == GeometryRecord::Kind::Mesh) triangleCount += record.indices.size() / 3;
    count += record.kind == GeometryRecord::Kind::Mesh ? record.indices.size() / 3 : 1;
  }
  if (count == 0 || count > limit) return false;
  // Padded to whole groups of sixteen with NaN boxes, which boxesEntered masks off.
  padded_ = (count + 15) / 16 * 16;
  bounds_.assign(6 * padded_, std::nanf(""));
  // The triangles come first, so that their bits and lanes are the same: 0 to triangleCount - 1.
  triangles_.assign(9 * padded_, 0.0f);
  triangleBits_ = triangleCount == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << triangleCount) - 1;
  const auto addBox = [this](glm::dvec3 lower, glm::dvec3 upper) {
    const std::size_t i = primitives_.size() - 1;
    for (int axis = 0; axis < 3; ++axis) {
      bounds_[axis * padded_ + i] = static_cast<float>(lower[axis]);
      bounds_[(3 + axis) * padded_ + i] = static_cast<float>(upper[axis]);
    }
  };
  for (std::size_t r = 0; r < records.size(); ++r) {
    const GeometryRecord& record = records[r];
    if (record.kind != GeometryRecord::Kind::Mesh) continue;
    for (std::size_t t = 0; t + 2 < record.indices.size(); t += 3) {
      Primitive primitive;
      primitive.record = static_cast<unsigned>(r);
      primitive.triangle = static_cast<unsigned>(t / 3);
      const glm::vec3 p0 = record.positions[record.indices[t]];
      const glm::vec3 p1 = record.positions[record.indices[t + 1]];
      const glm::vec3 p2 = record.positions[record.indices[t + 2]];
      const glm::vec3 edge1 = p1 - p0, edge2 = p2 - p0;
      const std::size_t lane = primitives_.size();
      for (int axis = 0; axis < 3; ++axis) {
        triangles_[axis * padded_ + lane] = p0[axis];
        triangles_[(3 + axis) * padded_ + lane] = edge1[axis];
        triangles_[(6 + axis) * padded_ + lane] = edge2[axis];
      }
      primitives_.push_back(primitive);
      glm::dvec3 lower = glm::min(glm::dvec3(p0), glm::min(glm::dvec3(p1), glm::dvec3(p2)));
      glm::dvec3 upper = glm::max(glm::dvec3(p0), glm::max(glm::dvec3(p1), glm::dvec3(p2)));
      padForFloatRounding(lower, upper);  // as quadric boxes are
      addBox(lower, upper);
    }
  }
  for (std::size_t r = 0; r < records.size(); ++r) {
    const GeometryRecord& record = records[r];
    if (record.kind != GeometryRecord::Kind::Quadric) continue;
    Primitive primitive;
    primitive.record = static_cast<unsigned>(r);
    primitives_.push_back(primitive);
    glm::dvec3 lower, upper;
    record.quadric.parentBounds(lower, upper);
    addBox(lower, upper);
  }
  return true;
}

std::uint64_t FlatPrimitives::boxesEntered(KernelKind kernels, glm::vec3 origin,
                                           glm::vec3 direction, float tMax, float* entry) const {
  const std::uint64_t entered =
      boxTest(kernels)({bounds_.data(), padded_}, origin, safeInverse(direction), tMax, entry);
  // The NaN boxes of the padding fail the SIMD comparisons, but std::min and std::max skip a
  // NaN: mask them off.
  const std::size_t count = primitives_.size();
  return count == 64 ? entered : entered & ((std::uint64_t{1} << count) - 1);
}

bool FlatPrimitives::quadricHits(const std::vector<GeometryRecord>& records,
                                 const Primitive& quadric, glm::vec3 origin, glm::vec3 direction,
                                 float tMax, FlatHit* hit) const {
  const GeometryRecord& record = records[quadric.record];
  const auto quadricHit = record.quadric.intersect(glm::dvec3(origin), glm::dvec3(direction), 0.0,
                                                   tMax, hit && record.quadricNeedsUv);
  if (!quadricHit) return false;
  if (hit) {
    *hit = {quadric.record,
            0,
            static_cast<float>(quadricHit->t),
            static_cast<float>(quadricHit->uv.x),
            static_cast<float>(quadricHit->uv.y),
            glm::vec3(quadricHit->normal)};
  }
  return true;
}

namespace {
// Bit g set when any of bits 16 g to 16 g + 15 is.
unsigned groupsOf(std::uint64_t bits) {
  unsigned groups = 0;
  for (unsigned g = 0; g < 4; ++g) {
    if ((bits >> (16 * g)) & 0xFFFFu) groups |= 1u << g;
  }
  return groups;
}
}  // namespace

std::uint64_t FlatPrimitives::trianglesHit(KernelKind kernels, std::uint64_t candidates,
                                           glm::vec3 origin, glm::vec3 direction, float tMax,
                                           float* t, float* u, float* v) const {
  if (const TriangleTest test = triangleTest(kernels)) {
    // Every lane of a group with a candidate is tested (it costs the same); only the
    // candidates count, as in the scalar loop.
    return candidates & test({triangles_.data(), padded_}, groupsOf(candidates), origin, direction,
                             tMax, t, u, v);
  }
  std::uint64_t hit = 0;
  for (std::uint64_t left = candidates; left != 0; left &= left - 1) {
    const int i = __builtin_ctzll(left);
    const auto at = [&](int component) {
      return triangles_[static_cast<std::size_t>(component) * padded_ +
                        static_cast<std::size_t>(i)];
    };
    if (intersectTriangle({at(0), at(1), at(2)}, {at(3), at(4), at(5)}, {at(6), at(7), at(8)},
                          origin, direction, tMax, t[i], u[i], v[i])) {
      hit |= std::uint64_t{1} << i;
    }
  }
  return hit;
}

bool FlatPrimitives::intersect(const std::vector<GeometryRecord>& records, glm::vec3 origin,
                               glm::vec3 direction, float tMax, FlatHit& hit) const {
  const KernelKind kernels = kernelsInUse();
  float entry[kMaxPrimitives];
  std::uint64_t entered = boxesEntered(kernels, origin, direction, tMax, entry);
  bool found = false;
  if (const std::uint64_t candidates = entered & triangleBits_) {
    // All the triangles at once (a quad's two halves share a box: most rays that test one test
    // both, and a branch per test mispredicts which half).
    float t[kMaxPrimitives], u[kMaxPrimitives], v[kMaxPrimitives];
    std::uint64_t triangles = trianglesHit(kernels, candidates, origin, direction, tMax, t, u, v);
    // The nearest; of equal ones the first, as a scan that shrinks tMax keeps.
    for (; triangles != 0; triangles &= triangles - 1) {
      const int i = __builtin_ctzll(triangles);
      if (!(t[i] < tMax)) continue;
      const Primitive& triangle = primitives_[static_cast<std::size_t>(i)];
      hit = {triangle.record, triangle.triangle, t[i], u[i], v[i], glm::vec3(0.0f)};
      tMax = t[i];
      found = true;
    }
    entered &= ~triangleBits_;
  }
  while (entered != 0) {
    const int i = __builtin_ctzll(entered);
    entered &= entered - 1;
    // A box entered beyond the nearest hit so far holds no nearer hit.
    if (entry[i] > tMax * kExitSlack) continue;
    if (quadricHits(records, primitives_[static_cast<std::size_t>(i)], origin, direction, tMax,
                    &hit)) {
      tMax = hit.t;
      found = true;
    }
  }
  return found;
}

bool FlatPrimitives::occluded(const std::vector<GeometryRecord>& records, glm::vec3 origin,
                              glm::vec3 direction, float tMax) const {
  const KernelKind kernels = kernelsInUse();
  float entry[kMaxPrimitives];
  std::uint64_t entered = boxesEntered(kernels, origin, direction, tMax, entry);
  if (const std::uint64_t candidates = entered & triangleBits_) {
    float t[kMaxPrimitives], u[kMaxPrimitives], v[kMaxPrimitives];
    if (trianglesHit(kernels, candidates, origin, direction, tMax, t, u, v) != 0) {
      return true;
    }
    entered &= ~triangleBits_;
  }
  while (entered != 0) {
    const int i = __builtin_ctzll(entered);
    entered &= entered - 1;
    if (quadricHits(records, primitives_[static_cast<std::size_t>(i)], origin, direction, tMax,
                    nullptr)) {
      return true;
    }
  }
  return false;
}

}  // namespace lenslab::render
