// voxflame's entry point: everything happens in cli::runCommandLine, including the hidden
// subcommand core::kMeshImportSubcommand that a child process runs to import a mesh for its parent.
#include <string>
#include <vector>

#include "cli.h"
#include "core/mesh.h"
#include "programs.h"

int main(int argc, char** argv) {
  // Meshes a user opens are imported by this same binary in a child process. "--": the file and
  // its display name are positional arguments whatever they look like ("-x.obj", "render").
  voxflame::core::setMeshImportChild(
      {voxflame::app::currentExecutable(), {voxflame::core::kMeshImportSubcommand, "--"}});
  return voxflame::cli::runCommandLine(std::vector<std::string>(argv, argv + argc));
}
