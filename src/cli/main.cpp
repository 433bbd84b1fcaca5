#include "cli/cli.h"

int main(int argc, char** argv) { return lenslab::cli::run(argc, argv); }
