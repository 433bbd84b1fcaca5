#pragma once
// How the light of a wavelength that a dispersive lens lands away from its sample's film point
// is shared among pixels (the spectral render's "other" wavelengths: RealisticCamera::
// heroWavelengthWeights traces them back to where they meet the film).
//
// Why not simply the pixel it lands in: the RGB render gives each pixel its own stratified
// samples, exactly so many of them; a wavelength that the lens moves a little lands in the
// neighbour whenever its sample lies within that shift of the pixel's edge, and how many of its
// neighbours' wavelengths a pixel receives in return is then random. That count was most of the
// spectral render's excess noise in flat bright areas (bench/README.md, stop 33: through the
// double-Gauss, 3.6e-4 against 2.1e-4 in the chart's white checks when every wavelength was
// counted in its own sample's pixel). Shared linearly across the pixel edge, a small shift moves
// a small share instead of all or nothing, and the stratified samples then give every pixel
// nearly the same total: the pixel's filter is the box widened into a trapezoid, 1 out to
// 0.5 - a from the pixel's centre and 0 beyond 0.5 + a, falling linearly between (the box
// convolved with a box of width 2 a).
//
// Only those wavelengths: the hero lands at its own film point, in its sample's pixel, where the
// stratification already holds. Every wavelength is the hero in about one sample of K, so each
// is reconstructed nearly alike, with about (K - 1) / K of its light through the trapezoid (the
// share follows the MIS weights: where a sample's wavelengths land in different pixels the
// hero's weight leans up to 2 / (K + 1), realistic_camera.cpp) and the rest through the box: a
// contrast of sin(pi a) / (pi a) at the Nyquist frequency relative to the box for the shared
// light, 0.90 at a = 0.25, so about 0.93 for K = 4. The picture a dispersive spectral render
// converges to is that slightly softer one, not the box's.

namespace lenslab::render {

// a, in pixels. Chosen from bench/spectral-error.sh at 300 x 200, 16 against 1024 spp, spectral
// / RGB error (stop 36): 0 (the pixel it lands in): double-Gauss 1.567, Cooke triplet 1.889,
// flint singlet 2.526; 0.1: 1.423, 1.699, 2.409; 0.25: 1.364, 1.570, 2.232. Not the filter's own
// smoothing: with every sample of both renders shared alike (a trial), RGB's error fell only
// 0.6-8% and the ratios were 1.294, 1.453, 2.357. The cost: about 12% more per spectral pass
// through a dispersive lens (up to four deposits per wavelength instead of one).
inline constexpr float kLandingRampPx = 0.25f;

// Along one axis, the share of a wavelength that lands at `fraction` (in [0, 1)) across pixel
// `index` of `count` that goes to the neighbour on the nearer side, index + step (step -1 or
// +1); the pixel keeps 1 - share. (With a <= 1/2 only the nearer neighbour can have a share.)
// At the image's edge the share that would leave the image stays in the edge pixel: no sample
// is taken beyond the edge, so no light comes back from there either.
struct LandingShare {
  int step;
  float share;
};
inline LandingShare landingShare(float fraction, int index, int count) {
  constexpr float a = kLandingRampPx;
  static_assert(a > 0.0f && a <= 0.5f);
  const bool low = fraction < 0.5f;
  const float fromEdge = low ? fraction : 1.0f - fraction;
  const bool inside = low ? index > 0 : index < count - 1;
  return {low ? -1 : 1, inside && fromEdge < a ? 0.5f - fromEdge / (2.0f * a) : 0.0f};
}

}  // namespace lenslab::render
