#pragma once
// Whether a scene transform can place things: finite, and with an invertible linear part. A
// singular camera or object transform would put NaN or infinities into rays and bounds.

#include <glm/mat4x4.hpp>
#include <optional>
#include <string>

namespace lenslab::render {

// What is wrong with `m` ("is singular", "has a non-finite entry"), or nothing.
std::optional<std::string> transformProblem(const glm::dmat4& m);

}  // namespace lenslab::render
