#include "optics/analysis/pupil_mtf.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace lenslab::optics {

namespace {

// Buffers from fftw_malloc, so that every buffer has the alignment the plans were made with
// (the new-array execute functions require it).
struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};
template <class T>
using FftwBuffer = std::unique_ptr<T[], FftwFree>;
template <class T>
FftwBuffer<T> allocate(std::size_t count) {
  FftwBuffer<T> buffer(static_cast<T*>(fftw_malloc(sizeof(T) * count)));
  if (!buffer) throw std::bad_alloc();
  return buffer;
}

struct Plans {
  fftw_plan rows = nullptr;     // the n rows that hold the pupil, in place, along x
  fftw_plan columns = nullptr;  // all N columns, in place, along y
  fftw_plan line = nullptr;     // a real line of N to its N/2 + 1 complex coefficients
};

// One set of plans per (n, N), made on scratch buffers and kept for the process's life.
const Plans& plansFor(int samples, int fftSize) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, Plans> cache;
  const std::lock_guard lock(mutex);
  auto found = cache.find({samples, fftSize});
  if (found != cache.end()) return found->second;

  const std::size_t cells = static_cast<std::size_t>(fftSize) * fftSize;
  auto grid = allocate<fftw_complex>(cells);
  auto line = allocate<double>(fftSize);
  auto lineOut = allocate<fftw_complex>(fftSize / 2 + 1);
  Plans plans;
  int length = fftSize;
  // FFTW_ESTIMATE: planning in microseconds and the same plan (hence the same rounding) on
  // every run; measured plans were no faster at these sizes (bench/README.md).
  plans.rows = fftw_plan_many_dft(1, &length, samples, grid.get(), nullptr, 1, fftSize, grid.get(),
                                  nullptr, 1, fftSize, FFTW_FORWARD, FFTW_ESTIMATE);
  plans.columns = fftw_plan_many_dft(1, &length, fftSize, grid.get(), nullptr, fftSize, 1,
                                     grid.get(), nullptr, fftSize, 1, FFTW_FORWARD, FFTW_ESTIMATE);
  plans.line = fftw_plan_dft_r2c_1d(fftSize, line.get(), lineOut.get(), FFTW_ESTIMATE);
  if (!plans.rows || !plans.columns || !plans.line)
    throw std::runtime_error("FFTW could not plan the pupil transforms");
  return cache.emplace(std::make_pair(samples, fftSize), plans).first->second;
}

// Each thread's buffers, grown to the largest size asked for.
struct Workspace {
  int fftSize = 0;
  FftwBuffer<fftw_complex> grid;
  FftwBuffer<double> line;
  FftwBuffer<fftw_complex> lineOut;
  std::vector<double> projectionX, projectionY;

  void resize(int size) {
    if (size == fftSize) return;
    fftSize = size;
    grid = allocate<fftw_complex>(static_cast<std::size_t>(size) * size);
    line = allocate<double>(size);
    lineOut = allocate<fftw_complex>(size / 2 + 1);
    projectionX.assign(size, 0.0);
    projectionY.assign(size, 0.0);
  }
};

// |FFT(line)| at lags 0..samples, divided by its value at lag 0.
std::vector<double> modulation(const Plans& plans, Workspace& work,
                               const std::vector<double>& projection, int samples) {
  std::copy(projection.begin(), projection.end(), work.line.get());
  fftw_execute_dft_r2c(plans.line, work.line.get(), work.lineOut.get());
  std::vector<double> mtf(samples + 1, 0.0);
  const double zero = work.lineOut[0][0];
  if (!(zero > 0.0)) return mtf;
  for (int k = 0; k <= samples; ++k)
    mtf[k] = std::hypot(work.lineOut[k][0], work.lineOut[k][1]) / zero;
  return mtf;
}

}  // namespace

AxisMtf pupilAxisMtf(const std::vector<std::complex<double>>& pupil, int samples, int fftSize) {
  if (samples < 1 || fftSize < 2 * samples || fftSize % 2 != 0 ||
      pupil.size() != static_cast<std::size_t>(samples) * samples)
    throw std::invalid_argument("pupilAxisMtf: the pupil must be n x n with an FFT size >= 2n");
  const Plans& plans = plansFor(samples, fftSize);
  thread_local Workspace work;
  work.resize(fftSize);

  fftw_complex* grid = work.grid.get();
  std::memset(grid, 0, sizeof(fftw_complex) * static_cast<std::size_t>(fftSize) * fftSize);
  for (int j = 0; j < samples; ++j)
    for (int i = 0; i < samples; ++i) {
      const std::complex<double> value = pupil[static_cast<std::size_t>(j) * samples + i];
      grid[static_cast<std::size_t>(j) * fftSize + i][0] = value.real();
      grid[static_cast<std::size_t>(j) * fftSize + i][1] = value.imag();
    }
  fftw_execute_dft(plans.rows, grid, grid);
  fftw_execute_dft(plans.columns, grid, grid);

  // The PSF and its projections on the x and y axes.
  std::fill(work.projectionX.begin(), work.projectionX.end(), 0.0);
  std::fill(work.projectionY.begin(), work.projectionY.end(), 0.0);
  for (int y = 0; y < fftSize; ++y) {
    const fftw_complex* row = grid + static_cast<std::size_t>(y) * fftSize;
    double rowSum = 0.0;
    for (int x = 0; x < fftSize; ++x) {
      const double psf = row[x][0] * row[x][0] + row[x][1] * row[x][1];
      rowSum += psf;
      work.projectionX[x] += psf;
    }
    work.projectionY[y] = rowSum;
  }
  AxisMtf mtf;
  mtf.alongX = modulation(plans, work, work.projectionX, samples);
  mtf.alongY = modulation(plans, work, work.projectionY, samples);
  return mtf;
}

}  // namespace lenslab::optics
