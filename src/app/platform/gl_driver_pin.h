#pragma once
// The sanitizer build's hold on the GL driver (see gl_driver_pin.cpp).

namespace lenslab::app {

// Under AddressSanitizer (the build defines LENSLAB_ADDRESS_SANITIZER), keeps every Mesa DRI
// driver loaded so far (e.g. swrast_dri.so) in memory until the process exits. Elsewhere it does
// nothing. Call it once the GL context is current, when the driver is loaded.
void keepGlDriverLoadedUntilExit();

}  // namespace lenslab::app
