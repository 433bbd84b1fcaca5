#pragma once
// Helpers shared by the optics tests: the reference lens files beside the project, and small
// hand-made prescriptions.

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>

#include "optics/lens_file.h"
#include "optics/lens_system.h"

namespace lenslab::optics::testing {

inline std::filesystem::path referenceLensDir() { return LENSLAB_REFERENCE_LENS_DIR; }
inline std::filesystem::path bundledLensDir() { return LENSLAB_BUNDLED_LENS_DIR; }
// Lenses made for the tests (and benchmarks), not for users: tests/optics/lenses/.
inline std::filesystem::path testLensDir() { return LENSLAB_TEST_LENS_DIR; }

inline Prescription loadPrescription(const std::filesystem::path& path) {
  const LensFileResult file = readLensFile(path);
  EXPECT_TRUE(file.ok()) << file.diagnostics.formatAll();
  return file.ok() ? file.lens->prescription : Prescription{};
}

// Loads a lens file and builds it, with the film at `filmDistanceMm` when positive (the course's
// files have 0 as the last thickness; the scene gives the film distance).
inline std::shared_ptr<const LensSystem> loadLens(const std::filesystem::path& path,
                                                  double filmDistanceMm = 0.0) {
  Prescription p = loadPrescription(path);
  if (p.surfaces.empty()) return nullptr;
  if (filmDistanceMm > 0.0) p.surfaces.back().thicknessMm = filmDistanceMm;
  BuildResult built = LensSystem::build(p);
  EXPECT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().message);
  return built.system;
}

struct CourseLens {
  const char* file;       // in ../shared/reference/lenses
  const char* bundled;    // in lenses/
  double eflMm;           // paraxial EFL (issue 3)
  double filmDistanceMm;  // from the course scene
};

inline const CourseLens kCourseLenses[] = {
    {"dgauss.50mm.dat", "dgauss-50mm.dat", 50.36, 36.77},
    {"fisheye.10mm.dat", "fisheye-10mm.dat", 9.99, 23.192},
    {"telephoto.250mm.dat", "telephoto-250mm.dat", 249.57, 123.7439},
    {"wide.22mm.dat", "wide-22mm.dat", 22.02, 14.54},
};

// A front surface concave to the object (R -20, 18 mm across: its rim is 2.14 mm in front of its
// vertex) on a plano-concave lens, with the stop and every other aperture 40 mm wide: a beam
// from infinity is limited by that front rim alone.
inline Prescription concaveFrontLens() {
  Prescription p;
  p.surfaces = {{-20.0, 3.0, 1.5, std::nullopt, 18.0},
                {INFINITY, 1.0, 1.0, std::nullopt, 40.0},
                {0.0, 30.0, 1.0, std::nullopt, 40.0}};
  return p;
}

// A thick lens in air followed by a stop behind it; radii, thickness, index given.
inline Prescription singlet(double r1, double r2, double thickness, double n, double film,
                            double diameter = 20.0) {
  Prescription p;
  p.surfaces = {{r1, thickness, n, std::nullopt, diameter},
                {r2, 1.0, 1.0, std::nullopt, diameter},
                {0.0, film, 1.0, std::nullopt, diameter}};
  return p;
}

}  // namespace lenslab::optics::testing

namespace lenslab::optics::testing {

// Test names and failure messages show the lens file, not the struct's bytes.
inline void PrintTo(const CourseLens& lens, std::ostream* out) { *out << lens.bundled; }

}  // namespace lenslab::optics::testing
