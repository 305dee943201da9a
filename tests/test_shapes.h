// Meshes with known insides, built in code for the tests: a UV sphere (optionally with a cap cut
// off), a torus, an axis-aligned box (optionally missing a face), and helpers to join meshes
// and flip them inside out.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/mesh.h"

namespace voxflame::test {

// Triangles wound counter-clockwise seen from outside. Rings of latitude run from the south
// pole upwards; with capAboveZ < radius every triangle reaching above z = capAboveZ is left out,
// which opens a round hole at the top.
inline core::TriangleMesh uvSphere(glm::vec3 centre, float radius, int segments, int rings, float capAboveZ = 1e30f) {
  core::TriangleMesh mesh;
  mesh.name = "sphere";
  for (int r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;  // from the south pole
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      mesh.vertices.push_back(centre + radius * glm::vec3(static_cast<float>(std::sin(theta) * std::cos(phi)),
                                                          static_cast<float>(std::sin(theta) * std::sin(phi)),
                                                          static_cast<float>(-std::cos(theta))));
    }
  }
  auto at = [&](int r, int s) { return static_cast<std::uint32_t>(r * segments + (s % segments)); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const std::array<std::uint32_t, 3> a{at(r, s), at(r, s + 1), at(r + 1, s + 1)};
      const std::array<std::uint32_t, 3> b{at(r, s), at(r + 1, s + 1), at(r + 1, s)};
      for (const auto& tri : {a, b}) {
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
        const auto& v = mesh.vertices;
        // Pole rows collapse to a point in position but not in index: drop zero-area ones.
        const glm::vec3 n = glm::cross(v[tri[1]] - v[tri[0]], v[tri[2]] - v[tri[0]]);
        if (glm::dot(n, n) < 1e-12f * radius * radius) continue;
        if (std::max({v[tri[0]].z, v[tri[1]].z, v[tri[2]].z}) > capAboveZ) continue;
        mesh.triangles.push_back(tri);
      }
    }
  return mesh;
}

inline core::TriangleMesh torus(glm::vec3 centre, float major, float minor, int segments, int sides) {
  core::TriangleMesh mesh;
  mesh.name = "torus";
  for (int s = 0; s < segments; ++s) {
    const double phi = 2.0 * std::numbers::pi * s / segments;
    for (int t = 0; t < sides; ++t) {
      const double theta = 2.0 * std::numbers::pi * t / sides;
      const double ring = major + minor * std::cos(theta);
      mesh.vertices.push_back(centre + glm::vec3(static_cast<float>(ring * std::cos(phi)),
                                                 static_cast<float>(ring * std::sin(phi)),
                                                 static_cast<float>(minor * std::sin(theta))));
    }
  }
  auto at = [&](int s, int t) { return static_cast<std::uint32_t>((s % segments) * sides + (t % sides)); };
  for (int s = 0; s < segments; ++s)
    for (int t = 0; t < sides; ++t) {
      mesh.triangles.push_back({at(s, t), at(s + 1, t), at(s + 1, t + 1)});
      mesh.triangles.push_back({at(s, t), at(s + 1, t + 1), at(s, t + 1)});
    }
  return mesh;
}

// An axis-aligned box; openFace -1 keeps it closed, else 0..5 leaves out -x, +x, -y, +y, -z, +z.
inline core::TriangleMesh box(glm::vec3 lo, glm::vec3 hi, int openFace = -1) {
  core::TriangleMesh mesh;
  mesh.name = "box";
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
  const std::array<std::array<std::uint32_t, 3>, 12> faces = {{{0, 4, 2},
                                                               {2, 4, 6},  // -x
                                                               {1, 3, 5},
                                                               {3, 7, 5},  // +x
                                                               {0, 1, 4},
                                                               {1, 5, 4},  // -y
                                                               {2, 6, 3},
                                                               {3, 6, 7},  // +y
                                                               {0, 2, 1},
                                                               {1, 2, 3},  // -z
                                                               {4, 5, 6},
                                                               {5, 7, 6}}};  // +z
  for (int f = 0; f < 12; ++f)
    if (f / 2 != openFace) mesh.triangles.push_back(faces[static_cast<std::size_t>(f)]);
  return mesh;
}

inline core::TriangleMesh joined(const core::TriangleMesh& a, const core::TriangleMesh& b) {
  core::TriangleMesh mesh = a;
  const auto base = static_cast<std::uint32_t>(a.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& tri : b.triangles) mesh.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
  return mesh;
}

inline core::TriangleMesh insideOut(core::TriangleMesh mesh) {
  for (auto& tri : mesh.triangles) std::swap(tri[1], tri[2]);
  return mesh;
}

}  // namespace voxflame::test
