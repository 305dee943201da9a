// voxflame's entry point: everything happens in app::runCommandLine.
#include <string>
#include <vector>

#include "cli.h"

int main(int argc, char** argv) {
  return voxflame::app::runCommandLine(std::vector<std::string>(argv, argv + argc));
}
