// libFuzzer target: OpticStudio .zmx files (optics/import/zemax_file.h) as bytes in any encoding.
// Beyond not crashing, it holds the reader to its header: a file it accepts builds a LensSystem,
// has a row line for every surface, and its lens written as lenslab's .lens reads back to the
// identical prescription (the importer makes nothing .lens cannot hold).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz_check.h"
#include "optics/import/zemax_file.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"

namespace {

// The checkout's catalogues, so that glass names resolve as in the tests (unless the environment
// names others).
const bool kGlassDirectorySet = [] {
  ::setenv("LENSLAB_GLASS_DIR", LENSLAB_BUNDLED_GLASS_DIR, 0);
  return true;
}();

bool sameNumber(double a, double b) { return a == b || (a != a && b != b); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  (void)kGlassDirectorySet;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const optics::LensFileResult result = optics::parseZemaxBytes(bytes, "input.zmx");
  fuzz::checkDiagnostics(result.diagnostics, result.ok());
  if (!result.ok()) return 0;

  const optics::LensFile& lens = *result.lens;
  const optics::Prescription& prescription = lens.prescription;
  fuzz::check(lens.rowLines.size() == prescription.surfaces.size(),
              "every surface has its row's line");
  fuzz::check(prescription.stopIndex().has_value(), "an accepted file has one stop");
  fuzz::check(optics::LensSystem::build(prescription).ok(),
              "an accepted .zmx file builds a LensSystem");
  const optics::LensFileResult again =
      optics::parseNativeLensText(optics::formatNativeLensText(lens), "written.lens");
  fuzz::check(again.ok(), "the imported lens written as .lens reads back");
  const auto& a = prescription.surfaces;
  const auto& b = again.lens->prescription.surfaces;
  bool same = a.size() == b.size();
  for (std::size_t i = 0; same && i < a.size(); ++i)
    same = sameNumber(a[i].radiusMm, b[i].radiusMm) &&
           sameNumber(a[i].thicknessMm, b[i].thicknessMm) &&
           sameNumber(a[i].mediumIndexD(), b[i].mediumIndexD()) &&
           sameNumber(a[i].apertureDiameterMm, b[i].apertureDiameterMm) &&
           a[i].profile == b[i].profile && a[i].glass == b[i].glass;
  fuzz::check(same, "the .lens text reads back to the identical prescription");
  return 0;
}
