// libFuzzer target: the lens file readers on arbitrary text, pbrt's .dat (optics/lens_file.h) and
// lenslab's .lens (optics/native_lens_file.h), whichever the text's first line picks. Beyond not
// crashing, it holds each reader to its header: a file it accepts builds a LensSystem, and the
// text its writer writes for it reads back to the identical lens.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "optics/lens_file.h"
#include "optics/lens_system.h"
#include "optics/native_lens_file.h"

namespace {

bool sameNumber(double a, double b) { return a == b || (a != a && b != b); }

bool samePrescription(const lenslab::optics::Prescription& a,
                      const lenslab::optics::Prescription& b) {
  if (a.surfaces.size() != b.surfaces.size() || !(a.stopShape == b.stopShape)) return false;
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    const auto &s = a.surfaces[i], &t = b.surfaces[i];
    if (!sameNumber(s.radiusMm, t.radiusMm) || !sameNumber(s.thicknessMm, t.thicknessMm) ||
        !sameNumber(s.indexD, t.indexD) ||
        !sameNumber(s.apertureDiameterMm, t.apertureDiameterMm) ||
        s.abbeD.has_value() != t.abbeD.has_value() ||
        (s.abbeD && !sameNumber(*s.abbeD, *t.abbeD)) || !(s.profile == t.profile))
      return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lenslab;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // A folder that does not exist: an aperture image named relative to the lens file is never
  // found, so the target reads nothing from the disk but what an absolute name points at.
  const bool native = optics::isNativeLensText(text, "input.dat");
  const optics::LensFileResult result =
      native ? optics::parseNativeLensText(text, "/nonexistent-lenslab-fuzz/input.lens")
             : optics::parseLensText(text, "/nonexistent-lenslab-fuzz/input.dat");
  fuzz::checkDiagnostics(result.diagnostics, result.ok());
  if (!result.ok()) return 0;

  const optics::LensFile& lens = *result.lens;
  const optics::Prescription& prescription = lens.prescription;
  fuzz::check(lens.rowLines.size() == prescription.surfaces.size(),
              "every surface has its row's line");
  fuzz::check(optics::LensSystem::build(prescription).ok(),
              "an accepted lens file builds a LensSystem");
  const std::string written = native ? optics::formatNativeLensText(lens)
                                     : optics::formatLensText(prescription, lens.headerComments);
  const optics::LensFileResult again =
      native ? optics::parseNativeLensText(written, "/nonexistent-lenslab-fuzz/written.lens")
             : optics::parseLensText(written, "/nonexistent-lenslab-fuzz/written.dat");
  fuzz::check(again.ok(), "the text the writer writes reads back");
  fuzz::check(samePrescription(again.lens->prescription, prescription),
              "the written text reads back to the identical prescription");
  if (native) {
    fuzz::check(again.lens->title == lens.title && again.lens->source == lens.source &&
                    again.lens->headerComments == lens.headerComments &&
                    again.lens->publishedEflMm == lens.publishedEflMm,
                "the written text reads back to the same title, source, notes and focal length");
    fuzz::check(optics::formatNativeLensText(*again.lens) == written,
                "writing what was read back gives the same text");
  }
  return 0;
}
