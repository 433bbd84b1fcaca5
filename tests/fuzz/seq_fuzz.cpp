// libFuzzer target: the CODE V sequence reader (optics/import/codev_file.h) on arbitrary text.
// Beyond not crashing, it holds the reader to its header: a file it accepts builds a LensSystem,
// every surface has its line, the design conditions are finite numbers (they reach JSON and the
// analyses), and lenslab's own .lens text for the lens reads back to the identical prescription.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "optics/import/codev_file.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"

namespace {

bool samePrescription(const lenslab::optics::Prescription& a,
                      const lenslab::optics::Prescription& b) {
  if (a.surfaces.size() != b.surfaces.size()) return false;
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    const auto &s = a.surfaces[i], &t = b.surfaces[i];
    if (s.radiusMm != t.radiusMm || s.thicknessMm != t.thicknessMm || s.indexD != t.indexD ||
        s.apertureDiameterMm != t.apertureDiameterMm || s.abbeD != t.abbeD ||
        !(s.profile == t.profile) || (s.glass == nullptr) != (t.glass == nullptr) ||
        (s.glass && t.glass && s.glass->name != t.glass->name))
      return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const optics::LensFileResult result = optics::parseCodeVText(text, "input.seq");
  fuzz::checkDiagnostics(result.diagnostics, result.ok());
  if (!result.ok()) return 0;

  const optics::LensFile& lens = *result.lens;
  fuzz::check(lens.rowLines.size() == lens.prescription.surfaces.size(),
              "every surface has its line");
  fuzz::check(optics::LensSystem::build(lens.prescription).ok(),
              "an accepted sequence builds a LensSystem");
  const optics::DesignConditions& design = lens.design;
  for (double nm : design.wavelengths.nanometres)
    fuzz::check(std::isfinite(nm) && nm > 0.0, "design wavelengths are finite and positive");
  fuzz::check(
      design.wavelengths.empty() || (design.wavelengths.primaryIndex >= 0 &&
                                     design.wavelengths.primaryIndex <
                                         static_cast<int>(design.wavelengths.nanometres.size())),
      "the reference wavelength is one of them");
  for (double value : design.fields.values)
    fuzz::check(std::isfinite(value), "design fields are finite");
  fuzz::check(
      !design.aperture || (std::isfinite(design.aperture->value) && design.aperture->value > 0.0),
      "the design aperture is finite and positive");

  const optics::LensFileResult again =
      optics::parseNativeLensText(optics::formatNativeLensText(lens), "written.lens");
  fuzz::check(again.ok(), "lenslab's .lens text of an imported lens reads back");
  fuzz::check(samePrescription(again.lens->prescription, lens.prescription),
              "the .lens text reads back to the identical prescription");
  return 0;
}
