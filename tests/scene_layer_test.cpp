#include <gtest/gtest.h>

#include <string>

#include "core/color.h"
#include "core/scene.h"
#include "test_support.h"

using namespace voxflame::core;

namespace {

std::string errorOf(const std::string& json) {
  return voxflame::test::presetErrorOf(json);
}

}  // namespace

TEST(Scene, ColourModesPalettesAndTransformRoundTrip) {
  const std::string text = R"({"mesh":{"path":"m.obj"},"layers":[
    {"attractor":"lorenz84","color":{"mode":"axis","palette":"ember","axis":[1,0,0],"scale":2}},
    {"attractor":"rossler","weight":0.5,"color":{"mode":"time","gradient":["#000000","#ff0000","#ffffff"],"period":500},
     "transform":{"scale":0.8,"rotation_deg":[10,20,30],"offset":[0.1,0,-0.1],"fit":"stretch","copies":[[0,90,0],[180,0,45]],"locked_fit":{"center":[1,2,3],"scale":4.5,"axis_scale":[0.5,1,2]}}}
  ]})";
  const Scene scene = sceneFromJson(text, "t.json");
  ASSERT_EQ(scene.layers.size(), 2u);
  EXPECT_EQ(scene.layers[0].color.mode, ColorMode::Axis);
  EXPECT_EQ(scene.layers[0].color.palette, "ember");
  EXPECT_EQ(scene.layers[0].color.gradient.size(), paletteStops("ember").size());
  EXPECT_EQ(scene.layers[0].color.axis, glm::dvec3(1, 0, 0));
  EXPECT_EQ(scene.layers[1].color.mode, ColorMode::Time);
  EXPECT_EQ(scene.layers[1].color.period, 500.0);
  const LayerTransform& t = scene.layers[1].transform;
  EXPECT_EQ(t.scale, 0.8);
  EXPECT_EQ(t.rotationDeg, glm::dvec3(10, 20, 30));
  EXPECT_TRUE(t.lockFit);
  EXPECT_EQ(t.lockedCenter, glm::dvec3(1, 2, 3));
  EXPECT_EQ(t.lockedScale, 4.5);
  EXPECT_EQ(t.fit, FitMode::Stretch);
  ASSERT_EQ(t.copies.size(), 2u);
  EXPECT_EQ(t.copies[1], glm::dvec3(180, 0, 45));
  EXPECT_EQ(t.lockedAxisScale, glm::dvec3(0.5, 1, 2));
  EXPECT_EQ(scene.layers[0].transform.fit, FitMode::Contain);

  const Scene again = sceneFromJson(sceneToJson(scene), "again.json");
  EXPECT_EQ(sceneToJson(again), sceneToJson(scene));
  EXPECT_EQ(again.layers[1].transform.lockedScale, 4.5);
  EXPECT_EQ(again.layers[1].transform.fit, FitMode::Stretch);
  EXPECT_EQ(again.layers[1].transform.copies, t.copies);
  EXPECT_EQ(again.layers[1].transform.lockedAxisScale, glm::dvec3(0.5, 1, 2));
  EXPECT_EQ(again.layers[0].color.palette, "ember");
  EXPECT_EQ(again.layers[0].color.scale, 2.0);
}

TEST(Scene, BadColourAndTransformValuesAreNamed) {
  const auto layer = [](const std::string& inner) {
    return R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84",)" + inner + "}]}";
  };
  EXPECT_NE(errorOf(layer(R"("color":{"mode":"rainbow"})")).find("layers[0].color.mode"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("color":{"palette":"plaid"})")).find("unknown palette"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("color":{"palette":"ember","gradient":["#000000","#ffffff"]})")).find("together"),
            std::string::npos);
  EXPECT_NE(errorOf(layer(R"("color":{"axis":[0,0,0]})")).find("zero vector"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("color":{"period":0})")).find("color.period"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"scale":-1})")).find("transform.scale"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"rotation_deg":[1,2]})")).find("three numbers"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"locked_fit":{"center":[0,0,0]}})")).find("scale"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"fit":"squeeze"})")).find("'contain', 'cover', 'stretch' or 'previous'"),
            std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"copies":[[0,90]]})")).find("transform.copies[0]"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"copies":[[0,1e9,0]]})")).find("transform.copies[0]"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"copies":{"a":1}})")).find("at most 15"), std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"locked_fit":{"center":[0,0,0],"scale":1,"axis_scale":[1,0,1]}})"))
                .find("axis_scale"),
            std::string::npos);
  EXPECT_NE(errorOf(layer(R"("transform":{"sclae":2})")).find("not a known key"), std::string::npos);
}
