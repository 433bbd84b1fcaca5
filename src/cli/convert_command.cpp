#include "cli/convert_command.h"

#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "cli/lens_loading.h"
#include "optics/lens_file.h"

namespace lenslab::cli {

namespace {

struct ConvertArguments {
  std::string inputPath;
  std::string outputPath;
};

std::string lowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

int convert(const ConvertArguments& arguments) {
  const std::string extension = lowerExtension(arguments.outputPath);
  if (extension != ".lens" && extension != ".dat") {
    std::cerr << "lenslab convert: " << arguments.outputPath
              << ": lenslab writes .lens (its own format) or .dat (pbrt's), not '"
              << (extension.empty() ? std::string("no extension") : extension) << "'\n";
    return 1;
  }
  // Read, validated and built: what is written is a lens lenslab can open again.
  const optics::LoadedLens loaded = loadLensFileOrReport(arguments.inputPath, "convert");
  if (!loaded.ok()) return 1;
  std::string error;
  if (!optics::writeLensFile(arguments.outputPath, loaded.file, &error)) {
    std::cerr << "lenslab convert: " << arguments.outputPath << ": " << error << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

void addConvertCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<ConvertArguments>();
  CLI::App* command = app.add_subcommand(
      "convert", "Convert a lens file (.lens, .dat, .zmx, .seq, .txt) to .lens or .dat");
  command->add_option("IN", arguments->inputPath, "Lens file to read")->required();
  command->add_option("OUT", arguments->outputPath, "File to write: .lens or .dat")->required();
  command->callback([arguments, &run] { run = [arguments] { return convert(*arguments); }; });
}

}  // namespace lenslab::cli
