// ExitPupilTable::sampleRays: exit_pupil.cpp's sampler for a batch of camera rays, mostly in
// single precision, 16 rays at a time with AVX-512 or 8 with AVX2 (the caller picks what the CPU
// has; without either, exit_pupil.cpp samples ray by ray in double). The renderer calls it for
// every camera ray.
#include <cstddef>
#include <cstdint>

#include <immintrin.h>

// GCC 12's AVX-512 intrinsics start from _mm512_undefined_* values, which -Wmaybe-uninitialized
// reports in every caller (GCC bug 105593, fixed in GCC 13).
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "optics/exit_pupil.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

namespace {

// Where the batch comes from and goes to.
struct BatchSampling {
  const float* filmX;
  const float* filmY;
  const float* u0;
  const float* u1;
  float* ox;
  float* oy;
  float* oz;
  float* dx;
  float* dy;
  float* dz;
  std::uint8_t* alive;
  float* pdf;
};

struct BatchSamplingConstants {
  float planeZ = 0.0f, half = 0.0f, fallbackPdf = 0.0f, radiusMax = 0.0f;
  double invRadiusMax = 0.0, binScale = 0.0;
  int lastPair = 0;
  // A shaped stop's azimuth cells (stop_cells.h's stopCellOf): cells > 1 splits the table.
  int cells = 1, radialBins = 0;
  float cellOffsetRad = 0.0f, cellPeriodRad = 1.0f, cellsPerRad = 0.0f;
};

// stopCellOf's arctangent polynomial (Abramowitz and Stegun 4.4.49) and constants.
constexpr float kAtan1 = 0.9998660f, kAtan3 = -0.3302995f, kAtan5 = 0.1801410f,
                kAtan7 = -0.0851330f, kAtan9 = 0.0208351f;
constexpr float kHalfPi = 1.57079633f, kPi = 3.14159265f, kTwoPi = 6.28318531f;

// The vector kernels address the table as one float array: a bin's fields as offsets in floats.
template <class SamplingBin>
struct TableLayout {
  static_assert(sizeof(SamplingBin) % sizeof(float) == 0);
  static constexpr int kBinStride = sizeof(SamplingBin) / sizeof(float);
  static constexpr int kSlots = offsetof(SamplingBin, slots) / sizeof(float);
  static constexpr int kSectors = offsetof(SamplingBin, sectors) / sizeof(float);
  static constexpr int kCentre = offsetof(SamplingBin, centreXMm) / sizeof(float);
  static constexpr int kCentreY = offsetof(SamplingBin, centreYMm) / sizeof(float);
  static constexpr int kInvArea = offsetof(SamplingBin, invAreaPerMm2) / sizeof(float);
  static constexpr int kEmpty = offsetof(SamplingBin, empty) / sizeof(float);
};

// The same computation for AVX-512, 16 rays at a time, branch-free: which bin, the alias slot or
// its alias, inside or outside the table are masks (beyond the table, lanes still read the last
// two bins, then take the fallback square). The film radius, the bin weight and the stretched u
// run in double, eight lanes at a time, as above. Every ray, the last group's too, goes through
// the same lane code: a ray's result must not depend on where it sits in a batch (the
// renderer's image is the same for any tiling and thread count).
template <class SamplingBin>
__attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,fma"))) void sampleBatchAvx512(
    const BatchSamplingConstants& k, const SamplingBin* bins, const BatchSampling& io,
    std::size_t n) {
  const float* table = reinterpret_cast<const float*>(bins);
  using Layout = TableLayout<SamplingBin>;
  constexpr int kBinStride = Layout::kBinStride, kSlots = Layout::kSlots;
  constexpr int kSectorsAt = Layout::kSectors, kCentre = Layout::kCentre;
  constexpr int kCentreY = Layout::kCentreY;
  constexpr int kInvArea = Layout::kInvArea, kEmpty = Layout::kEmpty;
  const __m512 one = _mm512_set1_ps(1.0f), zero = _mm512_setzero_ps();
  const __m512d oneD = _mm512_set1_pd(1.0), zeroD = _mm512_setzero_pd();
  const __m512d invRadiusMax = _mm512_set1_pd(k.invRadiusMax);
  const __m512d halfBinScale = _mm512_set1_pd(0.5 * k.binScale);
  const __m256i lastPair = _mm256_set1_epi32(k.lastPair);
  const __m512 planeZ = _mm512_set1_ps(k.planeZ), planeZ2 = _mm512_set1_ps(k.planeZ * k.planeZ);
  const __m512i binStride = _mm512_set1_epi32(kBinStride);
  for (std::size_t i = 0; i < n; i += 16) {
    // The last group's missing lanes read zeros (which address bin 0, slot 0) and store nothing.
    const __mmask16 lanes =
        n - i >= 16 ? __mmask16{0xffff} : static_cast<__mmask16>((1u << (n - i)) - 1u);
    const __m512 fx = _mm512_maskz_loadu_ps(lanes, io.filmX + i);
    const __m512 fy = _mm512_maskz_loadu_ps(lanes, io.filmY + i);
    const __m512 u = _mm512_maskz_loadu_ps(lanes, io.u0 + i);
    const __m512 v = _mm512_maskz_loadu_ps(lanes, io.u1 + i);
    const __m512 r = _mm512_sqrt_ps(_mm512_fmadd_ps(fx, fx, _mm512_mul_ps(fy, fy)));
    __m256i jHalf[2];
    __m256 fHalf[2], uxHalf[2];
    __mmask8 secondHalf[2];
    for (int h = 0; h < 2; ++h) {
      const __m512d fxd =
          _mm512_cvtps_pd(h == 0 ? _mm512_castps512_ps256(fx) : _mm512_extractf32x8_ps(fx, 1));
      const __m512d fyd =
          _mm512_cvtps_pd(h == 0 ? _mm512_castps512_ps256(fy) : _mm512_extractf32x8_ps(fy, 1));
      const __m512d rd = _mm512_sqrt_pd(_mm512_fmadd_pd(fxd, fxd, _mm512_mul_pd(fyd, fyd)));
      const __m512d ud =
          _mm512_cvtps_pd(h == 0 ? _mm512_castps512_ps256(u) : _mm512_extractf32x8_ps(u, 1));
      const __m512d x = _mm512_mul_pd(rd, invRadiusMax);
      const __m512d t = _mm512_mul_pd(_mm512_fmadd_pd(x, x, x), halfBinScale);
      const __m256i j = _mm256_min_epi32(_mm512_cvttpd_epi32(t), lastPair);
      const __m512d f =
          _mm512_min_pd(_mm512_max_pd(_mm512_sub_pd(t, _mm512_cvtepi32_pd(j)), zeroD), oneD);
      const __m512d oneMinusF = _mm512_sub_pd(oneD, f);
      const __mmask8 second = _mm512_cmp_pd_mask(ud, oneMinusF, _CMP_GE_OQ);
      const __m512d numerator = _mm512_mask_sub_pd(ud, second, ud, oneMinusF);
      const __m512d denominator = _mm512_mask_blend_pd(second, oneMinusF, f);
      jHalf[h] = j;
      fHalf[h] = _mm512_cvtpd_ps(f);
      uxHalf[h] = _mm512_cvtpd_ps(_mm512_div_pd(numerator, denominator));
      secondHalf[h] = second;
    }
    __m512i cellFirst = _mm512_setzero_si512();
    if (k.cells > 1) {  // stopCellOf, lane by lane
      const __m512 ax = _mm512_abs_ps(fx), ay = _mm512_abs_ps(fy);
      const __m512 big = _mm512_max_ps(ax, ay), small = _mm512_min_ps(ax, ay);
      const __m512 t = _mm512_maskz_div_ps(_mm512_cmp_ps_mask(big, zero, _CMP_GT_OQ), small, big);
      const __m512 s = _mm512_mul_ps(t, t);
      __m512 p = _mm512_fmadd_ps(_mm512_set1_ps(kAtan9), s, _mm512_set1_ps(kAtan7));
      p = _mm512_fmadd_ps(p, s, _mm512_set1_ps(kAtan5));
      p = _mm512_fmadd_ps(p, s, _mm512_set1_ps(kAtan3));
      p = _mm512_fmadd_ps(p, s, _mm512_set1_ps(kAtan1));
      __m512 a = _mm512_mul_ps(t, p);
      a = _mm512_mask_sub_ps(a, _mm512_cmp_ps_mask(ay, ax, _CMP_GT_OQ), _mm512_set1_ps(kHalfPi), a);
      a = _mm512_mask_sub_ps(a, _mm512_cmp_ps_mask(fx, zero, _CMP_LT_OQ), _mm512_set1_ps(kPi), a);
      a = _mm512_mask_sub_ps(a, _mm512_cmp_ps_mask(fy, zero, _CMP_LT_OQ), _mm512_set1_ps(kTwoPi),
                             a);
      a = _mm512_add_ps(_mm512_sub_ps(a, _mm512_set1_ps(k.cellOffsetRad)), _mm512_set1_ps(kTwoPi));
      const __m512 period = _mm512_set1_ps(k.cellPeriodRad);
      const __m512 turns = _mm512_cvtepi32_ps(_mm512_cvttps_epi32(_mm512_div_ps(a, period)));
      const __m512 folded = _mm512_fnmadd_ps(period, turns, a);
      const __m512i cell = _mm512_min_epi32(
          _mm512_max_epi32(
              _mm512_cvttps_epi32(_mm512_mul_ps(folded, _mm512_set1_ps(k.cellsPerRad))),
              _mm512_setzero_si512()),
          _mm512_set1_epi32(k.cells - 1));
      cellFirst = _mm512_mullo_epi32(cell, _mm512_set1_epi32(k.radialBins));
    }
    const __m512i j = _mm512_add_epi32(
        _mm512_inserti64x4(_mm512_castsi256_si512(jHalf[0]), jHalf[1], 1), cellFirst);
    const __m512 f = _mm512_insertf32x8(_mm512_castps256_ps512(fHalf[0]), fHalf[1], 1);
    const __m512 ux = _mm512_insertf32x8(_mm512_castps256_ps512(uxHalf[0]), uxHalf[1], 1);
    const __mmask16 second = static_cast<__mmask16>(secondHalf[0] | (secondHalf[1] << 8));
    const __m512i bin0 = _mm512_mullo_epi32(j, binStride);
    const __m512i chosen = _mm512_mask_add_epi32(bin0, second, bin0, binStride);

    const __m512 scaled =
        _mm512_mul_ps(_mm512_min_ps(ux, _mm512_set1_ps(0x1.fffffep-1f)), _mm512_set1_ps(32.0f));
    const __m512i slot = _mm512_min_epi32(_mm512_cvttps_epi32(scaled), _mm512_set1_epi32(31));
    const __m512 fraction = _mm512_sub_ps(scaled, _mm512_cvtepi32_ps(slot));
    const __m512i slotAt = _mm512_add_epi32(_mm512_add_epi32(chosen, _mm512_set1_epi32(kSlots)),
                                            _mm512_slli_epi32(slot, 2));  // 4 floats per slot
    const __m512 keep = _mm512_i32gather_ps(slotAt, table, 4);
    const __m512 invKeep =
        _mm512_i32gather_ps(_mm512_add_epi32(slotAt, _mm512_set1_epi32(1)), table, 4);
    const __m512 invComplement =
        _mm512_i32gather_ps(_mm512_add_epi32(slotAt, _mm512_set1_epi32(2)), table, 4);
    const __m512i alias =
        _mm512_i32gather_epi32(_mm512_add_epi32(slotAt, _mm512_set1_epi32(3)), table, 4);
    const __mmask16 stay = _mm512_cmp_ps_mask(fraction, keep, _CMP_LT_OQ);
    const __m512i sector = _mm512_mask_blend_epi32(stay, alias, slot);
    const __m512 w =
        _mm512_mask_blend_ps(stay, _mm512_mul_ps(_mm512_sub_ps(fraction, keep), invComplement),
                             _mm512_mul_ps(fraction, invKeep));
    const __m512 s = _mm512_sqrt_ps(w);
    const __m512i sectorAt = _mm512_add_epi32(
        _mm512_add_epi32(chosen, _mm512_set1_epi32(kSectorsAt)), _mm512_slli_epi32(sector, 2));
    const __m512 ax = _mm512_i32gather_ps(sectorAt, table, 4);
    const __m512 ay =
        _mm512_i32gather_ps(_mm512_add_epi32(sectorAt, _mm512_set1_epi32(1)), table, 4);
    const __m512 bx =
        _mm512_i32gather_ps(_mm512_add_epi32(sectorAt, _mm512_set1_epi32(2)), table, 4);
    const __m512 by =
        _mm512_i32gather_ps(_mm512_add_epi32(sectorAt, _mm512_set1_epi32(3)), table, 4);
    const __m512i bin1 = _mm512_add_epi32(bin0, binStride);
    const __m512 centre0 =
        _mm512_i32gather_ps(_mm512_add_epi32(bin0, _mm512_set1_epi32(kCentre)), table, 4);
    const __m512 centre1 =
        _mm512_i32gather_ps(_mm512_add_epi32(bin1, _mm512_set1_epi32(kCentre)), table, 4);
    const __m512 invArea0 =
        _mm512_i32gather_ps(_mm512_add_epi32(bin0, _mm512_set1_epi32(kInvArea)), table, 4);
    const __m512 invArea1 =
        _mm512_i32gather_ps(_mm512_add_epi32(bin1, _mm512_set1_epi32(kInvArea)), table, 4);
    const __m512i empty =
        _mm512_i32gather_epi32(_mm512_add_epi32(chosen, _mm512_set1_epi32(kEmpty)), table, 4);

    const __m512 oneMinusF = _mm512_sub_ps(one, f), oneMinusV = _mm512_sub_ps(one, v);
    const __m512 lx =
        _mm512_fmadd_ps(s, _mm512_fmadd_ps(oneMinusV, ax, _mm512_mul_ps(v, bx)),
                        _mm512_fmadd_ps(oneMinusF, centre0, _mm512_mul_ps(f, centre1)));
    // A shaped stop's cells centre their bins off the x axis too (the circle's are on it).
    __m512 centreY = zero;
    if (k.cells > 1) {
      const __m512 centreY0 =
          _mm512_i32gather_ps(_mm512_add_epi32(bin0, _mm512_set1_epi32(kCentreY)), table, 4);
      const __m512 centreY1 =
          _mm512_i32gather_ps(_mm512_add_epi32(bin1, _mm512_set1_epi32(kCentreY)), table, 4);
      centreY = _mm512_fmadd_ps(oneMinusF, centreY0, _mm512_mul_ps(f, centreY1));
    }
    const __m512 ly =
        _mm512_fmadd_ps(s, _mm512_fmadd_ps(oneMinusV, ay, _mm512_mul_ps(v, by)), centreY);
    const __mmask16 positive = _mm512_cmp_ps_mask(r, zero, _CMP_GT_OQ);
    const __m512 invR = _mm512_maskz_div_ps(positive, one, r);
    const __m512 c = _mm512_mask_mul_ps(one, positive, fx, invR);
    const __m512 sn = _mm512_mul_ps(fy, invR);
    const __mmask16 inTable = _mm512_cmp_ps_mask(r, _mm512_set1_ps(k.radiusMax), _CMP_LE_OQ);
    const __m512 half = _mm512_set1_ps(k.half);
    const __m512 px = _mm512_mask_blend_ps(
        inTable, _mm512_mul_ps(half, _mm512_fmsub_ps(_mm512_set1_ps(2.0f), u, one)),
        _mm512_fmsub_ps(c, lx, _mm512_mul_ps(sn, ly)));
    const __m512 py = _mm512_mask_blend_ps(
        inTable, _mm512_mul_ps(half, _mm512_fmsub_ps(_mm512_set1_ps(2.0f), v, one)),
        _mm512_fmadd_ps(sn, lx, _mm512_mul_ps(c, ly)));
    const __mmask16 ok =
        static_cast<__mmask16>(~inTable | _mm512_cmpeq_epi32_mask(empty, _mm512_setzero_si512()));
    const __m512 dx = _mm512_sub_ps(px, fx), dy = _mm512_sub_ps(py, fy);
    const __m512 invLength = _mm512_div_ps(
        one, _mm512_sqrt_ps(_mm512_fmadd_ps(dx, dx, _mm512_fmadd_ps(dy, dy, planeZ2))));
    _mm512_mask_storeu_ps(io.ox + i, lanes, fx);
    _mm512_mask_storeu_ps(io.oy + i, lanes, fy);
    _mm512_mask_storeu_ps(io.oz + i, lanes, zero);
    _mm512_mask_storeu_ps(io.dx + i, lanes, _mm512_mul_ps(dx, invLength));
    _mm512_mask_storeu_ps(io.dy + i, lanes, _mm512_mul_ps(dy, invLength));
    _mm512_mask_storeu_ps(io.dz + i, lanes, _mm512_mul_ps(planeZ, invLength));
    _mm_mask_storeu_epi8(io.alive + i, lanes, _mm_maskz_set1_epi8(ok, 1));
    const __m512 pdf =
        _mm512_mask_blend_ps(inTable, _mm512_set1_ps(k.fallbackPdf),
                             _mm512_fmadd_ps(oneMinusF, invArea0, _mm512_mul_ps(f, invArea1)));
    _mm512_mask_storeu_ps(io.pdf + i, lanes, _mm512_maskz_mov_ps(ok, pdf));
  }
}

// Lanes 0-3 (h = 0) or 4-7 (h = 1) of x.
__attribute__((target("avx2,fma"))) inline __m128 halfOf(__m256 x, int h) {
  return h == 0 ? _mm256_castps256_ps128(x) : _mm256_extractf128_ps(x, 1);
}

// table[at + offset], lane by lane.
__attribute__((target("avx2,fma"))) inline __m256 gatherAt(const float* table, __m256i at,
                                                           int offset) {
  return _mm256_i32gather_ps(table, _mm256_add_epi32(at, _mm256_set1_epi32(offset)), 4);
}

// The AVX-512 kernel's computation with AVX2 and FMA, 8 rays at a time, for CPUs without
// AVX-512 (most laptops). Masks are all-ones lanes instead of mask registers.
template <class SamplingBin>
__attribute__((target("avx2,fma"))) void sampleBatchAvx2(const BatchSamplingConstants& k,
                                                         const SamplingBin* bins,
                                                         const BatchSampling& io, std::size_t n) {
  const float* table = reinterpret_cast<const float*>(bins);
  const int* tableInts = reinterpret_cast<const int*>(bins);
  using Layout = TableLayout<SamplingBin>;
  constexpr int kBinStride = Layout::kBinStride, kSlots = Layout::kSlots;
  constexpr int kSectorsAt = Layout::kSectors, kCentre = Layout::kCentre;
  constexpr int kCentreY = Layout::kCentreY;
  constexpr int kInvArea = Layout::kInvArea, kEmpty = Layout::kEmpty;
  const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
  const __m256d oneD = _mm256_set1_pd(1.0), zeroD = _mm256_setzero_pd();
  const __m256d invRadiusMax = _mm256_set1_pd(k.invRadiusMax);
  const __m256d halfBinScale = _mm256_set1_pd(0.5 * k.binScale);
  const __m128i lastPair = _mm_set1_epi32(k.lastPair);
  const __m256 planeZ = _mm256_set1_ps(k.planeZ), planeZ2 = _mm256_set1_ps(k.planeZ * k.planeZ);
  const __m256i binStride = _mm256_set1_epi32(kBinStride);
  const __m256i laneIndex = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (std::size_t i = 0; i < n; i += 8) {
    // The last group's missing lanes read zeros (which address bin 0, slot 0) and store nothing.
    const int remaining = n - i >= 8 ? 8 : static_cast<int>(n - i);
    const __m256i lanes = _mm256_cmpgt_epi32(_mm256_set1_epi32(remaining), laneIndex);
    const __m256 fx = _mm256_maskload_ps(io.filmX + i, lanes);
    const __m256 fy = _mm256_maskload_ps(io.filmY + i, lanes);
    const __m256 u = _mm256_maskload_ps(io.u0 + i, lanes);
    const __m256 v = _mm256_maskload_ps(io.u1 + i, lanes);
    const __m256 r = _mm256_sqrt_ps(_mm256_fmadd_ps(fx, fx, _mm256_mul_ps(fy, fy)));
    __m128i jHalf[2], secondHalf[2];
    __m128 fHalf[2], uxHalf[2];
    for (int h = 0; h < 2; ++h) {
      const __m256d fxd = _mm256_cvtps_pd(halfOf(fx, h)), fyd = _mm256_cvtps_pd(halfOf(fy, h));
      const __m256d ud = _mm256_cvtps_pd(halfOf(u, h));
      const __m256d rd = _mm256_sqrt_pd(_mm256_fmadd_pd(fxd, fxd, _mm256_mul_pd(fyd, fyd)));
      const __m256d x = _mm256_mul_pd(rd, invRadiusMax);
      const __m256d t = _mm256_mul_pd(_mm256_fmadd_pd(x, x, x), halfBinScale);
      const __m128i j = _mm_min_epi32(_mm256_cvttpd_epi32(t), lastPair);
      const __m256d f =
          _mm256_min_pd(_mm256_max_pd(_mm256_sub_pd(t, _mm256_cvtepi32_pd(j)), zeroD), oneD);
      const __m256d oneMinusF = _mm256_sub_pd(oneD, f);
      const __m256d second = _mm256_cmp_pd(ud, oneMinusF, _CMP_GE_OQ);
      const __m256d numerator = _mm256_sub_pd(ud, _mm256_and_pd(second, oneMinusF));
      const __m256d denominator = _mm256_blendv_pd(oneMinusF, f, second);
      jHalf[h] = j;
      fHalf[h] = _mm256_cvtpd_ps(f);
      uxHalf[h] = _mm256_cvtpd_ps(_mm256_div_pd(numerator, denominator));
      secondHalf[h] = _mm256_cvtpd_epi32(_mm256_and_pd(second, oneD));  // 1 or 0
    }
    __m256i cellFirst = _mm256_setzero_si256();
    if (k.cells > 1) {  // stopCellOf, lane by lane
      const __m256 signBit = _mm256_set1_ps(-0.0f);
      const __m256 ax = _mm256_andnot_ps(signBit, fx), ay = _mm256_andnot_ps(signBit, fy);
      const __m256 big = _mm256_max_ps(ax, ay), small = _mm256_min_ps(ax, ay);
      const __m256 t =
          _mm256_and_ps(_mm256_div_ps(small, big), _mm256_cmp_ps(big, zero, _CMP_GT_OQ));
      const __m256 s = _mm256_mul_ps(t, t);
      __m256 p = _mm256_fmadd_ps(_mm256_set1_ps(kAtan9), s, _mm256_set1_ps(kAtan7));
      p = _mm256_fmadd_ps(p, s, _mm256_set1_ps(kAtan5));
      p = _mm256_fmadd_ps(p, s, _mm256_set1_ps(kAtan3));
      p = _mm256_fmadd_ps(p, s, _mm256_set1_ps(kAtan1));
      __m256 a = _mm256_mul_ps(t, p);
      a = _mm256_blendv_ps(a, _mm256_sub_ps(_mm256_set1_ps(kHalfPi), a),
                           _mm256_cmp_ps(ay, ax, _CMP_GT_OQ));
      a = _mm256_blendv_ps(a, _mm256_sub_ps(_mm256_set1_ps(kPi), a),
                           _mm256_cmp_ps(fx, zero, _CMP_LT_OQ));
      a = _mm256_blendv_ps(a, _mm256_sub_ps(_mm256_set1_ps(kTwoPi), a),
                           _mm256_cmp_ps(fy, zero, _CMP_LT_OQ));
      a = _mm256_add_ps(_mm256_sub_ps(a, _mm256_set1_ps(k.cellOffsetRad)), _mm256_set1_ps(kTwoPi));
      const __m256 period = _mm256_set1_ps(k.cellPeriodRad);
      const __m256 turns = _mm256_cvtepi32_ps(_mm256_cvttps_epi32(_mm256_div_ps(a, period)));
      const __m256 folded = _mm256_fnmadd_ps(period, turns, a);
      const __m256i cell = _mm256_min_epi32(
          _mm256_max_epi32(
              _mm256_cvttps_epi32(_mm256_mul_ps(folded, _mm256_set1_ps(k.cellsPerRad))),
              _mm256_setzero_si256()),
          _mm256_set1_epi32(k.cells - 1));
      cellFirst = _mm256_mullo_epi32(cell, _mm256_set1_epi32(k.radialBins));
    }
    const __m256i j = _mm256_add_epi32(_mm256_set_m128i(jHalf[1], jHalf[0]), cellFirst);
    const __m256 f = _mm256_set_m128(fHalf[1], fHalf[0]);
    const __m256 ux = _mm256_set_m128(uxHalf[1], uxHalf[0]);
    const __m256i second = _mm256_set_m128i(secondHalf[1], secondHalf[0]);
    const __m256i bin0 = _mm256_mullo_epi32(j, binStride);
    const __m256i chosen = _mm256_add_epi32(bin0, _mm256_mullo_epi32(second, binStride));

    const __m256 scaled =
        _mm256_mul_ps(_mm256_min_ps(ux, _mm256_set1_ps(0x1.fffffep-1f)), _mm256_set1_ps(32.0f));
    const __m256i slot = _mm256_min_epi32(_mm256_cvttps_epi32(scaled), _mm256_set1_epi32(31));
    const __m256 fraction = _mm256_sub_ps(scaled, _mm256_cvtepi32_ps(slot));
    const __m256i slotAt = _mm256_add_epi32(_mm256_add_epi32(chosen, _mm256_set1_epi32(kSlots)),
                                            _mm256_slli_epi32(slot, 2));  // 4 floats per slot
    const __m256 keep = gatherAt(table, slotAt, 0);
    const __m256 invKeep = gatherAt(table, slotAt, 1);
    const __m256 invComplement = gatherAt(table, slotAt, 2);
    const __m256i alias =
        _mm256_i32gather_epi32(tableInts, _mm256_add_epi32(slotAt, _mm256_set1_epi32(3)), 4);
    const __m256 stay = _mm256_cmp_ps(fraction, keep, _CMP_LT_OQ);
    const __m256i sector = _mm256_blendv_epi8(alias, slot, _mm256_castps_si256(stay));
    const __m256 w = _mm256_blendv_ps(_mm256_mul_ps(_mm256_sub_ps(fraction, keep), invComplement),
                                      _mm256_mul_ps(fraction, invKeep), stay);
    const __m256 s = _mm256_sqrt_ps(w);
    const __m256i sectorAt = _mm256_add_epi32(
        _mm256_add_epi32(chosen, _mm256_set1_epi32(kSectorsAt)), _mm256_slli_epi32(sector, 2));
    const __m256 ax = gatherAt(table, sectorAt, 0), ay = gatherAt(table, sectorAt, 1);
    const __m256 bx = gatherAt(table, sectorAt, 2), by = gatherAt(table, sectorAt, 3);
    const __m256i bin1 = _mm256_add_epi32(bin0, binStride);
    const __m256 centre0 = gatherAt(table, bin0, kCentre), centre1 = gatherAt(table, bin1, kCentre);
    const __m256 invArea0 = gatherAt(table, bin0, kInvArea),
                 invArea1 = gatherAt(table, bin1, kInvArea);
    const __m256i empty =
        _mm256_i32gather_epi32(tableInts, _mm256_add_epi32(chosen, _mm256_set1_epi32(kEmpty)), 4);

    const __m256 oneMinusF = _mm256_sub_ps(one, f), oneMinusV = _mm256_sub_ps(one, v);
    const __m256 lx =
        _mm256_fmadd_ps(s, _mm256_fmadd_ps(oneMinusV, ax, _mm256_mul_ps(v, bx)),
                        _mm256_fmadd_ps(oneMinusF, centre0, _mm256_mul_ps(f, centre1)));
    // A shaped stop's cells centre their bins off the x axis too (the circle's are on it).
    __m256 centreY = zero;
    if (k.cells > 1) {
      centreY = _mm256_fmadd_ps(oneMinusF, gatherAt(table, bin0, kCentreY),
                                _mm256_mul_ps(f, gatherAt(table, bin1, kCentreY)));
    }
    const __m256 ly =
        _mm256_fmadd_ps(s, _mm256_fmadd_ps(oneMinusV, ay, _mm256_mul_ps(v, by)), centreY);
    const __m256 positive = _mm256_cmp_ps(r, zero, _CMP_GT_OQ);
    const __m256 invR = _mm256_and_ps(_mm256_div_ps(one, r), positive);  // 1/0 masked to 0
    const __m256 c = _mm256_blendv_ps(one, _mm256_mul_ps(fx, invR), positive);
    const __m256 sn = _mm256_mul_ps(fy, invR);
    const __m256 inTable = _mm256_cmp_ps(r, _mm256_set1_ps(k.radiusMax), _CMP_LE_OQ);
    const __m256 halfSide = _mm256_set1_ps(k.half);
    const __m256 px =
        _mm256_blendv_ps(_mm256_mul_ps(halfSide, _mm256_fmsub_ps(_mm256_set1_ps(2.0f), u, one)),
                         _mm256_fmsub_ps(c, lx, _mm256_mul_ps(sn, ly)), inTable);
    const __m256 py =
        _mm256_blendv_ps(_mm256_mul_ps(halfSide, _mm256_fmsub_ps(_mm256_set1_ps(2.0f), v, one)),
                         _mm256_fmadd_ps(sn, lx, _mm256_mul_ps(c, ly)), inTable);
    const __m256 notEmpty = _mm256_castsi256_ps(_mm256_cmpeq_epi32(empty, _mm256_setzero_si256()));
    const __m256 ok = _mm256_or_ps(_mm256_cmp_ps(r, _mm256_set1_ps(k.radiusMax), _CMP_NLE_UQ),
                                   notEmpty);  // outside the table, or a bin with a region
    const __m256 dx = _mm256_sub_ps(px, fx), dy = _mm256_sub_ps(py, fy);
    const __m256 invLength = _mm256_div_ps(
        one, _mm256_sqrt_ps(_mm256_fmadd_ps(dx, dx, _mm256_fmadd_ps(dy, dy, planeZ2))));
    _mm256_maskstore_ps(io.ox + i, lanes, fx);
    _mm256_maskstore_ps(io.oy + i, lanes, fy);
    _mm256_maskstore_ps(io.oz + i, lanes, zero);
    _mm256_maskstore_ps(io.dx + i, lanes, _mm256_mul_ps(dx, invLength));
    _mm256_maskstore_ps(io.dy + i, lanes, _mm256_mul_ps(dy, invLength));
    _mm256_maskstore_ps(io.dz + i, lanes, _mm256_mul_ps(planeZ, invLength));
    const int okBits = _mm256_movemask_ps(ok);
    for (int lane = 0; lane < remaining; ++lane) {
      io.alive[i + lane] = static_cast<std::uint8_t>((okBits >> lane) & 1);
    }
    const __m256 pdf =
        _mm256_blendv_ps(_mm256_set1_ps(k.fallbackPdf),
                         _mm256_fmadd_ps(oneMinusF, invArea0, _mm256_mul_ps(f, invArea1)), inTable);
    _mm256_maskstore_ps(io.pdf + i, lanes, _mm256_and_ps(pdf, ok));
  }
}

}  // namespace

void ExitPupilTable::sampleRays(const float* filmX, const float* filmY, const float* u0,
                                const float* u1, std::size_t n, LensRayBatch& rays,
                                float* pdfPerMm2, SampleKernel kernel) const {
  rays.resize(n);
  // Without a table (nothing to gather) or vector instructions: sampleInline, ray by ray.
  if (samplingBins_.empty() || kernel == SampleKernel::Portable) {
    sampleRaysOneByOne(filmX, filmY, u0, u1, n, rays, pdfPerMm2);
    return;
  }
  BatchSamplingConstants k;
  k.planeZ = static_cast<float>(planeZMm_);
  k.half = static_cast<float>(fallbackRadiusMm_);
  k.fallbackPdf = static_cast<float>(1.0 / (4.0 * fallbackRadiusMm_ * fallbackRadiusMm_));
  k.radiusMax = static_cast<float>(filmRadiusMaxMm_);
  k.invRadiusMax = invFilmRadiusMaxMm_;
  k.binScale = binScale_;
  k.lastPair = radialBins_ - 2;
  k.cells = cells_;
  k.radialBins = radialBins_;
  k.cellOffsetRad = cellOffsetRadF_;
  k.cellPeriodRad = cellPeriodRadF_;
  k.cellsPerRad = cellsPerRadF_;
  const BatchSampling io{filmX,
                         filmY,
                         u0,
                         u1,
                         rays.ox.data(),
                         rays.oy.data(),
                         rays.oz.data(),
                         rays.dx.data(),
                         rays.dy.data(),
                         rays.dz.data(),
                         rays.alive.data(),
                         pdfPerMm2};
  switch (kernel) {
    case SampleKernel::Avx512:
      sampleBatchAvx512(k, samplingBins_.data(), io, n);
      break;
    case SampleKernel::Avx2:
      sampleBatchAvx2(k, samplingBins_.data(), io, n);
      break;
    case SampleKernel::Portable:
      break;  // above
  }
}

}  // namespace lenslab::optics
