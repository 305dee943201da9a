#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "test_support.h"

using namespace voxflame::core;

namespace {

std::string errorOf(const std::string& json) {
  return voxflame::test::presetErrorOf(json);
}

const char* kMinimal = R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}]})";

}  // namespace

TEST(Scene, DefaultPresetLoadsWithSeedParameters) {
  const Scene scene = defaultScene();
  ASSERT_EQ(scene.layers.size(), 1u);
  const PatternLayer& layer = scene.layers[0];
  EXPECT_EQ(layer.attractor, "lorenz84");
  ASSERT_EQ(layer.params.size(), 4u);
  EXPECT_DOUBLE_EQ(layer.params[0], 1.111);
  EXPECT_DOUBLE_EQ(layer.params[1], 1.479);
  EXPECT_DOUBLE_EQ(layer.params[2], 4.494);
  EXPECT_DOUBLE_EQ(layer.params[3], 0.44);
  EXPECT_DOUBLE_EQ(layer.step, 0.135);
  EXPECT_EQ(layer.integrator, Integrator::Euler);
  EXPECT_TRUE(scene.embedded);
}

TEST(Scene, ShippedDefaultFileEqualsEmbeddedOne) {
  Scene file = loadScene(voxflame::test::sourcePath("presets/default.json"));
  file.embedded = true;  // the same document, read from the binary instead of the folder
  EXPECT_EQ(sceneToJson(file), sceneToJson(defaultScene()));
}

TEST(Scene, MinimalPresetGetsDefaults) {
  const Scene scene = sceneFromJson(kMinimal, "test.json");
  EXPECT_EQ(scene.layers[0].params.size(), 4u);
  EXPECT_EQ(scene.gridResolution, 192);
}

TEST(Scene, AFlameLayerProjectsItsPointsUnlessThePresetSaysOtherwise) {
  // Without `render.method`, a scene with a flame layer takes the points method, any other the
  // volume method; a method the preset names is kept either way, and it is what a saved scene says.
  const std::string flame = R"({"kind":"flame","flame":{"xforms":[{"affine":[0.5,0,0,0, 0,0.5,0,0, 0,0,0.5,0]}]}})";
  const auto load = [](const std::string& layers, const std::string& render) {
    return sceneFromJson(R"({"mesh":{"path":"m.obj"},"layers":[)" + layers + "]" + render + "}", "m.json");
  };
  EXPECT_EQ(load(R"({"attractor":"lorenz84"})", "").render.method, RenderMethod::Volume);
  EXPECT_EQ(load(flame, "").render.method, RenderMethod::Points);
  EXPECT_EQ(load(R"({"attractor":"lorenz84"},)" + flame, "").render.method, RenderMethod::Points);
  EXPECT_EQ(load(flame, R"(,"render":{"method":"volume"})").render.method, RenderMethod::Volume);
  EXPECT_EQ(load(R"({"attractor":"lorenz84"})", R"(,"render":{"method":"points"})").render.method,
            RenderMethod::Points);
  const Scene volumeFlame = load(flame, R"(,"render":{"method":"volume"})");
  EXPECT_EQ(sceneFromJson(sceneToJson(volumeFlame), "again.json").render.method, RenderMethod::Volume);
}

TEST(Scene, SerialisedSceneLoadsBackEqual) {
  const Scene scene = defaultScene();
  const std::string text = sceneToJson(scene);
  const Scene back = sceneFromJson(text, "roundtrip.json");
  EXPECT_EQ(sceneToJson(back), text);
}

TEST(Scene, ErrorsNameTheSourceKeyAndReason) {
  EXPECT_NE(errorOf("{not json").find("not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf("[]").find("must be a JSON object"), std::string::npos);
  EXPECT_NE(errorOf(R"({"layers":[{"attractor":"lorenz84"}]})").find("'mesh' is missing"), std::string::npos);
  const std::string unknown = errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],"colour":1})");
  EXPECT_NE(unknown.find("test.json"), std::string::npos);
  EXPECT_NE(unknown.find("'colour' is not a known key"), std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"nope"}]})").find("unknown attractor 'nope'"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84","params":{"q":1}}]})")
                .find("'layers[0].params.q' is not a known key"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"grid":{"resolution":5000},"layers":[{"attractor":"lorenz84"}]})")
                .find("'grid.resolution' is 5000, outside the allowed range"),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84","step":1e300}]})").find("'layers[0].step'"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84","integrator":"verlet"}]})")
                .find("unknown integrator"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[],"seed":1})").find("'layers'"), std::string::npos);
  EXPECT_NE(errorOf(R"({"schema_version":99,"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}]})")
                .find("newer than this voxflame"),
            std::string::npos);
}

TEST(Scene, BuiltinMeshPathRoundTrips) {
  const Scene scene = sceneFromJson(sceneToJson(defaultScene()), "copy.json");
  EXPECT_TRUE(scene.embedded);
  EXPECT_EQ(scene.meshPath, "meshes/bunny.obj");
}

TEST(Scene, RendererKeysAreReadAndChecked) {
  const Scene scene = sceneFromJson(
      R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],
          "tone":{"gamma_threshold":0.05,"vibrancy":0.5,"highlight_power":1,"contrast":1.2},
          "camera":{"projection":"orthographic","target":[0.1,0,0],"near":1.5,"far":4,"roll_deg":10},
          "render":{"samples":4,"mesh":"silhouette","step":0.25,"lighting":false}})",
      "r.json");
  EXPECT_EQ(scene.camera.projection, Projection::Orthographic);
  EXPECT_DOUBLE_EQ(scene.camera.target.x, 0.1);
  EXPECT_DOUBLE_EQ(scene.camera.nearClip, 1.5);
  EXPECT_EQ(scene.render.samples, 4);
  EXPECT_EQ(scene.render.meshDisplay, MeshDisplay::Silhouette);
  EXPECT_DOUBLE_EQ(scene.tone.vibrancy, 0.5);
  EXPECT_EQ(sceneToJson(sceneFromJson(sceneToJson(scene), "again.json")), sceneToJson(scene));
  EXPECT_NE(
      errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],"camera":{"projection":"fisheye"}})")
          .find("'camera.projection'"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],"camera":{"near":3,"far":2}})")
                .find("'camera.far'"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],"render":{"samples":0}})")
                .find("'render.samples'"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"mesh":{"path":"m.obj"},"layers":[{"attractor":"lorenz84"}],"camera":{"target":[1,2]}})")
                .find("'camera.target'"),
            std::string::npos);
}

TEST(Scene, MissingPresetFileIsNamed) {
  try {
    loadScene("/nonexistent/where.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/where.json"), std::string::npos);
  }
}

TEST(Scene, RelativeMeshResolvesAgainstThePresetFolder) {
  voxflame::test::TemporaryFolder folder;
  std::ofstream(folder / "p.json") << kMinimal;
  const Scene scene = loadScene(folder / "p.json");
  EXPECT_EQ(scene.resolvedMeshPath(), folder.path() / "m.obj");
}

// Mutated presets must give an Error or a valid Scene, never a crash or another exception.
TEST(Scene, FuzzedPresetsNeverCrash) {
  const std::string base = sceneToJson(defaultScene());
  std::uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::size_t>(state >> 33);
  };
  const std::string alphabet = "{}[]\",:0123456789.eE-+ntrufalsx\\#";
  for (int round = 0; round < 3000; ++round) {
    std::string text = base;
    const int edits = 1 + static_cast<int>(next() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = next() % text.size();
      switch (next() % 3) {
        case 0:
          text[at] = alphabet[next() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + next() % 8);
          break;
        default:
          text.insert(at, 1, alphabet[next() % alphabet.size()]);
          break;
      }
      if (text.empty()) text = "{";
    }
    try {
      sceneFromJson(text, "fuzz.json");
    } catch (const Error&) {
    }
  }
}
