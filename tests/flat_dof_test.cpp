// JWildfire's depth of field in the flat view (FlatCamera in core/flame/flat_render.h): its blur
// shapes spread an out-of-focus point into their shapes, its depth of field about a focus point
// (new_dof) keeps points near the focus sharp with a smooth fade, and the import keeps the keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/flame/flat_render.h"
#include "core/flame/xml.h"
#include "core/scene.h"
#include "core/scene_io.h"

using namespace voxflame;

namespace {

// A JWildfire camera that looks straight down with the legacy depth of field: a point at depth 0
// lies 1 in front of the depth in focus, so its blur radius ρ is 0.1 · 10 · scale = scale.
core::FlatViewSettings blurredCamera(core::FlatDofShape shape, double scale = 1.0) {
  core::FlatViewSettings flat;
  flat.cameraModel = core::FlatCameraModel::Jwildfire;
  flat.cameraDof = 10.0;
  flat.cameraDofScale = scale;
  flat.cameraDofFade = 0.0;
  flat.cameraZ = 1.0;
  flat.cameraDofShape = shape;
  return flat;
}

// Where the point (0, 0, 0) lands for n pairs of draws.
std::vector<glm::dvec2> spread(const core::FlatViewSettings& flat, int n = 4000) {
  const core::FlatCamera camera(flat);
  std::vector<glm::dvec2> points;
  for (int i = 0; i < n; ++i) {
    const double a = (i + 0.5) / n, b = std::fmod((i * 0.6180339887498949) + 0.25, 1.0);
    points.push_back(camera.project(0.0, 0.0, 0.0, a, b));
  }
  return points;
}

double largest(const std::vector<glm::dvec2>& points) {
  double r = 0.0;
  for (const glm::dvec2& p : points) r = std::max(r, std::hypot(p.x, p.y));
  return r;
}

}  // namespace

TEST(FlatDof, BubbleSpreadsOntoACircleOrADisc) {
  core::FlatViewSettings flat = blurredCamera(core::FlatDofShape::Bubble);
  for (const glm::dvec2& p : spread(flat)) EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, 1e-12);  // fade 0: the whole radius
  flat.cameraDofFade = 1.0;  // a random part of it: the disc, filled from the middle out
  const std::vector<glm::dvec2> disc = spread(flat);
  int inner = 0;
  for (const glm::dvec2& p : disc) {
    EXPECT_LE(std::hypot(p.x, p.y), 1.0 + 1e-12);
    if (std::hypot(p.x, p.y) < 0.5) ++inner;
  }
  EXPECT_NEAR(inner / static_cast<double>(disc.size()), 0.5, 0.05);
}

TEST(FlatDof, RectSpreadsIntoItsTurnedRectangle) {
  core::FlatViewSettings flat = blurredCamera(core::FlatDofShape::Rect, 2.0);  // ρ = 2
  flat.cameraDofParam1 = 0.5;                                                  // width
  flat.cameraDofRotateDeg = 30.0;
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  double reachU = 0.0, reachV = 0.0;
  for (const glm::dvec2& p : spread(flat)) {
    // Back into the rectangle's own axes: ρ (Ψ₁ − ½) · width across, ρ (Ψ₂ − ½) along.
    const double u = p.x * c + p.y * s, v = -p.x * s + p.y * c;
    EXPECT_LE(std::abs(u), 0.5 + 1e-12);
    EXPECT_LE(std::abs(v), 1.0 + 1e-12);
    reachU = std::max(reachU, std::abs(u));
    reachV = std::max(reachV, std::abs(v));
  }
  EXPECT_GT(reachU, 0.45);
  EXPECT_GT(reachV, 0.9);
}

// The cloverleaf r = sin 2θ + ¼ sin 6θ has its four leaves on the diagonals and none on the axes.
TEST(FlatDof, CloverleafSpreadsIntoFourLeavesOnTheDiagonals) {
  const std::vector<glm::dvec2> points = spread(blurredCamera(core::FlatDofShape::Cloverleaf));
  int onAxes = 0, onDiagonals = 0;
  for (const glm::dvec2& p : points) {
    if (std::hypot(p.x, p.y) < 0.3) continue;
    const double angle = std::fmod(std::atan2(p.y, p.x) + 2.0 * std::numbers::pi, std::numbers::pi / 2.0);
    if (angle < 0.05 || angle > std::numbers::pi / 2.0 - 0.05) ++onAxes;  // r < 3.5 · 0.05 there
    if (std::abs(angle - std::numbers::pi / 4.0) < 0.15) ++onDiagonals;
  }
  EXPECT_EQ(onAxes, 0);
  EXPECT_GT(onDiagonals, 200);
  EXPECT_LE(largest(points), 1.25 + 1e-9);
}

// Every shape spreads the point (a real blur, finite, within a few radii), grows with the radius,
// and turns with the shape's rotate (sineblur, round, does not turn; bubble has no rotate).
TEST(FlatDof, EveryShapeSpreadsScalesAndTurns) {
  for (std::size_t k = 0; k < std::size(core::kFlatDofShapeNames); ++k) {
    const auto shape = static_cast<core::FlatDofShape>(k);
    SCOPED_TRACE(std::string(core::kFlatDofShapeNames[k]));
    core::FlatViewSettings flat = blurredCamera(shape);
    // Parameters that make each shape a shape (JWildfire's editor's defaults where 0 draws nothing).
    if (shape == core::FlatDofShape::Rect) flat.cameraDofParam1 = 0.67;
    if (shape == core::FlatDofShape::Flower) flat.cameraDofParam1 = 0.4, flat.cameraDofParam2 = 7.0;
    if (shape == core::FlatDofShape::NBlur) flat.cameraDofParam1 = 5.0, flat.cameraDofParam3 = 1.0;
    if (shape == core::FlatDofShape::PerlinNoise)
      flat.cameraDofParam2 = 0.2, flat.cameraDofParam3 = 2.0, flat.cameraDofParam4 = 0.25, flat.cameraDofParam5 = 0.5;
    if (shape == core::FlatDofShape::SineBlur) flat.cameraDofParam1 = 1.4;
    if (shape == core::FlatDofShape::StarBlur) flat.cameraDofParam1 = 5.0, flat.cameraDofParam2 = 0.4;
    if (shape == core::FlatDofShape::Taurus)
      flat.cameraDofParam1 = 3.0, flat.cameraDofParam2 = 5.0, flat.cameraDofParam3 = 1.5, flat.cameraDofParam4 = 1.0;
    const std::vector<glm::dvec2> points = spread(flat, 2000);
    double sum = 0.0;
    for (const glm::dvec2& p : points) {
      ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
      sum += std::hypot(p.x, p.y);
    }
    EXPECT_GT(sum / static_cast<double>(points.size()), 0.05);
    EXPECT_LT(largest(points), 8.0);
    // The shapes' own sizes for ρ = 1: sineblur's and starblur's unit discs (the star's points
    // reach 1), heart's xheart of a point in [−2, 2]² (below 2), flower's 2 (Ψ − holes) cos(·)
    // (below 2 · 1.4), taurus' ¼ (|R| + 1) with R = inv r + (1 − inv) r cos(n x) (below ¼ · 7).
    if (shape == core::FlatDofShape::SineBlur || shape == core::FlatDofShape::StarBlur) {
      EXPECT_LE(largest(points), 1.0 + 1e-9);
      EXPECT_GT(largest(points), 0.8);
    }
    if (shape == core::FlatDofShape::Heart) {
      EXPECT_LT(largest(points), 2.0);
    }
    if (shape == core::FlatDofShape::Flower) {
      EXPECT_LT(largest(points), 2.8);
    }
    if (shape == core::FlatDofShape::Taurus) {
      EXPECT_LE(largest(points), 1.75 + 1e-9);
    }
    // Twice the scale: twice the offset, for the same draws.
    core::FlatViewSettings twice = flat;
    twice.cameraDofScale = 2.0;
    const std::vector<glm::dvec2> doubled = spread(twice, 2000);
    for (std::size_t i = 0; i < points.size(); i += 97) {
      EXPECT_NEAR(doubled[i].x, 2.0 * points[i].x, 1e-9);
      EXPECT_NEAR(doubled[i].y, 2.0 * points[i].y, 1e-9);
    }
    // A quarter turn of the shape.
    core::FlatViewSettings turned = flat;
    turned.cameraDofRotateDeg = 90.0;
    const std::vector<glm::dvec2> quarter = spread(turned, 2000);
    const bool turns = shape != core::FlatDofShape::Bubble && shape != core::FlatDofShape::SineBlur;
    for (std::size_t i = 0; i < points.size(); i += 97) {
      EXPECT_NEAR(quarter[i].x, turns ? -points[i].y : points[i].x, 1e-9);
      EXPECT_NEAR(quarter[i].y, turns ? points[i].x : points[i].y, 1e-9);
    }
  }
}

// new_dof: the blur grows with the distance from the focus point; within `area` less its fade band
// (area/2.25) points stay sharp, and across the band the blur rises smoothly to the full one.
TEST(FlatDof, NewDofKeepsTheAreaAboutTheFocusSharpAndFadesSmoothly) {
  core::FlatViewSettings flat = blurredCamera(core::FlatDofShape::Bubble);
  flat.cameraDofNew = true;
  flat.cameraDofFocus = {0.5, 0.0, 0.0};
  flat.cameraDofArea = 1.0;
  flat.cameraDofExponent = 2.0;  // the plain distance
  const core::FlatCamera camera(flat);
  // The blur's size for a point at distance d from the focus (along x): fade 0 gives all of it.
  const auto blur = [&](double d) {
    const glm::dvec2 p = camera.project(0.5 + d, 0.0, 0.0, 0.3, 0.7);
    return std::hypot(p.x - (0.5 + d), p.y);
  };
  const double band = 1.0 / 2.25;
  EXPECT_EQ(blur(0.0), 0.0);
  EXPECT_EQ(blur(1.0 - band - 1e-6), 0.0);
  EXPECT_NEAR(blur(-3.0), 3.0, 1e-12);  // beyond the area: 0.1 dof · scale · d, on either side
  EXPECT_NEAR(blur(2.0), 2.0, 1e-12);
  EXPECT_NEAR(blur(1.0 + 1e-9), 1.0, 1e-6);
  // Continuous at both ends of the band and rising through it.
  EXPECT_LT(blur(1.0 - band + 1e-4), 1e-9);
  EXPECT_NEAR(blur(1.0 - 1e-7), 1.0, 1e-5);
  double last = 0.0;
  for (int i = 1; i < 100; ++i) {
    const double d = 1.0 - band + band * i / 100.0, b = blur(d);
    EXPECT_GT(b, last);
    EXPECT_LT(b - last, 0.05);  // no jump
    last = b;
  }
  // Halfway through the band the smootherstep is ½.
  EXPECT_NEAR(blur(1.0 - band / 2.0), 0.5 * (1.0 - band / 2.0), 1e-12);
  // The exponent bends the distance: (d²)^(1/4) = √d.
  flat.cameraDofExponent = 4.0;
  const glm::dvec2 p = core::FlatCamera(flat).project(0.5 + 4.0, 0.0, 0.0, 0.3, 0.7);
  EXPECT_NEAR(std::hypot(p.x - 4.5, p.y), 2.0, 1e-12);
  // The solid rendering's projection stays sharp.
  const glm::dvec2 sharp = core::FlatCamera(flat).projectSharp(4.5, 0.0, 0.0);
  EXPECT_EQ(sharp, glm::dvec2(4.5, 0.0));
}

namespace {

const char* kFlameBody =
    "<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 -0.5 -0.4\"/>\n"
    "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 -0.4\"/>\n"
    "<xform weight=\"1\" color=\"0.5\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0.6\"/>\n";

core::ImportedFlame jwildfireFlame(const std::string& attributes) {
  const std::string xml = "<flame version=\"JWildfire V8.00\" size=\"120 100\" center=\"0 0\" scale=\"40\" " +
                          attributes + ">\n" + kFlameBody + "</flame>\n";
  return core::readFlameXml(xml, "dof.flame").flame;
}

bool warned(const core::ImportedFlame& flame, const std::string& part) {
  return std::any_of(flame.warnings.begin(), flame.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

}  // namespace

TEST(FlatDof, ImportKeepsJwildfiresNewDofAndShapes) {
  const core::ImportedFlame flame = jwildfireFlame(
      "cam_pitch=\"0.6\" cam_persp=\"0.2\" cam_dof=\"0.4\" new_dof=\"1\" cam_xfocus=\"0.1\" cam_yfocus=\"-0.2\" "
      "cam_zfocus=\"0.3\" cam_dof_area=\"0.25\" cam_dof_exponent=\"1.5\" cam_dof_shape=\"STARBLUR\" "
      "cam_dof_scale=\"2\" cam_dof_rotate=\"12.5\" cam_dof_fade=\"0.3\" cam_dof_param1=\"6\" "
      "cam_dof_param2=\"0.35\"");
  EXPECT_TRUE(flame.leftOut.empty());
  EXPECT_FALSE(warned(flame, "does not draw"));
  const core::FlatViewSettings& flat = flame.flat;
  EXPECT_TRUE(flat.cameraDofNew);
  EXPECT_EQ(flat.cameraDofFocus, glm::dvec3(0.1, -0.2, 0.3));
  EXPECT_DOUBLE_EQ(flat.cameraDofArea, 0.25);
  EXPECT_DOUBLE_EQ(flat.cameraDofExponent, 1.5);
  EXPECT_EQ(flat.cameraDofShape, core::FlatDofShape::StarBlur);
  EXPECT_DOUBLE_EQ(flat.cameraDofRotateDeg, 12.5);
  EXPECT_DOUBLE_EQ(flat.cameraDofParam1, 6.0);
  EXPECT_DOUBLE_EQ(flat.cameraDofParam2, 0.35);
  // Every shape name JWildfire writes for a shape the flat view draws.
  for (const char* name : {"BUBBLE", "RECT", "CLOVERLEAF", "HEART", "FLOWER", "NBLUR", "PERLIN_NOISE", "SINEBLUR",
                           "STARBLUR", "TAURUS", "CANNABISCURVE"}) {
    const core::ImportedFlame shaped =
        jwildfireFlame(std::string("cam_pitch=\"0.6\" cam_dof=\"0.4\" cam_dof_shape=\"") + name + "\"");
    EXPECT_TRUE(shaped.leftOut.empty()) << name;
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    EXPECT_EQ(core::kFlatDofShapeNames[static_cast<std::size_t>(shaped.flat.cameraDofShape)], lower);
  }
  // Those that need an image, a flame or a grown crystal are named lost and drawn as bubbles.
  for (const char* name : {"SNOWFLAKE", "BRUSH_STROKE", "SUB_FLAME"}) {
    const core::ImportedFlame lost =
        jwildfireFlame(std::string("cam_pitch=\"0.6\" cam_dof=\"0.4\" cam_dof_shape=\"") + name + "\"");
    EXPECT_NE(std::find(lost.leftOut.begin(), lost.leftOut.end(), "3D camera"), lost.leftOut.end()) << name;
    EXPECT_TRUE(warned(lost, name));
    EXPECT_EQ(lost.flat.cameraDofShape, core::FlatDofShape::Bubble);
  }
  // An unknown name is JWildfire's BUBBLE, with a warning; a bad exponent keeps a usable one.
  const core::ImportedFlame odd = jwildfireFlame(
      "cam_pitch=\"0.6\" cam_dof=\"0.4\" new_dof=\"1\" cam_dof_shape=\"WOBBLE\" cam_dof_exponent=\"0\" "
      "cam_dof_area=\"nan\"");
  EXPECT_TRUE(odd.leftOut.empty());
  EXPECT_TRUE(warned(odd, "WOBBLE"));
  EXPECT_EQ(odd.flat.cameraDofShape, core::FlatDofShape::Bubble);
  EXPECT_GT(odd.flat.cameraDofExponent, 0.0);
  EXPECT_DOUBLE_EQ(odd.flat.cameraDofArea, 0.5);
  EXPECT_TRUE(warned(odd, "cam_dof_exponent"));
  EXPECT_TRUE(warned(odd, "cam_dof_area"));
}

TEST(FlatDof, NewDofAndShapesRoundTripThroughPresets) {
  core::Scene scene = core::defaultScene();
  scene.flat.cameraModel = core::FlatCameraModel::Jwildfire;
  scene.flat.cameraPitchDeg = 30.0;
  scene.flat.cameraDof = 0.3;
  scene.flat.cameraDofNew = true;
  scene.flat.cameraDofFocus = {0.1, 0.2, -0.3};
  scene.flat.cameraDofArea = 0.7;
  scene.flat.cameraDofExponent = 3.0;
  scene.flat.cameraDofShape = core::FlatDofShape::PerlinNoise;
  scene.flat.cameraDofRotateDeg = 45.0;
  scene.flat.cameraDofParam1 = 1.0;
  scene.flat.cameraDofParam6 = -2.0;
  const std::string json = core::sceneToJson(scene);
  EXPECT_NE(json.find("\"camera_dof_shape\": \"perlin_noise\""), std::string::npos);
  EXPECT_EQ(core::sceneFromJson(json, "round trip").flat, scene.flat);
}

// A flame drawn with a shaped depth of field about a focus point differs from its sharp self only
// away from the focus: the picture's middle (the focus) keeps its light.
TEST(FlatDof, ARenderBlursAwayFromTheFocus) {
  const auto render = [](const std::string& dof) {
    core::Scene scene = core::sceneFromImportedFlame(
        jwildfireFlame("estimator_radius=\"0\" cam_pitch=\"0.000001\" cam_zpos=\"0\" " + dof), core::Scene{});
    core::FlatRenderOptions options;
    options.quality = 30.0;
    return core::renderFlat(scene, options).image;
  };
  const core::ImageRGBA sharp = render("");
  const core::ImageRGBA blurred = render(
      "cam_dof=\"3\" new_dof=\"1\" cam_dof_area=\"0.3\" cam_dof_shape=\"RECT\" cam_dof_param1=\"0.7\" "
      "cam_dof_scale=\"1\" cam_dof_fade=\"0\"");
  // The lit share of the pixels: the blur spreads the far parts over more of the picture.
  const auto lit = [](const core::ImageRGBA& image, int x0, int x1, int y0, int y1) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const float* p = image.at(x, y);
        if (p[0] + p[1] + p[2] > 0.05f) ++n;
      }
    return n;
  };
  EXPECT_GT(lit(blurred, 0, 120, 0, 100), lit(sharp, 0, 120, 0, 100) * 1.2);
  // Near the focus (the middle, within 0.3 · 40 = 12 pixels less the fade) nothing moved.
  double difference = 0.0;
  for (int y = 46; y < 54; ++y)
    for (int x = 56; x < 64; ++x) difference += std::abs(blurred.at(x, y)[1] - sharp.at(x, y)[1]);
  EXPECT_LT(difference / 64.0, 0.1);
}
