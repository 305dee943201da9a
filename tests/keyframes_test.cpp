#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "core/keyframes.h"
#include "core/scene.h"
#include "core/scene_io.h"

using namespace voxflame::core;

namespace {

// A minimal preset with these keyframes (a JSON array) and animation block.
Scene animatedScene(const std::string& keyframes, const std::string& animation = "{}") {
  return sceneFromJson(R"({"schema_version":2,"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84",
      "color":{"gradient":["#000000","#ffffff"]}}],"animation":)" +
                           animation + R"(,"keyframes":)" + keyframes + "}",
                       "anim.json");
}

double azimuthAt(const Scene& scene, double seconds) {
  return sceneAtTime(scene, seconds).camera.azimuthDeg;
}

}  // namespace

TEST(Keyframes, LinearValuesAtKnownTimes) {
  const Scene scene = animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"linear",
      "keys":[{"time":0,"value":0},{"time":2,"value":10},{"time":3,"value":4}]}])");
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 2.5), 7.0);
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 2.0), 10.0);
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 5.0), 4.0);  // held after the last key
  EXPECT_DOUBLE_EQ(animationDuration(scene), 3.0);
  EXPECT_EQ(animationFrameCount(scene, 10.0), 31);  // open: 0 … 3 s inclusive
}

TEST(Keyframes, CatmullRomValuesAtKnownTimes) {
  // Keys (0, 0), (1, 2), (3, 2). Tangents: one-sided 2 at the first key, (2 - 0) / (3 - 0) at the
  // second, 0 at the last. Hermite at s = 1/2: (p0 + p1) / 2 + h (m0 - m1) / 8.
  const Scene scene = animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"smooth",
      "keys":[{"time":0,"value":0},{"time":1,"value":2},{"time":3,"value":2}]}])");
  EXPECT_NEAR(azimuthAt(scene, 0.5), 1.0 + (2.0 - 2.0 / 3.0) / 8.0, 1e-12);
  EXPECT_NEAR(azimuthAt(scene, 2.0), 2.0 + 2.0 * (2.0 / 3.0) / 8.0, 1e-12);  // overshoots between equal keys
  EXPECT_NEAR(azimuthAt(scene, 1.0), 2.0, 1e-12);
  EXPECT_NEAR(azimuthAt(scene, 0.0), 0.0, 1e-12);
}

TEST(Keyframes, LoopWrapsTimeAndJoinsWithoutAKink) {
  // Key at 2 closes the loop; the periodic keys are (0, 0) and (1, 1) with period 2.
  Scene scene = animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"linear",
      "keys":[{"time":0,"value":0},{"time":1,"value":1},{"time":2,"value":0}]}])",
                              R"({"loop":true,"fps":10})");
  EXPECT_TRUE(animationLoops(scene));
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 2.5), 0.5);
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 1.5), 0.5);
  EXPECT_EQ(animationFrameCount(scene, 10.0), 20);  // frame 20 would be frame 0 again

  // Smooth: the wrapped neighbours make the tangent at time 0 zero here, so s = 1/4 gives h01 = 5/32.
  scene.keyframes[0].interpolation = Interpolation::Smooth;
  EXPECT_NEAR(azimuthAt(scene, 0.25), 5.0 / 32.0, 1e-12);
  EXPECT_NEAR(azimuthAt(scene, 4.25), 5.0 / 32.0, 1e-12);

  // Uneven keys: the slope just before the wrap equals the slope just after it.
  const Scene uneven = animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"smooth",
      "keys":[{"time":0,"value":0},{"time":0.5,"value":10},{"time":1.5,"value":2}]}])",
                                     R"({"loop":true,"duration":2})");
  const double e = 1e-5;
  const double after = (azimuthAt(uneven, e) - azimuthAt(uneven, 0.0)) / e;
  const double before = (azimuthAt(uneven, 2.0) - azimuthAt(uneven, 2.0 - e)) / e;
  EXPECT_NEAR(after, before, 1e-3 * std::abs(after) + 1e-6);
  EXPECT_NEAR(azimuthAt(uneven, 2.0), 0.0, 1e-12);
}

TEST(Keyframes, LoopClosingKeyCarriesATurntableOn) {
  Scene scene = animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"smooth",
      "keys":[{"time":0,"value":0},{"time":4,"value":360}]}])",
                              R"({"loop":true})");
  // Every period continues 360° on, so the Catmull-Rom tangents are 90°/s everywhere: a straight line.
  EXPECT_NEAR(azimuthAt(scene, 1.0), 90.0, 1e-9);
  EXPECT_NEAR(azimuthAt(scene, 3.0), 270.0, 1e-9);
  EXPECT_NEAR(azimuthAt(scene, 5.0), 90.0, 1e-9);
  scene.keyframes[0].interpolation = Interpolation::Linear;
  EXPECT_NEAR(azimuthAt(scene, 2.0), 180.0, 1e-9);
  EXPECT_EQ(animationFrameCount(scene, 30.0), 120);
}

TEST(Keyframes, ColoursInterpolateInOklab) {
  const Scene scene = animatedScene(R"([{"path":"/tone/background","interpolation":"linear",
      "keys":[{"time":0,"value":"#000000"},{"time":1,"value":"#ffffff"}]},
      {"path":"/layers/0/color/gradient/1","interpolation":"linear",
      "keys":[{"time":0,"value":"#ffffff"},{"time":1,"value":"#ff0000"}]}])");
  // OKLab L = 1/2 with a = b = 0 is linear grey 1/8, sRGB 0.3886 → 99 = 0x63.
  EXPECT_EQ(toHexColor(sceneAtTime(scene, 0.5).tone.background), "#636363");
  EXPECT_EQ(toHexColor(sceneAtTime(scene, 0.0).tone.background), "#000000");
  EXPECT_EQ(toHexColor(sceneAtTime(scene, 1.0).layers[0].color.gradient[1].color), "#ff0000");
}

TEST(Keyframes, VectorsParametersAndWholeNumbers) {
  const Scene scene = animatedScene(R"([{"path":"/camera/target","interpolation":"linear",
      "keys":[{"time":0,"value":[0,0,0]},{"time":1,"value":[1,2,3]}]},
      {"path":"/layers/0/params/a","interpolation":"linear","keys":[{"time":0,"value":1.0},{"time":1,"value":1.2}]},
      {"path":"/grid/resolution","interpolation":"linear","keys":[{"time":0,"value":64},{"time":1,"value":65}]}])");
  const Scene quarter = sceneAtTime(scene, 0.25);
  EXPECT_DOUBLE_EQ(quarter.camera.target.x, 0.25);
  EXPECT_DOUBLE_EQ(quarter.camera.target.y, 0.5);
  EXPECT_DOUBLE_EQ(quarter.camera.target.z, 0.75);
  EXPECT_DOUBLE_EQ(quarter.layers[0].params[0], 1.05);
  EXPECT_EQ(quarter.gridResolution, 64);
  EXPECT_EQ(sceneAtTime(scene, 0.75).gridResolution, 65);
  // The result keeps its keyframes: evaluating it again at another time is evaluating the original.
  EXPECT_EQ(sceneToJson(sceneAtTime(quarter, 0.6)), sceneToJson(sceneAtTime(scene, 0.6)));
  EXPECT_DOUBLE_EQ(quarter.animation.time, 0.25);
}

TEST(Keyframes, RoundTripThroughJson) {
  const Scene scene = animatedScene(R"([{"path":"/tone/background","interpolation":"linear",
      "keys":[{"time":0,"value":"#102030"},{"time":1.5,"value":"#ffffff"}]},
      {"path":"/camera/target","keys":[{"time":0,"value":[0,0,0]}]}])",
                                    R"({"duration":4,"fps":24,"loop":true,"time":1})");
  const std::string text = sceneToJson(scene);
  const Scene back = sceneFromJson(text, "back.json");
  EXPECT_EQ(sceneToJson(back), text);
  ASSERT_EQ(back.keyframes.size(), 2u);
  EXPECT_EQ(back.keyframes[0].interpolation, Interpolation::Linear);
  EXPECT_EQ(back.keyframes[1].interpolation, Interpolation::Smooth);
  EXPECT_EQ(back.keyframes[1].kind, KeyKind::Array);
  EXPECT_DOUBLE_EQ(back.animation.fps, 24.0);
  EXPECT_DOUBLE_EQ(animationDuration(back), 4.0);
  EXPECT_NE(text.find("\"#102030\""), std::string::npos);
}

TEST(Keyframes, WithKeyframeAtAddsAndReplacesKeys) {
  const Scene animated = animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"linear",
      "keys":[{"time":0,"value":0},{"time":2,"value":90}]}])");
  Scene edited = sceneAtTime(animated, 1.0);
  edited.camera.azimuthDeg = 10.0;
  edited.tone.brightness = 6.0;
  edited.layers[0].color.gradient[1].color = parseHexColor("#ff8800");
  edited.camera.target = glm::dvec3(0.5, 0.0, 0.0);
  const Scene keyed = withKeyframeAt(animated, edited, 1.0);

  ASSERT_EQ(keyed.keyframes.size(), 4u);
  const KeyframeTrack& azimuth = keyed.keyframes[0];
  EXPECT_EQ(azimuth.path, "/camera/azimuth_deg");
  ASSERT_EQ(azimuth.keys.size(), 3u);
  EXPECT_DOUBLE_EQ(azimuth.keys[1].time, 1.0);
  EXPECT_DOUBLE_EQ(azimuth.keys[1].values[0], 10.0);
  EXPECT_DOUBLE_EQ(azimuthAt(keyed, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(azimuthAt(keyed, 2.0), 90.0);

  std::set<std::string> paths;
  for (const auto& track : keyed.keyframes) paths.insert(track.path);
  EXPECT_TRUE(paths.count("/tone/brightness"));
  EXPECT_TRUE(paths.count("/layers/0/color/gradient/1"));
  EXPECT_TRUE(paths.count("/camera/target"));
  const Scene atOne = sceneAtTime(keyed, 1.0);
  EXPECT_DOUBLE_EQ(atOne.tone.brightness, 6.0);
  EXPECT_EQ(toHexColor(atOne.layers[0].color.gradient[1].color), "#ff8800");
  EXPECT_DOUBLE_EQ(atOne.camera.target.x, 0.5);

  // Keying the same time again replaces the key instead of adding one.
  Scene again = sceneAtTime(keyed, 1.0);
  again.camera.azimuthDeg = 20.0;
  const Scene rekeyed = withKeyframeAt(keyed, again, 1.0);
  EXPECT_EQ(rekeyed.keyframes[0].keys.size(), 3u);
  EXPECT_DOUBLE_EQ(azimuthAt(rekeyed, 1.0), 20.0);
  EXPECT_EQ(rekeyed.keyframes.size(), 4u);

  // A track whose value is gone is an error, not a silent loss.
  Scene palette = sceneAtTime(keyed, 1.0);
  palette.layers[0].color.palette = "ember";
  palette.layers[0].color.gradient = paletteStops("ember");
  EXPECT_THROW(withKeyframeAt(keyed, palette, 1.0), Error);
}

TEST(Keyframes, DefaultSceneWithoutKeyframesIsAStill) {
  const Scene scene = defaultScene();
  EXPECT_DOUBLE_EQ(animationDuration(scene), 0.0);
  EXPECT_EQ(animationFrameCount(scene, 30.0), 1);
  EXPECT_EQ(sceneToJson(sceneAtTime(scene, 0.0)), sceneToJson(scene));
}

// Found while fuzzing the preset reader, by a hand-made input larger than the fuzzer's (its 32 kB
// inputs hold about 1300 keys, a few seconds under ASan): the load-time check evaluates a track at
// every key, and every evaluation laid all the keys out again, so loading was quadratic in the
// keys: 5000 took a minute, the 100 000 a track may hold hours.
TEST(Keyframes, TracksOfManyKeysLoadInLinearTime) {
  constexpr std::size_t kKeys = kMaxKeyframes;
  std::string keys;
  for (std::size_t i = 0; i < kKeys; ++i)
    keys += (i == 0 ? "" : ",") + std::string(R"({"time":)") + std::to_string(i) + R"(,"value":)" +
            std::to_string(i % 360) + "}";
  const Scene scene =
      animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"linear","keys":[)" + keys + "]}]");
  ASSERT_EQ(scene.keyframes.front().keys.size(), kKeys);
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 1000.5), 280.5);
  EXPECT_DOUBLE_EQ(azimuthAt(scene, 1e9), static_cast<double>((kKeys - 1) % 360));
  // Smooth tracks evaluate through the same laid-out keys; their overshoot is still checked.
  const Scene smooth =
      animatedScene(R"([{"path":"/camera/azimuth_deg","interpolation":"smooth","keys":[)" + keys + "]}]");
  EXPECT_DOUBLE_EQ(azimuthAt(smooth, 1000.0), 280.0);
}
