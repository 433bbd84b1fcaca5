#pragma once
// Saves that fail, for tests: a directory on a disk that is full or read-only, made for one
// command. The tests may run as root, where a chmod'ed directory stops no write, so the directory
// is a small tmpfs mounted in a private user and mount namespace (unshare -rm): a real full disk
// (ENOSPC) or a real read-only filesystem (EROFS), gone when the command ends, with nothing to
// clean up. The old files are written before the disk is filled or made read-only; after the
// command, what the directory holds is copied out for the test to compare.

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "support/run_process.h"

namespace lenslab::hostile {

enum class DiskState { Full, ReadOnly };

struct FailingDiskRun {
  testing::ProcessResult result;  // the command's exit code and output
  std::filesystem::path after;    // a copy of the directory as the command left it
};

// Whether this machine lets a test mount a tmpfs of its own (a user namespace is allowed).
inline bool privateMountsWork(const std::filesystem::path& scratch) {
  const auto probe = testing::runProcess(
      "unshare -rm sh -c 'mkdir -p \"$0\" && mount -t tmpfs -o size=64k tmpfs \"$0\"' '" +
          (scratch / "probe").string() + "'",
      scratch);
  return probe.exitCode == 0;
}

// Runs `command` (a shell command line) with `directory` a tmpfs that holds `oldFiles`, full or
// read-only. `directory` is the path the command writes to; it exists only inside the namespace.
inline FailingDiskRun runOnFailingDisk(const std::filesystem::path& scratch,
                                       const std::filesystem::path& directory,
                                       const std::map<std::string, std::string>& oldFiles,
                                       DiskState state, const std::string& command) {
  namespace fs = std::filesystem;
  const fs::path old = scratch / "old-files", after = scratch / "after";
  fs::remove_all(old);
  fs::remove_all(after);
  fs::create_directories(old);
  fs::create_directories(after);
  fs::create_directories(directory);
  for (const auto& [name, contents] : oldFiles) {
    std::ofstream(old / name, std::ios::binary) << contents;
  }
  const std::string script =
      "set -u\n"
      "mount -t tmpfs -o size=1m tmpfs '" +
      directory.string() +
      "' || exit 97\n"
      "cp -a '" +
      old.string() + "/.' '" + directory.string() + "/' || exit 98\n" +
      (state == DiskState::Full
           // Fill every block that is left: the next write anywhere on it fails with ENOSPC.
           ? "head -c 4000000 /dev/zero > '" + directory.string() + "/filler' 2>/dev/null\n"
           : "mount -o remount,ro '" + directory.string() + "' || exit 99\n") +
      "( " + command + " ) > '" + (scratch / "command-stdout.txt").string() + "' 2> '" +
      (scratch / "command-stderr.txt").string() +
      "'\n"
      "status=$?\n"
      "cp -a '" +
      directory.string() + "/.' '" + after.string() +
      "/'\n"
      "rm -f '" +
      after.string() +
      "/filler'\n"
      "exit $status\n";
  std::ofstream(scratch / "failing-disk.sh") << script;
  FailingDiskRun run;
  const auto outer = testing::runProcess(
      "unshare -rm sh '" + (scratch / "failing-disk.sh").string() + "'", scratch);
  run.result.exitCode = outer.exitCode;
  run.result.out = testing::readWholeFile(scratch / "command-stdout.txt");
  run.result.err = testing::readWholeFile(scratch / "command-stderr.txt") + outer.err;
  run.after = after;
  return run;
}

// The names in `directory`, one per line, sorted: what a failed save must leave as it was.
inline std::string listing(const std::filesystem::path& directory) {
  std::map<std::string, int> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names[entry.path().filename().string()] = 1;
  }
  std::string text;
  for (const auto& [name, unused] : names) text += name + "\n";
  return text;
}

}  // namespace lenslab::hostile
