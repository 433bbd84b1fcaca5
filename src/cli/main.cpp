#include <csignal>

#include "cli/cli.h"

int main(int argc, char** argv) {
  // A write past the file-size limit (ulimit -f) would otherwise kill the process with SIGXFSZ,
  // leaving the half-written temporary of an atomic save behind. Ignored, the write fails with
  // EFBIG instead, and the save reports it like a full disk and removes the temporary.
  std::signal(SIGXFSZ, SIG_IGN);
  return lenslab::cli::run(argc, argv);
}
