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
  fftw_plan lines = nullptr;  // n contiguous complex lines of N, in place
  fftw_plan line = nullptr;   // a real line of N to its N/2 + 1 complex coefficients
};

// One set of plans per (n, N), made on scratch buffers and kept until the process exits. The
// cache owns its plans and destroys them when static objects are destroyed: a map of bare
// fftw_plan handles would free its nodes and leave the plans unreachable, which LeakSanitizer
// reports at exit (./test --sanitize). Every thread that executes plans has been joined by then.
class PlanCache {
 public:
  PlanCache() = default;
  PlanCache(const PlanCache&) = delete;
  PlanCache& operator=(const PlanCache&) = delete;
  ~PlanCache() {
    for (auto& [size, plans] : cache_) {
      fftw_destroy_plan(plans.lines);
      fftw_destroy_plan(plans.line);
    }
  }

  const Plans& plansFor(int samples, int fftSize) {
    const std::lock_guard lock(mutex_);
    auto found = cache_.find({samples, fftSize});
    if (found != cache_.end()) return found->second;

    auto lines = allocate<fftw_complex>(static_cast<std::size_t>(samples) * fftSize);
    auto line = allocate<double>(fftSize);
    auto lineOut = allocate<fftw_complex>(fftSize / 2 + 1);
    Plans plans;
    int length = fftSize;
    // FFTW_ESTIMATE: planning in microseconds, and the same plan (hence the same rounding) on
    // every run. FFTW's planner is not thread-safe, hence planning under the lock.
    plans.lines = fftw_plan_many_dft(1, &length, samples, lines.get(), nullptr, 1, fftSize,
                                     lines.get(), nullptr, 1, fftSize, FFTW_FORWARD, FFTW_ESTIMATE);
    plans.line = fftw_plan_dft_r2c_1d(fftSize, line.get(), lineOut.get(), FFTW_ESTIMATE);
    if (!plans.lines || !plans.line) {
      if (plans.lines) fftw_destroy_plan(plans.lines);
      if (plans.line) fftw_destroy_plan(plans.line);
      throw std::runtime_error("FFTW could not plan the pupil transforms");
    }
    return cache_.emplace(std::make_pair(samples, fftSize), plans).first->second;
  }

 private:
  std::mutex mutex_;
  std::map<std::pair<int, int>, Plans> cache_;
};

const Plans& plansFor(int samples, int fftSize) {
  static PlanCache cache;
  return cache.plansFor(samples, fftSize);
}

// Each thread's buffers, for the largest size asked for.
struct Workspace {
  int samples = 0, fftSize = 0;
  FftwBuffer<fftw_complex> lines;
  FftwBuffer<double> line;
  FftwBuffer<fftw_complex> lineOut;
  std::vector<double> projection;

  void resize(int n, int size) {
    if (n == samples && size == fftSize) return;
    samples = n;
    fftSize = size;
    lines = allocate<fftw_complex>(static_cast<std::size_t>(n) * size);
    line = allocate<double>(size);
    lineOut = allocate<fftw_complex>(size / 2 + 1);
    projection.assign(size, 0.0);
  }
};

// The MTF along one axis: the pupil's lines across that axis (line v holds the samples
// pupilAt(u, v), u = 0..n-1), transformed; their summed squared moduli are the line spread
// function (up to the factor N); its |FFT| at lags 0..n over its value at lag 0.
template <class PupilAt>
std::vector<double> axisMtf(const Plans& plans, Workspace& work, int samples, int fftSize,
                            PupilAt pupilAt) {
  fftw_complex* lines = work.lines.get();
  for (int v = 0; v < samples; ++v) {
    fftw_complex* row = lines + static_cast<std::size_t>(v) * fftSize;
    for (int u = 0; u < samples; ++u) {
      const std::complex<double> value = pupilAt(u, v);
      row[u][0] = value.real();
      row[u][1] = value.imag();
    }
    std::memset(row + samples, 0, sizeof(fftw_complex) * (fftSize - samples));
  }
  fftw_execute_dft(plans.lines, lines, lines);

  std::fill(work.projection.begin(), work.projection.end(), 0.0);
  for (int v = 0; v < samples; ++v) {
    const fftw_complex* row = lines + static_cast<std::size_t>(v) * fftSize;
    for (int x = 0; x < fftSize; ++x)
      work.projection[x] += row[x][0] * row[x][0] + row[x][1] * row[x][1];
  }
  std::copy(work.projection.begin(), work.projection.end(), work.line.get());
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
  work.resize(samples, fftSize);
  const auto at = [&](int i, int j) { return pupil[static_cast<std::size_t>(j) * samples + i]; };
  AxisMtf mtf;
  // Along x: the pupil's rows; along y: its columns.
  mtf.alongX = axisMtf(plans, work, samples, fftSize, [&](int u, int v) { return at(u, v); });
  mtf.alongY = axisMtf(plans, work, samples, fftSize, [&](int u, int v) { return at(v, u); });
  return mtf;
}

}  // namespace lenslab::optics
