// Opening other programs' lens files (issue 41: at most 50 ms a file beyond building the lens).
//
// BM_ImportRead/<path>: readLensFile on one reference file that opens
// (../shared/reference/import/*/{zemax,codev}/ and ../shared/reference/patent-text/): reading the
// bytes, decoding, parsing, the catalogue glasses' lookup and the clear apertures derived from the
// design conditions (import/clear_apertures.h). Wall time per file.
// BM_ImportLoad/<path>: loadLens, the same and then validation and LensSystem::build,
// what File > Open and every CLI command do.
// Only files that open are registered (the refused ones stop at their first error, sooner). The
// glass catalogues (the checkout's data/glass) are read once, when the files are first tried at
// registration, as the viewer and the CLI read them once per process.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "optics/lens_file.h"
#include "optics/lens_loader.h"

namespace {

namespace fs = std::filesystem;

void BM_ImportRead(benchmark::State& state, const fs::path& path) {
  for (auto _ : state) {
    const lenslab::optics::LensFileResult result = lenslab::optics::readLensFile(path);
    if (!result.ok()) state.SkipWithError("the file no longer opens");
    benchmark::DoNotOptimize(result);
  }
}

void BM_ImportLoad(benchmark::State& state, const fs::path& path) {
  for (auto _ : state) {
    const lenslab::optics::LoadedLens loaded = lenslab::optics::loadLens(path);
    if (!loaded.ok()) state.SkipWithError("the lens no longer loads");
    benchmark::DoNotOptimize(loaded);
  }
}

const fs::path kImportReference = fs::path(LENSLAB_SOURCE_DIR) / ".." / "shared" / "reference";

// The reference files an importer reads, in a stable order.
std::vector<fs::path> importReferenceFiles() {
  const fs::path& reference = kImportReference;
  std::vector<fs::path> files;
  std::error_code error;
  for (const fs::path& folder : {reference / "import", reference / "patent-text"}) {
    for (const auto& entry : fs::recursive_directory_iterator(folder, error)) {
      std::string extension = entry.path().extension().string();
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (entry.is_regular_file(error) &&
          (extension == ".zmx" || extension == ".seq" || extension == ".txt"))
        files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

[[maybe_unused]] const bool kImportRegistered = [] {
  // The checkout's catalogues (the bench binary is not where the lookup of bundled data looks),
  // unless the environment names others.
  ::setenv("LENSLAB_GLASS_DIR", (std::string(LENSLAB_SOURCE_DIR) + "/data/glass").c_str(), 0);
  for (const fs::path& path : importReferenceFiles()) {
    if (!lenslab::optics::loadLens(path).ok()) continue;
    // "import/optiland/zemax/lens2.zmx" less "import/"; "patent-text/..." as it is.
    std::string name = fs::relative(path, kImportReference).generic_string();
    if (name.rfind("import/", 0) == 0) name.erase(0, 7);
    benchmark::RegisterBenchmark(("BM_ImportRead/" + name).c_str(), BM_ImportRead, path)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("BM_ImportLoad/" + name).c_str(), BM_ImportLoad, path)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  return true;
}();

}  // namespace
