#include "mesh.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <mutex>
#include <optional>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "error.h"

namespace voxflame::core {

Box TriangleMesh::bounds() const {
  Box box;
  if (vertices.empty()) return box;
  box.min = box.max = glm::dvec3(vertices.front());
  for (const auto& v : vertices) {
    box.min = glm::min(box.min, glm::dvec3(v));
    box.max = glm::max(box.max, glm::dvec3(v));
  }
  return box;
}

namespace {

// Reading is two steps. The reader's output is checked first (ValidateDataStructure, then our
// own check of every face), because Assimp's post-processing asserts, i.e. aborts the program,
// on some malformed faces a corrupt file yields (a face with no vertices). Only then are node
// transforms applied and meshes merged (PreTransformVertices), polygons of any size split
// (Triangulate) and shared corners joined, so that neighbouring triangles share vertex indices.
constexpr unsigned kReadFlags = aiProcess_ValidateDataStructure;
constexpr unsigned kPostProcessFlags =
    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType | aiProcess_PreTransformVertices;

// Throws core::Error naming the file when the reader produced faces post-processing cannot take.
void checkFaces(const aiScene& scene, const std::string& name) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (!mesh || (mesh->mNumVertices > 0 && !mesh->mVertices))
      throw Error("mesh '" + name + "' is corrupt: a sub-mesh has no vertex data");
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices == 0 || !face.mIndices)
        throw Error("mesh '" + name + "' is corrupt: face " + std::to_string(f + 1) + " has no vertices");
      for (unsigned c = 0; c < face.mNumIndices; ++c)
        if (face.mIndices[c] >= mesh->mNumVertices)
          throw Error("mesh '" + name + "' is corrupt: face " + std::to_string(f + 1) + " uses vertex index " +
                      std::to_string(face.mIndices[c]) + ", out of range (the mesh has " +
                      std::to_string(mesh->mNumVertices) + " vertices)");
    }
  }
}

struct PrimitiveCounts {
  std::size_t points = 0, lines = 0, degenerate = 0;
};

void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out,
                PrimitiveCounts& skipped) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    if (node.mMeshes[m] >= scene.mNumMeshes)
      throw Error("mesh '" + out.name + "' refers to a sub-mesh that does not exist");
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices == 1) ++skipped.points;
      if (face.mNumIndices == 2) ++skipped.lines;
      if (face.mNumIndices != 3) continue;  // points and lines carry no volume
      for (unsigned c = 0; c < 3; ++c)
        if (face.mIndices[c] >= mesh.mNumVertices)
          throw Error("mesh '" + out.name + "' has a face using vertex " + std::to_string(face.mIndices[c] + 1) +
                      ", but its mesh has only " + std::to_string(mesh.mNumVertices) + " vertices");
      const std::array<std::uint32_t, 3> tri{base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]};
      // Repeated corners or corners on one line: no area, no crossing, no winding number.
      const glm::vec3 a = out.vertices[tri[0]], b = out.vertices[tri[1]], c = out.vertices[tri[2]];
      const glm::vec3 normal = glm::cross(b - a, c - a);
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || glm::dot(normal, normal) == 0.0f) {
        ++skipped.degenerate;
        continue;
      }
      out.triangles.push_back(tri);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(scene, *node.mChildren[c], transform, out, skipped);
}

void throwReadError(Assimp::Importer& importer, const std::string& name) {
  const std::string reason = importer.GetErrorString();
  if (reason.find("mNumMeshes is 0") != std::string::npos)
    throw Error("mesh '" + name + "' holds no geometry (empty, corrupt, or not the format its name says)");
  if (reason.find("out of range") != std::string::npos)
    throw Error("mesh '" + name + "' is corrupt: a face uses a vertex index out of range (" + reason + ")");
  if (reason.find("Validation failed") != std::string::npos)
    throw Error("mesh '" + name + "' is corrupt or truncated (" + reason + ")");
  if (reason.empty()) throw Error("cannot read mesh '" + name + "': not a mesh format Assimp can read");
  throw Error("cannot read mesh '" + name + "': " + reason);
}

// `read` is the scene as the reader returned it (owned by `importer`).
TriangleMesh convertScene(const aiScene* read, Assimp::Importer& importer, std::string_view displayName) {
  if (!read || !read->mRootNode) throwReadError(importer, std::string(displayName));
  checkFaces(*read, std::string(displayName));
  const aiScene* scene = importer.ApplyPostProcessing(kPostProcessFlags);
  if (!scene || !scene->mRootNode) throwReadError(importer, std::string(displayName));
  TriangleMesh mesh;
  mesh.name = std::string(displayName);
  if (scene->mNumMeshes == 0)
    throw Error("mesh '" + mesh.name +
                "' holds no geometry (an empty scene, or not a file of the format its name says)");
  PrimitiveCounts skipped;
  appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), mesh, skipped);
  if (mesh.triangles.empty()) {
    if (skipped.points + skipped.lines > 0)
      throw Error("mesh '" + mesh.name + "' has only points or lines (" + std::to_string(skipped.points) + " points, " +
                  std::to_string(skipped.lines) + " lines), no triangles to enclose a volume");
    if (skipped.degenerate > 0)
      throw Error("mesh '" + mesh.name + "' has no triangles with any area (all " + std::to_string(skipped.degenerate) +
                  " are degenerate)");
    throw Error("mesh '" + mesh.name + "' has no triangles");
  }
  // Keep only the vertices triangles use: stray points (or the corners of dropped lines) must
  // not stretch the bounding box the grid is fitted to.
  {
    std::vector<std::uint32_t> remap(mesh.vertices.size(), UINT32_MAX);
    std::vector<glm::vec3> used;
    used.reserve(mesh.vertices.size());
    for (auto& tri : mesh.triangles)
      for (std::uint32_t& v : tri) {
        if (remap[v] == UINT32_MAX) {
          remap[v] = static_cast<std::uint32_t>(used.size());
          used.push_back(mesh.vertices[v]);
        }
        v = remap[v];
      }
    mesh.vertices = std::move(used);
  }
  for (const auto& v : mesh.vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw Error("mesh '" + mesh.name + "' has a vertex that is not a finite number");
  const glm::dvec3 extent = mesh.bounds().extent();
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0.0) || std::min({extent.x, extent.y, extent.z}) <= longest * 1e-6)
    throw Error("mesh '" + mesh.name + "' is flat: it encloses no volume");
  return mesh;
}

// Assimp's PLY reader can loop forever on a truncated binary body, so PLY input is checked
// here first: the header's element counts must fit in the bytes (or lines) that follow it.
void checkPlyComplete(std::span<const std::byte> data, const std::string& name) {
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  const std::size_t headerEnd = text.find("end_header");
  if (text.substr(0, 3) != "ply" || headerEnd == std::string_view::npos)
    throw Error("mesh '" + name + "' is not a valid PLY file (no complete header)");
  std::size_t bodyStart = text.find('\n', headerEnd);
  bodyStart = bodyStart == std::string_view::npos ? text.size() : bodyStart + 1;
  std::istringstream header{std::string(text.substr(0, headerEnd))};
  std::string line, format;
  struct Element {
    std::uint64_t count = 0;
    std::uint64_t fixedBytes = 0;  // bytes per item of the scalar properties, plus list counts
  };
  std::vector<Element> elements;
  auto typeSize = [&](const std::string& type) -> std::uint64_t {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
      return 4;
    if (type == "double" || type == "float64") return 8;
    throw Error("mesh '" + name + "' has a PLY property of unknown type '" + type + "'");
  };
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> format;
    } else if (keyword == "element") {
      std::string elementName;
      Element element;
      if (!(words >> elementName >> element.count))
        throw Error("mesh '" + name + "' has a malformed PLY element line: " + line);
      elements.push_back(element);
    } else if (keyword == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      if (type == "list") {
        std::string countType;
        words >> countType;
        elements.back().fixedBytes += typeSize(countType);
      } else {
        elements.back().fixedBytes += typeSize(type);
      }
    }
  }
  const std::uint64_t body = data.size() - bodyStart;
  if (format == "ascii") {
    std::uint64_t needed = 0;
    for (const auto& e : elements) needed += e.count;
    std::uint64_t lines = 0;
    for (std::size_t i = bodyStart; i < text.size(); ++i) lines += text[i] == '\n';
    if (!text.empty() && text.back() != '\n' && text.size() > bodyStart) ++lines;
    if (lines < needed)
      throw Error("mesh '" + name + "' is truncated: its PLY header promises " + std::to_string(needed) +
                  " lines of data, the file has " + std::to_string(lines));
  } else if (format == "binary_little_endian" || format == "binary_big_endian") {
    std::uint64_t needed = 0;
    for (const auto& e : elements) {
      if (e.fixedBytes && e.count > body / e.fixedBytes + 1)
        throw Error("mesh '" + name + "' is truncated: its PLY header promises more data than the file holds");
      needed += e.count * e.fixedBytes;
    }
    if (needed > body)
      throw Error("mesh '" + name + "' is truncated: its PLY header promises at least " + std::to_string(needed) +
                  " bytes of data, the file has " + std::to_string(body));
  } else {
    throw Error("mesh '" + name + "' has an unknown PLY format '" + format + "'");
  }
}

}  // namespace

namespace {

// Assimp's readers are not hardened against corrupt input: a flipped byte can crash one (binary
// PLY) or send one into an endless loop (Collada). So the import runs in a child process (the
// program setMeshImportChild names, normally voxflame itself with a hidden subcommand) that sends
// the finished mesh, or its error message, back through a pipe; a child that crashes or overruns
// its time limit is reported as a corrupt file instead of taking voxflame down. The child is
// spawned, never forked: a fork would copy a process whose worker threads may hold locks and
// write a grid of gigabytes (copy on write), and would run Assimp in that copy.

std::mutex gChildMutex;
std::optional<MeshImportChild> gChild;

bool writeAll(int fd, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

TriangleMesh importWithAssimp(const std::filesystem::path& path, const std::string& name) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), kReadFlags);
  return convertScene(scene, importer, name);
}

// A file holding `data` that is removed with this object (for importing bytes in a child).
class TemporaryMeshFile {
 public:
  TemporaryMeshFile(std::span<const std::byte> data, std::string_view extension) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "voxflame-mesh-XXXXXX").string() + "." + std::string(extension);
    const int fd = ::mkstemps(pattern.data(), static_cast<int>(extension.size() + 1));
    if (fd < 0) throw Error("cannot write a temporary copy of the mesh: " + std::string(std::strerror(errno)));
    path_ = pattern;
    const bool written = writeAll(fd, data.data(), data.size());
    ::close(fd);
    if (!written) throw Error("cannot write a temporary copy of the mesh (disk full?)");
  }
  ~TemporaryMeshFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

TriangleMesh importInChild(const MeshImportChild& importer, const std::filesystem::path& path, const std::string& name,
                           std::uint64_t fileBytes, double timeLimitSeconds) {
  if (timeLimitSeconds <= 0.0) timeLimitSeconds = 30.0 + 4.0 * static_cast<double>(fileBytes) / (1024.0 * 1024.0);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw Error("cannot read mesh '" + name + "': no pipe for the importer");
  std::vector<std::string> arguments;
  arguments.push_back(importer.program.string());
  arguments.insert(arguments.end(), importer.arguments.begin(), importer.arguments.end());
  arguments.push_back(path.string());
  arguments.push_back(name);  // what the child's messages call the mesh (a temporary file has no good name)
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // The child starts with default signal handling and no blocked signals, whatever this process set.
  sigset_t none, defaults;
  sigemptyset(&none);
  sigfillset(&defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t child = -1;
  const int spawned = ::posix_spawn(&child, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(fds[1]);
  if (spawned != 0) {
    ::close(fds[0]);
    throw Error("cannot read mesh '" + name + "': the importer " + importer.program.string() +
                " could not be started (" + std::strerror(spawned) + ")");
  }

  std::string received;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeLimitSeconds);
  bool timedOut = false;
  char buffer[1 << 16];
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0.0) {
      timedOut = true;
      break;
    }
    pollfd poller{fds[0], POLLIN, 0};
    const int ready = ::poll(&poller, 1, static_cast<int>(std::min(left * 1000.0, 1000.0)) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    received.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(fds[0]);
  if (timedOut) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (timedOut)
    throw Error("mesh '" + name + "' could not be read within " + std::to_string(static_cast<int>(timeLimitSeconds)) +
                " s: the importer got stuck on it (corrupt or truncated file?)");
  if (WIFSIGNALED(status) || received.empty())
    throw Error("mesh '" + name + "' is corrupt: the importer failed on it" +
                (WIFSIGNALED(status) ? " (signal " + std::to_string(WTERMSIG(status)) + ")" : std::string()));
  if (received[0] == 0) throw Error(received.substr(1));
  std::uint64_t counts[2] = {0, 0};
  if (received.size() < 1 + sizeof counts) throw Error("mesh '" + name + "': the importer's answer was cut short");
  std::memcpy(counts, received.data() + 1, sizeof counts);
  TriangleMesh mesh;
  mesh.name = name;
  const std::size_t vertexBytes = counts[0] * sizeof(glm::vec3);
  const std::size_t triangleBytes = counts[1] * sizeof(mesh.triangles[0]);
  if (counts[0] > received.size() || counts[1] > received.size() ||
      received.size() != 1 + sizeof counts + vertexBytes + triangleBytes)
    throw Error("mesh '" + name + "': the importer's answer was cut short");
  mesh.vertices.resize(counts[0]);
  mesh.triangles.resize(counts[1]);
  std::memcpy(mesh.vertices.data(), received.data() + 1 + sizeof counts, vertexBytes);
  std::memcpy(mesh.triangles.data(), received.data() + 1 + sizeof counts + vertexBytes, triangleBytes);
  return mesh;
}

// Imports `path` in the child when one is set, else in this process (a program that never
// named an importer, such as a small tool linking the core: it gets no protection).
TriangleMesh importIsolated(const std::filesystem::path& path, const std::string& name, std::uint64_t fileBytes,
                            double timeLimitSeconds) {
  std::optional<MeshImportChild> importer;
  {
    std::lock_guard lock(gChildMutex);
    importer = gChild;
  }
  if (!importer) return importWithAssimp(path, name);
  return importInChild(*importer, path, name, fileBytes, timeLimitSeconds);
}

}  // namespace

void setMeshImportChild(MeshImportChild importer) {
  std::lock_guard lock(gChildMutex);
  gChild = std::move(importer);
}

void runMeshImportChild(const std::filesystem::path& path, const std::string& displayName) {
  // The answer goes to the original standard output; anything the importer prints goes nowhere.
  std::fflush(stdout);
  const int answer = ::dup(STDOUT_FILENO);
  if (answer < 0) ::_exit(3);
  const int devNull = ::open("/dev/null", O_WRONLY);
  if (devNull >= 0) {
    ::dup2(devNull, STDOUT_FILENO);
    ::close(devNull);
  }
  std::string message;
  try {
    const TriangleMesh mesh = importWithAssimp(path, displayName.empty() ? path.string() : displayName);
    const std::uint64_t counts[2] = {mesh.vertices.size(), mesh.triangles.size()};
    const char ok = 1;
    const bool sent = writeAll(answer, &ok, 1) && writeAll(answer, counts, sizeof counts) &&
                      writeAll(answer, mesh.vertices.data(), mesh.vertices.size() * sizeof(glm::vec3)) &&
                      writeAll(answer, mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
    ::_exit(sent ? 0 : 3);
  } catch (const std::exception& e) {
    message = e.what();
  } catch (...) {
    message = "unknown failure";
  }
  const char failed = 0;
  writeAll(answer, &failed, 1);
  writeAll(answer, message.data(), message.size());
  // The answer is in the pipe: end at once, as a forked importer did, without static destructors
  // or a leak check at exit (a corrupt file can make Assimp leak on its way out, which would turn a
  // clear "corrupt file" message into a killed child under LeakSanitizer).
  ::_exit(0);
}

TriangleMesh loadMesh(const std::filesystem::path& path, const MeshLoadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error("mesh file '" + path.string() + "' does not exist");
  if (std::filesystem::is_directory(path, ec)) throw Error("mesh path '" + path.string() + "' is a folder, not a file");
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error("cannot read mesh file '" + path.string() + "': " + ec.message());
  if (size == 0) throw Error("mesh file '" + path.string() + "' is empty");
  if (path.extension() == ".ply" || path.extension() == ".PLY") {
    // A truncated PLY is refused here, before any importer sees it, with a precise message.
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) throw Error("cannot read mesh file '" + path.string() + "'");
    checkPlyComplete(std::as_bytes(std::span<const char>(bytes)), path.string());
  }
  if (!options.isolate) return importWithAssimp(path, path.string());
  return importIsolated(path, path.string(), size, options.timeLimitSeconds);
}

TriangleMesh loadMeshFromMemory(std::span<const std::byte> data, std::string_view extensionHint,
                                std::string_view displayName, const MeshLoadOptions& options) {
  if (data.empty()) throw Error("mesh '" + std::string(displayName) + "' is empty");
  if (extensionHint == "ply" || extensionHint == "PLY") checkPlyComplete(data, std::string(displayName));
  if (!options.isolate) {
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFileFromMemory(data.data(), data.size(), kReadFlags, std::string(extensionHint).c_str());
    return convertScene(scene, importer, displayName);
  }
  // The child reads files: the bytes go to a temporary one that it imports.
  const TemporaryMeshFile copy(data, extensionHint);
  TriangleMesh mesh = importIsolated(copy.path(), std::string(displayName), data.size(), options.timeLimitSeconds);
  mesh.name = std::string(displayName);
  return mesh;
}

}  // namespace voxflame::core
