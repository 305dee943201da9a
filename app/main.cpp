// voxflame's entry point: everything happens in cli::runCommandLine.
#include <string>
#include <vector>

#include "cli.h"

int main(int argc, char** argv) {
  return voxflame::cli::runCommandLine(std::vector<std::string>(argv, argv + argc));
}
