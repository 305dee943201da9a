#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "test_support.h"

using namespace voxflame::core;

namespace {

std::string errorOf(const std::string& json) {
  return voxflame::test::presetErrorOf(json);
}

// A version-2 preset with these extra top-level members (text starting with a comma, or empty).
std::string preset(const std::string& extra) {
  return R"({"schema_version":2,"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}])" + extra + "}";
}

std::string withTrack(const std::string& track, const std::string& animation = "") {
  return preset((animation.empty() ? "" : R"(,"animation":)" + animation) + R"(,"keyframes":[)" + track + "]");
}

#define EXPECT_MESSAGE(text, fragment) EXPECT_NE((text).find(fragment), std::string::npos) << (text)

}  // namespace

TEST(Schema, VersionOnePresetLoadsAndSavesAsVersionTwo) {
  const std::string v1 = R"({"schema_version":1,"name":"old","mesh":{"path":"m.obj"},
      "layers":[{"attractor":"lorenz84","params":{"a":1.2}}],"tone":{"gamma":2.0},"seed":7})";
  const Scene scene = sceneFromJson(v1, "old.json");
  EXPECT_EQ(scene.name, "old");
  EXPECT_DOUBLE_EQ(scene.layers[0].params[0], 1.2);
  EXPECT_DOUBLE_EQ(scene.tone.gamma, 2.0);
  EXPECT_EQ(scene.seed, 7u);
  EXPECT_TRUE(scene.keyframes.empty());
  const nlohmann::json saved = nlohmann::json::parse(sceneToJson(scene));
  EXPECT_EQ(saved.at("schema_version"), 2);
  EXPECT_EQ(sceneToJson(sceneFromJson(saved.dump(), "new.json")), sceneToJson(scene));

  // The migration itself is a function on documents, so later versions chain after it.
  const nlohmann::json migrated = migratePreset(nlohmann::json::parse(v1), "old.json");
  EXPECT_EQ(migrated.at("schema_version"), kSchemaVersion);
  EXPECT_EQ(migrated.at("layers"), nlohmann::json::parse(v1).at("layers"));
}

TEST(Schema, VersionsOutsideTheKnownOnesAreRefused) {
  EXPECT_MESSAGE(errorOf(R"({"schema_version":3,"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}]})"),
                 "test.json: 'schema_version' is 3, newer than this voxflame understands (2)");
  EXPECT_MESSAGE(errorOf(R"({"schema_version":"2","mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}]})"),
                 "'schema_version' must be a whole number from 1 to 2");
  EXPECT_MESSAGE(errorOf(R"({"schema_version":0,"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}]})"),
                 "'schema_version' must be a whole number");
  // Keys of a later version in an older document are an error, not silently accepted.
  EXPECT_MESSAGE(errorOf(R"({"schema_version":1,"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],
                             "keyframes":[]})"),
                 "'keyframes' needs schema_version 2");
}

TEST(Schema, ShippedPresetsAreCurrent) {
  std::ifstream in(voxflame::test::sourcePath("presets/default.json"));
  const nlohmann::json document = nlohmann::json::parse(in);
  EXPECT_EQ(document.at("schema_version"), kSchemaVersion);
}

TEST(Schema, EachKindOfErrorNamesFileKeyAndReason) {
  // Unknown key, at the top and deep inside.
  EXPECT_MESSAGE(errorOf(preset(R"(,"colour":1)")), "test.json: 'colour' is not a known key");
  EXPECT_MESSAGE(errorOf(preset(R"(,"animation":{"fsp":30})")), "'animation.fsp' is not a known key");
  // Wrong type.
  EXPECT_MESSAGE(errorOf(preset(R"(,"tone":{"gamma":"high"})")), "'tone.gamma' must be a number");
  EXPECT_MESSAGE(errorOf(preset(R"(,"animation":{"loop":1})")), "'animation.loop' must be true or false");
  EXPECT_MESSAGE(errorOf(preset(R"(,"seed":1.5)")), "'seed' must be a whole number");
  // Out of range, with the range.
  EXPECT_MESSAGE(errorOf(preset(R"(,"tone":{"gamma":50})")), "'tone.gamma' is 50, outside the allowed range [0.1, 10]");
  EXPECT_MESSAGE(errorOf(preset(R"(,"animation":{"fps":0})")), "'animation.fps' is 0, outside the allowed range");
  // NaN and infinity: JSON has neither, and a number too large for a double is refused by the parser.
  EXPECT_MESSAGE(errorOf(preset(R"(,"camera":{"distance":1e999})")), "test.json: not valid JSON");
  EXPECT_MESSAGE(errorOf(preset(R"(,"camera":{"distance":NaN})")), "not valid JSON");
  // Bad colour.
  EXPECT_MESSAGE(errorOf(preset(R"(,"tone":{"background":"#12"})")),
                 "'tone.background' colour '#12' is not of the form");
  // Missing mesh: in the preset, and on disk.
  EXPECT_MESSAGE(errorOf(R"({"layers":[{"attractor":"lorenz84"}]})"), "test.json: 'mesh' is missing");
  EXPECT_MESSAGE(errorOf(R"({"mesh":{"path":""},"layers":[{"attractor":"lorenz84"}]})"),
                 "'mesh.path' must not be empty");
  try {
    loadSceneMesh(sceneFromJson(preset(""), "test.json"));
    ADD_FAILURE() << "a missing mesh file loaded";
  } catch (const Error& e) {
    EXPECT_MESSAGE(std::string(e.what()), "m.obj");
  }
}

TEST(Schema, EachKindOfKeyframeErrorIsNamed) {
  const auto key = [](const std::string& path, const std::string& keys, const std::string& extra = "") {
    return R"({"path":")" + path + R"(",)" + extra + R"("keys":)" + keys + "}";
  };
  const std::string twoKeys = R"([{"time":0,"value":1},{"time":1,"value":2}])";
  // A path that names nothing, a malformed pointer, something that is not a number.
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gama", twoKeys))),
                 "test.json: 'keyframes[0].path' is '/tone/gama', which names no value of the preset");
  EXPECT_MESSAGE(errorOf(withTrack(key("tone/gamma", twoKeys))), "'keyframes[0].path' is 'tone/gamma'; a JSON Pointer");
  EXPECT_MESSAGE(errorOf(withTrack(key("/layers/x/step", twoKeys))), "names no value");
  EXPECT_MESSAGE(errorOf(withTrack(key("/layers/0/attractor", twoKeys))),
                 "only numbers, arrays of numbers and colours");
  EXPECT_MESSAGE(errorOf(withTrack(key("/schema_version", twoKeys))), "names no value");
  // Keys that do not fit the value they animate.
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/background", twoKeys))),
                 "'keyframes[0].keys' hold numbers but '/tone/background' is a colour");
  EXPECT_MESSAGE(errorOf(withTrack(key("/camera/target", R"([{"time":0,"value":[1,2]}])"))),
                 "hold arrays of 2 numbers but '/camera/target' is an array of 3 numbers");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([{"time":0,"value":1},{"time":1,"value":"#ffffff"}])"))),
                 "'keyframes[0].keys[1].value' must be of the same kind");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([{"time":0,"value":true}])"))),
                 "'keyframes[0].keys[0].value' must be a number, an array");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/background", R"([{"time":0,"value":"#gg0000"}])"))),
                 "'keyframes[0].keys[0].value' colour '#gg0000'");
  // Times.
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([{"time":1,"value":1},{"time":1,"value":2}])"))),
                 "'keyframes[0].keys[1].time' is 1, not after the previous key's 1; key times must increase");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([{"time":-1,"value":1}])"))),
                 "'keyframes[0].keys[0].time' is -1");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", twoKeys), R"({"duration":0.5})")),
                 "'keyframes[0].keys[1].time' is 1, after the animation's duration 0.5");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([])"))), "'keyframes[0].keys' must be an array of 1 to");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([{"value":1}])"))), "'keyframes[0].keys[0].time' is missing");
  // Interpolation, unknown keys, duplicate tracks.
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", twoKeys, R"("interpolation":"cubic",)"))),
                 "'keyframes[0].interpolation' is 'cubic'; expected 'linear' or 'smooth'");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", twoKeys, R"("ease":1,)"))),
                 "'keyframes[0].ease' is not a known key");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", twoKeys) + "," + key("/tone/gamma", twoKeys))),
                 "'keyframes[1].path' '/tone/gamma' already has a track");
  // Values out of range, at a key and where a curve overshoots between keys.
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/gamma", R"([{"time":0,"value":2},{"time":1,"value":50}])"))),
                 "test.json: keyframes[0] ('/tone/gamma') at 1 s: 'tone.gamma' is 50, outside the allowed range");
  EXPECT_MESSAGE(errorOf(withTrack(key("/tone/vibrancy", R"([{"time":0,"value":0},{"time":1,"value":1},
                                                             {"time":2,"value":1},{"time":3,"value":0}])"))),
                 "keyframes[0] ('/tone/vibrancy') at 1.125 s: 'tone.vibrancy' is 1.05");
  // The same keys move linearly without overshooting.
  EXPECT_EQ(errorOf(withTrack(key("/tone/vibrancy", R"([{"time":0,"value":0},{"time":1,"value":1},
                                                        {"time":2,"value":1},{"time":3,"value":0}])",
                                  R"("interpolation":"linear",)"))),
            "");
}
