// libFuzzer target: the CODE V sequence reader (optics/import/codev_file.h) on arbitrary text.
// Beyond not crashing, it holds the reader to its header: a file it accepts builds a LensSystem,
// every surface has its line, the design conditions are finite numbers (they reach JSON and the
// analyses), and lenslab's own .lens text for the lens reads back to the identical prescription.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "imported_lens_checks.h"
#include "optics/import/codev_file.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const optics::LensFileResult result = optics::parseCodeVText(text, "input.seq");
  fuzz::checkDiagnostics(result.diagnostics, result.ok());
  if (!result.ok()) return 0;

  fuzz::checkImportedLens(*result.lens);
  return 0;
}
