// obj_mesh_primitive_wf (JWildfire's random points on a built-in mesh: variations_jwildfire_mesh.cpp).
// The shapes' sizes, vertex and face counts are those of JWildfire's own mesh files (read once to
// learn them); the tetrahedron, which published flames use, is checked corner by corner.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/flame/obj_mesh_primitives.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "variation_point_case.h"

using namespace voxflame::core;

namespace {

using namespace voxflame::test;
using Vec = std::array<double, 3>;

// ---- Check rows ------------------------------------------------------------------------------------

// Worked out by hand: the tetrahedron's faces are equal, so Ψ₁ picks face ⌊4Ψ₁⌋ of the four planes through
// three of its corners V0 = (s, s, −s), V1 = (s, −s, s), V2 = (−s, s, s), V3 = (−s, −s, −s), s = 1/√3 as a float,
// taken in the order (012, 013, 023, 123); each face's corners go round it starting from the one before its
// first. Seed 0x2545F491: Ψ = 0.879466, 0.545326, 0.394069 → face 123 as (V3, V1, V2). Seed 0x9E3779B9:
// Ψ = 0.316594, 0.875707, 0.483300 → face 013 as (V3, V0, V1). The point is a V₁ + b V₂ + c V₃ with
// a = 1 − √Ψ₂, b = √Ψ₂ (1 − Ψ₃), c = √Ψ₂ Ψ₃; the second row scales by (2, −1, 0.5) and offsets by (0.1, 0.2,
// −0.3) first (each corner rounded to a float, as JWildfire's), weight 1.5.
const std::vector<PointCase>& pointCases() {
  static const std::vector<PointCase> cases = {
      {"obj_mesh_primitive_wf",
       {8, 1, 1, 1, 0, 0, 0, 0, 12, 0.42, -0.45, 1, 0.1, 1, 0},
       {0.3, -0.7, 0.5},
       0.8,
       kHighSeed,
       {-0.0485372866241373, -0.19306154471453352, 0.22028137572309686}},
      {"obj_mesh_primitive_wf",
       {8, 2, -1, 0.5, 0.1, 0.2, -0.3, 0, 12, 0.42, -0.45, 1, 0.1, 1, 0},
       {0.3, -0.7, 0.5},
       1.5,
       kLowSeed,
       {1.6596283413438444, 0.3285378217280274, -0.4913367075882724}},
  };
  return cases;
}
const PointCaseTableRegistration registered(&pointCases);

class FlameVariationMesh : public testing::TestWithParam<PointCase> {};
TEST_P(FlameVariationMesh, MatchesTheHandComputedValue) {
  expectMatchesTheHandComputedValue(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Cases, FlameVariationMesh, testing::ValuesIn(pointCases()), caseLabel);

// ---- Helpers -----------------------------------------------------------------------------------------

std::vector<double> params(double primitive) {
  std::vector<double> p = variationOrThrow("obj_mesh_primitive_wf").defaultParams();
  p[0] = primitive;
  return p;
}

// The variation's points over `lanes` lanes, each seeded differently, starting from 0 (weight 1).
std::vector<Vec> samples(const std::vector<double>& p, std::size_t lanes) {
  const VariationInfo& info = variationOrThrow("obj_mesh_primitive_wf");
  std::vector<double> xs(lanes, 0.3), ys(lanes, -0.2), zs(lanes, 0.5), ox(lanes, 0.0), oy(lanes, 0.0), oz(lanes, 0.0),
      colour(lanes, 0.5);
  std::vector<std::uint32_t> random(lanes);
  for (std::size_t i = 0; i < lanes; ++i) random[i] = 0x9E3779B9u * static_cast<std::uint32_t>(i + 1) | 1u;
  VariationInput in;
  in.x = in.tx = xs.data();
  in.y = in.ty = ys.data();
  in.z = in.tz = zs.data();
  in.random = random.data();
  in.count = lanes;
  in.weight = 1.0;
  in.params = p.data();
  in.affine = kAffine;
  in.colour = colour.data();
  info.apply(in, ox.data(), oy.data(), oz.data());
  std::vector<Vec> out;
  for (std::size_t i = 0; i < lanes; ++i) out.push_back({ox[i], oy[i], oz[i]});
  return out;
}

Vec corner(const PrimitiveMesh& mesh, std::size_t face, int c) {
  const std::uint32_t v = mesh.faces[3 * face + static_cast<std::size_t>(c)];
  return {mesh.vertices[3 * v], mesh.vertices[3 * v + 1], mesh.vertices[3 * v + 2]};
}

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec& a) {
  return std::sqrt(dot(a, a));
}

// The distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double triangleDistance(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  const Vec ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const auto at = [&](double v, double w) {
    return norm(sub(p, Vec{a[0] + v * ab[0] + w * ac[0], a[1] + v * ab[1] + w * ac[1], a[2] + v * ab[2] + w * ac[2]}));
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(ap);
  const Vec bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return at(d1 / (d1 - d3), 0.0);
  const Vec cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return at(0.0, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(1.0 - t, t);
  }
  const double denominator = 1.0 / (va + vb + vc);
  return at(vb * denominator, vc * denominator);
}

double meshDistance(const PrimitiveMesh& mesh, const Vec& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    best = std::min(best, triangleDistance(p, corner(mesh, f, 0), corner(mesh, f, 1), corner(mesh, f, 2)));
  return best;
}

// ---- The shapes --------------------------------------------------------------------------------------

// Per primitive: vertices, faces (quads as two triangles) and bounding box of JWildfire's mesh file, and a test of
// the shape's own geometry that every drawn point must pass (within the tessellation's sag for the round ones).
struct ShapeCase {
  std::size_t index;
  std::size_t vertices, faces;
  Vec low, high;
  std::function<bool(const Vec&)> onSurface;
};

const double kS = 1.0 / std::sqrt(3.0);
bool near(double a, double b, double tolerance = 1e-5) {
  return std::abs(a - b) <= tolerance;
}
double radialXZ(const Vec& p) {
  return std::hypot(p[0], p[2]);
}

std::vector<ShapeCase> shapeCases() {
  return {
      {0,
       642,
       1280,
       {-0.5, -0.5, -0.5},
       {0.5, 0.5, 0.5},
       [](const Vec& p) { return norm(p) > 0.49 && norm(p) < 0.50001; }},
      {1,
       554,
       48 + 2 * 528,
       {-0.5, -0.5, -1.0},
       {0.5, 0.5, 1.0},
       [](const Vec& p) {
         const double axis = std::clamp(p[2], -0.5, 0.5);
         const double d = norm(Vec{p[0], p[1], p[2] - axis});
         return d > 0.49 && d < 0.50001;
       }},
      {2,
       25,
       46,
       {-0.5, -0.5, -0.5},
       {0.5, 0.5, 0.5},
       [](const Vec& p) {
         if (near(p[1], -0.5)) return radialXZ(p) < 0.50001;
         const double side = (0.5 - p[1]) / 2.0;
         return p[1] < 0.50001 && radialXZ(p) < side + 1e-5 &&
                radialXZ(p) > side * std::cos(7.5 * std::numbers::pi / 180) - 1e-5;
       }},
      {3, 49, 94, {-0.5, -0.7125, -0.45}, {0.5, 0.2875, 0.55}, nullptr},
      {4,
       1152,
       2 * 1152,
       {-1.5, -0.5, -1.5},
       {1.5, 0.5, 1.5},
       [](const Vec& p) {
         // Flat faces fall inside the tube by up to 0.5 (1 − cos 7.5°) and, on the tube's inner side, a chord of
         // the hole's circle lies further from the tube's centre line by up to 0.5 (1 − cos 3.75°).
         const double d = std::hypot(radialXZ(p) - 1.0, p[1]);
         return d > 0.48 && d < 0.5012;
       }},
      {5,
       8,
       12,
       {-0.5, -0.5, -0.5},
       {0.5, 0.5, 0.5},
       [](const Vec& p) {
         return near(std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}), 0.5);
       }},
      {7, 12, 20, {-0.850651, -0.850651, -0.850651}, {0.850651, 0.850651, 0.850651}, nullptr},
      {8,
       4,
       4,
       {-0.57735, -0.57735, -0.57735},
       {0.57735, 0.57735, 0.57735},
       [](const Vec& p) {
         // Each face is 1/3 from the centre, its outward normal the opposite corner's direction reversed.
         const std::array<Vec, 4> corners = {{{kS, kS, -kS}, {kS, -kS, kS}, {-kS, kS, kS}, {-kS, -kS, -kS}}};
         double most = -1.0;
         for (const Vec& c : corners) most = std::max(most, -dot(c, p));
         return near(most, 1.0 / 3.0);
       }},
      {9,
       6,
       8,
       {-1, -1, -1},
       {1, 1, 1},
       [](const Vec& p) { return near(std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]), 1.0); }},
      {10, 20, 36, {-0.539345, -0.539345, -0.539345}, {0.539345, 0.539345, 0.539345}, nullptr},
      {11,
       128,
       256,
       {-1, 0, -1},
       {1, 0.5, 1},
       [](const Vec& p) {
         const double r = radialXZ(p), sag = std::cos(5.625 * std::numbers::pi / 180);
         const bool capped = (near(p[1], 0.0) || near(p[1], 0.5)) && r > 0.5 * sag - 1e-5 && r < 1.00001;
         const bool walled = p[1] > -1e-5 && p[1] < 0.50001 &&
                             ((r > sag - 1e-5 && r < 1.00001) || (r > 0.5 * sag - 1e-5 && r < 0.50001));
         return capped || walled;
       }},
      {12, 30, 56, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, nullptr},
      {13, 12, 20, {-0.707107, -0.707107, -0.707107}, {0.707107, 0.707107, 0.707107}, nullptr},
  };
}

TEST(FlameVariationMesh, ShapesHaveJwildfiresSizesAndTessellations) {
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE(objMeshPrimitiveName(shape.index));
    ASSERT_TRUE(objMeshPrimitiveReproduced(shape.index));
    const PrimitiveMesh mesh = buildObjMeshPrimitive(shape.index, 0, 12, 0.42, -0.45);
    EXPECT_EQ(mesh.vertices.size() / 3, shape.vertices);
    EXPECT_EQ(mesh.faceCount(), shape.faces);
    for (int c = 0; c < 3; ++c) {
      double low = 1e9, high = -1e9;
      for (std::size_t v = 0; v < mesh.vertices.size() / 3; ++v) {
        low = std::min(low, static_cast<double>(mesh.vertices[3 * v + static_cast<std::size_t>(c)]));
        high = std::max(high, static_cast<double>(mesh.vertices[3 * v + static_cast<std::size_t>(c)]));
      }
      EXPECT_NEAR(low, shape.low[static_cast<std::size_t>(c)], 1e-5) << "axis " << c;
      EXPECT_NEAR(high, shape.high[static_cast<std::size_t>(c)], 1e-5) << "axis " << c;
    }
  }
}

// The tetrahedron of published flames: JWildfire's corners (0.57735 ±, as its file writes 1/√3) and nothing else.
TEST(FlameVariationMesh, TheTetrahedronHasJwildfiresCorners) {
  const PrimitiveMesh mesh = buildObjMeshPrimitive(8, 0, 12, 0.42, -0.45);
  ASSERT_EQ(mesh.vertices.size(), 12u);
  const std::array<Vec, 4> expected = {{{0.57735, 0.57735, -0.57735},
                                        {0.57735, -0.57735, 0.57735},
                                        {-0.57735, 0.57735, 0.57735},
                                        {-0.57735, -0.57735, -0.57735}}};
  for (std::size_t v = 0; v < 4; ++v) {
    const Vec got = {mesh.vertices[3 * v], mesh.vertices[3 * v + 1], mesh.vertices[3 * v + 2]};
    EXPECT_NEAR(norm(sub(got, expected[v])), 0.0, 1e-6) << "corner " << v;
  }
  EXPECT_TRUE(mesh.cumulative.empty());  // equal faces: picked alike
  for (std::size_t f = 0; f < 4; ++f) {
    std::array<std::uint32_t, 3> c = {mesh.faces[3 * f], mesh.faces[3 * f + 1], mesh.faces[3 * f + 2]};
    std::sort(c.begin(), c.end());
    EXPECT_TRUE(c[0] != c[1] && c[1] != c[2]);
  }
}

TEST(FlameVariationMesh, EveryPointLiesOnThePrimitivesSurface) {
  for (const ShapeCase& shape : shapeCases()) {
    SCOPED_TRACE(objMeshPrimitiveName(shape.index));
    const PrimitiveMesh mesh = buildObjMeshPrimitive(shape.index, 0, 12, 0.42, -0.45);
    const std::vector<Vec> points = samples(params(static_cast<double>(shape.index)), 1500);
    int off = 0, offShape = 0;
    for (const Vec& p : points) {
      if (meshDistance(mesh, p) > 1e-6) ++off;
      if (shape.onSurface && !shape.onSurface(p)) ++offShape;
    }
    EXPECT_EQ(off, 0);
    EXPECT_EQ(offShape, 0);
  }
}

// Corners are scaled per axis and then offset: the points, moved back, lie on the unit tetrahedron.
TEST(FlameVariationMesh, ScaleAndOffsetMoveTheCorners) {
  std::vector<double> p = params(8);
  const Vec scale = {2.0, -1.0, 0.5}, offset = {0.1, 0.2, -0.3};
  for (int c = 0; c < 3; ++c) {
    p[1 + static_cast<std::size_t>(c)] = scale[static_cast<std::size_t>(c)];
    p[4 + static_cast<std::size_t>(c)] = offset[static_cast<std::size_t>(c)];
  }
  const PrimitiveMesh mesh = buildObjMeshPrimitive(8, 0, 12, 0.42, -0.45);
  Vec low = {1e9, 1e9, 1e9}, high = {-1e9, -1e9, -1e9};
  for (const Vec& q : samples(p, 2000)) {
    Vec back{};
    for (std::size_t c = 0; c < 3; ++c) {
      back[c] = (q[c] - offset[c]) / scale[c];
      low[c] = std::min(low[c], q[c]);
      high[c] = std::max(high[c], q[c]);
    }
    EXPECT_LT(meshDistance(mesh, back), 1e-6);
  }
  // The points reach close to the scaled corners' box: x in 0.1 ± 2s, y in 0.2 ± s, z in −0.3 ± s/2.
  for (std::size_t c = 0; c < 3; ++c) {
    const double half = std::abs(scale[c]) * 0.57735;
    EXPECT_GT(low[c], offset[c] - half - 1e-6);
    EXPECT_LT(high[c], offset[c] + half + 1e-6);
    EXPECT_LT(low[c], offset[c] - 0.8 * half);
    EXPECT_GT(high[c], offset[c] + 0.8 * half);
  }
}

// JWildfire repeats each face round(area / smallest area) times. The dodecahedron's pentagons are split into a
// middle triangle φ times the area of each side one: counts 2, 1, 1, so 48 for the 12 faces. The cone's sides are
// 33 times its smallest base triangle (as in JWildfire's file: 0.1457 / 0.00441).
TEST(FlameVariationMesh, FacesCountByTheirAreaRelativeToTheSmallest) {
  const PrimitiveMesh dodecahedron = buildObjMeshPrimitive(10, 0, 12, 0.42, -0.45);
  ASSERT_EQ(dodecahedron.cumulative.size(), 36u);
  EXPECT_EQ(dodecahedron.cumulative.back(), 48u);
  const PrimitiveMesh cone = buildObjMeshPrimitive(2, 0, 12, 0.42, -0.45);
  ASSERT_EQ(cone.cumulative.size(), 46u);
  std::uint64_t sides = 0, base = 0;
  for (std::size_t f = 0; f < cone.faceCount(); ++f) {
    const std::uint64_t count = cone.cumulative[f] - (f ? cone.cumulative[f - 1] : 0);
    const bool onBase = corner(cone, f, 0)[1] < -0.49 && corner(cone, f, 1)[1] < -0.49 && corner(cone, f, 2)[1] < -0.49;
    if (onBase) {
      base += count;
    } else {
      EXPECT_EQ(count, 33u);
      sides += count;
    }
  }
  EXPECT_EQ(sides, 24u * 33u);
  // Drawn points follow the counts: the share on the cone's side is sides / (sides + base) (about its share of
  // the area, 0.69), not the share of faces (24 / 46).
  const double expected = static_cast<double>(sides) / static_cast<double>(sides + base);
  const std::vector<Vec> points = samples(params(2), 40000);
  const double onSide =
      static_cast<double>(std::count_if(points.begin(), points.end(), [](const Vec& q) { return q[1] > -0.4999; })) /
      static_cast<double>(points.size());
  const double sigma = std::sqrt(expected * (1.0 - expected) / static_cast<double>(points.size()));
  EXPECT_NEAR(onSide, expected, 4.0 * sigma);
  EXPECT_NEAR(expected, 0.69, 0.01);
}

// subdiv_level 1 splits each of the tetrahedron's faces into four (10 vertices, 16 faces, picked alike). A Laplace
// step of strength t moves every vertex v by t (mean of its neighbours − v): a corner's three neighbours (edge
// midpoints) average to v/3 and a midpoint's six to v/3 as well (the corners sum to 0), so each step scales the
// whole mesh by 1 − 2t/3, and a Taubin pass (lambda 0.42, mu −0.45) by 0.72 · 1.3 = 0.936.
TEST(FlameVariationMesh, SubdivisionAndTaubinSmoothingFollowJwildfire) {
  for (const int passes : {0, 1, 2}) {
    SCOPED_TRACE(passes);
    const PrimitiveMesh mesh = buildObjMeshPrimitive(8, 1, passes, 0.42, -0.45);
    ASSERT_EQ(mesh.vertices.size(), 30u);
    EXPECT_EQ(mesh.faceCount(), 16u);
    EXPECT_TRUE(mesh.cumulative.empty());
    const double shrink = std::pow(0.936, passes);
    int corners = 0, midpoints = 0;
    for (std::size_t v = 0; v < 10; ++v) {
      const double r = norm(Vec{mesh.vertices[3 * v], mesh.vertices[3 * v + 1], mesh.vertices[3 * v + 2]});
      if (near(r, shrink, 1e-5)) ++corners;
      if (near(r, kS * shrink, 1e-5)) ++midpoints;
    }
    EXPECT_EQ(corners, 4);
    EXPECT_EQ(midpoints, 6);
  }
  // The parameters as JWildfire limits them: subdiv_level and subdiv_smooth_passes rounded into 0–6 and 0–24.
  std::vector<double> p = params(8);
  p[7] = 0.6;   // level 1
  p[8] = -3.0;  // no smoothing
  const PrimitiveMesh unsmoothed = buildObjMeshPrimitive(8, 1, 0, 0.42, -0.45);
  for (const Vec& q : samples(p, 500)) EXPECT_LT(meshDistance(unsmoothed, q), 1e-6);
}

// Parameters JWildfire's list does not have: outside 0–25 its stand-in cube from −1 to 1, NaN the ball (FTOI of
// NaN is 0), a gear (not built here) nothing at all; a NaN scale makes that coordinate NaN (the chaos game's
// escape) and leaves the others.
TEST(FlameVariationMesh, BadParametersAreHandled) {
  EXPECT_EQ(objMeshPrimitiveIndex(26.0), kObjMeshPrimitiveCount);
  EXPECT_EQ(objMeshPrimitiveIndex(-0.6), kObjMeshPrimitiveCount);
  EXPECT_EQ(objMeshPrimitiveIndex(7.5), 8u);
  EXPECT_EQ(objMeshPrimitiveIndex(std::numeric_limits<double>::quiet_NaN()), 0u);
  EXPECT_EQ(objMeshPrimitiveIndex(1e300), kObjMeshPrimitiveCount);
  for (const double outside : {26.0, -1.0, 1e300, -std::numeric_limits<double>::infinity()})
    for (const Vec& q : samples(params(outside), 300))
      EXPECT_NEAR(std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}), 1.0, 1e-6) << outside;
  for (const Vec& q : samples(params(std::numeric_limits<double>::quiet_NaN()), 300)) EXPECT_NEAR(norm(q), 0.5, 0.01);
  for (const double unbuilt : {6.0, 14.0, 23.0, 24.0, 25.0}) {
    EXPECT_FALSE(objMeshPrimitiveReproduced(static_cast<std::size_t>(unbuilt)));
    for (const Vec& q : samples(params(unbuilt), 50)) EXPECT_EQ(norm(q), 0.0) << unbuilt;
  }
  std::vector<double> p = params(8);
  p[1] = std::numeric_limits<double>::quiet_NaN();
  for (const Vec& q : samples(p, 50)) {
    EXPECT_TRUE(std::isnan(q[0]));
    EXPECT_TRUE(std::isfinite(q[1]) && std::isfinite(q[2]));
  }
}

// Import: JWildfire's parameters and empty image names are read with nothing lost; an unbuilt primitive, an image
// and receive_only_shadows are named as lost; an index outside the list is warned of only.
TEST(FlameVariationMesh, ImportNamesWhatIsLost) {
  const auto importXform = [](const std::string& xform) {
    const std::string text = "<flames><flame name=\"t\" size=\"64 64\"><xform weight=\"1\" color=\"0\" " + xform +
                             " coefs=\"1 0 0 1 0 0\"/><color index=\"0\" rgb=\"255 255 255\"/></flame></flames>";
    return readFlameXml(text, "t.flame");
  };
  const std::string full =
      R"(obj_mesh_primitive_wf="1.0" obj_mesh_primitive_wf_primitive="8" obj_mesh_primitive_wf_scale_x="1.5" )"
      R"(obj_mesh_primitive_wf_scale_y="1.0" obj_mesh_primitive_wf_scale_z="1.0" obj_mesh_primitive_wf_offset_x="0.0" )"
      R"(obj_mesh_primitive_wf_offset_y="0.25" obj_mesh_primitive_wf_offset_z="0.0" obj_mesh_primitive_wf_subdiv_level="0" )"
      R"(obj_mesh_primitive_wf_subdiv_smooth_passes="12" obj_mesh_primitive_wf_subdiv_smooth_lambda="0.42" )"
      R"(obj_mesh_primitive_wf_subdiv_smooth_mu="-0.45" obj_mesh_primitive_wf_blend_colormap="1" )"
      R"(obj_mesh_primitive_wf_displ_amount="0.1" obj_mesh_primitive_wf_blend_displ_map="1" )"
      R"(obj_mesh_primitive_wf_receive_only_shadows="0" obj_mesh_primitive_wf_colormap_filename="" )"
      R"(obj_mesh_primitive_wf_displ_map_filename="" obj_mesh_primitive_wf_fx_priority="0")";
  const FlameFileContents whole = importXform(full);
  EXPECT_TRUE(whole.flame.leftOut.empty()) << whole.flame.leftOut.front();
  EXPECT_TRUE(whole.flame.warnings.empty()) << whole.flame.warnings.front();
  const VariationTerm& term = whole.flame.genome.xforms.at(0).variations.at(0);
  EXPECT_EQ(term.name, "obj_mesh_primitive_wf");
  EXPECT_EQ(term.params.at(0), 8.0);
  EXPECT_EQ(term.params.at(1), 1.5);
  EXPECT_EQ(term.params.at(5), 0.25);

  const FlameFileContents gear = importXform(R"(obj_mesh_primitive_wf="1" obj_mesh_primitive_wf_primitive="6")");
  EXPECT_EQ(gear.flame.leftOut, (std::vector<std::string>{"primitive gear15 of obj_mesh_primitive_wf"}));
  const FlameFileContents outside = importXform(R"(obj_mesh_primitive_wf="1" obj_mesh_primitive_wf_primitive="40")");
  EXPECT_TRUE(outside.flame.leftOut.empty());
  ASSERT_EQ(outside.flame.warnings.size(), 1u);
  EXPECT_NE(outside.flame.warnings.front().find("stand-in"), std::string::npos) << outside.flame.warnings.front();
  // "image.png" as JWildfire's hex of its bytes.
  const FlameFileContents image =
      importXform(R"(obj_mesh_primitive_wf="1" obj_mesh_primitive_wf_colormap_filename="696d6167652e706e67")");
  EXPECT_EQ(image.flame.leftOut, (std::vector<std::string>{"image obj_mesh_primitive_wf_colormap_filename"}));
  const FlameFileContents shadows =
      importXform(R"(obj_mesh_primitive_wf="1" obj_mesh_primitive_wf_receive_only_shadows="1")");
  EXPECT_EQ(shadows.flame.leftOut, (std::vector<std::string>{"receive_only_shadows of obj_mesh_primitive_wf"}));
}

}  // namespace
