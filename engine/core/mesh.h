// A triangle mesh as the rest of voxflame sees it: one flat list of vertices and triangles in the
// file's own coordinates, with every sub-mesh of the file merged and its node transform applied.
// Loading goes through Assimp, so any format Assimp reads works; what cannot be used (missing
// file, no triangles, a flat mesh) is refused with a message naming the file.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace voxflame::core {

struct Box {
  glm::dvec3 min{0.0};
  glm::dvec3 max{0.0};
  glm::dvec3 extent() const { return max - min; }
  glm::dvec3 center() const { return 0.5 * (min + max); }
};

struct TriangleMesh {
  std::vector<glm::vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::string name;  // file name, for messages and statistics

  Box bounds() const;
};

struct MeshLoadOptions {
  // The importer runs in a child process and is stopped after this long (a corrupt file can send
  // Assimp into an endless loop). 0: 30 s plus 4 s per MB of file.
  double timeLimitSeconds = 0.0;
  // false: import in this process. Only for data voxflame itself ships (the meshes compiled into
  // the binary): a trusted file needs no isolation and no child process to start.
  bool isolate = true;
};

// The program that imports a mesh in a child process: run as `program arguments... FILE NAME`, it
// answers on its standard output with runMeshImportChild's record. voxflame names itself with the
// hidden subcommand kMeshImportSubcommand; test programs name the built voxflame binary. Until a
// program sets one, meshes are imported in-process, without protection from a crashing importer.
struct MeshImportChild {
  std::filesystem::path program;
  std::vector<std::string> arguments;
};
void setMeshImportChild(MeshImportChild importer);
inline constexpr const char* kMeshImportSubcommand = "__import-mesh";

// The child's side: imports FILE with Assimp and writes the mesh (or the error message, calling
// the mesh displayName) to standard output in the record the parent reads, then ends the process.
[[noreturn]] void runMeshImportChild(const std::filesystem::path& path, const std::string& displayName);

// Loads and merges every mesh of the file. Throws core::Error naming the file on any problem:
// missing, empty, corrupt, truncated, no triangles, only points or lines, indices out of range,
// flat. A file that crashes or hangs the importer is reported as corrupt; voxflame carries on.
TriangleMesh loadMesh(const std::filesystem::path& path, const MeshLoadOptions& options = {});

// Same, from bytes in memory (an embedded resource); extensionHint is the format's extension
// without the dot ("obj", "ply") and displayName is what messages call it.
TriangleMesh loadMeshFromMemory(std::span<const std::byte> data, std::string_view extensionHint,
                                std::string_view displayName, const MeshLoadOptions& options = {});

}  // namespace voxflame::core
