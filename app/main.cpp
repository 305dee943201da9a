// voxflame's entry point: everything happens in app::runCommandLine, except the hidden mesh
// import a child process runs for its parent (core/mesh.h), which must not load anything else.
#include <string>
#include <vector>

#include "cli.h"
#include "core/mesh.h"
#include "programs.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  if (args.size() == 4 && args[1] == voxflame::core::kMeshImportSubcommand)
    return voxflame::core::runMeshImportChild(args[2], args[3]);
  // Meshes a user opens are imported by this same binary in a child process.
  voxflame::core::setMeshImportChild({voxflame::app::currentExecutable(), {voxflame::core::kMeshImportSubcommand}});
  return voxflame::app::runCommandLine(args);
}
