// ExitPupilTable::sampleRays: exit_pupil.cpp's sampler for a batch of camera rays, mostly in
// single precision: 16 rays at a time with AVX-512 where the CPU has it, one at a time
// otherwise. The renderer calls it for every camera ray.
#include <algorithm>
#include <cmath>
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
};

// The table half of ExitPupilTable::sampleInline, one ray at a time. (A template so that it can
// take the table's private bin type.)
template <class SamplingBin>
void sampleBatchPortable(const BatchSamplingConstants& k, const SamplingBin* bins,
                         const BatchSampling& io, std::size_t n) {
  constexpr int kSectors = ExitPupilTable::kSectors;
  for (std::size_t i = 0; i < n; ++i) {
    const float fx = io.filmX[i], fy = io.filmY[i], u = io.u0[i], v = io.u1[i];
    const float r = std::sqrt(fx * fx + fy * fy);
    float px = k.half * (2.0f * u - 1.0f), py = k.half * (2.0f * v - 1.0f);  // beyond the table
    float pdf = k.fallbackPdf;
    bool ok = true;
    if (r <= k.radiusMax) {
      // The film radius, the bin weight f and the stretched u in double: where f or 1 - f is
      // small, stretching divides by it and would magnify float rounding in f.
      const double x =
          std::sqrt(static_cast<double>(fx) * fx + static_cast<double>(fy) * fy) * k.invRadiusMax;
      const double t = 0.5 * (x + x * x) * k.binScale;
      const int j = std::min(static_cast<int>(t), k.lastPair);
      const double f = std::clamp(t - j, 0.0, 1.0);
      const bool second = u >= 1.0 - f;
      const SamplingBin& chosen = bins[j + (second ? 1 : 0)];
      const auto ux = static_cast<float>(second ? (u - (1.0 - f)) / f : u / (1.0 - f));
      const float scaled = std::min(ux, 0x1.fffffep-1f) * kSectors;
      const int slot = std::min(static_cast<int>(scaled), kSectors - 1);
      const float fraction = scaled - static_cast<float>(slot);
      const auto& alias = chosen.slots[slot];
      const bool stay = fraction < alias.keep;
      const auto& e = chosen.sectors[stay ? slot : alias.alias];
      const float s = std::sqrt(stay ? fraction * alias.invKeep
                                     : (fraction - alias.keep) * alias.invComplement);
      const auto fFloat = static_cast<float>(f);
      const float lx = (1.0f - fFloat) * bins[j].centreXMm + fFloat * bins[j + 1].centreXMm +
                       s * ((1.0f - v) * e.ax + v * e.bx);
      const float ly = s * ((1.0f - v) * e.ay + v * e.by);
      // Rotate from the bin frame (film point on +x) to the film point's azimuth.
      const float invR = r > 0.0f ? 1.0f / r : 0.0f;
      const float c = r > 0.0f ? fx * invR : 1.0f;
      const float sn = fy * invR;
      px = c * lx - sn * ly;
      py = sn * lx + c * ly;
      pdf = (1.0f - fFloat) * bins[j].invAreaPerMm2 + fFloat * bins[j + 1].invAreaPerMm2;
      ok = chosen.empty == 0;
    }
    const float dx = px - fx, dy = py - fy;
    const float invLength = 1.0f / std::sqrt(dx * dx + dy * dy + k.planeZ * k.planeZ);
    io.ox[i] = fx;
    io.oy[i] = fy;
    io.oz[i] = 0.0f;
    io.dx[i] = dx * invLength;
    io.dy[i] = dy * invLength;
    io.dz[i] = k.planeZ * invLength;
    io.alive[i] = ok ? 1 : 0;
    io.pdf[i] = ok ? pdf : 0.0f;
  }
}

// The same computation for AVX-512, 16 rays at a time, branch-free: which bin, the alias slot or
// its alias, inside or outside the table are masks (beyond the table, lanes still read the last
// two bins, then take the fallback square). The film radius, the
// bin weight and the stretched u run in double, eight lanes at a time, as above. Every ray, the
// last group's too, goes through the same lane code: a ray's result must not depend on where it
// sits in a batch (the renderer's image is the same for any tiling and thread count).
template <class SamplingBin>
__attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,fma"))) void sampleBatchAvx512(
    const BatchSamplingConstants& k, const SamplingBin* bins, const BatchSampling& io,
    std::size_t n) {
  static_assert(sizeof(SamplingBin) % sizeof(float) == 0);
  const float* table = reinterpret_cast<const float*>(bins);
  // Offsets in floats: gathers address the table as one float array.
  constexpr int kBinStride = sizeof(SamplingBin) / sizeof(float);
  constexpr int kSlots = offsetof(SamplingBin, slots) / sizeof(float);
  constexpr int kSectorsAt = offsetof(SamplingBin, sectors) / sizeof(float);
  constexpr int kCentre = offsetof(SamplingBin, centreXMm) / sizeof(float);
  constexpr int kInvArea = offsetof(SamplingBin, invAreaPerMm2) / sizeof(float);
  constexpr int kEmpty = offsetof(SamplingBin, empty) / sizeof(float);
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
    const __m512i j = _mm512_inserti64x4(_mm512_castsi256_si512(jHalf[0]), jHalf[1], 1);
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
    const __m512 ly = _mm512_mul_ps(s, _mm512_fmadd_ps(oneMinusV, ay, _mm512_mul_ps(v, by)));
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

}  // namespace

void ExitPupilTable::sampleRays(const float* filmX, const float* filmY, const float* u0,
                                const float* u1, std::size_t n, LensRayBatch& rays,
                                float* pdfPerMm2, bool avx512) const {
  rays.resize(n);
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
  BatchSamplingConstants k;
  k.planeZ = static_cast<float>(planeZMm_);
  k.half = static_cast<float>(fallbackRadiusMm_);
  k.fallbackPdf = static_cast<float>(1.0 / (4.0 * fallbackRadiusMm_ * fallbackRadiusMm_));
  if (samplingBins_.empty()) {  // no table: uniform over the square (see sampleInline)
    const bool noSamples = filmRadiusMaxMm_ == 0.0 && planeZMm_ <= 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const float px = k.half * (2.0f * u0[i] - 1.0f), py = k.half * (2.0f * u1[i] - 1.0f);
      const float dx = px - filmX[i], dy = py - filmY[i];
      const float invLength = 1.0f / std::sqrt(dx * dx + dy * dy + k.planeZ * k.planeZ);
      io.ox[i] = filmX[i];
      io.oy[i] = filmY[i];
      io.oz[i] = 0.0f;
      io.dx[i] = dx * invLength;
      io.dy[i] = dy * invLength;
      io.dz[i] = k.planeZ * invLength;
      io.alive[i] = noSamples ? 0 : 1;
      io.pdf[i] = noSamples ? 0.0f : k.fallbackPdf;
    }
    return;
  }
  k.radiusMax = static_cast<float>(filmRadiusMaxMm_);
  k.invRadiusMax = invFilmRadiusMaxMm_;
  k.binScale = binScale_;
  k.lastPair = static_cast<int>(samplingBins_.size()) - 2;
  if (avx512)
    sampleBatchAvx512(k, samplingBins_.data(), io, n);
  else
    sampleBatchPortable(k, samplingBins_.data(), io, n);
}

}  // namespace lenslab::optics
