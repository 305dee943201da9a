// JWildfire's obj_mesh_primitive_wf: random points on the surface of a built-in mesh. JWildfire
// (OBJMeshPrimitiveWFFunc, AbstractOBJMeshWFFunc, OBJMeshUtil, SimpleMesh) loads the primitive's
// Wavefront file, splits its quads into two triangles (corners 0 1 2 and 0 2 3), merges vertices
// that agree to 1e-4, and either repeats each face in its list by its area relative to the smallest
// (subdiv_level 0) or subdivides and smooths the mesh (subdiv_level 1–6, faces then picked alike).
// Each call picks a face from that list, scales and offsets its corners, and adds weight times a
// uniformly distributed point of the triangle; the input point is not used.
//
// The shapes are built here from their geometry, with the size, orientation and tessellation of
// JWildfire's files (obj_mesh_primitives.h lists which): once per parameter set, shared through
// RecentBuilds; the kernel below only picks faces. The vertices are JWildfire's (to its files' six
// digits) and so are the faces, except where a flat polygon is split: the cone's base and the
// diamond's table are fans here, and some of the capsule's, ring's and box's quads are split along
// the other diagonal than in JWildfire's files. Each such polygon gets the same share of the points
// (the area counts add up alike); only how it is shared inside the polygon can differ slightly.
// JWildfire's colour and displacement images are not read (the import names them as lost).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/flame/obj_mesh_primitives.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

constexpr std::array<const char*, kObjMeshPrimitiveCount> kPrimitiveNames = {"ball",
                                                                             "capsule",
                                                                             "cone",
                                                                             "diamond",
                                                                             "torus",
                                                                             "box",
                                                                             "gear15",
                                                                             "icosahedron",
                                                                             "tetrahedron",
                                                                             "octahedron",
                                                                             "dodecahedron",
                                                                             "wedge",
                                                                             "icosidodecahedron",
                                                                             "cubeoctahedron",
                                                                             "gears6a",
                                                                             "gears6s",
                                                                             "gears8a",
                                                                             "gears8s",
                                                                             "gears12a",
                                                                             "gears12s",
                                                                             "gears16a",
                                                                             "gears16s",
                                                                             "gears24a",
                                                                             "gears24s",
                                                                             "mandelbulb",
                                                                             "drop"};

enum Primitive : std::size_t {
  kBall = 0,
  kCapsule = 1,
  kCone = 2,
  kDiamond = 3,
  kTorus = 4,
  kBox = 5,
  kIcosahedron = 7,
  kTetrahedron = 8,
  kOctahedron = 9,
  kDodecahedron = 10,
  kWedge = 11,
  kIcosidodecahedron = 12,
  kCubeoctahedron = 13,
};

constexpr double kDeg = kPi / 180.0;
const double kPhi = std::numbers::phi;

// Tools.FTOI: half away from 0; NaN is 0 (its sign is 0). Kept a double (a huge value would
// overflow an int), as countParam does.
double jwfFtoi(double value) {
  return std::isnan(value) ? 0.0 : std::round(value);
}

// ---- Building a mesh as SimpleMesh does ---------------------------------------------------------

// SimpleMesh: float vertices, merged when FTOI(coordinate · 10000) agree in all three.
class MeshBuilder {
 public:
  void reserve(std::size_t vertices, std::size_t faces) {
    index_.reserve(vertices);
    mesh_.vertices.reserve(3 * vertices);
    mesh_.faces.reserve(3 * faces);
  }
  std::uint32_t vertex(double x, double y, double z) {
    const std::array<std::int64_t, 3> key = {keyOf(x), keyOf(y), keyOf(z)};
    const auto [it, added] = index_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size() / 3));
    if (added) {
      mesh_.vertices.push_back(static_cast<float>(x));
      mesh_.vertices.push_back(static_cast<float>(y));
      mesh_.vertices.push_back(static_cast<float>(z));
    }
    return it->second;
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { mesh_.faces.insert(mesh_.faces.end(), {a, b, c}); }
  // A quad as OBJMeshUtil splits it.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  PrimitiveMesh take() { return std::move(mesh_); }
  const PrimitiveMesh& mesh() const { return mesh_; }

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& k) const {
      std::uint64_t h = static_cast<std::uint64_t>(k[0]) * 0x9E3779B97F4A7C15ull;
      h ^= static_cast<std::uint64_t>(k[1]) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      h ^= static_cast<std::uint64_t>(k[2]) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };
  static std::int64_t keyOf(double v) {
    // Java's (int) saturates; the coordinates here are small, the clamp only keeps the cast defined.
    return static_cast<std::int64_t>(std::clamp(jwfFtoi(v * 10000.0), -2147483648.0, 2147483647.0));
  }
  PrimitiveMesh mesh_;
  std::unordered_map<std::array<std::int64_t, 3>, std::uint32_t, KeyHash> index_;
};

// ---- The shapes ----------------------------------------------------------------------------------

// A convex polyhedron from its vertices: every plane through three of them with all others on one
// side is a face; its vertices, in order around its centre, are split as a fan (as JWildfire's files
// split their pentagons).
void convexHull(MeshBuilder& builder, const std::vector<std::array<double, 3>>& points) {
  using V = std::array<double, 3>;
  const auto sub = [](const V& a, const V& b) { return V{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  const auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  constexpr double kTolerance = 1e-9;
  std::vector<std::uint32_t> ids;
  for (const V& p : points) ids.push_back(builder.vertex(p[0], p[1], p[2]));
  std::vector<std::vector<std::size_t>> seen;
  const std::size_t count = points.size();
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = i + 1; j < count; ++j)
      for (std::size_t k = j + 1; k < count; ++k) {
        V normal = cross(sub(points[j], points[i]), sub(points[k], points[i]));
        const double length = std::sqrt(dot(normal, normal));
        if (length < kTolerance) continue;
        for (double& c : normal) c /= length;
        const double offset = dot(normal, points[i]);
        bool above = false, below = false;
        std::vector<std::size_t> onPlane;
        for (std::size_t m = 0; m < count; ++m) {
          const double s = dot(normal, points[m]) - offset;
          if (s > kTolerance) above = true;
          if (s < -kTolerance) below = true;
          if (std::abs(s) <= kTolerance) onPlane.push_back(m);
        }
        if ((above && below) || std::find(seen.begin(), seen.end(), onPlane) != seen.end()) continue;
        seen.push_back(onPlane);
        // Order the face's vertices by angle around its centre, in a basis of its plane.
        V centre{0.0, 0.0, 0.0};
        for (const std::size_t m : onPlane)
          for (int c = 0; c < 3; ++c) centre[c] += points[m][c] / static_cast<double>(onPlane.size());
        V u = sub(points[onPlane[0]], centre);
        const double uLength = std::sqrt(dot(u, u));
        for (double& c : u) c /= uLength;
        const V v = cross(normal, u);
        std::sort(onPlane.begin(), onPlane.end(), [&](std::size_t a, std::size_t b) {
          const V da = sub(points[a], centre), db = sub(points[b], centre);
          return std::atan2(dot(da, v), dot(da, u)) < std::atan2(dot(db, v), dot(db, u));
        });
        // The fan's first corner as in JWildfire's dodecahedron and icosidodecahedron: the corner with the
        // most zero coordinates less those of its two neighbours (the one on the face's mirror line through
        // the solid's axes), so that each face's larger middle triangle lies where JWildfire's does.
        const auto zeros = [&](std::size_t m) {
          return static_cast<int>(
              std::count_if(points[m].begin(), points[m].end(), [](double c) { return std::abs(c) < 1e-12; }));
        };
        const std::size_t sides = onPlane.size();
        std::size_t first = 0;
        int best = std::numeric_limits<int>::min();
        for (std::size_t m = 0; m < sides; ++m) {
          const int score =
              2 * zeros(onPlane[m]) - zeros(onPlane[(m + 1) % sides]) - zeros(onPlane[(m + sides - 1) % sides]);
          if (score > best) best = score, first = m;
        }
        std::rotate(onPlane.begin(), onPlane.begin() + static_cast<std::ptrdiff_t>(first), onPlane.end());
        for (std::size_t f = 1; f + 1 < onPlane.size(); ++f)
          builder.triangle(ids[onPlane[0]], ids[onPlane[f]], ids[onPlane[f + 1]]);
      }
}

// Every sign combination of (a, b, c) (zeros once), and their cyclic permutations when `cyclic`.
std::vector<std::array<double, 3>> signedPoints(double a, double b, double c, bool cyclic) {
  std::vector<std::array<double, 3>> out;
  const std::array<std::array<double, 3>, 3> orders = {{{a, b, c}, {c, a, b}, {b, c, a}}};
  for (std::size_t o = 0; o < (cyclic ? 3u : 1u); ++o)
    for (const double sx : {1.0, -1.0})
      for (const double sy : {1.0, -1.0})
        for (const double sz : {1.0, -1.0}) {
          const std::array<double, 3>& p = orders[o];
          if ((sx < 0 && p[0] == 0.0) || (sy < 0 && p[1] == 0.0) || (sz < 0 && p[2] == 0.0)) continue;
          out.push_back({sx * p[0], sy * p[1], sz * p[2]});
        }
  return out;
}

// ball: an icosahedron of radius 0.5 with a vertex on +y (its next ring's first vertex towards −z),
// each triangle split into four three times, new vertices pushed out onto the sphere: 642 vertices,
// 1280 faces.
void ball(MeshBuilder& builder) {
  using V = std::array<double, 3>;
  constexpr double kRadius = 0.5;
  const double ringY = 1.0 / std::sqrt(5.0), ringR = 2.0 / std::sqrt(5.0);
  std::vector<V> points = {{0.0, 1.0, 0.0}};
  for (int k = 0; k < 5; ++k)
    points.push_back({ringR * std::sin(72.0 * k * kDeg), ringY, -ringR * std::cos(72.0 * k * kDeg)});
  for (int k = 0; k < 5; ++k)
    points.push_back({ringR * std::sin((36.0 + 72.0 * k) * kDeg), -ringY, -ringR * std::cos((36.0 + 72.0 * k) * kDeg)});
  points.push_back({0.0, -1.0, 0.0});
  std::vector<std::array<std::size_t, 3>> faces;
  for (std::size_t k = 0; k < 5; ++k) {
    const std::size_t u0 = 1 + k, u1 = 1 + (k + 1) % 5, l0 = 6 + k, l1 = 6 + (k + 1) % 5;
    faces.push_back({0, u0, u1});
    faces.push_back({u0, l0, u1});
    faces.push_back({u1, l0, l1});
    faces.push_back({11, l1, l0});
  }
  std::vector<std::array<V, 3>> triangles;
  for (const auto& f : faces) triangles.push_back({points[f[0]], points[f[1]], points[f[2]]});
  const auto onSphere = [](const V& a, const V& b) {
    const V m{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    return V{m[0] / length, m[1] / length, m[2] / length};
  };
  for (int level = 0; level < 3; ++level) {
    std::vector<std::array<V, 3>> finer;
    for (const auto& t : triangles) {
      const V ab = onSphere(t[0], t[1]), bc = onSphere(t[1], t[2]), ca = onSphere(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({bc, t[2], ca});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }
  for (const auto& t : triangles) {
    std::array<std::uint32_t, 3> id{};
    for (int c = 0; c < 3; ++c) id[c] = builder.vertex(kRadius * t[c][0], kRadius * t[c][1], kRadius * t[c][2]);
    builder.triangle(id[0], id[1], id[2]);
  }
}

// capsule: along z, radius 0.5, from z = −1 to 1: 24 segments around; each half-sphere cap in 8
// steps of 11.25°, the cylinder between z = ±0.5 in 8 steps.
void capsule(MeshBuilder& builder) {
  constexpr int kSegments = 24;
  std::vector<std::array<double, 2>> rings;  // (radius, z)
  for (int k = 1; k <= 8; ++k) {
    const double a = (-90.0 + 11.25 * k) * kDeg;
    rings.push_back({0.5 * std::cos(a), -0.5 + 0.5 * std::sin(a)});
  }
  for (int k = 1; k <= 8; ++k) rings.push_back({0.5, -0.5 + 0.125 * k});
  for (int k = 1; k <= 7; ++k) {
    const double a = 11.25 * k * kDeg;
    rings.push_back({0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a)});
  }
  std::vector<std::vector<std::uint32_t>> ids;
  for (const auto& ring : rings) {
    std::vector<std::uint32_t>& row = ids.emplace_back();
    for (int s = 0; s < kSegments; ++s) {
      const double a = 15.0 * s * kDeg;
      row.push_back(builder.vertex(ring[0] * std::cos(a), ring[0] * std::sin(a), ring[1]));
    }
  }
  const std::uint32_t bottom = builder.vertex(0.0, 0.0, -1.0), top = builder.vertex(0.0, 0.0, 1.0);
  for (int s = 0; s < kSegments; ++s) {
    const int t = (s + 1) % kSegments;
    builder.triangle(bottom, ids.front()[t], ids.front()[s]);
    builder.triangle(top, ids.back()[s], ids.back()[t]);
    for (std::size_t r = 0; r + 1 < ids.size(); ++r) builder.quad(ids[r][s], ids[r][t], ids[r + 1][t], ids[r + 1][s]);
  }
}

// cone: along y, apex (0, 0.5, 0), base of radius 0.5 at y = −0.5 in 24 segments, the base split as
// a fan from its first vertex (its smallest triangles as small as JWildfire's, so the area weights
// come out as fine).
void cone(MeshBuilder& builder) {
  constexpr int kSegments = 24;
  std::vector<std::uint32_t> base;
  for (int s = 0; s < kSegments; ++s) {
    const double a = 15.0 * s * kDeg;
    base.push_back(builder.vertex(-0.5 * std::sin(a), -0.5, -0.5 * std::cos(a)));
  }
  const std::uint32_t apex = builder.vertex(0.0, 0.5, 0.0);
  for (int s = 0; s < kSegments; ++s) builder.triangle(apex, base[s], base[(s + 1) % kSegments]);
  for (int s = 1; s + 1 < kSegments; ++s) builder.triangle(base[0], base[s + 1], base[s]);
}

// diamond: a round brilliant along y, centred on (0, ·, 0.05): pavilion point at y = −0.7125, a
// girdle of 16 at radius 0.5 between y = −0.0625 and −0.0375, 8 crown vertices at radius 0.375,
// y = 0.20625, and an octagonal table of radius 0.25 at y = 0.2875 turned by 22.5°.
void diamond(MeshBuilder& builder) {
  constexpr double kCentreZ = 0.05;
  const auto ring = [&](int count, double radius, double y, double startDeg) {
    std::vector<std::uint32_t> ids;
    for (int k = 0; k < count; ++k) {
      const double a = (startDeg + 360.0 * k / count) * kDeg;
      ids.push_back(builder.vertex(radius * std::sin(a), y, kCentreZ - radius * std::cos(a)));
    }
    return ids;
  };
  const std::uint32_t culet = builder.vertex(0.0, -0.7125, kCentreZ);
  const std::vector<std::uint32_t> low = ring(16, 0.5, -0.0625, 0.0), high = ring(16, 0.5, -0.0375, 0.0);
  const std::vector<std::uint32_t> crown = ring(8, 0.375, 0.20625, 0.0), table = ring(8, 0.25, 0.2875, 22.5);
  for (int i = 0; i < 16; ++i) {
    const int j = (i + 1) % 16;
    builder.triangle(low[i], low[j], culet);
    builder.quad(low[i], high[i], high[j], low[j]);
  }
  for (int k = 0; k < 8; ++k) {
    const int next = (k + 1) % 8, previous = (k + 7) % 8;
    builder.triangle(high[(2 * k + 15) % 16], crown[k], high[2 * k]);
    builder.triangle(high[2 * k], crown[k], high[2 * k + 1]);
    builder.triangle(crown[k], crown[next], high[2 * k + 1]);
    builder.triangle(crown[k], table[k], crown[next]);
    builder.triangle(table[previous], table[k], crown[k]);
  }
  for (int k = 1; k + 1 < 8; ++k) builder.triangle(table[0], table[k], table[k + 1]);
}

// torus: around y, radii 1 and 0.5, 48 steps around y by 24 around the tube, starting at the tube's
// top over +x.
void torus(MeshBuilder& builder) {
  constexpr int kAround = 48, kTube = 24;
  std::vector<std::vector<std::uint32_t>> ids(kAround);
  for (int i = 0; i < kAround; ++i)
    for (int j = 0; j < kTube; ++j) {
      const double around = 7.5 * i * kDeg, tube = 15.0 * j * kDeg;
      const double rho = 1.0 - 0.5 * std::sin(tube);
      ids[i].push_back(builder.vertex(rho * std::cos(around), 0.5 * std::cos(tube), rho * std::sin(around)));
    }
  for (int i = 0; i < kAround; ++i)
    for (int j = 0; j < kTube; ++j) {
      const int i1 = (i + 1) % kAround, j1 = (j + 1) % kTube;
      // JWildfire's file splits its quads mirror-symmetrically: along (i, j + 1)–(i + 1, j) where the
      // quad lies on the +x side and the hole's side of the tube or on neither, else the other way.
      // With the faces' areas counted as coarsely as the torus's are (1 to 3 times), the split shows.
      const bool plusX = i < kAround / 4 || i >= 3 * kAround / 4, holeSide = j < kTube / 2;
      if (plusX == holeSide)
        builder.quad(ids[i][j1], ids[i1][j1], ids[i1][j], ids[i][j]);
      else
        builder.quad(ids[i][j], ids[i][j1], ids[i1][j1], ids[i1][j]);
    }
}

// wedge (a flat ring): around y, radii 0.5 and 1, from y = 0 to 0.5, in 32 segments.
void wedge(MeshBuilder& builder) {
  constexpr int kSegments = 32;
  std::vector<std::array<std::uint32_t, 4>> ids;  // inner top, outer top, outer bottom, inner bottom
  for (int s = 0; s < kSegments; ++s) {
    const double a = 11.25 * s * kDeg, c = std::cos(a), n = -std::sin(a);
    ids.push_back({builder.vertex(0.5 * c, 0.5, 0.5 * n), builder.vertex(c, 0.5, n), builder.vertex(c, 0.0, n),
                   builder.vertex(0.5 * c, 0.0, 0.5 * n)});
  }
  for (int s = 0; s < kSegments; ++s) {
    const auto& a = ids[s];
    const auto& b = ids[(s + 1) % kSegments];
    builder.quad(a[0], a[1], b[1], b[0]);
    builder.quad(a[1], a[2], b[2], b[1]);
    builder.quad(a[2], a[3], b[3], b[2]);
    builder.quad(a[3], a[0], b[0], b[3]);
  }
}

// ---- Subdivision, smoothing and weights ----------------------------------------------------------

// SimpleMesh.interpolate: each triangle into four at its edges' midpoints (floats, as JWildfire's).
PrimitiveMesh subdivide(const PrimitiveMesh& mesh) {
  MeshBuilder builder;
  // A closed mesh gains one vertex per edge (3/2 per face).
  builder.reserve(mesh.vertices.size() / 3 + 3 * mesh.faceCount() / 2, 4 * mesh.faceCount());
  const auto corner = [&](std::uint32_t v) {
    return std::array<float, 3>{mesh.vertices[3 * v], mesh.vertices[3 * v + 1], mesh.vertices[3 * v + 2]};
  };
  const auto middle = [](const std::array<float, 3>& a, const std::array<float, 3>& b) {
    std::array<float, 3> m{};
    for (int c = 0; c < 3; ++c) m[c] = static_cast<float>(a[c] + static_cast<double>(b[c] - a[c]) * 0.5);
    return m;
  };
  const auto add = [&](const std::array<float, 3>& p) { return builder.vertex(p[0], p[1], p[2]); };
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto v1 = corner(mesh.faces[3 * f]), v2 = corner(mesh.faces[3 * f + 1]), v3 = corner(mesh.faces[3 * f + 2]);
    const std::uint32_t n1 = add(v1), n2 = add(v2), n3 = add(v3);
    const std::uint32_t n4 = add(middle(v1, v2)), n5 = add(middle(v2, v3)), n6 = add(middle(v3, v1));
    builder.triangle(n1, n4, n6);
    builder.triangle(n4, n2, n5);
    builder.triangle(n5, n3, n6);
    builder.triangle(n4, n5, n6);
  }
  return builder.take();
}

// SimpleMesh.taubinSmooth: per pass a Laplacian step by lambda, then one by mu; each moves a vertex
// with more than one neighbour by strength times the mean of (neighbour − vertex).
void taubinSmooth(PrimitiveMesh& mesh, int passes, double lambda, double mu) {
  if (passes <= 0) return;
  const std::size_t count = mesh.vertices.size() / 3;
  // Each vertex's neighbours in the order JWildfire's NeightboursList meets them (faces in order, per
  // face a→b, a→c, b→a, b→c, c→a, c→b), each once: every link in a flat list grouped by vertex
  // (a subdivided mesh has millions of vertices: no list per vertex), then duplicates dropped.
  std::vector<std::uint32_t> start(count + 1, 0);
  for (const std::uint32_t v : mesh.faces) start[v + 1] += 2;
  for (std::size_t v = 0; v < count; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> links(start.back()), filled(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const std::uint32_t a = mesh.faces[3 * f], b = mesh.faces[3 * f + 1], c = mesh.faces[3 * f + 2];
    links[filled[a]++] = b, links[filled[a]++] = c;
    links[filled[b]++] = a, links[filled[b]++] = c;
    links[filled[c]++] = a, links[filled[c]++] = b;
  }
  std::vector<std::uint32_t> first(count + 1, 0), neighbours;
  neighbours.reserve(links.size() / 2);
  for (std::size_t v = 0; v < count; ++v) {
    first[v] = static_cast<std::uint32_t>(neighbours.size());
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k)
      if (std::find(neighbours.begin() + first[v], neighbours.end(), links[k]) == neighbours.end())
        neighbours.push_back(links[k]);
  }
  first[count] = static_cast<std::uint32_t>(neighbours.size());
  std::vector<float> displacement(mesh.vertices.size());
  const auto step = [&](double strength) {
    std::fill(displacement.begin(), displacement.end(), 0.0f);
    for (std::size_t v = 0; v < count; ++v) {
      const std::uint32_t size = first[v + 1] - first[v];
      if (size <= 1) continue;
      const double weight = 1.0 / static_cast<double>(size);
      for (std::uint32_t k = first[v]; k < first[v + 1]; ++k)
        for (std::size_t u = neighbours[k], c = 0; c < 3; ++c)
          displacement[3 * v + c] =
              static_cast<float>(displacement[3 * v + c] +
                                 static_cast<double>(mesh.vertices[3 * u + c] - mesh.vertices[3 * v + c]) * weight);
    }
    for (std::size_t k = 0; k < mesh.vertices.size(); ++k)
      mesh.vertices[k] = static_cast<float>(mesh.vertices[k] + displacement[k] * strength);
  };
  for (int pass = 0; pass < passes; ++pass) {
    step(lambda);
    step(mu);
  }
}

// SimpleMesh.distributeFaces: with areas (twice the triangle's, as JWildfire measures them) that
// differ by more than 1e-8, face i counts min(FTOI(area_i / smallest), 5000) times (500 for meshes
// of 5000 faces or more). A face of zero area then counts 0 times, as in JWildfire.
void weighFaces(PrimitiveMesh& mesh) {
  const std::size_t faces = mesh.faceCount();
  std::vector<double> areas(faces);
  double smallest = std::numeric_limits<double>::max(), largest = 0.0;
  for (std::size_t f = 0; f < faces; ++f) {
    const float* p1 = &mesh.vertices[3 * mesh.faces[3 * f]];
    const float* p2 = &mesh.vertices[3 * mesh.faces[3 * f + 1]];
    const float* p3 = &mesh.vertices[3 * mesh.faces[3 * f + 2]];
    const double ax = p2[0] - p1[0], ay = p2[1] - p1[1], az = p2[2] - p1[2];
    const double bx = p3[0] - p1[0], by = p3[1] - p1[1], bz = p3[2] - p1[2];
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    areas[f] = std::sqrt(cx * cx + cy * cy + cz * cz);
    smallest = std::min(smallest, areas[f]);
    largest = std::max(largest, areas[f]);
  }
  if (!(std::abs(smallest - largest) > kJwfEpsilon)) return;
  const double most = faces < 5000 ? 5000.0 : 500.0;
  std::uint64_t total = 0;
  mesh.cumulative.resize(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    total += static_cast<std::uint64_t>(std::min(jwfFtoi(areas[f] / smallest), most));
    mesh.cumulative[f] = total;
  }
}

// ---- The variation -------------------------------------------------------------------------------

struct PrimitiveKey {
  std::size_t index;
  int level, passes;
  double lambda, mu;
  bool operator==(const PrimitiveKey& o) const {
    // Smoothing parameters bitwise (a NaN finds its mesh again); they matter only when used.
    const bool smoothed = level > 0 && passes > 0;
    return index == o.index && level == o.level && passes == o.passes &&
           (!smoothed || (std::bit_cast<std::uint64_t>(lambda) == std::bit_cast<std::uint64_t>(o.lambda) &&
                          std::bit_cast<std::uint64_t>(mu) == std::bit_cast<std::uint64_t>(o.mu)));
  }
};

struct BuiltPrimitive {
  PrimitiveKey key;
  PrimitiveMesh mesh;
};

std::shared_ptr<const BuiltPrimitive> builtPrimitive(const PrimitiveKey& key) {
  thread_local std::shared_ptr<const BuiltPrimitive> last;
  static RecentBuilds<BuiltPrimitive> meshes(4);
  return meshes.get(
      last, [&](const BuiltPrimitive& built) { return built.key == key; },
      [&] {
        auto built = std::make_shared<BuiltPrimitive>();
        built->key = key;
        built->mesh = buildObjMeshPrimitive(key.index, key.level, key.passes, key.lambda, key.mu);
        return std::shared_ptr<const BuiltPrimitive>(std::move(built));
      });
}

// JWildfire's limitIntVal(FTOI(v), low, high).
int jwfLimitedCount(double value, int low, int high) {
  return static_cast<int>(std::clamp(jwfFtoi(value), static_cast<double>(low), static_cast<double>(high)));
}

// obj_mesh_primitive_wf: w · (a P₁ + b P₂ + c P₃), P the corners of a face of the primitive's mesh
// (Ψ₁ picks it, weighted as above), each scaled by scale_x/y/z and offset (as floats), and
// a = 1 − √Ψ₂, b = √Ψ₂ (1 − Ψ₃), c = √Ψ₂ Ψ₃: uniform on the triangle. The point itself is not used.
VOXFLAME_VARIATION_TARGETS void objMeshPrimitiveWf(const VariationInput& in, double* __restrict ox,
                                                   double* __restrict oy, double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const PrimitiveKey key{objMeshPrimitiveIndex(P[0]), jwfLimitedCount(P[7], 0, 6), jwfLimitedCount(P[8], 0, 24), P[9],
                         P[10]};
  const std::shared_ptr<const BuiltPrimitive> built = builtPrimitive(key);
  const PrimitiveMesh& mesh = built->mesh;
  const std::size_t faces = mesh.faceCount();
  if (faces == 0) return;
  const double scale[3] = {P[1], P[2], P[3]}, offset[3] = {P[4], P[5], P[6]};
  const bool weighted = !mesh.cumulative.empty();
  const double picks = weighted ? static_cast<double>(mesh.cumulative.back()) : static_cast<double>(faces);
  for (std::size_t i = 0; i < n; ++i) {
    const auto pick = static_cast<std::uint64_t>(std::min(std::floor(laneUniform(rnd[i]) * picks), picks - 1.0));
    const std::size_t face =
        weighted ? static_cast<std::size_t>(std::upper_bound(mesh.cumulative.begin(), mesh.cumulative.end(), pick) -
                                            mesh.cumulative.begin())
                 : static_cast<std::size_t>(pick);
    const double sqrtR1 = std::sqrt(laneUniform(rnd[i])), r2 = laneUniform(rnd[i]);
    const double bary[3] = {1.0 - sqrtR1, sqrtR1 * (1.0 - r2), r2 * sqrtR1};
    double sum[3] = {0.0, 0.0, 0.0};
    for (int corner = 0; corner < 3; ++corner) {
      const float* v = &mesh.vertices[3 * mesh.faces[3 * face + corner]];
      for (int c = 0; c < 3; ++c) sum[c] += bary[corner] * static_cast<float>(v[c] * scale[c] + offset[c]);
    }
    outX[i] += w * sum[0];
    outY[i] += w * sum[1];
    outZ[i] += w * sum[2];
  }
}

// obj_mesh_primitive_wf's faces for a backend of its own: the face count, 1 when the faces are
// weighted (else 0), the picks Ψ is scaled to, the cumulative weights when weighted, then each face's
// three corners as the kernel takes them (scaled and moved, in float): 9 numbers a face.
std::vector<double> objMeshTable(const double* params, const std::string*) {
  const PrimitiveKey key{objMeshPrimitiveIndex(params[0]), jwfLimitedCount(params[7], 0, 6),
                         jwfLimitedCount(params[8], 0, 24), params[9], params[10]};
  const std::shared_ptr<const BuiltPrimitive> built = builtPrimitive(key);
  const PrimitiveMesh& mesh = built->mesh;
  const std::size_t faces = mesh.faceCount();
  const bool weighted = !mesh.cumulative.empty();
  std::vector<double> table = {static_cast<double>(faces), weighted ? 1.0 : 0.0,
                               weighted ? static_cast<double>(mesh.cumulative.back()) : static_cast<double>(faces)};
  if (weighted)
    for (const std::uint64_t c : mesh.cumulative) table.push_back(static_cast<double>(c));
  for (std::size_t f = 0; f < faces; ++f)
    for (int corner = 0; corner < 3; ++corner) {
      const float* v = &mesh.vertices[3 * mesh.faces[3 * f + static_cast<std::size_t>(corner)]];
      for (int c = 0; c < 3; ++c) table.push_back(static_cast<float>(v[c] * params[1 + c] + params[4 + c]));
    }
  return table;
}

}  // namespace

const char* objMeshPrimitiveName(std::size_t index) {
  return index < kObjMeshPrimitiveCount ? kPrimitiveNames[index] : "JWildfire's stand-in cube";
}

bool objMeshPrimitiveReproduced(std::size_t index) {
  switch (index) {
    case kBall:
    case kCapsule:
    case kCone:
    case kDiamond:
    case kTorus:
    case kBox:
    case kIcosahedron:
    case kTetrahedron:
    case kOctahedron:
    case kDodecahedron:
    case kWedge:
    case kIcosidodecahedron:
    case kCubeoctahedron:
    case kObjMeshPrimitiveCount:
      return true;
    default:
      return false;
  }
}

std::size_t objMeshPrimitiveIndex(double value) {
  const double rounded = jwfFtoi(value);
  return rounded >= 0.0 && rounded < static_cast<double>(kObjMeshPrimitiveCount) ? static_cast<std::size_t>(rounded)
                                                                                 : kObjMeshPrimitiveCount;
}

PrimitiveMesh buildObjMeshPrimitive(std::size_t index, int subdivLevel, int smoothPasses, double lambda, double mu) {
  MeshBuilder builder;
  switch (index) {
    case kBall:
      ball(builder);
      break;
    case kCapsule:
      capsule(builder);
      break;
    case kCone:
      cone(builder);
      break;
    case kDiamond:
      diamond(builder);
      break;
    case kTorus:
      torus(builder);
      break;
    case kBox:
      convexHull(builder, signedPoints(0.5, 0.5, 0.5, false));
      break;
    case kIcosahedron: {
      // (0, ±φ, ±1) and its cyclic permutations, on the unit sphere.
      const double s = 1.0 / std::sqrt(1.0 + kPhi * kPhi);
      convexHull(builder, signedPoints(0.0, kPhi * s, s, true));
      break;
    }
    case kTetrahedron: {
      // Alternate corners of a cube, on the unit sphere: (s, s, −s), (s, −s, s), (−s, s, s), (−s, −s, −s).
      const double s = 1.0 / std::sqrt(3.0);
      convexHull(builder, {{s, s, -s}, {s, -s, s}, {-s, s, s}, {-s, -s, -s}});
      break;
    }
    case kOctahedron:
      convexHull(builder, signedPoints(1.0, 0.0, 0.0, true));
      break;
    case kDodecahedron: {
      // (±1, ±1, ±1) and (0, ±1/φ, ±φ) cyclically, times 1/3 (circumradius 1/√3).
      std::vector<std::array<double, 3>> points = signedPoints(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, false);
      for (const auto& p : signedPoints(0.0, 1.0 / kPhi / 3.0, kPhi / 3.0, true)) points.push_back(p);
      convexHull(builder, points);
      break;
    }
    case kWedge:
      wedge(builder);
      break;
    case kIcosidodecahedron: {
      // (±1, 0, 0) cyclically and (±φ/2, ±1/(2φ), ±1/2) cyclically, times 1/2 (circumradius 1/2).
      std::vector<std::array<double, 3>> points = signedPoints(0.5, 0.0, 0.0, true);
      for (const auto& p : signedPoints(kPhi / 4.0, 0.25 / kPhi, 0.25, true)) points.push_back(p);
      convexHull(builder, points);
      break;
    }
    case kCubeoctahedron:
      convexHull(builder, signedPoints(0.0, std::sqrt(0.5), std::sqrt(0.5), true));
      break;
    case kObjMeshPrimitiveCount:
      // JWildfire's createDfltMesh, used as it is (neither subdivided nor weighted; its faces are equal).
      convexHull(builder, signedPoints(1.0, 1.0, 1.0, false));
      return builder.take();
    default:
      return {};
  }
  PrimitiveMesh mesh = builder.take();
  if (subdivLevel <= 0) {
    weighFaces(mesh);
    return mesh;
  }
  for (int level = 0; level < subdivLevel; ++level) {
    mesh = subdivide(mesh);
    taubinSmooth(mesh, smoothPasses, lambda, mu);
  }
  return mesh;
}

// The primitive's slider stops at 13, the last shape built here; files may name any of JWildfire's.
void variation_kernels::addJwildfireMeshVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k3D = CatalogueAdder::k3D, kRandom = CatalogueAdder::kRandom;
  add("obj_mesh_primitive_wf",
      "w (a P₁ + b P₂ + c P₃): P a face (Ψ, weighted by its area relative to the smallest when subdiv_level is 0) of "
      "JWildfire's built-in mesh number `primitive` (0 ball, 1 capsule, 2 cone, 3 diamond, 4 torus, 5 box, 7 "
      "icosahedron, 8 tetrahedron, 9 octahedron, 10 dodecahedron, 11 wedge, 12 icosidodecahedron, 13 cubeoctahedron; "
      "the gears, 24 mandelbulb and 25 drop draw nothing; outside 0–25 a cube from −1 to 1), corners scaled by "
      "scale_x/y/z and moved by offset_x/y/z, subdivided subdiv_level times with subdiv_smooth_passes Taubin passes "
      "(lambda, mu); a = 1 − √Ψ, b = √Ψ (1 − Ψ'), c = √Ψ Ψ'; the point itself is not used",
      k3D, kRandom, &objMeshPrimitiveWf,
      {CatalogueAdder::jwildfireInt("primitive", 0.0, 0.0, 13.0),
       {"scale_x", 1.0, 0.5, 2.0},
       {"scale_y", 1.0, 0.5, 2.0},
       {"scale_z", 1.0, 0.5, 2.0},
       {"offset_x", 0.0, -1.0, 1.0},
       {"offset_y", 0.0, -1.0, 1.0},
       {"offset_z", 0.0, -1.0, 1.0},
       CatalogueAdder::jwildfireInt("subdiv_level", 0.0, 0.0, 6.0),
       CatalogueAdder::jwildfireInt("subdiv_smooth_passes", 12.0, 0.0, 24.0),
       {"subdiv_smooth_lambda", 0.42, 0.0, 1.0},
       {"subdiv_smooth_mu", -0.45, -1.0, 0.0},
       CatalogueAdder::jwildfireInt("blend_colormap", 1.0, 0.0, 1.0),
       {"displ_amount", 0.1, -1.0, 1.0},
       CatalogueAdder::jwildfireInt("blend_displ_map", 1.0, 0.0, 1.0),
       CatalogueAdder::jwildfireInt("receive_only_shadows", 0.0, 0.0, 1.0)});
  catalogue.back().table = &objMeshTable;
}

}  // namespace voxflame::core
