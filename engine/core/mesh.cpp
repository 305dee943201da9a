#include "mesh.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
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

constexpr unsigned kImportFlags =
    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType | aiProcess_PreTransformVertices;

void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no volume
      const std::array<std::uint32_t, 3> tri{base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]};
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
      out.triangles.push_back(tri);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(scene, *node.mChildren[c], transform, out);
}

TriangleMesh convertScene(const aiScene* scene, Assimp::Importer& importer, std::string_view displayName) {
  if (!scene || !scene->mRootNode) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "not a mesh Assimp can read";
    throw Error("cannot read mesh '" + std::string(displayName) + "': " + reason);
  }
  TriangleMesh mesh;
  mesh.name = std::string(displayName);
  appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  if (mesh.triangles.empty()) throw Error("mesh '" + mesh.name + "' has no triangles (only points or lines, or empty)");
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

TriangleMesh loadMesh(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error("mesh file '" + path.string() + "' does not exist");
  if (std::filesystem::is_directory(path, ec)) throw Error("mesh path '" + path.string() + "' is a folder, not a file");
  if (std::filesystem::file_size(path, ec) == 0) throw Error("mesh file '" + path.string() + "' is empty");
  if (path.extension() == ".ply" || path.extension() == ".PLY") {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) throw Error("cannot read mesh file '" + path.string() + "'");
    return loadMeshFromMemory(std::as_bytes(std::span<const char>(bytes)), "ply", path.string());
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), kImportFlags);
  return convertScene(scene, importer, path.string());
}

TriangleMesh loadMeshFromMemory(std::span<const std::byte> data, std::string_view extensionHint,
                                std::string_view displayName) {
  if (data.empty()) throw Error("mesh '" + std::string(displayName) + "' is empty");
  if (extensionHint == "ply" || extensionHint == "PLY") checkPlyComplete(data, std::string(displayName));
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFileFromMemory(data.data(), data.size(), kImportFlags, std::string(extensionHint).c_str());
  return convertScene(scene, importer, displayName);
}

}  // namespace voxflame::core
