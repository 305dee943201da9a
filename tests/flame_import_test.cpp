// Importing what flame files hold beyond a still genome, and names that could be read two ways:
// variation names that extend other variation names (blur, blur_square), flam3's <motion> and
// JWildfire's motion curves as keyframes, JWildfire's layers, and JWildfire's weighting fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/chaos_game.h"
#include "core/flame/variations.h"
#include "core/flame/xml.h"
#include "core/keyframes.h"
#include "core/random.h"
#include "core/scene.h"
#include "core/scene_io.h"

using namespace voxflame::core;

namespace {

std::string flameFile(const std::string& xforms, const std::string& attributes = "") {
  std::string palette = "<palette count=\"256\" format=\"RGB\">\n";
  char hex[8];
  for (int i = 0; i < 256; ++i) {
    std::snprintf(hex, sizeof hex, "%02X%02X%02X", i, 255 - i, 128);
    palette += hex;
  }
  palette += "\n</palette>\n";
  return "<flames><flame name=\"t\" " + attributes + ">\n" + xforms + palette + "</flame></flames>\n";
}

ImportedFlame importFlat(const std::string& text) {
  FlameImportOptions options;
  options.depth = 0.0;  // depth would drop flatten
  return readFlameXml(text, "t.flame", options).flame;
}

bool hasWarningContaining(const ImportedFlame& flame, const std::string& text) {
  return std::any_of(flame.warnings.begin(), flame.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

std::string allWarnings(const ImportedFlame& flame) {
  std::string out;
  for (const std::string& w : flame.warnings) out += w + "\n";
  return out;
}

const VariationTerm* termNamed(const FlameXform& x, const std::string& name) {
  for (const VariationTerm& term : x.variations)
    if (term.name == name) return &term;
  return nullptr;
}

}  // namespace

// Every pair of catalogue names where one is a prefix of the other (julia, julian; blur,
// blur_circle; ...) on one transform: both are variations with their own weights, and the longer
// name is never read as a parameter of the shorter one.
TEST(FlameImport, CatalogueNamesThatExtendOthersAreVariationsNotParameters) {
  std::size_t pairs = 0;
  for (const VariationInfo& shorter : variationCatalogue()) {
    for (const VariationInfo& longer : variationCatalogue()) {
      if (&shorter == &longer || !longer.name.starts_with(shorter.name)) continue;
      ++pairs;
      const std::string xform = "<xform weight=\"1\" " + shorter.name + "=\"0.25\" " + longer.name +
                                "=\"0.75\" coefs=\"0.5 0 0 0.5 0 0\"/>\n";
      const ImportedFlame flame = importFlat(flameFile(xform));
      const FlameXform& x = flame.genome.xforms.at(0);
      const VariationTerm* a = termNamed(x, shorter.name);
      const VariationTerm* b = termNamed(x, longer.name);
      ASSERT_NE(a, nullptr) << shorter.name << " beside " << longer.name;
      ASSERT_NE(b, nullptr) << longer.name << " beside " << shorter.name;
      EXPECT_EQ(x.variations.size(), 2u) << shorter.name << ", " << longer.name;
      EXPECT_DOUBLE_EQ(a->weight, 0.25) << shorter.name << " beside " << longer.name;
      EXPECT_DOUBLE_EQ(b->weight, 0.75) << longer.name << " beside " << shorter.name;
      EXPECT_EQ(a->params, shorter.defaultParams()) << longer.name << " was read as a parameter of " << shorter.name;
      EXPECT_EQ(b->params, longer.defaultParams()) << longer.name;
      EXPECT_FALSE(hasWarningContaining(flame, "does not"))
          << shorter.name << ", " << longer.name << ": " << allWarnings(flame);
      EXPECT_TRUE(
          std::none_of(flame.leftOut.begin(), flame.leftOut.end(),
                       [](const std::string& s) { return s.starts_with("variation") || s.starts_with("parameter"); }))
          << shorter.name << ", " << longer.name;
    }
  }
  EXPECT_GT(pairs, 10u) << "the catalogue has fewer prefix pairs than expected";
}

// blur beside blur_square (a catalogue variation), and beside variations voxflame does not know
// whose names extend a known one: those are unknown variations with their weight, in the one
// warning that names everything left out, never "parameters that blur does not have".
TEST(FlameImport, UnknownVariationsExtendingAKnownNameAreUnknownVariations) {
  if (findVariation("blur_square")) {
    const ImportedFlame both =
        importFlat(flameFile("<xform weight=\"1\" blur=\"0.4\" blur_square=\"0.6\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"));
    ASSERT_NE(termNamed(both.genome.xforms[0], "blur"), nullptr);
    ASSERT_NE(termNamed(both.genome.xforms[0], "blur_square"), nullptr);
    EXPECT_DOUBLE_EQ(termNamed(both.genome.xforms[0], "blur_square")->weight, 0.6);
    EXPECT_TRUE(both.leftOut.empty()) << allWarnings(both);
  }
  // Names the catalogue will never have, extending blur (no parameters) and julian (parameters).
  const ImportedFlame flame = importFlat(
      flameFile("<xform weight=\"1\" blur=\"0.1\" blur_zzsquare=\"0.9\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                "<xform weight=\"1\" julian=\"1\" julian_power=\"3\" julian_zzwave=\"0.5\" julian_zzwave_size=\"2\" "
                "coefs=\"0.5 0 0 0.5 0 0\"/>\n"));
  EXPECT_EQ(flame.genome.xforms[0].variations.size(), 1u);
  EXPECT_DOUBLE_EQ(flame.genome.xforms[1].variations.at(0).params.at(0), 3.0);
  EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"variation blur_zzsquare", "variation julian_zzwave"}));
  EXPECT_FALSE(hasWarningContaining(flame, "does not have; it was left out")) << allWarnings(flame);
  // One warning names both, the julian one as possibly a parameter julian lacks.
  const auto named = std::count_if(flame.warnings.begin(), flame.warnings.end(), [](const std::string& w) {
    return w.find("blur_zzsquare") != std::string::npos || w.find("julian_zzwave") != std::string::npos;
  });
  EXPECT_EQ(named, 2) << allWarnings(flame);  // the list, and transform 0's lost weight below
  EXPECT_TRUE(hasWarningContaining(flame,
                                   "left out: blur_zzsquare, julian_zzwave (or a parameter that voxflame's "
                                   "julian does not have)"))
      << allWarnings(flame);
  EXPECT_FALSE(hasWarningContaining(flame, "zzwave_size")) << allWarnings(flame);
  // Its weight counts: transform 0 keeps 0.1 of 1.
  EXPECT_TRUE(hasWarningContaining(flame, "transform 0 keeps 0.1 of its variation weight 1 without blur_zzsquare"))
      << allWarnings(flame);
}

// A transform's own attributes own no parameters: post_zzstroke_wf (a name the catalogue will never have) beside
// the post-affine `post` is a variation voxflame does not know, named with its weight, not post's parameter
// dropped without a word; its own parameters go with it, and so does color_type beside `color`.
TEST(FlameImport, AnUnknownVariationExtendingATransformAttributeIsNamed) {
  const ImportedFlame flame =
      importFlat(flameFile("<xform weight=\"1\" color=\"0.5\" opacity=\"0\" waves2=\"1\" post_zzstroke_wf=\"1\" "
                           "post_zzstroke_wf_blend=\"0.25\" coefs=\"1 0 0 1 0 0\" post=\"0.12 0 0 1 0 0\"/>\n"
                           "<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"));
  EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"variation post_zzstroke_wf"})) << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "left out: post_zzstroke_wf")) << allWarnings(flame);
  EXPECT_FALSE(hasWarningContaining(flame, "post_zzstroke_wf_blend")) << allWarnings(flame);
}

namespace {

double numberAt(const Scene& scene, const std::string& path, double seconds) {
  for (const KeyframeTrack& track : scene.keyframes)
    if (track.path == path)
      return evaluateTrack(track, seconds, animationDuration(scene), animationLoops(scene)).get<double>();
  ADD_FAILURE() << "no track " << path;
  return std::nan("");
}

}  // namespace

// flam3's <motion>: each element adds amplitude · f(frequency · t) over a loop; the import keys it
// so that the scene moves as flam3's loop does.
TEST(FlameImport, Flam3MotionBecomesLoopingKeyframes) {
  const ImportedFlame flame = importFlat(flameFile(
      "<xform weight=\"1\" color=\"0.5\" julian=\"1\" julian_power=\"3\" coefs=\"0.5 0 0 0.5 0.2 0\">\n"
      "  <motion motion_frequency=\"2\" motion_function=\"sin\" coefs=\"0 0 0 0 0.1 0\" sinusoidal=\"0.5\"/>\n"
      "  <motion motion_frequency=\"1\" motion_function=\"triangle\" color=\"0.8\" julian_dist=\"0.25\"/>\n"
      "</xform>\n"
      "<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 -0.2 0\"/>\n"));
  EXPECT_TRUE(flame.leftOut.empty()) << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "flam3's <motion> became 4 keyframe tracks, a loop of"))
      << allWarnings(flame);
  EXPECT_TRUE(flame.animation.loop);
  const double loop = 128.0 / 30.0;
  EXPECT_NEAR(flame.animation.duration, loop, 1e-12);
  // sinusoidal joined transform 0 at weight 0, to be moved by the motion.
  const FlameXform& x = flame.genome.xforms[0];
  ASSERT_EQ(x.variations.size(), 2u);
  EXPECT_EQ(x.variations[1].name, "sinusoidal");
  EXPECT_EQ(x.variations[1].weight, 0.0);

  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  ASSERT_EQ(scene.keyframes.size(), 4u);
  // At an eighth of the loop sin(2π · 2 · 1/8) = 1; triangle(1/8) = 0.5.
  const double eighth = loop / 8.0;
  EXPECT_NEAR(numberAt(scene, "/layers/0/flame/xforms/0/affine/3", 0.0), 0.2, 1e-9);
  EXPECT_NEAR(numberAt(scene, "/layers/0/flame/xforms/0/affine/3", eighth), 0.3, 1e-9);
  EXPECT_NEAR(numberAt(scene, "/layers/0/flame/xforms/0/variations/1/weight", eighth), 0.5, 1e-9);
  EXPECT_NEAR(numberAt(scene, "/layers/0/flame/xforms/0/variations/0/dist", eighth), 1.0 + 0.125, 1e-9);
  // The colour is held within 0–1: 0.5 + 0.8 · 0.5 = 0.9 at an eighth, 1 (not 1.3) at a quarter.
  EXPECT_NEAR(numberAt(scene, "/layers/0/flame/xforms/0/color", eighth), 0.9, 1e-9);
  EXPECT_NEAR(numberAt(scene, "/layers/0/flame/xforms/0/color", 2 * eighth), 1.0, 1e-9);
  // Two frames differ: the scene at them holds different genomes.
  const Scene first = sceneAtTime(scene, 0.0), later = sceneAtTime(scene, eighth);
  EXPECT_NE(first.layers[0].flame.xforms[0].affine.m[3], later.layers[0].flame.xforms[0].affine.m[3]);
  EXPECT_NE(first.layers[0].flame.xforms[0].variations[1].weight, later.layers[0].flame.xforms[0].variations[1].weight);
  // The preset with its keyframes loads back as saved.
  const std::string saved = sceneToJson(scene);
  EXPECT_EQ(sceneToJson(sceneFromJson(saved, "motion.json")), saved);
}

// Electric Sheep's genomes move their transforms with <motion> (here sinusoidal variations that
// none of the transforms holds): the real file imports with keyframes and nothing left out.
TEST(FlameImport, ElectricSheepMotionImportsAsKeyframes) {
  const std::filesystem::path file = std::filesystem::path(VOXFLAME_TEST_FLAMES) /
                                     "earthbound19__electric_sheep_genomes__electricsheep.247.14508.flam3";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not here";
  FlameImportOptions options;
  options.index = 1;
  const ImportedFlame flame = loadFlameFile(file, options).flame;
  EXPECT_TRUE(std::none_of(flame.leftOut.begin(), flame.leftOut.end(), [](const std::string& s) {
    return s.find("motion") != std::string::npos;
  })) << allWarnings(flame);
  ASSERT_EQ(flame.keyframes.size(), 3u) << allWarnings(flame);
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  const double quarter = animationDuration(scene) / 4.0;
  // Transform 0: sinusoidal 0.5 · sin(2π t): 0.5 at a quarter of the loop.
  EXPECT_NEAR(numberAt(scene, flame.keyframes[0].path, quarter), 0.5, 1e-9) << flame.keyframes[0].path;
  EXPECT_NE(sceneAtTime(scene, 0.0).layers[0].flame, sceneAtTime(scene, quarter).layers[0].flame);
}

// JWildfire's motion curves: points (frame, value) that replace the value, played at the flame's
// fps from frame 1, with their interpolation.
TEST(FlameImport, JwildfireMotionCurvesBecomeKeyframes) {
  const std::string curve =
      "julian_power_enabled=\"true\" julian_power_interpolation=\"LINEAR\" julian_power_point_count=\"3\" "
      "julian_power_x0=\"1\" julian_power_y0=\"2\" julian_power_x1=\"26\" julian_power_y1=\"6\" "
      "julian_power_x2=\"51\" julian_power_y2=\"4\" julian_power_view_xmin=\"0\" "
      "weightCurve_enabled=\"true\" weightCurve_interpolation=\"SPLINE\" weightCurve_point_count=\"2\" "
      "weightCurve_x0=\"1\" weightCurve_y0=\"1\" weightCurve_x1=\"51\" weightCurve_y1=\"3\" "
      "xyCoeff20Curve_enabled=\"true\" xyCoeff20Curve_point_count=\"2\" xyCoeff20Curve_x0=\"1\" "
      "xyCoeff20Curve_y0=\"0\" xyCoeff20Curve_x1=\"26\" xyCoeff20Curve_y1=\"1\" "
      "colorCurve_enabled=\"false\" colorCurve_point_count=\"1\" colorCurve_x0=\"1\" colorCurve_y0=\"0.3\" "
      "spherical_amountCurve_enabled=\"true\" spherical_amountCurve_interpolation=\"LINEAR\" "
      "spherical_amountCurve_point_count=\"2\" spherical_amountCurve_x0=\"1\" spherical_amountCurve_y0=\"0\" "
      "spherical_amountCurve_x1=\"51\" spherical_amountCurve_y1=\"1\"";
  const ImportedFlame flame = importFlat(flameFile(
      "<xform weight=\"1\" color=\"0.5\" julian=\"1\" julian_power=\"2\" spherical=\"0\" coefs=\"0.5 0 0 0.5 0 0\" " +
          curve + "/>\n<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\"/>\n",
      "fps=\"25\" frame_count=\"101\" frame=\"26\""));
  EXPECT_TRUE(flame.leftOut.empty()) << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "JWildfire's motion curves became 4 keyframe tracks")) << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "SPLINE curves are played as Catmull-Rom")) << allWarnings(flame);
  EXPECT_FALSE(flame.animation.loop);
  EXPECT_DOUBLE_EQ(flame.animation.fps, 25.0);
  EXPECT_DOUBLE_EQ(flame.animation.duration, 4.0);  // frame 101
  EXPECT_DOUBLE_EQ(flame.animation.time, 1.0);      // frame 26, the one the file shows
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  const std::string power = "/layers/0/flame/xforms/0/variations/0/power";
  EXPECT_DOUBLE_EQ(numberAt(scene, power, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(numberAt(scene, power, 0.5), 4.0);  // frame 13.5, halfway from 2 to 6
  EXPECT_DOUBLE_EQ(numberAt(scene, power, 1.0), 6.0);
  EXPECT_DOUBLE_EQ(numberAt(scene, power, 3.0), 4.0);  // after the last point, its value
  EXPECT_DOUBLE_EQ(numberAt(scene, "/layers/0/flame/xforms/0/affine/3", 1.0), 1.0);
  EXPECT_DOUBLE_EQ(numberAt(scene, "/layers/0/flame/xforms/0/variations/1/weight", 1.0), 0.5);
  for (const KeyframeTrack& track : scene.keyframes)
    EXPECT_EQ(track.interpolation,
              track.path.find("variations") == std::string::npos ? Interpolation::Smooth : Interpolation::Linear)
        << track.path;  // weightCurve and xyCoeff20Curve are SPLINE (the default), the others LINEAR
  EXPECT_NE(sceneAtTime(scene, 0.0).layers[0].flame, sceneAtTime(scene, 1.0).layers[0].flame);
  const std::string saved = sceneToJson(scene);
  EXPECT_EQ(sceneToJson(sceneFromJson(saved, "curves.json")), saved);
}

// Broken motion is named and left out, never a crash or a refused flame.
TEST(FlameImport, BrokenMotionIsAWarning) {
  const ImportedFlame flame = importFlat(flameFile(
      "<xform weight=\"1\" julian=\"1\" coefs=\"0.5 0 0 0.5 0 0\" julian_power_enabled=\"true\" "
      "julian_power_point_count=\"-3\" julian_dist_enabled=\"true\" julian_dist_point_count=\"2\" julian_dist_x0=\"5\" "
      "julian_dist_y0=\"1\" julian_dist_x1=\"2\" julian_dist_y1=\"1\" julian_zz_enabled=\"true\" "
      "weightCurve_enabled=\"true\" weightCurve_point_count=\"1\" weightCurve_x0=\"1\" weightCurve_y0=\"nan\">\n"
      "  <motion motion_frequency=\"x\" julian=\"1\"/>\n"
      "  <motion motion_frequency=\"1\" motion_function=\"wobble\" coefs=\"1 2 3\" animate=\"1\" julian_power=\"y\"/>\n"
      "</xform>\n"));
  EXPECT_TRUE(flame.keyframes.empty());
  for (const char* text :
       {"point_count is not a whole number", "julian_dist_x1 does not come after the point before it",
        "julian_zz, which voxflame cannot animate", "weightCurve, whose point weightCurve_y0 is not a number",
        "needs motion_frequency", "wobble", "coefs of 3 numbers", "animates animate", "julian_power=\"y\""})
    EXPECT_TRUE(hasWarningContaining(flame, text)) << text << "\n" << allWarnings(flame);
}

// JWildfire's layered files: each visible <layer> is a scene layer with its own transforms and
// palette, weighted as JWildfire weighs it; a layer's weight curve keys that layer's weight.
TEST(FlameImport, JwildfireLayersBecomeSceneLayers) {
  std::string palette = "<palette count=\"2\" format=\"RGB\">FF0000 0000FF</palette>";
  const std::string text =
      "<jwf-flame name=\"two\" fps=\"10\">"
      "<layer weight=\"1\" density=\"1\" visible=\"1\">"
      "<xform weight=\"1\" color=\"0\" spherical=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>" +
      palette +
      "</layer><layer weight=\"2\" density=\"0.5\" visible=\"1\" weightCurve_enabled=\"true\" "
      "weightCurve_interpolation=\"LINEAR\" weightCurve_point_count=\"2\" weightCurve_x0=\"1\" weightCurve_y0=\"2\" "
      "weightCurve_x1=\"11\" weightCurve_y1=\"4\">"
      "<xform weight=\"1\" color=\"1\" julia=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\"/>"
      "<bgxform weight=\"1\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>" +
      palette + "</layer></jwf-flame>";
  const ImportedFlame flame = importFlat(text);
  ASSERT_EQ(flame.otherLayers.size(), 1u);
  EXPECT_DOUBLE_EQ(flame.weight, 1.0);
  EXPECT_DOUBLE_EQ(flame.otherLayers[0].weight, 0.5);  // 2 × density²
  EXPECT_TRUE(hasWarningContaining(flame, "background transforms")) << allWarnings(flame);
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  ASSERT_EQ(scene.layers.size(), 2u);
  EXPECT_EQ(scene.layers[0].flame.xforms[0].variations[0].name, "spherical");
  EXPECT_EQ(scene.layers[1].flame.xforms[0].variations[0].name, "julia");
  EXPECT_EQ(scene.layers[1].transform.fit, FitMode::Previous);
  ASSERT_EQ(scene.keyframes.size(), 1u);
  EXPECT_EQ(scene.keyframes[0].path, "/layers/1/weight");
  EXPECT_DOUBLE_EQ(numberAt(scene, "/layers/1/weight", 0.0), 0.5);
  EXPECT_DOUBLE_EQ(numberAt(scene, "/layers/1/weight", 1.0), 1.0);  // frame 11: 4 × 0.25
  EXPECT_DOUBLE_EQ(sceneAtTime(scene, 0.5).layers[1].weight, 0.75);
}

// The real layered files of the corpus import every visible layer.
TEST(FlameImport, RealJwildfireLayeredFilesImportEveryLayer) {
  const std::filesystem::path file =
      std::filesystem::path(VOXFLAME_TEST_FLAMES) / "thargor6__JWildfireSwan__example208.flame";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not here";
  const ImportedFlame flame = loadFlameFile(file).flame;
  EXPECT_EQ(flame.otherLayers.size(), 2u);
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  EXPECT_EQ(scene.layers.size(), 3u);
  EXPECT_DOUBLE_EQ(scene.layers[1].weight, 0.4);
}

// JWildfire's weighting fields: the variation weights of a transform scale per point by
// 1 + amount · noise(p), p the point after the affine map (or before it: input position).
TEST(FlameImport, WeightingFieldScalesVariationWeightsPerPoint) {
  for (const WeightFieldInput input : {WeightFieldInput::Affine, WeightFieldInput::Position}) {
    PatternLayer layer;
    layer.kind = PatternKind::Flame;
    FlameXform x;
    x.affine.m = {0.5, 0.1, 0, 0.2, -0.1, 0.5, 0, 0.1, 0, 0, 0.5, 0.3};
    x.variations = {{"linear", 1.0, {}}, {"spherical", 0.5, {}}};
    x.fieldKind = WeightFieldKind::Fractal;
    x.fieldInput = input;
    x.fieldAmount = 0.8;
    x.fieldFrequency = 1.7;
    x.fieldSeed = 42;
    layer.flame.xforms = {x};
    const ChaosGame game(layer, "field");
    FlameXform plain = x;
    plain.fieldKind = WeightFieldKind::None;
    layer.flame.xforms = {plain};
    const ChaosGame without(layer, "no field");
    constexpr std::size_t kLanes = 16;
    ChaosLanes lanes, plainLanes;
    lanes.resize(kLanes);
    SplitMix64 rng(3);
    for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
    plainLanes = lanes;
    const std::vector<double> px = lanes.x, py = lanes.y, pz = lanes.z;
    std::vector<double> ox(kLanes), oy(kLanes), oz(kLanes), oc(kLanes), qx(kLanes), qy(kLanes), qz(kLanes), qc(kLanes);
    game.step(lanes, ox.data(), oy.data(), oz.data(), oc.data(), kLanes);
    without.step(plainLanes, qx.data(), qy.data(), qz.data(), qc.data(), kLanes);
    double largest = 0.0;
    for (std::size_t i = 0; i < kLanes; ++i) {
      // Both variations scale alike: the step is the plain step's variation sum times the factor.
      const glm::dvec3 p(px[i], py[i], pz[i]);
      const glm::dvec3 t = x.affine.apply(p);
      const glm::dvec3 at = input == WeightFieldInput::Affine ? t : p;
      const double factor = 1.0 + 0.8 * weightFieldNoise(x, at.x, at.y, at.z);
      EXPECT_NEAR(ox[i], factor * qx[i], 1e-9) << i;
      EXPECT_NEAR(oy[i], factor * qy[i], 1e-9) << i;
      EXPECT_NEAR(oz[i], factor * qz[i], 1e-9) << i;
      largest = std::max(largest, std::abs(factor - 1.0));
    }
    EXPECT_GT(largest, 0.05) << "the noise hardly moved: the test shows nothing";
  }
}

TEST(FlameImport, JwildfireWeightingFieldsAreRead) {
  const ImportedFlame flame = importFlat(flameFile(
      "<xform weight=\"1\" julian=\"1\" coefs=\"0.5 0 0 0.5 0 0\" wfield_type=\"PERLIN_FRACTAL_NOISE\" "
      "wfield_input=\"AFFINE\" wfield_color_intensity=\"0.3\" wfield_var_amount_intensity=\"0.5\" "
      "wfield_var_param1_intensity=\"0.0\" wfield_jitter_intensity=\"0.0\" wfield_noise_seed=\"7\" "
      "wfield_noise_frequency=\"2.5\" wfield_fract_noise_fract_type=\"BILLOW\" wfield_fract_noise_gain=\"0.4\" "
      "wfield_fract_noise_lacunarity=\"2.2\" wfield_fract_noise_octaves=\"4\"/>\n"
      "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" wfield_type=\"IMAGE_MAP\" "
      "wfield_var_amount_intensity=\"1\"/>\n"
      "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" wfield_type=\"SIMPLEX_NOISE\" "
      "wfield_noise_frequency=\"fast\"/>\n"
      "<xform weight=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0\" wfield_type=\"7\" wfield_input=\"1\" "
      "wfield_var_amount=\"0.2\" wfield_scale=\"1.5\" wfield_octaves=\"3\"/>\n"));
  const FlameXform& x = flame.genome.xforms[0];
  EXPECT_EQ(x.fieldKind, WeightFieldKind::Fractal);
  EXPECT_EQ(x.fieldInput, WeightFieldInput::Affine);
  EXPECT_EQ(x.fieldFractal, WeightFieldFractal::Billow);
  EXPECT_DOUBLE_EQ(x.fieldAmount, 0.5);
  EXPECT_DOUBLE_EQ(x.fieldFrequency, 2.5);
  EXPECT_EQ(x.fieldSeed, 7);
  EXPECT_EQ(x.fieldOctaves, 4);
  EXPECT_DOUBLE_EQ(x.fieldGain, 0.4);
  EXPECT_DOUBLE_EQ(x.fieldLacunarity, 2.2);
  EXPECT_EQ(flame.genome.xforms[1].fieldKind, WeightFieldKind::None);  // an image map: not drawn
  EXPECT_EQ(flame.genome.xforms[2].fieldKind, WeightFieldKind::None);  // its frequency is not a number
  // JWildfire's GPU export: ordinals and its own names (7: SIMPLEX_FRACTAL_NOISE, input 1: position).
  const FlameXform& gpu = flame.genome.xforms[3];
  EXPECT_EQ(gpu.fieldKind, WeightFieldKind::Fractal);
  EXPECT_EQ(gpu.fieldInput, WeightFieldInput::Position);
  EXPECT_DOUBLE_EQ(gpu.fieldAmount, 0.2);
  EXPECT_DOUBLE_EQ(gpu.fieldFrequency, 1.5);
  EXPECT_EQ(x.fieldNoise, WeightFieldNoise::Perlin);
  EXPECT_DOUBLE_EQ(x.fieldColor, 0.3);
  EXPECT_EQ(flame.leftOut, (std::vector<std::string>{"JWildfire weighting field"}));
  EXPECT_TRUE(hasWarningContaining(flame, "IMAGE_MAP) of a kind voxflame does not draw")) << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "wfield_noise_frequency=\"fast\"")) << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "PERLIN_FRACTAL_NOISE, SIMPLEX_FRACTAL_NOISE) scale the variation weights"))
      << allWarnings(flame);
  // The preset keeps the field and loads it back; a transform without one writes no field.
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  const std::string saved = sceneToJson(scene);
  const Scene back = sceneFromJson(saved, "field.json");
  EXPECT_EQ(back.layers[0].flame.xforms[0], scene.layers[0].flame.xforms[0]);
  EXPECT_EQ(sceneToJson(back), saved);
  const nlohmann::json document = nlohmann::json::parse(saved);
  EXPECT_EQ(document["layers"][0]["flame"]["xforms"][0]["field"]["kind"], "fractal");
  EXPECT_FALSE(document["layers"][0]["flame"]["xforms"][1].contains("field"));
}

// The one real file with a weighting field: JWildfire's GPU-renderer export (a simplex fractal
// field read at the point's position, which also scales colour and jitters the point).
TEST(FlameImport, RealWeightingFieldFileImportsItsField) {
  const std::filesystem::path file =
      std::filesystem::path(VOXFLAME_TEST_FLAMES) / "thargor6__JWildfire__selftest.flame";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not here";
  const ImportedFlame flame = loadFlameFile(file).flame;
  const auto withField = std::find_if(flame.genome.xforms.begin(), flame.genome.xforms.end(),
                                      [](const FlameXform& x) { return x.hasWeightField(); });
  ASSERT_NE(withField, flame.genome.xforms.end()) << allWarnings(flame);
  EXPECT_EQ(withField->fieldKind, WeightFieldKind::Fractal);
  EXPECT_EQ(withField->fieldInput, WeightFieldInput::Position);
  EXPECT_NEAR(withField->fieldAmount, 0.21416904132907888, 1e-15);
  EXPECT_DOUBLE_EQ(withField->fieldFrequency, 1.468);
  EXPECT_EQ(withField->fieldOctaves, 3);
  // Its colour and jitter intensities are kept too: nothing of the field is left out.
  EXPECT_NEAR(withField->fieldColor, 0.26564915787570376, 1e-15);
  EXPECT_NEAR(withField->fieldJitter, 0.13887944166913668, 1e-15);
  EXPECT_TRUE(std::none_of(flame.leftOut.begin(), flame.leftOut.end(), [](const std::string& what) {
    return what.find("weighting field") != std::string::npos;
  })) << allWarnings(flame);
}

// JWildfire's motion curves of flame values key the paths where the import keeps those values: a
// camPitchCurve (degrees, as JWildfire's Flame holds it) the flat view's camera pitch, a centreXCurve
// its centre, with their interpolation; the centre also moves the frame in the mesh, so that an
// animation plays it; a curve of a value voxflame does not have is named and left out.
TEST(FlameImport, JwildfireFlameCurvesKeyTheViewAndCamera) {
  const std::string curves =
      "version=\"JWildfire V8.00\" fps=\"25\" frame_count=\"51\" center=\"0.5 0\" cam_pitch=\"0\" "
      "camPitchCurve_enabled=\"true\" camPitchCurve_interpolation=\"LINEAR\" camPitchCurve_point_count=\"2\" "
      "camPitchCurve_x0=\"1\" camPitchCurve_y0=\"0\" camPitchCurve_x1=\"51\" camPitchCurve_y1=\"60\" "
      "centreXCurve_enabled=\"true\" centreXCurve_interpolation=\"SPLINE\" centreXCurve_point_count=\"3\" "
      "centreXCurve_x0=\"1\" centreXCurve_y0=\"0.5\" centreXCurve_x1=\"26\" centreXCurve_y1=\"1\" "
      "centreXCurve_x2=\"51\" centreXCurve_y2=\"0.5\" "
      "contrastCurve_enabled=\"true\" contrastCurve_point_count=\"1\" contrastCurve_x0=\"1\" contrastCurve_y0=\"2\"";
  const ImportedFlame flame =
      importFlat(flameFile("<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                           "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0.5\"/>\n",
                           curves));
  EXPECT_EQ(flame.leftOut, std::vector<std::string>{"JWildfire flame motion curve contrastCurve"})
      << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "the flame animates contrastCurve with JWildfire motion curves"))
      << allWarnings(flame);
  EXPECT_TRUE(hasWarningContaining(flame, "JWildfire's motion curves became 2 keyframe tracks")) << allWarnings(flame);
  // The pitch curve turns JWildfire's camera on although the file's own pitch is 0.
  EXPECT_EQ(flame.flat.cameraModel, FlatCameraModel::Jwildfire);
  EXPECT_DOUBLE_EQ(flame.animation.duration, 2.0);  // frame 51 at 25 fps from frame 1
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  const auto track = [&](const std::string& path) {
    const auto found = std::find_if(scene.keyframes.begin(), scene.keyframes.end(),
                                    [&](const KeyframeTrack& t) { return t.path == path; });
    EXPECT_NE(found, scene.keyframes.end()) << path;
    return found == scene.keyframes.end() ? KeyframeTrack{} : *found;
  };
  EXPECT_EQ(track("/flat/camera_pitch").interpolation, Interpolation::Linear);
  EXPECT_EQ(track("/flat/center_x").interpolation, Interpolation::Smooth);
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/camera_pitch", 0.0), 0.0);
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/camera_pitch", 1.0), 30.0);  // frame 26, halfway
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/center_x", 0.0), 0.5);
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/center_x", 1.0), 1.0);  // frame 26, the middle point
  // What `animate` renders: the scene at each frame's time. The flat view moves with the curves,
  // and the flame's place in the mesh follows the centre.
  const Scene first = sceneAtTime(scene, 0.0), middle = sceneAtTime(scene, 1.0);
  EXPECT_DOUBLE_EQ(middle.flat.cameraPitchDeg, 30.0);
  EXPECT_DOUBLE_EQ(middle.flat.centerX, 1.0);
  EXPECT_DOUBLE_EQ(first.layers[0].transform.lockedCenter.x, 0.5);
  EXPECT_DOUBLE_EQ(middle.layers[0].transform.lockedCenter.x, 1.0);
  EXPECT_EQ(middle.layers[0].transform.lockedScale, first.layers[0].transform.lockedScale);
  const std::string saved = sceneToJson(scene);
  EXPECT_EQ(sceneToJson(sceneFromJson(saved, "flame-curves.json")), saved);
}

// pixelsPerUnit and camZoom both make the flat view's scale (pixels per unit × cam_zoom): a curve of
// one keys it with the other's value, and the roll (JWildfire's camRoll, flam3's rotate) turns the
// frame in the mesh as well as in the flat view.
TEST(FlameImport, JwildfireScaleAndRollCurvesMoveTheFrame) {
  const ImportedFlame flame = importFlat(
      flameFile("<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.5 0 0 0.5 0 0\"/>\n"
                "<xform weight=\"1\" color=\"1\" linear=\"1\" coefs=\"0.5 0 0 0.5 0.5 0.5\"/>\n",
                "version=\"JWildfire V8.00\" fps=\"10\" scale=\"40\" cam_zoom=\"2\" rotate=\"0\" "
                "camZoomCurve_enabled=\"true\" camZoomCurve_interpolation=\"LINEAR\" camZoomCurve_point_count=\"2\" "
                "camZoomCurve_x0=\"1\" camZoomCurve_y0=\"2\" camZoomCurve_x1=\"11\" camZoomCurve_y1=\"4\" "
                "camRollCurve_enabled=\"true\" camRollCurve_interpolation=\"LINEAR\" camRollCurve_point_count=\"2\" "
                "camRollCurve_x0=\"1\" camRollCurve_y0=\"0\" camRollCurve_x1=\"11\" camRollCurve_y1=\"90\""));
  EXPECT_TRUE(flame.leftOut.empty()) << allWarnings(flame);
  EXPECT_DOUBLE_EQ(flame.flat.scale, 80.0);
  const Scene scene = sceneFromImportedFlame(flame, defaultScene());
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/scale", 0.0), 80.0);
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/scale", 0.5), 120.0);  // 40 × 3
  EXPECT_DOUBLE_EQ(numberAt(scene, "/flat/rotate", 0.5), 45.0);
  const Scene first = sceneAtTime(scene, 0.0), middle = sceneAtTime(scene, 0.5), last = sceneAtTime(scene, 1.0);
  EXPECT_NEAR(middle.layers[0].transform.lockedScale / first.layers[0].transform.lockedScale, 1.5, 1e-12);
  // The frame in the mesh turns as placing the flame with that roll would turn it.
  for (const Scene* at : {&middle, &last}) {
    ImportedFlame still = flame;
    still.flat.rotateDeg = at->flat.rotateDeg;
    still.keyframes.clear();
    const glm::dvec3 expected = sceneFromImportedFlame(still, defaultScene()).layers[0].transform.rotationDeg;
    const glm::dvec3 turned = at->layers[0].transform.rotationDeg;
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_NEAR(std::remainder(turned[axis] - expected[axis], 360.0), 0.0, 0.05) << axis << " " << at->flat.rotateDeg;
  }
}
