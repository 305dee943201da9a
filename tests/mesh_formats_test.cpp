// Loading: every format the tests can write by hand, every bad-file case of issue 4 with a
// message naming the file, and truncated or bit-flipped files that must neither hang nor crash.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "core/error.h"
#include "core/mesh.h"
#include "test_support.h"

using namespace voxflame::core;
using voxflame::test::meshPath;
using voxflame::test::TemporaryFolder;

namespace {

// A unit tetrahedron, outward-facing, 1-based for OBJ.
const float kCorners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::string objText() {
  std::ostringstream out;
  for (const auto& c : kCorners) out << "v " << c[0] << " " << c[1] << " " << c[2] << "\n";
  for (const auto& f : kFaces) out << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
  return out.str();
}

std::string plyHeader(const char* format) {
  return std::string("ply\nformat ") + format +
         " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string plyAscii() {
  std::ostringstream out;
  out << plyHeader("ascii");
  for (const auto& c : kCorners) out << c[0] << " " << c[1] << " " << c[2] << "\n";
  for (const auto& f : kFaces) out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  return out.str();
}

template <class T>
void appendBytes(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string plyBinary() {
  std::string out = plyHeader("binary_little_endian");
  for (const auto& c : kCorners)
    for (float v : c) appendBytes(out, v);
  for (const auto& f : kFaces) {
    appendBytes(out, std::uint8_t{3});
    for (int v : f) appendBytes(out, static_cast<std::int32_t>(v));
  }
  return out;
}

std::string stlAscii() {
  std::ostringstream out;
  out << "solid tetra\n";
  for (const auto& f : kFaces) {
    out << "facet normal 0 0 0\nouter loop\n";
    for (int v : f) out << "vertex " << kCorners[v][0] << " " << kCorners[v][1] << " " << kCorners[v][2] << "\n";
    out << "endloop\nendfacet\n";
  }
  out << "endsolid tetra\n";
  return out.str();
}

std::string stlBinary() {
  std::string out(80, ' ');
  appendBytes(out, std::uint32_t{4});
  for (const auto& f : kFaces) {
    for (int n = 0; n < 3; ++n) appendBytes(out, 0.0f);
    for (int v : f)
      for (float x : kCorners[v]) appendBytes(out, x);
    appendBytes(out, std::uint16_t{0});
  }
  return out;
}

// Collada with one geometry placed by two nodes, the second translated by (5, 0, 0) and a child
// of a node scaled by 2: the loader must apply the whole chain of transforms.
std::string collada() {
  std::ostringstream positions, indices;
  for (const auto& c : kCorners) positions << c[0] << " " << c[1] << " " << c[2] << " ";
  for (const auto& f : kFaces) indices << f[0] << " " << f[1] << " " << f[2] << " ";
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="tetra" name="tetra"><mesh>
      <source id="tetra-positions">
        <float_array id="tetra-array" count="12">)" +
         positions.str() + R"(</float_array>
        <technique_common><accessor source="#tetra-array" count="4" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="tetra-vertices"><input semantic="POSITION" source="#tetra-positions"/></vertices>
      <triangles count="4"><input semantic="VERTEX" source="#tetra-vertices" offset="0"/><p>)" +
         indices.str() + R"(</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="a" name="a"><instance_geometry url="#tetra"/></node>
      <node id="b" name="b"><scale>2 2 2</scale>
        <node id="c" name="c"><translate>5 0 0</translate><instance_geometry url="#tetra"/></node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

// glTF 2.0 with the buffer inline as a data URI; the node is translated by (0, 3, 0).
std::string gltf() {
  std::string buffer;
  for (const auto& c : kCorners)
    for (float v : c) appendBytes(buffer, v);
  for (const auto& f : kFaces)
    for (int v : f) appendBytes(buffer, static_cast<std::uint16_t>(v));
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string base64;
  for (std::size_t i = 0; i < buffer.size(); i += 3) {
    std::uint32_t chunk = static_cast<std::uint8_t>(buffer[i]) << 16;
    if (i + 1 < buffer.size()) chunk |= static_cast<std::uint8_t>(buffer[i + 1]) << 8;
    if (i + 2 < buffer.size()) chunk |= static_cast<std::uint8_t>(buffer[i + 2]);
    base64 += kAlphabet[(chunk >> 18) & 63];
    base64 += kAlphabet[(chunk >> 12) & 63];
    base64 += i + 1 < buffer.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
    base64 += i + 2 < buffer.size() ? kAlphabet[chunk & 63] : '=';
  }
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"translation":[0,3,0]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":4}]}],
"buffers":[{"byteLength":)" +
         std::to_string(buffer.size()) + R"(,"uri":"data:application/octet-stream;base64,)" + base64 + R"("}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},
{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})";
}

void write(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The message loading `path` fails with; fails the test if it loads.
std::string loadError(const std::filesystem::path& path) {
  try {
    loadMesh(path);
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " loaded";
  return "";
}

}  // namespace

TEST(MeshFormats, EveryHandWrittenFormatLoadsTheTetrahedron) {
  TemporaryFolder folder;
  const std::pair<const char*, std::string> files[] = {{"t.obj", objText()},    {"t.ply", plyAscii()},
                                                       {"tb.ply", plyBinary()}, {"t.stl", stlAscii()},
                                                       {"tb.stl", stlBinary()}, {"t.gltf", gltf()}};
  for (const auto& [name, bytes] : files) {
    write(folder / name, bytes);
    const TriangleMesh mesh = loadMesh(folder / name);
    EXPECT_EQ(mesh.triangles.size(), 4u) << name;
    const Box box = mesh.bounds();
    const glm::dvec3 offset = std::string(name) == "t.gltf" ? glm::dvec3(0, 3, 0) : glm::dvec3(0.0);
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(box.min[a], offset[a], 1e-6) << name;
      EXPECT_NEAR(box.max[a], offset[a] + 1.0, 1e-6) << name;
    }
  }
}

TEST(MeshFormats, ColladaNodesAreMergedWithTheirTransforms) {
  TemporaryFolder folder;
  write(folder / "two.dae", collada());
  const TriangleMesh mesh = loadMesh(folder / "two.dae");
  EXPECT_EQ(mesh.triangles.size(), 8u);
  const Box box = mesh.bounds();
  // Child c: scaled by 2 after being moved by 5 → x in [10, 12].
  EXPECT_NEAR(box.min.x, 0.0, 1e-5);
  EXPECT_NEAR(box.max.x, 12.0, 1e-5);
  EXPECT_NEAR(box.max.z, 2.0, 1e-5);
}

TEST(MeshFormats, PolygonsAreTriangulatedAndDegenerateTrianglesDropped) {
  TemporaryFolder folder;
  // A hexagonal prism: two hexagons and six quads → 4 + 4 + 12 triangles; plus one triangle
  // whose corners lie on a line and one that repeats a vertex, both dropped.
  std::ostringstream obj;
  for (int z = 0; z < 2; ++z)
    for (int s = 0; s < 6; ++s)
      obj << "v " << std::cos(s * 3.14159265 / 3) << " " << std::sin(s * 3.14159265 / 3) << " " << z << "\n";
  obj << "v 5 5 5\nv 6 6 6\nv 7 7 7\n";
  obj << "f 6 5 4 3 2 1\nf 7 8 9 10 11 12\n";
  for (int s = 0; s < 6; ++s)
    obj << "f " << s + 1 << " " << (s + 1) % 6 + 1 << " " << (s + 1) % 6 + 7 << " " << s + 7 << "\n";
  obj << "f 13 14 15\nf 1 1 2\n";
  // A stray point far away and a line: neither may stretch the mesh's box.
  obj << "v 100 100 100\np 16\nl 1 16\n";
  write(folder / "prism.obj", obj.str());
  const TriangleMesh mesh = loadMesh(folder / "prism.obj");
  EXPECT_EQ(mesh.triangles.size(), 20u);
  EXPECT_EQ(mesh.vertices.size(), 12u);
  EXPECT_NEAR(mesh.bounds().max.z, 1.0, 1e-6);
}

TEST(MeshFormats, EveryBadFileGetsAMessageNamingItAndTheProblem) {
  TemporaryFolder folder;
  const std::string plyTruncated = plyBinary().substr(0, plyBinary().size() - 7);
  std::string outOfRange = plyAscii();
  outOfRange.replace(outOfRange.rfind("3 1 2 3"), 7, "3 1 2 9");
  struct Case {
    const char* name;
    std::string bytes;
    const char* expected;
  };
  const Case cases[] = {
      {"empty.obj", "", "empty"},
      {"corrupt.fbx", "this is not an FBX file at all\n", "cannot read"},
      {"corrupt.stl", std::string(30, '\x07'), "cannot read"},
      {"truncated.ply", plyTruncated, "truncated"},
      {"truncated.stl", stlBinary().substr(0, 120), "cannot read"},
      {"nothing.obj", "# only a comment\n", "no geometry"},
      {"points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1\np 2\np 3\n", "only points or lines"},
      {"lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n", "only points or lines"},
      {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 99\n", "out of range"},
      {"range.ply", outOfRange, "out of range"},
      {"flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n", "flat"},
      {"degenerate.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n", "no triangles with any area"},
  };
  for (const Case& c : cases) {
    write(folder / c.name, c.bytes);
    const std::string message = loadError(folder / c.name);
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": " << message;
  }
  const std::string missing = loadError(folder / "missing.obj");
  EXPECT_NE(missing.find("missing.obj"), std::string::npos);
  EXPECT_NE(missing.find("does not exist"), std::string::npos);
}

// Truncated and bit-flipped copies of every format: each must load or fail with core::Error;
// a hang or a crash fails the whole suite.
TEST(MeshFormats, TruncatedAndCorruptedFilesNeverHangOrCrash) {
  TemporaryFolder folder;
  const std::pair<const char*, std::string> files[] = {
      {"f.obj", objText()},    {"f.ply", plyAscii()}, {"fb.ply", plyBinary()}, {"f.stl", stlAscii()},
      {"fb.stl", stlBinary()}, {"f.gltf", gltf()},    {"f.dae", collada()}};
  // VOXFLAME_FUZZ_SEED explores other corruptions (a fixed one keeps the suite repeatable).
  const char* seed = std::getenv("VOXFLAME_FUZZ_SEED");
  std::mt19937 random(seed ? static_cast<unsigned>(std::strtoul(seed, nullptr, 10)) : 2026u);
  int loaded = 0, refused = 0;
  // Each variant is imported by a voxflame child process, whose start-up is most of the cost
  // (several times a load under a sanitizer): five cuts (a tenth to nine tenths of the file, so
  // within the header, the middle and the tail of each) and eight copies with one to four flipped
  // bits per format.
  constexpr int kCuts = 5, kFlipped = 8;
  for (const auto& [name, original] : files) {
    std::vector<std::string> variants;
    for (int cut = 1; cut < 10; cut += 2) variants.push_back(original.substr(0, original.size() * cut / 10));
    for (int flips = 0; flips < kFlipped; ++flips) {
      std::string bytes = original;
      for (int n = 0; n < 1 + flips % 4; ++n) {
        const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random);
        bytes[at] = static_cast<char>(bytes[at] ^ (1 << std::uniform_int_distribution<int>(0, 7)(random)));
      }
      variants.push_back(bytes);
    }
    for (const std::string& bytes : variants) {
      write(folder / name, bytes);
      if (std::getenv("VOXFLAME_FUZZ_TRACE")) {
        std::fprintf(stderr, "%s\n", name);
        write(std::string("/tmp/wt4tools/last-") + name, bytes);
      }
      try {
        MeshLoadOptions options;
        options.timeLimitSeconds = 5.0;
        loadMesh(folder / name, options);
        ++loaded;
      } catch (const Error& e) {
        ++refused;
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_EQ(loaded + refused, 7 * (kCuts + kFlipped));
}

TEST(MeshFormats, AllSharedMeshesLoad) {
  const std::pair<const char*, std::size_t> meshes[] = {
      {"bunny.obj", 3674}, {"teapot.obj", 992}, {"dragon_200k.ply", 202520}, {"dragon.ply", 871414}};
  for (const auto& [name, triangles] : meshes) {
    const TriangleMesh mesh = loadMesh(meshPath(name));
    // A few of the scans' triangles are degenerate and dropped.
    EXPECT_LE(mesh.triangles.size(), triangles) << name;
    EXPECT_GT(mesh.triangles.size(), triangles * 99 / 100) << name;
  }
}
