// `voxflame import FILE.flame|FILE.flam3 -o PRESET.json [--mesh MESH] [--depth D] [--index N | --name NAME]`:
// turns a flame that flam3, Apophysis, Fractorium or JWildfire wrote into a complete voxflame
// preset (core/flame/xml.h does the reading), so `voxflame render PRESET.json` renders it.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "core/error.h"
#include "core/file_output.h"
#include "core/flame/xml.h"
#include "core/scene_io.h"
#include "usage_error.h"

namespace voxflame::app {

namespace {

// The mesh as the preset will name it: "builtin:..." as given, a file relative to the preset's
// folder (so the two can move together), absolute when no relative path exists.
void placeMesh(core::Scene& scene, const std::string& mesh, const std::filesystem::path& output) {
  if (mesh.rfind(core::kBuiltinMeshPrefix, 0) == 0) {
    scene.meshPath = mesh.substr(std::string_view(core::kBuiltinMeshPrefix).size());
    scene.embedded = true;
    scene.baseDirectory.clear();
    return;
  }
  if (!std::filesystem::is_regular_file(mesh)) throw core::Error("mesh '" + mesh + "': no such file");
  const std::filesystem::path absolute = std::filesystem::absolute(mesh).lexically_normal();
  const std::filesystem::path folder = std::filesystem::absolute(output).parent_path();
  const std::filesystem::path relative = absolute.lexically_relative(folder);
  scene.meshPath = relative.empty() ? absolute.string() : relative.string();
  scene.embedded = false;
  scene.baseDirectory = folder;
}

}  // namespace

core::Scene importBaseScene() {
  core::Scene base = core::defaultScene();
  base.points = kImportedFlamePoints;
  return base;
}

core::FlameFileContents importFlameScene(const std::filesystem::path& path, const core::Scene& base,
                                         const core::FlameImportOptions& options, core::Scene& scene) {
  core::FlameFileContents contents = core::loadFlameFile(path, options);
  scene = core::sceneFromImportedFlame(contents.flame, base);
  return contents;
}

int importCommand(const ImportArguments& arguments) {
  if (!arguments.flameFile) throw UsageError("import needs a flame file: voxflame import FILE.flame -o PRESET.json");
  if (!arguments.output) throw UsageError("import needs an output file: -o PRESET.json");
  const std::string& output = *arguments.output;
  if (std::filesystem::path(output).extension() != ".json")
    throw UsageError("output '" + output + "' must end in .json (a voxflame preset)");
  if (arguments.index && arguments.name) throw UsageError("--index and --name both pick a flame; give one of them");
  core::FlameImportOptions options;
  options.depth = arguments.depth;
  if (arguments.index) options.index = static_cast<std::size_t>(*arguments.index - 1);
  if (arguments.name) options.name = *arguments.name;

  const std::filesystem::path input = *arguments.flameFile;
  core::Scene base = importBaseScene();
  if (arguments.mesh) placeMesh(base, *arguments.mesh, output);
  core::Scene scene;
  const core::FlameFileContents contents = importFlameScene(input, base, options, scene);
  for (const std::string& warning : contents.flame.warnings)
    std::cerr << "voxflame: warning: " << input.string() << ": " << warning << "\n";
  // What is written must load: read it back before it replaces anything.
  const std::string json = core::sceneToJson(scene);
  core::sceneFromJson(json, output);
  core::writeFileAtomically(output, json, {.mode = 0644, .createFolder = true, .what = "cannot write preset"});
  const std::size_t count = contents.names.size();
  const std::size_t transforms = contents.flame.genome.xforms.size();
  char depth[48] = "";
  if (contents.flame.depthAdded) std::snprintf(depth, sizeof depth, ", depth %g", options.depth);
  std::printf("imported flame '%s' (%zu of %zu in %s; %zu transform%s%s%s) into %s\n", contents.flame.name.c_str(),
              contents.index + 1, count, input.string().c_str(), transforms, transforms == 1 ? "" : "s",
              contents.flame.genome.hasFinal ? " and a final one" : "", depth, output.c_str());
  if (!contents.flame.otherLayers.empty())
    std::printf("with %zu more JWildfire layer%s, each a flame layer placed with the first\n",
                contents.flame.otherLayers.size(), contents.flame.otherLayers.size() == 1 ? "" : "s");
  if (count > 1 && !arguments.index && !arguments.name)
    std::printf("the file holds %zu flames; --index N or --name NAME picks another\n", count);
  return 0;
}

}  // namespace voxflame::app
