// JWildfire's background transforms (<bgxform>, FlameGenome::backgroundXforms): imported with the layer that
// holds them, kept through the scene's JSON, and painted under the flame by the flat view.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/flame/flat_render.h"
#include "core/flame/xml.h"
#include "core/error.h"
#include "core/scene.h"

using namespace voxflame::core;

namespace {

// A one-layer JWildfire flame, 41 × 31 pixels, whose one transform throws its points far outside the picture,
// with a palette of one colour and the given background transforms.
std::string flameWith(const std::string& background, const std::string& zoom = "1") {
  std::string palette;
  for (int k = 0; k < 256; ++k) palette += "<color index=\"" + std::to_string(k) + "\" rgb=\"128 64 32\"/>";
  return "<jwf-flame name=\"bg\" version=\"JWildfire V8.00\" size=\"41 31\" center=\"0 0\" scale=\"10\" cam_zoom=\"" +
         zoom +
         "\" estimator_radius=\"0\" background=\"0 0 0\"><layer weight=\"1\" visible=\"1\">"
         "<xform weight=\"1\" color=\"0\" linear=\"1\" coefs=\"0.001 0 0 0.001 500 500\"/>" +
         background + palette + "</layer></jwf-flame>";
}

ImageRGBA renderOf(const ImportedFlame& flame) {
  FlatRenderOptions options;
  options.quality = 1.0;
  return renderFlat(sceneFromImportedFlame(flame, Scene{}), options).image;
}

int byteAt(const ImageRGBA& image, int x, int y, int channel) {
  return static_cast<int>(std::lround(image.at(x, y)[channel] * 255.0f));
}

TEST(FlameBackgroundXforms, ImportWithTheirLayerAndTheZoom) {
  const ImportedFlame flame =
      readFlameXml(flameWith("<bgxform weight=\"0.5\" color=\"1\" symmetry=\"-1\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>"
                             "<bgxform weight=\"0.25\" color=\"0\" spherical=\"1\" coefs=\"1 0 0 1 0 0\"/>",
                             "2"),
                   "bg.flame")
          .flame;
  ASSERT_EQ(flame.genome.backgroundXforms.size(), 2u);
  EXPECT_DOUBLE_EQ(flame.genome.backgroundXforms[0].weight, 0.5);
  EXPECT_EQ(flame.genome.backgroundXforms[1].variations.at(0).name, "spherical");
  EXPECT_DOUBLE_EQ(flame.genome.backgroundZoom, 2.0);
  EXPECT_EQ(flame.genome.xforms.size(), 1u);
  // Only the 3D renders' part is left out.
  ASSERT_EQ(flame.leftOut.size(), 1u);
  EXPECT_NE(flame.leftOut[0].find("3D renders"), std::string::npos);

  // Through the scene's JSON and back.
  Scene base;
  base.meshPath = "mesh.obj";
  const Scene scene = sceneFromImportedFlame(flame, base);
  const Scene again = sceneFromJson(sceneToJson(scene), "bg.json");
  EXPECT_EQ(again.layers.at(0).flame, scene.layers.at(0).flame);
  EXPECT_DOUBLE_EQ(again.layers.at(0).flame.backgroundZoom, 2.0);
  // A background transform the JSON spells badly is refused with its place named.
  std::string broken = sceneToJson(scene);
  broken.replace(broken.find("\"background_zoom\": 2.0"), 23, "\"background_zoom\": -1.0");
  EXPECT_THROW(sceneFromJson(broken, "bg.json"), Error);
}

// A background transform of colour 1 with symmetry −1 takes every pixel to colour index 1, the palette's entry
// ⌊254 + ½⌋ = 254, (128, 64, 32) · 200/256 = (100, 50, 25) in JWildfire's render palette, times its weight ½:
// (50, 25, 12.5), truncated to (50, 25, 12) on the black background, everywhere (the flame's points are far away).
TEST(FlameBackgroundXforms, TheFlatViewPaintsThePaletteColourTimesTheWeight) {
  const ImportedFlame flame =
      readFlameXml(
          flameWith("<bgxform weight=\"0.5\" color=\"1\" symmetry=\"-1\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>"),
          "bg.flame")
          .flame;
  const ImageRGBA image = renderOf(flame);
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{20, 15}, std::pair{40, 30}}) {
    EXPECT_EQ(byteAt(image, x, y, 0), 50) << x << "," << y;
    EXPECT_EQ(byteAt(image, x, y, 1), 25);
    EXPECT_EQ(byteAt(image, x, y, 2), 12);
  }
  // Without background transforms the background stays black.
  const ImageRGBA plain = renderOf(readFlameXml(flameWith(""), "plain.flame").flame);
  EXPECT_EQ(byteAt(plain, 20, 15, 0), 0);
}

// colormap_wf with dc_color 0 paints each pixel the default picture's colour at its place: the centre pixel
// (20, 15) of the 41 × 31 picture lies at (0, 0), pixel (127, 127) of the picture, (128, 127, 127), at weight 1.
// The top-left pixel lies at (−20, −15) / 25.5 · 1.41 = (−1.1059, −0.8294), which (scaled by 254 and
// rounded: (−154, −84), tiled to (102, 172)) reads another colour; with cam_zoom 2 it lies half as far out.
TEST(FlameBackgroundXforms, APaintingVariationPaintsEachPixelByItsPlace) {
  const std::string bg =
      "<bgxform weight=\"1\" color=\"0\" colormap_wf=\"1\" colormap_wf_dc_color=\"0\" coefs=\"1 0 0 1 0 0\"/>";
  const ImportedFlame flame = readFlameXml(flameWith(bg), "bg.flame").flame;
  EXPECT_EQ(flame.leftOut.size(), 1u);
  const ImageRGBA image = renderOf(flame);
  EXPECT_EQ(byteAt(image, 20, 15, 0), 128);
  EXPECT_EQ(byteAt(image, 20, 15, 1), 127);
  EXPECT_EQ(byteAt(image, 20, 15, 2), 127);
  const ImageRGBA zoomed = renderOf(readFlameXml(flameWith(bg, "2"), "bg.flame").flame);
  EXPECT_EQ(byteAt(zoomed, 20, 15, 0), 128);
  EXPECT_NE(byteAt(image, 0, 0, 1), byteAt(zoomed, 0, 0, 1));
}

}  // namespace
