// JWildfire's solid rendering in the flat view: its shading model on synthetic surfaces, a lit
// sphere rendered from a flame, and the import of sld_render_* keys through a preset.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/flame/flat_render.h"
#include "core/flame/flat_solid.h"
#include "core/flame/xml.h"
#include "core/scene.h"
#include "core/scene_schema.h"

using namespace voxflame::core;

namespace {

FlatSolidSettings oneLight(double altitude, double azimuth, double phong = 0.0) {
  FlatSolidSettings solid;
  solid.enabled = true;
  solid.lights = {{altitude, azimuth, 1.0, glm::dvec3(1.0), false, 0.8}};
  solid.materials = {{0.8, 0.2, phong, 16.0, glm::dvec3(1.0), SolidDiffuseResponse::Cosa}};
  return solid;
}

// A hemisphere of radius r pixels (flame units = pixels) bulging towards the viewer, which in
// JWildfire's depth convention is +z (larger depth is nearer), over an empty raster.
SolidRaster hemisphere(int size, double r, double planeDepth = std::nan("")) {
  SolidRaster raster;
  raster.resize(size, size);
  const double c = 0.5 * size;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double dx = x - c, dy = y - c, d2 = dx * dx + dy * dy;
      SolidTexel t;
      if (d2 < r * r) {
        t.depth = static_cast<float>(std::sqrt(r * r - d2));
      } else if (!std::isnan(planeDepth)) {
        // Slightly tilted: JWildfire's occlusion search divides by the normal's x and y.
        t.depth = static_cast<float>(planeDepth + 0.02 * x + 0.01 * y);
      } else {
        continue;
      }
      t.x = static_cast<float>(x);
      t.y = static_cast<float>(y);
      t.z = t.depth;
      t.r = t.g = t.b = 0.5f;
      raster.at(x, y) = t;
    }
  return raster;
}

double brightness(const DensityImage& image, int x0, int y0, int x1, int y1) {
  double sum = 0.0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const float* v = image.at(x, y);
      if (v[3] == 0.0f) continue;
      sum += v[0] + v[1] + v[2];
      ++n;
    }
  return n ? sum / n : 0.0;
}

TEST(FlatSolid, LightDirectionFollowsJwildfire) {
  // Altitude 0, azimuth 0 faces the viewer head-on (−z in JWildfire's normals).
  const glm::dvec3 head = solidLightDirection({0.0, 0.0, 1.0, glm::dvec3(1.0), false, 0.0});
  EXPECT_NEAR(head.z, -1.0, 1e-12);
  const glm::dvec3 side = solidLightDirection({0.0, 90.0, 1.0, glm::dvec3(1.0), false, 0.0});
  EXPECT_NEAR(std::abs(side.x), 1.0, 1e-12);
}

TEST(FlatSolid, SphereIsBrighterOnItsLitSide) {
  // A light low from one side: the half of the sphere facing it is brighter than the other.
  FlatSolidSettings solid = oneLight(0.0, 60.0);
  const glm::dvec3 l = solidLightDirection(solid.lights[0]);
  const SolidRaster raster = hemisphere(64, 28.0);
  const DensityImage shaded = shadeSolidRaster(solid, raster, {}, 1.0, glm::dvec3(0.0));
  const double left = brightness(shaded, 4, 8, 30, 56), right = brightness(shaded, 34, 8, 60, 56);
  ASSERT_GT(left, 0.0);
  ASSERT_GT(right, 0.0);
  // The lit side is the one the light's x points to, with the normals' sign JWildfire gives them.
  const double lit = std::max(left, right), dark = std::min(left, right);
  EXPECT_GT(lit, 1.5 * dark) << "left " << left << " right " << right << " light x " << l.x;
  // Turning the light to the other side swaps them.
  solid.lights[0].azimuthDeg = -60.0;
  const DensityImage mirrored = shadeSolidRaster(solid, raster, {}, 1.0, glm::dvec3(0.0));
  const double left2 = brightness(mirrored, 4, 8, 30, 56), right2 = brightness(mirrored, 34, 8, 60, 56);
  EXPECT_EQ(left > right, right2 > left2);
}

TEST(FlatSolid, PhongAddsAHighlight) {
  const SolidRaster raster = hemisphere(64, 28.0);
  const DensityImage matte = shadeSolidRaster(oneLight(40.0, 20.0, 0.0), raster, {}, 1.0, glm::dvec3(0.0));
  const DensityImage shiny = shadeSolidRaster(oneLight(40.0, 20.0, 1.0), raster, {}, 1.0, glm::dvec3(0.0));
  double most = 0.0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) most = std::max(most, double(shiny.at(x, y)[0] - matte.at(x, y)[0]));
  EXPECT_GT(most, 0.3);  // a white highlight near the mirror direction
  // and nowhere darker
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) ASSERT_GE(shiny.at(x, y)[0], matte.at(x, y)[0] - 1e-6f);
}

TEST(FlatSolid, AmbientOcclusionDarkensWhereTheSphereMeetsThePlane) {
  FlatSolidSettings solid = oneLight(90.0, 0.0);
  solid.materials[0].ambient = 0.8;
  const SolidRaster raster = hemisphere(96, 30.0, 0.0);
  const DensityImage plain = shadeSolidRaster(solid, raster, {}, 1.0, glm::dvec3(0.0));
  solid.aoEnabled = true;
  solid.aoIntensity = 2.0;
  solid.aoSearchRadius = 40.0;
  const DensityImage occluded = shadeSolidRaster(solid, raster, {}, 1.0, glm::dvec3(0.0));
  // The plane just outside the sphere's rim sees the sphere rise above it.
  const double before = brightness(plain, 80, 44, 84, 52), after = brightness(occluded, 80, 44, 84, 52);
  EXPECT_LT(after, before - 0.01) << before << " " << after;
  // Far out on the open plane it changes less.
  const double farBefore = brightness(plain, 0, 0, 4, 4), farAfter = brightness(occluded, 0, 0, 4, 4);
  EXPECT_LT(farBefore - farAfter, before - after);
}

TEST(FlatSolid, ALightWithShadowsShadowsThePlaneBehindTheSphere) {
  // A light 40 degrees to the side: the sphere's shadow falls on the plane on the far side.
  FlatSolidSettings solid = oneLight(0.0, 40.0);
  solid.lights[0].castShadows = true;
  solid.lights[0].shadowIntensity = 1.0;
  solid.shadowType = SolidShadowType::Fast;
  solid.shadowmapSize = 512;
  solid.shadowmapBias = 0.5;
  const SolidRaster raster = hemisphere(96, 24.0, 0.0);
  std::vector<glm::dvec3> points;
  for (const SolidTexel& t : raster.texels) points.emplace_back(t.x, t.y, t.z);
  std::vector<SolidShadowMap> maps = makeSolidShadowMaps(solid, points);
  ASSERT_TRUE(maps[0].active);
  for (const glm::dvec3& p : points) maps[0].deposit(p);
  const DensityImage lit = shadeSolidRaster(solid, raster, {}, 1.0, glm::dvec3(0.0));
  const DensityImage shadowed = shadeSolidRaster(solid, raster, maps, 1.0, glm::dvec3(0.0));
  // Count plane pixels that the shadow darkened.
  int darker = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x)
      if (shadowed.at(x, y)[0] < lit.at(x, y)[0] - 0.05f) ++darker;
  EXPECT_GT(darker, 200);
  EXPECT_LT(darker, 96 * 96 / 2);
}

TEST(FlatSolid, MaterialsBlendBetweenWholeIndices) {
  FlatSolidSettings solid = oneLight(0.0, 0.0);
  solid.materials.push_back({0.1, 0.9, 0.0, 1.0, glm::dvec3(0.0), SolidDiffuseResponse::CosaSquare});
  EXPECT_FALSE(pickSolidMaterial(solid, -0.5).valid);
  EXPECT_EQ(pickSolidMaterial(solid, 1.0).from, solid.materials[1]);
  EXPECT_EQ(pickSolidMaterial(solid, 7.0).from, solid.materials[1]);
  const SolidMaterialPick half = pickSolidMaterial(solid, 0.5);
  EXPECT_EQ(half.from, solid.materials[0]);
  EXPECT_EQ(half.to, solid.materials[1]);
  EXPECT_DOUBLE_EQ(half.blend, 0.5);
}

std::string solidFlame(const std::string& extra) {
  std::string palette = "<palette count=\"256\" format=\"RGB\">\n";
  for (int i = 0; i < 256; ++i) palette += "8080FF";
  palette += "\n</palette>\n";
  return "<flames><flame name=\"s\" version=\"JWildfire V7.50\" size=\"64 64\" center=\"0 0\" scale=\"20\" "
         "sld_render_enabled=\"1\" sld_render_ao_enabled=\"0\" sld_render_shadow_type=\"SMOOTH\" "
         "sld_render_shadow_smooth_radius=\"2.5\" sld_render_material_count=\"2\" "
         "sld_render_material_diffuse0=\"0.6\" sld_render_material_ambient0=\"0.3\" sld_render_material_phong0=\"0.9\" "
         "sld_render_material_phong_size0=\"30\" sld_render_material_phong_red0=\"1\" "
         "sld_render_material_phong_green0=\"0.5\" sld_render_material_phong_blue0=\"0.25\" "
         "sld_render_material_light_diif_func0=\"COSA_HALVE\" sld_render_material_diffuse1=\"0.2\" "
         "sld_render_ligtht_count=\"1\" sld_render_light_altitude0=\"45\" sld_render_light_azimuth0=\"-30\" "
         "sld_render_light_intensity0=\"0.9\" sld_render_light_red0=\"1\" sld_render_light_green0=\"0.9\" "
         "sld_render_light_blue0=\"0.8\" sld_render_light_shadows0=\"1\" sld_render_light_shadow_intensity0=\"0.5\" " +
         extra +
         ">\n<xform weight=\"1\" color=\"0\" coefs=\"1 0 0 1 0 0\" spherical3D=\"1\" material=\"1\" "
         "material_speed=\"0.25\"/>\n" +
         palette + "</flame></flames>\n";
}

TEST(FlatSolid, ImportKeepsTheSolidSettingsThroughAPreset) {
  const ImportedFlame flame = readFlameXml(solidFlame(""), "s.flame", {}).flame;
  const FlatSolidSettings& solid = flame.flat.solid;
  ASSERT_TRUE(solid.enabled);
  EXPECT_FALSE(solid.aoEnabled);
  EXPECT_EQ(solid.shadowType, SolidShadowType::Smooth);
  EXPECT_DOUBLE_EQ(solid.shadowSmoothRadius, 2.5);
  ASSERT_EQ(solid.materials.size(), 2u);
  EXPECT_DOUBLE_EQ(solid.materials[0].phongSize, 30.0);
  EXPECT_EQ(solid.materials[0].phongColor, glm::dvec3(1.0, 0.5, 0.25));
  EXPECT_EQ(solid.materials[0].diffuseResponse, SolidDiffuseResponse::CosaHalve);
  EXPECT_DOUBLE_EQ(solid.materials[1].diffuse, 0.2);
  ASSERT_EQ(solid.lights.size(), 1u);
  EXPECT_DOUBLE_EQ(solid.lights[0].altitudeDeg, 45.0);
  EXPECT_EQ(solid.lights[0].color, glm::dvec3(1.0, 0.9, 0.8));
  EXPECT_TRUE(solid.lights[0].castShadows);
  EXPECT_DOUBLE_EQ(flame.genome.xforms[0].material, 1.0);
  EXPECT_DOUBLE_EQ(flame.genome.xforms[0].materialSpeed, 0.25);
  for (const std::string& lost : flame.leftOut) EXPECT_EQ(lost.find("solid"), std::string::npos) << lost;

  Scene scene = sceneFromImportedFlame(flame, Scene{});
  scene.meshPath = "meshes/bunny.obj";
  scene.embedded = true;
  const nlohmann::json document = sceneDocument(scene, false);
  ASSERT_TRUE(document["flat"].contains("solid"));
  const Scene back = sceneFromDocument(document, "round trip");
  EXPECT_EQ(back.flat.solid, scene.flat.solid);
  EXPECT_EQ(back.layers[0].flame.xforms[0].material, 1.0);
  EXPECT_EQ(back.layers[0].flame.xforms[0].materialSpeed, 0.25);
  // A default scene writes no solid block.
  EXPECT_FALSE(sceneDocument(Scene{}, false).contains("flat"));
}

TEST(FlatSolid, MalformedValuesWarnAndKeepDefaults) {
  const ImportedFlame flame =
      readFlameXml(solidFlame("sld_render_ao_intensity=\"nan\" sld_render_shadowmap_size=\"1e30\" "
                              "sld_render_ao_radius_samples=\"x\""),
                   "s.flame", {})
          .flame;
  std::string all;
  for (const std::string& w : flame.warnings) all += w + "\n";
  EXPECT_NE(all.find("sld_render_ao_intensity=\"nan\" is not a number"), std::string::npos) << all;
  EXPECT_NE(all.find("sld_render_shadowmap_size"), std::string::npos) << all;
  EXPECT_NE(all.find("sld_render_ao_radius_samples"), std::string::npos) << all;
  EXPECT_DOUBLE_EQ(flame.flat.solid.aoIntensity, 0.6);
  EXPECT_EQ(flame.flat.solid.shadowmapSize, 8192);
  EXPECT_EQ(flame.flat.solid.aoRadiusSamples, 6);
  // A preset with a value out of range is refused with the key's path.
  Scene scene = sceneFromImportedFlame(flame, Scene{});
  scene.meshPath = "meshes/bunny.obj";
  scene.embedded = true;
  nlohmann::json document = sceneDocument(scene, false);
  document["flat"]["solid"]["lights"][0]["intensity"] = 1e9;
  try {
    (void)sceneFromDocument(document, "bad");
    FAIL() << "accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("flat.solid.lights[0].intensity"), std::string::npos) << e.what();
  }
}

TEST(FlatSolid, ARenderedSolidFlameIsShaded) {
  // spherical3D draws a shell; lit from one side its two halves differ, and the render differs
  // from the glowing flame's.
  ImportedFlame flame = readFlameXml(solidFlame(""), "s.flame", {}).flame;
  flame.flat.solid.shadowType = SolidShadowType::Off;
  Scene scene = sceneFromImportedFlame(flame, Scene{});
  FlatRenderOptions options;
  options.quality = 40.0;
  const FlatRenderResult solid = renderFlat(scene, options);
  scene.flat.solid.enabled = false;
  const FlatRenderResult glow = renderFlat(scene, options);
  ASSERT_EQ(solid.image.width, glow.image.width);
  double difference = 0.0;
  for (std::size_t i = 0; i < solid.image.pixels.size(); ++i)
    difference += std::abs(solid.image.pixels[i] - glow.image.pixels[i]);
  EXPECT_GT(difference, 10.0);
}

}  // namespace
