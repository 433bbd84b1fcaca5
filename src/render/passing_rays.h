#pragma once
// The indices of the rays a batch lens trace let through, listed without a branch per ray: the
// loops after the trace then run over them alone. Testing each ray instead is a branch that
// mispredicts often where few pass (a shaped stop; the course scenes' rear-disk sampling, 28%).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lenslab::render {

// Fills `list` with the i < count where passed[i] != 0, in order; returns how many.
inline std::size_t listPassingRays(const std::uint8_t* passed, std::size_t count,
                                   std::vector<std::uint32_t>& list) {
  list.resize(count);
  std::uint32_t* __restrict out = list.data();
  const std::uint8_t* __restrict flags = passed;
  std::size_t passCount = 0;
  for (std::size_t i = 0; i < count; ++i) {
    out[passCount] = static_cast<std::uint32_t>(i);  // overwritten unless ray i passed
    passCount += flags[i] != 0 ? 1 : 0;
  }
  return passCount;
}

}  // namespace lenslab::render
