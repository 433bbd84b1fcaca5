#pragma once
// The ray queries of a scene of few primitives, without a BVH: every primitive's bounding box is
// tested at once (sixteen at a time with AVX-512, eight with AVX2), and only the primitives whose
// boxes the ray enters are tested exactly. For a few dozen primitives this is cheaper than
// Embree's traversal, whose fixed cost per ray and per user-geometry callback dominates when there
// is so little to cull: on the default scene's 22 primitives (4 triangles, 4 spheres, 7 cylinders,
// 7 disks) a ray costs 0.53-0.90 of Embree's time, and a 1-spp preview pass (BM_PreviewPass)
// 0.70-1.0 of it, depending on the machine's load (bench/README.md).
// Larger scenes, and scenes with Embree instances, keep Embree.
//
// Quadrics are tested by the same double-precision code as Embree's callbacks
// (PlacedQuadric::intersect); triangles by the Moller-Trumbore test (Moller and Trumbore, "Fast,
// Minimum Storage Ray-Triangle Intersection", 1997), whose barycentrics are Embree's u and v.
// When the ray enters any triangle's box, the triangles are tested sixteen (AVX-512) or eight
// (AVX2) at a time, without a branch per triangle: a quad's two halves share one box, so most
// rays that reach one test both, and a branch per test mispredicts which half.

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace lenslab::render {

struct GeometryRecord;

// A hit found by FlatPrimitives, in the terms of an Embree hit.
struct FlatHit {
  unsigned record = 0;     // index of the primitive's GeometryRecord (its Embree geomID)
  unsigned primitive = 0;  // the triangle's index in its mesh (primID); 0 for a quadric
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;  // a triangle's barycentrics of vertices 1 and 2; a quadric's (u, v)
  glm::vec3 normal{0.0f};    // a quadric's parent-space normal (not normalised); unset for meshes
};

class FlatPrimitives {
 public:
  // The width of the entered-box mask. Up to it the flat path was the faster at every size
  // measured: BM_ScatteredSpheres with 8, 16, 32 and 64 spheres took 0.90, 0.82, 0.84 and 0.85
  // of Embree's time per ray (bench/README.md).
  static constexpr std::size_t kMaxPrimitives = 64;

  // Takes the primitives of `records` (meshes and quadrics). False, leaving this empty, when
  // they are more than `limit` (at most kMaxPrimitives) or include an instance.
  bool build(const std::vector<GeometryRecord>& records, std::size_t limit = kMaxPrimitives);
  bool empty() const { return primitives_.empty(); }
  std::size_t size() const { return primitives_.size(); }

  // Nearest hit along origin + t * direction for t in (0, tMax); `records` are the ones built
  // from.
  bool intersect(const std::vector<GeometryRecord>& records, glm::vec3 origin, glm::vec3 direction,
                 float tMax, FlatHit& hit) const;
  // Whether anything lies on the segment (0, tMax).
  bool occluded(const std::vector<GeometryRecord>& records, glm::vec3 origin, glm::vec3 direction,
                float tMax) const;

  // For tests: which vector kernels (the box test and the triangle test) every FlatPrimitives
  // uses. Fastest is AVX-512 where the CPU has it, else AVX2, else the portable scalar loops.
  // False (and no change) when the CPU lacks AVX2.
  enum class KernelKind { Fastest, Avx2, Portable };
  static bool useKernels(KernelKind kind);

 private:
  struct Primitive {
    unsigned record = 0;
    unsigned triangle = 0;  // a triangle's index in its mesh (the triangles' own data: triangles_)
  };
  // The bits of the primitives whose boxes the ray enters within (0, tMax), and each box's entry
  // distance in `entry`.
  std::uint64_t boxesEntered(KernelKind kernels, glm::vec3 origin, glm::vec3 direction, float tMax,
                             float* entry) const;
  // Of the triangles whose bits are in `candidates`, the bits of those hit within (0, tMax), and
  // their t, u and v at their indices in the arrays.
  std::uint64_t trianglesHit(KernelKind kernels, std::uint64_t candidates, glm::vec3 origin,
                             glm::vec3 direction, float tMax, float* t, float* u, float* v) const;
  // The exact test of one quadric for t in (0, tMax); with `hit`, its shading data too.
  bool quadricHits(const std::vector<GeometryRecord>& records, const Primitive& quadric,
                   glm::vec3 origin, glm::vec3 direction, float tMax, FlatHit* hit) const;

  std::vector<Primitive> primitives_;  // the triangles first, then the quadrics
  // Bounding boxes: six arrays of padded_ floats (lower x, y, z, upper x, y, z), padded_ the
  // primitive count rounded up to a multiple of 16.
  std::vector<float> bounds_;
  std::size_t padded_ = 0;
  // The triangles, for the vector and scalar tests: nine arrays of padded_ floats (vertex 0, edge
  // 1, edge 2; x, y, z each), zero beyond the last triangle. Their bits: triangleBits_.
  std::vector<float> triangles_;
  std::uint64_t triangleBits_ = 0;
};

}  // namespace lenslab::render
