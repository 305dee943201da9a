// The schema tables: every field reads back what was written, every range is enforced by the
// reader and by keyframes alike, the explorer's slider ranges lie inside the allowed ones,
// diff() names what changed, and presets/SCHEMA.md is what the tables generate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/scene_io.h"
#include "core/scene_schema.h"
#include "test_support.h"

using namespace voxflame::core;
using nlohmann::json;

namespace {

// Every kind of layer and every optional block: attractor with a palette, copies and a locked
// fit; a flame with post map, final transform, variations with parameters and symmetry; a
// quaternion Julia set in slice view.
const char* kRich = R"({"schema_version":2,"name":"rich","mesh":{"path":"m.obj"},
  "layers":[
    {"attractor":"lorenz84","params":{"a":1.2},"color":{"palette":"ember"},
     "transform":{"copies":[[0,90,0]],"locked_fit":{"center":[0.1,0.2,0.3],"scale":2}}},
    {"kind":"flame","weight":0.5,"flame":{"xforms":[
       {"weight":1,"affine":[0.5,0,0,0.1,0,0.5,0,0,0,0,0.5,0],"post":[1,0,0,0,0,1,0,0,0,0,1,0.2],
        "variations":[{"name":"linear"},{"name":"julian","weight":0.5}]},
       {"weight":2,"color":1}],
     "final":{"variations":[{"name":"swirl"}]},"symmetry":{"rotational":3,"axis":[0,0,1],"mirror":true}},
     "color":{"gradient":["#000000","#808080","#ffffff"]}},
    {"kind":"quaternion_julia","julia":{"view":"slice","c":[-0.2,0.8,0.1,0]}}]})";

Scene richScene() {
  return sceneFromJson(kRich, "rich.json");
}

std::string errorOf(const std::string& text) {
  return voxflame::test::presetErrorOf(text);
}

std::string slashed(std::string_view key) {
  std::string out(key);
  std::replace(out.begin(), out.end(), '.', '/');
  return out;
}

// One table with where its owner lives in richScene(): the owner, the JSON Pointer of its object
// and the path messages use.
template <class Owner>
struct Place {
  Table<Owner> table;
  std::function<Owner&(Scene&)> owner;
  std::string pointer;  // "/tone"
  std::string message;  // "tone"
  std::string_view skip = {};
};

std::string pointerOf(const std::string& base, std::string_view key) {
  return base + "/" + slashed(key);
}
std::string messageOf(const std::string& base, std::string_view key) {
  return base.empty() ? std::string(key) : base + "." + std::string(key);
}

// Calls `visit` with each table and where it lives.
void forEachPlace(const auto& visit) {
  visit(Place<Scene>{sceneFields(), [](Scene& s) -> Scene& { return s; }, "", ""});
  visit(Place<ToneMapSettings>{toneFields(), [](Scene& s) -> ToneMapSettings& { return s.tone; }, "/tone", "tone"});
  visit(
      Place<CameraSettings>{cameraFields(), [](Scene& s) -> CameraSettings& { return s.camera; }, "/camera", "camera"});
  visit(Place<RenderSettingsDoc>{renderFields(), [](Scene& s) -> RenderSettingsDoc& { return s.render; }, "/render",
                                 "render"});
  visit(Place<PatternLayer>{layerFields(), [](Scene& s) -> PatternLayer& { return s.layers[0]; }, "/layers/0",
                            "layers[0]"});
  visit(Place<ColorSettings>{colorFields(), [](Scene& s) -> ColorSettings& { return s.layers[1].color; },
                             "/layers/1/color", "layers[1].color"});
  visit(Place<LayerTransform>{transformFields(), [](Scene& s) -> LayerTransform& { return s.layers[0].transform; },
                              "/layers/0/transform", "layers[0].transform"});
  visit(Place<LayerTransform>{lockedFitFields(), [](Scene& s) -> LayerTransform& { return s.layers[0].transform; },
                              "/layers/0/transform/locked_fit", "layers[0].transform.locked_fit"});
  visit(Place<FlameXform>{xformFields(), [](Scene& s) -> FlameXform& { return s.layers[1].flame.xforms[0]; },
                          "/layers/1/flame/xforms/0", "layers[1].flame.xforms[0]"});
  visit(Place<FlameXform>{xformFields(), [](Scene& s) -> FlameXform& { return s.layers[1].flame.finalXform; },
                          "/layers/1/flame/final", "layers[1].flame.final", "weight"});
  visit(Place<VariationTerm>{variationFields(),
                             [](Scene& s) -> VariationTerm& { return s.layers[1].flame.xforms[0].variations[1]; },
                             "/layers/1/flame/xforms/0/variations/1", "layers[1].flame.xforms[0].variations[1]"});
  visit(Place<FlameSymmetry>{symmetryFields(), [](Scene& s) -> FlameSymmetry& { return s.layers[1].flame.symmetry; },
                             "/layers/1/flame/symmetry", "layers[1].flame.symmetry"});
  visit(Place<QuaternionJuliaSettings>{juliaFields(),
                                       [](Scene& s) -> QuaternionJuliaSettings& { return s.layers[2].julia; },
                                       "/layers/2/julia", "layers[2].julia"});
  visit(Place<AnimationSettings>{animationFields(), [](Scene& s) -> AnimationSettings& { return s.animation; },
                                 "/animation", "animation"});
}

bool isNumeric(FieldType type) {
  return type == FieldType::Number || type == FieldType::Integer || type == FieldType::Unsigned;
}

// A value in [min, max] other than `current`, whole for whole-number fields.
double otherValue(double min, double max, double current, bool whole) {
  for (double fraction : {0.13, 0.87, 0.5, 0.0, 1.0}) {
    double v = min + (max - min) * fraction;
    if (whole) v = std::round(v);
    if (v != current && v >= min && v <= max) return v;
  }
  return current;
}

// Sets the field in `owner` to a valid value different from its current one.
template <class Owner>
void changeField(Owner& owner, const Field<Owner>& f) {
  std::visit(
      [&]<class M>(const M& member) {
        if constexpr (std::is_same_v<M, double Owner::*>) {
          owner.*member = otherValue(f.min, f.max, owner.*member, false);
        } else if constexpr (std::is_same_v<M, int Owner::*>) {
          owner.*member = static_cast<int>(otherValue(f.min, f.max, owner.*member, true));
        } else if constexpr (std::is_same_v<M, std::uint64_t Owner::*>) {
          owner.*member =
              static_cast<std::uint64_t>(otherValue(f.min, f.max, static_cast<double>(owner.*member), true));
        } else if constexpr (std::is_same_v<M, bool Owner::*>) {
          owner.*member = !(owner.*member);
        } else if constexpr (std::is_same_v<M, std::string Owner::*>) {
          owner.*member += " renamed";
        } else if constexpr (std::is_same_v<M, glm::vec3 Owner::*>) {
          owner.*member = parseHexColor(owner.*member == parseHexColor("#123456") ? "#654321" : "#123456");
        } else if constexpr (std::is_same_v<M, glm::dvec3 Owner::*>) {
          glm::dvec3& v = owner.*member;
          v = glm::dvec3(otherValue(f.min, f.max, v.x, false), otherValue(f.min, f.max, v.y, false) * 0.5,
                         otherValue(f.min, f.max, v.z, false) * 0.25);
        } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
          member.set(owner, (member.get(owner) + 1) % static_cast<int>(member.names.size()));
        }
      },
      f.member);
}

#define EXPECT_MESSAGE(text, fragment) EXPECT_NE((text).find(fragment), std::string::npos) << (text)

}  // namespace

TEST(SchemaTable, EveryFieldRoundTripsThroughBothWriters) {
  int checked = 0;
  forEachPlace([&](const auto& place) {
    for (const auto& f : place.table) {
      if (f.type() == FieldType::Hand || f.key == place.skip) continue;
      Scene scene = richScene();
      auto& owner = place.owner(scene);
      if (!f.presentIn(owner)) continue;
      changeField(owner, f);
      const std::string what = place.message + " " + std::string(f.key);
      // The saved form (defaults left out) and the complete document both read back equal.
      Scene saved;
      ASSERT_NO_THROW(saved = sceneFromJson(sceneToJson(scene), "saved.json")) << what;
      EXPECT_TRUE(saved == scene) << what;
      EXPECT_TRUE(diff(saved, scene).empty()) << what;
      EXPECT_EQ(sceneToJson(saved), sceneToJson(scene)) << what;
      const Scene complete = sceneFromJson(sceneToDocument(scene).dump(), "complete.json");
      EXPECT_TRUE(complete == scene) << what;
      // The change is seen by diff, under the field's path, with the field's class.
      const SceneDiff d = diff(richScene(), scene);
      EXPECT_TRUE(d.touches(pointerOf(place.pointer, f.key))) << what;
      EXPECT_EQ(d.affects, f.affects) << what;
      ++checked;
    }
  });
  EXPECT_GT(checked, 60);
}

TEST(SchemaTable, EveryRangeIsEnforcedByTheReaderAndByKeyframes) {
  int checked = 0;
  forEachPlace([&](const auto& place) {
    for (const auto& f : place.table) {
      if (f.key == place.skip || (!isNumeric(f.type()) && f.type() != FieldType::Vector3)) continue;
      const Scene scene = richScene();
      const std::string pointer = pointerOf(place.pointer, f.key);
      const std::string message = "'" + messageOf(place.message, f.key) + "'";
      const bool whole = f.type() != FieldType::Number && f.type() != FieldType::Vector3;
      for (double bad : {f.max + std::abs(f.max) + 1.0, f.min - std::abs(f.min) - 1.0, 1e300, -1e300}) {
        if (bad <= f.max && bad >= f.min) continue;
        json document = sceneToDocument(scene);
        const json::json_pointer at(f.type() == FieldType::Vector3 ? pointer + "/1" : pointer);
        if (whole && std::abs(bad) < 9e18)
          document[at] = static_cast<std::int64_t>(bad);
        else
          document[at] = bad;
        const std::string error = errorOf(document.dump());
        EXPECT_MESSAGE(error, message);
        EXPECT_MESSAGE(error, whole && std::abs(bad) >= 9e18 ? "must be a whole number" : "outside the allowed range");
        // A keyframe reaching the same value is refused with the same words (the animation
        // settings themselves cannot be animated).
        if (place.pointer == "/animation") continue;
        Scene animated = scene;
        const ValueRef ref = resolveValue(animated, pointer);
        ASSERT_NE(ref.kind, ValueRef::Kind::Missing) << pointer;
        std::vector<double> values(ref.numbers.size(), bad);
        try {
          setNumbers(ref, values, "k");
          ADD_FAILURE() << pointer << " took " << bad;
        } catch (const Error& e) {
          EXPECT_MESSAGE(std::string(e.what()), "k: " + message + " is ");
        }
        EXPECT_TRUE(animated == scene) << "a refused value is not written: " << pointer;
      }
      ++checked;
    }
  });
  EXPECT_GT(checked, 50);
}

TEST(SchemaTable, SliderRangesLieInsideTheAllowedRanges) {
  forEachPlace([&](const auto& place) {
    for (const auto& f : place.table) {
      const std::string what = place.message + " " + std::string(f.key);
      if (!isNumeric(f.type()) && f.type() != FieldType::Vector3) {
        EXPECT_EQ(f.ui.min, f.ui.max) << what << ": only numbers have a slider range";
        continue;
      }
      EXPECT_LT(f.min, f.max) << what;
      if (f.ui.label.empty()) continue;
      EXPECT_LT(f.ui.min, f.ui.max) << what;
      EXPECT_GE(f.ui.min, f.min) << what << ": Ctrl+click on the slider could type a value the reader refuses";
      EXPECT_LE(f.ui.max, f.max) << what << ": Ctrl+click on the slider could type a value the reader refuses";
      if (f.ui.logarithmic) {
        EXPECT_GT(f.ui.min, 0.0) << what;
      }
      // Sliders of whole numbers show whole numbers.
      if (f.type() != FieldType::Number && f.type() != FieldType::Vector3) {
        EXPECT_NE(f.ui.format.find('d'), std::string_view::npos) << what;
      }
    }
  });
}

TEST(SchemaTable, BadValuesOfEveryKeyGiveAnErrorNeverACrash) {
  const json base = sceneToDocument(richScene());
  std::vector<std::string> leaves;
  std::function<void(const json&, const std::string&)> walk = [&](const json& value, const std::string& path) {
    if (value.is_object()) {
      for (auto it = value.begin(); it != value.end(); ++it) walk(it.value(), path + "/" + it.key());
    } else if (value.is_array() && !value.empty() && !value.front().is_number()) {
      for (std::size_t i = 0; i < value.size(); ++i) walk(value[i], path + "/" + std::to_string(i));
    }
    leaves.push_back(path);
  };
  walk(base, "");
  const json bad[] = {"x",    true, nullptr, json::array(),       json::object(), 1e300,
                      -1e300, 0.5,  -1,      json::array({1, 2}), "#zzzzzz"};
  int refused = 0;
  for (const std::string& path : leaves) {
    if (path.empty()) continue;
    for (const json& value : bad) {
      json document = base;
      document[json::json_pointer(path)] = value;
      try {
        sceneFromJson(document.dump(), "bad.json");
      } catch (const Error& e) {
        ++refused;
        EXPECT_MESSAGE(std::string(e.what()), "bad.json: ");
      }
    }
  }
  EXPECT_GT(refused, static_cast<int>(leaves.size()));
}

TEST(SchemaTable, PointersReachEveryAnimatableValueOfTheCompleteDocument) {
  const Scene scene = richScene();
  const json document = sceneToDocument(scene, false);
  const std::vector<std::string> paths = animatablePaths(scene);
  for (const std::string& path : paths) {
    const ValueRef ref = resolveValue(scene, path);
    ASSERT_TRUE(document.contains(json::json_pointer(path))) << path;
    const json& value = document.at(json::json_pointer(path));
    switch (ref.kind) {
      case ValueRef::Kind::Number:
        EXPECT_TRUE(value.is_number()) << path;
        EXPECT_EQ(value.get<double>(), ref.numbers[0].get()) << path;
        break;
      case ValueRef::Kind::Array:
        ASSERT_TRUE(value.is_array() && value.size() == ref.numbers.size()) << path;
        for (std::size_t i = 0; i < ref.numbers.size(); ++i) EXPECT_EQ(value[i].get<double>(), ref.numbers[i].get());
        break;
      case ValueRef::Kind::Color:
        EXPECT_EQ(value, toHexColor(*ref.color)) << path;
        break;
      default:
        ADD_FAILURE() << path << " is " << describe(ref);
    }
  }
  // And every number, array of numbers or colour of the document has its pointer.
  std::size_t found = 0;
  std::function<void(const json&, const std::string&)> walk = [&](const json& value, const std::string& path) {
    const bool numbers = value.is_array() && !value.empty() &&
                         std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_number(); });
    const bool colour = value.is_string() && value.get<std::string>().size() == 7 && value.get<std::string>()[0] == '#';
    if ((value.is_number() || numbers || colour) && path != "/schema_version") {
      EXPECT_NE(std::find(paths.begin(), paths.end(), path), paths.end()) << path;
      ++found;
    }
    if (value.is_object())
      for (auto it = value.begin(); it != value.end(); ++it) walk(it.value(), path + "/" + it.key());
    if (value.is_array() && !numbers)
      for (std::size_t i = 0; i < value.size(); ++i) walk(value[i], path + "/" + std::to_string(i));
  };
  walk(document, "");
  EXPECT_EQ(found, paths.size());
  // Elements of arrays, and what cannot be animated.
  EXPECT_EQ(resolveValue(scene, "/camera/target/2").kind, ValueRef::Kind::Number);
  EXPECT_EQ(resolveValue(scene, "/layers/1/flame/xforms/0/affine/3").kind, ValueRef::Kind::Number);
  EXPECT_EQ(describe(resolveValue(scene, "/layers/0/attractor")), "the text \"lorenz84\"");
  EXPECT_EQ(describe(resolveValue(scene, "/render/lighting")), "true or false");
  EXPECT_EQ(describe(resolveValue(scene, "/render/dof")), "an object");
  EXPECT_EQ(resolveValue(scene, "/layers/0/color/gradient/0").kind, ValueRef::Kind::Missing) << "a palette";
  EXPECT_EQ(resolveValue(scene, "/layers/01/weight").kind, ValueRef::Kind::Missing);
  EXPECT_EQ(resolveValue(scene, "/camera/target/3").kind, ValueRef::Kind::Missing);
  EXPECT_EQ(resolveValue(scene, "/layers/2/flame").kind, ValueRef::Kind::Missing) << "not a flame layer";
}

TEST(SceneDiff, NamesWhatChangedAndWhatItAffects) {
  const Scene base = defaultScene();
  EXPECT_TRUE(diff(base, base).empty());
  EXPECT_FALSE(diff(base, base).pattern());

  const auto changed = [&](const std::function<void(Scene&)>& edit) {
    Scene scene = base;
    edit(scene);
    return diff(base, scene);
  };
  SceneDiff d = changed([](Scene& s) { s.tone.gamma = 3.0; });
  EXPECT_EQ(d.paths, std::vector<std::string>{"/tone/gamma"});
  EXPECT_EQ(d.affects, Affects::Tone);
  EXPECT_TRUE(d.tone() && !d.view() && !d.pattern());

  d = changed([](Scene& s) { s.tone.opacity = 2.0; });  // what a ray sees: the march restarts
  EXPECT_EQ(d.paths, std::vector<std::string>{"/tone/opacity"});
  EXPECT_TRUE(d.view() && !d.pattern() && !d.tone());

  d = changed([](Scene& s) { s.camera.azimuthDeg += 10.0, s.render.dofFocusDistance = 3.0; });
  EXPECT_EQ(d.paths, (std::vector<std::string>{"/camera/azimuth_deg", "/render/dof/focus_distance"}));
  EXPECT_EQ(d.affects, Affects::View | Affects::Still);

  d = changed([](Scene& s) { s.layers[0].params[0] = 1.2, s.seed = 9; });
  EXPECT_EQ(d.paths, (std::vector<std::string>{"/seed", "/layers/0/params/a"}));
  EXPECT_TRUE(d.pattern() && !d.view());
  EXPECT_TRUE(d.touches("/layers/0") && d.touches("/layers/0/params/a") && !d.touches("/layers/0/params/b"));

  d = changed([](Scene& s) { s.layers.push_back(s.layers[0]); });
  EXPECT_EQ(d.paths, std::vector<std::string>{"/layers"});
  EXPECT_TRUE(d.touches("/layers/1/weight"));

  d = changed([](Scene& s) { s.gridResolution = 64; });
  EXPECT_EQ(d.affects, Affects::Pattern | Affects::View);
  d = changed([](Scene& s) { s.baseDirectory = "elsewhere"; });
  EXPECT_EQ(d.paths, std::vector<std::string>{"/mesh/path"});
  EXPECT_TRUE(d.pattern() && d.view());

  // Document-only changes are changes that affect nothing drawn.
  d = changed([](Scene& s) { s.name = "renamed", s.animation.fps = 24.0; });
  EXPECT_EQ(d.paths, (std::vector<std::string>{"/name", "/animation/fps"}));
  EXPECT_EQ(d.affects, Affects::None);
  EXPECT_FALSE(d.empty());
  d = changed([](Scene& s) { s.points = 5000, s.render.method = RenderMethod::Points; });
  EXPECT_EQ(d.affects, Affects::Still);

  // The live view's question: did anything a ray sees change, layers and tone (but opacity) aside.
  d = changed([](Scene& s) { s.layers[0].color.scale = 3.0, s.tone.brightness = 9.0; });
  EXPECT_FALSE(d.view());
  EXPECT_TRUE(d.pattern() && d.tone());
  EXPECT_EQ(toString(d.affects), "pattern, tone");
}

TEST(SceneEquality, ComparesEveryMember) {
  const Scene a = richScene();
  Scene b = a;
  EXPECT_TRUE(a == b);
  b.layers[1].flame.xforms[0].variations[1].params[0] += 1.0;
  EXPECT_FALSE(a == b);
  EXPECT_EQ(diff(a, b).paths, std::vector<std::string>{"/layers/1/flame/xforms/0/variations"});
  b = a;
  b.layers[1].color.gradient[1].position = 0.25f;  // not in the preset, but a different scene
  EXPECT_FALSE(a == b);
  EXPECT_TRUE(diff(a, b).touches("/layers/1/color/gradient"));
  b = a;
  b.embedded = true;
  EXPECT_FALSE(a == b);
  EXPECT_TRUE(sceneFromJson(sceneToJson(a), "again.json") == a);
}

TEST(SchemaDocument, CommittedFileIsWhatTheTablesGenerate) {
  const std::filesystem::path file = voxflame::test::sourcePath("presets/SCHEMA.md");
  const std::string generated = schemaMarkdown();
  const char* update = std::getenv("VOXFLAME_UPDATE_SCHEMA");
  if (update && std::string(update) == "1") {
    std::ofstream(file, std::ios::binary) << generated;
    GTEST_SKIP() << "wrote " << file;
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream committed;
  committed << in.rdbuf();
  EXPECT_TRUE(committed.str() == generated)
      << file << " differs from what the schema tables (engine/core/scene_schema_tables.cpp) and the prose of "
      << "engine/core/scene_schema_doc.cpp generate. Edit those, not the file, then regenerate it:\n"
      << "  VOXFLAME_UPDATE_SCHEMA=1 ctest --test-dir build -R SchemaDocument\n";
  // Every key of the tables is documented.
  forEachPlace([&](const auto& place) {
    for (const auto& f : place.table) EXPECT_NE(generated.find(std::string(f.key) + "` |"), std::string::npos) << f.key;
  });
}
