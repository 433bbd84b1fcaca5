#pragma once
// The analyses' way of saying why they have no answer: the caller passes a string to be told, or
// nullptr when it only needs to know that there is none.

#include <string>
#include <utility>

namespace lenslab::optics {

inline void sayWhyNot(std::string* whyNot, std::string text) {
  if (whyNot) *whyNot = std::move(text);
}

}  // namespace lenslab::optics
