#pragma once
// The CLI tests' way to run the real binary headless: no display, so a subcommand that reached
// for one would fail, and the bundled lenses by name.

#include <string>

namespace lenslab {

// A shell command that runs lenslab with `arguments` and no display.
inline std::string lenslab(const std::string& arguments) {
  return std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + LENSLAB_BINARY + "' " + arguments;
}

// A bundled lens file (lenses/NAME).
inline std::string lensPath(const std::string& name) {
  return std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name;
}

}  // namespace lenslab
