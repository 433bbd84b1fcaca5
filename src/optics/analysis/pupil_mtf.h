#pragma once
// The MTF of a sampled pupil function along the two axes, by FFT (FFTW):
//   P = A exp(2 pi i W),  PSF = |FFT2(P)|^2,  OTF = FFT2(PSF),  MTF = |OTF| / OTF(0).
// The pupil (n x n samples) sits in a zero-padded N x N array, N >= 2n, so the OTF, the pupil's
// autocorrelation, does not wrap around. Only the OTF's two axes are needed, and by the
// projection-slice theorem OTF(fx, 0) is the 1-D FFT of the PSF summed over y (the line spread
// function along x), OTF(0, fy) that of the PSF summed over x. Those sums need no 2-D PSF: with
// H(x, v) the 1-D FFT along x of the pupil's row v, FFT2(P)(x, y) is the FFT of H(x, .) along y,
// so by Parseval's theorem sum_y PSF(x, y) = N sum_v |H(x, v)|^2; likewise along y with the
// pupil's columns. So: n FFTs of the rows, n of the columns (each of length N), two projections
// and two 1-D FFTs, instead of a 2-D FFT of N x N (N + n transforms) and a pass over its N^2
// intensities: about three times less work, the same numbers.
//
// Frequencies come as lags: lag k is a shift of the pupil by k samples, so the MTF at lag k is
// at k * (direction-cosine step per sample) / wavelength cycles per unit length; lag n, a shift
// by the whole pupil, is the cutoff.
//
// FFTW plans are made once per (n, N) under a mutex (FFTW's planner is not thread-safe; its
// execute functions are) and reused on each calling thread's own buffers, so analyses may run
// on worker threads.

#include <complex>
#include <vector>

namespace lenslab::optics {

struct AxisMtf {
  // At lags 0..n (n + 1 values), 1 at lag 0. x: sagittal (frequency along x); y: tangential.
  std::vector<double> alongX;
  std::vector<double> alongY;
};

// pupil: n x n, row-major (row = y index). fftSize >= 2n, even. An all-zero pupil gives zeros.
AxisMtf pupilAxisMtf(const std::vector<std::complex<double>>& pupil, int samples, int fftSize);

}  // namespace lenslab::optics
