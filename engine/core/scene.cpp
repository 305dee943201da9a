#include "scene.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "error.h"
#include "grid.h"

namespace voxflame::core {

using nlohmann::json;

std::filesystem::path Scene::resolvedMeshPath() const {
  const std::filesystem::path mesh(meshPath);
  if (mesh.is_absolute() || embedded) return mesh;
  return baseDirectory / mesh;
}

std::string_view toString(ColorMode mode) {
  switch (mode) {
    case ColorMode::Speed:
      return "speed";
    case ColorMode::Curvature:
      return "curvature";
    case ColorMode::Time:
      return "time";
    case ColorMode::Axis:
      return "axis";
    case ColorMode::Distance:
      return "distance";
  }
  return "speed";
}

ColorMode colorModeFromString(std::string_view name) {
  for (ColorMode mode : {ColorMode::Speed, ColorMode::Curvature, ColorMode::Time, ColorMode::Axis, ColorMode::Distance})
    if (toString(mode) == name) return mode;
  throw Error("is '" + std::string(name) + "'; the known colour modes are: speed, curvature, time, axis, distance");
}

namespace {

// Reads one JSON object strictly: every key read is remembered, and finish() reports any key
// that was not, so misspelt keys are errors. Messages carry the source and the key path.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string source, std::string path)
      : object_(object), source_(std::move(source)), path_(std::move(path)) {
    if (!object_.is_object()) fail(path_.empty() ? "the preset must be a JSON object" : "must be an object");
  }

  [[noreturn]] void fail(const std::string& reason, const std::string& key = "") const {
    const std::string where = key.empty() ? path_ : keyPath(key);
    throw Error(source_ + ": " + (where.empty() ? "" : "'" + where + "' ") + reason);
  }
  std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const std::string& source() const { return source_; }

  const json* find(const std::string& key) {
    seen_.insert(key);
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }

  double number(const std::string& key, double fallback, double min, double max) {
    const json* value = find(key);
    if (!value) return fallback;
    return checkNumber(*value, key, min, max);
  }

  double checkNumber(const json& value, const std::string& key, double min, double max) const {
    if (!value.is_number()) fail("must be a number", key);
    const double v = value.get<double>();
    if (!std::isfinite(v) || v < min || v > max) {
      std::ostringstream range;
      range << "is " << v << ", outside the allowed range [" << min << ", " << max << "]";
      fail(range.str(), key);
    }
    return v;
  }

  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t min, std::int64_t max) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_number_integer()) fail("must be a whole number", key);
    const auto v = value->get<std::int64_t>();
    if (v < min || v > max)
      fail("is " + std::to_string(v) + ", outside the allowed range [" + std::to_string(min) + ", " +
               std::to_string(max) + "]",
           key);
    return v;
  }

  std::string string(const std::string& key, const std::string& fallback) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_string()) fail("must be a string", key);
    return value->get<std::string>();
  }

  std::string requiredString(const std::string& key) {
    if (!object_.contains(key)) fail("is missing", key);
    return string(key, "");
  }

  glm::vec3 color(const std::string& key, glm::vec3 fallback) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_string()) fail("must be a colour string like \"#ff8800\"", key);
    try {
      return parseHexColor(value->get<std::string>());
    } catch (const Error& e) {
      fail(e.what(), key);
    }
  }

  glm::dvec3 vector(const std::string& key, glm::dvec3 fallback, double min, double max) {
    const json* value = find(key);
    if (!value) return fallback;
    if (!value->is_array() || value->size() != 3) fail("must be an array of three numbers", key);
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = checkNumber((*value)[static_cast<std::size_t>(i)], key, min, max);
    return v;
  }

  void finish() const {
    for (auto it = object_.begin(); it != object_.end(); ++it)
      if (!seen_.count(it.key())) fail("is not a known key", it.key());
  }

 private:
  const json& object_;
  std::string source_;
  std::string path_;
  std::set<std::string> seen_;
};

glm::dvec3 readVector(ObjectReader& reader, const std::string& key, glm::dvec3 fallback, double limit) {
  const json* value = reader.find(key);
  if (!value) return fallback;
  if (!value->is_array() || value->size() != 3) reader.fail("must be an array of three numbers", key);
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) v[i] = reader.checkNumber((*value)[static_cast<std::size_t>(i)], key, -limit, limit);
  return v;
}

ColorSettings readColor(ObjectReader& parent, const std::string& key) {
  ColorSettings color;
  color.gradient = {{0.0f, parseHexColor("#2a6cff")}, {1.0f, parseHexColor("#ffb347")}};
  const json* value = parent.find(key);
  if (!value) return color;
  ObjectReader reader(*value, parent.source(), parent.keyPath(key));
  const std::string mode = reader.string("mode", "speed");
  try {
    color.mode = colorModeFromString(mode);
  } catch (const Error& e) {
    reader.fail(e.what(), "mode");
  }
  const json* stops = reader.find("gradient");
  color.palette = reader.string("palette", "");
  if (!color.palette.empty()) {
    if (stops) reader.fail("cannot be given together with 'gradient'; choose one", "palette");
    try {
      color.gradient = paletteStops(color.palette);
    } catch (const Error& e) {
      reader.fail(e.what(), "palette");
    }
  }
  if (stops) {
    const std::string path = reader.keyPath("gradient");
    if (!stops->is_array() || stops->size() < 2 || stops->size() > 64)
      reader.fail("must be an array of 2 to 64 colours like \"#ff8800\"", "gradient");
    color.gradient.clear();
    const std::size_t count = stops->size();
    for (std::size_t i = 0; i < count; ++i) {
      const json& stop = (*stops)[i];
      if (!stop.is_string())
        throw Error(parent.source() + ": '" + path + "[" + std::to_string(i) + "]' must be a colour string");
      try {
        color.gradient.push_back(
            {static_cast<float>(i) / static_cast<float>(count - 1), parseHexColor(stop.get<std::string>())});
      } catch (const Error& e) {
        throw Error(parent.source() + ": '" + path + "[" + std::to_string(i) + "]' " + e.what());
      }
    }
  }
  color.axis = readVector(reader, "axis", color.axis, 1e6);
  if (glm::dot(color.axis, color.axis) < 1e-24) reader.fail("must not be the zero vector", "axis");
  color.period = reader.number("period", color.period, 1.0, 1e9);
  color.scale = reader.number("scale", color.scale, 1e-6, 1e6);
  reader.finish();
  return color;
}

LayerTransform readTransform(ObjectReader& parent, const std::string& key) {
  LayerTransform transform;
  const json* value = parent.find(key);
  if (!value) return transform;
  ObjectReader reader(*value, parent.source(), parent.keyPath(key));
  transform.scale = reader.number("scale", transform.scale, 1e-3, 1e3);
  transform.rotationDeg = readVector(reader, "rotation_deg", transform.rotationDeg, 3600.0);
  transform.offset = readVector(reader, "offset", transform.offset, 100.0);
  if (const json* locked = reader.find("locked_fit")) {
    ObjectReader lockedReader(*locked, parent.source(), reader.keyPath("locked_fit"));
    transform.lockFit = true;
    if (!locked->contains("center")) lockedReader.fail("is missing", "center");
    if (!locked->contains("scale")) lockedReader.fail("is missing", "scale");
    transform.lockedCenter = readVector(lockedReader, "center", transform.lockedCenter, 1e9);
    transform.lockedScale = lockedReader.number("scale", transform.lockedScale, 1e-12, 1e12);
    lockedReader.finish();
  }
  reader.finish();
  return transform;
}

PatternLayer readLayer(const json& value, const std::string& source, const std::string& path) {
  ObjectReader reader(value, source, path);
  PatternLayer layer;
  layer.attractor = reader.requiredString("attractor");
  const AttractorInfo* info = findAttractor(layer.attractor);
  if (!info) {
    try {
      attractorOrThrow(layer.attractor);
    } catch (const Error& e) {
      reader.fail(e.what(), "attractor");
    }
  }
  layer.params = info->defaultParams();
  if (const json* params = reader.find("params")) {
    ObjectReader paramReader(*params, source, reader.keyPath("params"));
    for (std::size_t i = 0; i < info->params.size(); ++i)
      layer.params[i] = paramReader.number(info->params[i].name, info->params[i].defaultValue, -1e6, 1e6);
    paramReader.finish();
  }
  const std::string integrator = reader.string("integrator", std::string(toString(info->defaultIntegrator)));
  try {
    layer.integrator = integratorFromString(integrator);
  } catch (const Error& e) {
    reader.fail(e.what(), "integrator");
  }
  layer.step = reader.number("step", info->defaultStep, 1e-6, 1.0);
  layer.weight = reader.number("weight", 1.0, 0.0, 1000.0);
  layer.color = readColor(reader, "color");
  layer.transform = readTransform(reader, "transform");
  reader.finish();
  return layer;
}

}  // namespace

Scene sceneFromJson(std::string_view text, std::string_view sourceName) {
  const std::string source(sourceName);
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(source + ": not valid JSON (" + e.what() + ")");
  }
  ObjectReader root(document, source, "");
  Scene scene;
  const auto version = root.integer("schema_version", kSchemaVersion, 1, 1'000'000);
  if (version > kSchemaVersion)
    root.fail("is " + std::to_string(version) + ", newer than this voxflame understands (" +
                  std::to_string(kSchemaVersion) + ")",
              "schema_version");
  scene.name = root.string("name", scene.name);

  const json* mesh = root.find("mesh");
  if (!mesh) root.fail("is missing", "mesh");
  {
    ObjectReader meshReader(*mesh, source, "mesh");
    scene.meshPath = meshReader.requiredString("path");
    if (scene.meshPath.empty()) meshReader.fail("must not be empty", "path");
    if (scene.meshPath.rfind(kBuiltinMeshPrefix, 0) == 0) {
      scene.meshPath = scene.meshPath.substr(std::string_view(kBuiltinMeshPrefix).size());
      scene.embedded = true;
      scene.baseDirectory = "presets";
    }
    meshReader.finish();
  }
  if (const json* grid = root.find("grid")) {
    ObjectReader gridReader(*grid, source, "grid");
    scene.gridResolution = static_cast<int>(
        gridReader.integer("resolution", scene.gridResolution, kMinGridResolution, kMaxGridResolution));
    gridReader.finish();
  }

  const json* layers = root.find("layers");
  if (!layers) root.fail("is missing", "layers");
  if (!layers->is_array() || layers->empty() || layers->size() > 16)
    root.fail("must be an array of 1 to 16 pattern layers", "layers");
  for (std::size_t i = 0; i < layers->size(); ++i)
    scene.layers.push_back(readLayer((*layers)[i], source, "layers[" + std::to_string(i) + "]"));

  if (const json* tone = root.find("tone")) {
    ObjectReader toneReader(*tone, source, "tone");
    ToneMapSettings& t = scene.tone;
    t.brightness = toneReader.number("brightness", t.brightness, 0.0, 1000.0);
    t.gamma = toneReader.number("gamma", t.gamma, 0.1, 10.0);
    t.gammaThreshold = toneReader.number("gamma_threshold", t.gammaThreshold, 0.0, 1.0);
    t.vibrancy = toneReader.number("vibrancy", t.vibrancy, 0.0, 1.0);
    t.highlightPower = toneReader.number("highlight_power", t.highlightPower, -1.0, 10.0);
    t.exposure = toneReader.number("exposure", t.exposure, -20.0, 20.0);
    t.contrast = toneReader.number("contrast", t.contrast, 0.0, 10.0);
    t.opacity = toneReader.number("opacity", t.opacity, 0.0, 100.0);
    t.background = toneReader.color("background", t.background);
    toneReader.finish();
  }
  if (const json* camera = root.find("camera")) {
    ObjectReader cameraReader(*camera, source, "camera");
    CameraSettings& c = scene.camera;
    c.azimuthDeg = cameraReader.number("azimuth_deg", c.azimuthDeg, -3600.0, 3600.0);
    c.elevationDeg = cameraReader.number("elevation_deg", c.elevationDeg, -360.0, 360.0);
    c.rollDeg = cameraReader.number("roll_deg", c.rollDeg, -360.0, 360.0);
    c.distance = cameraReader.number("distance", c.distance, 0.01, 1000.0);
    c.fovDeg = cameraReader.number("fov_deg", c.fovDeg, 1.0, 170.0);
    c.orthoHeight = cameraReader.number("ortho_height", c.orthoHeight, 0.001, 1000.0);
    const std::string projection = cameraReader.string("projection", "perspective");
    if (projection == "perspective") {
      c.projection = Projection::Perspective;
    } else if (projection == "orthographic") {
      c.projection = Projection::Orthographic;
    } else {
      cameraReader.fail("is '" + projection + "'; expected 'perspective' or 'orthographic'", "projection");
    }
    c.target = cameraReader.vector("target", c.target, -1000.0, 1000.0);
    c.nearClip = cameraReader.number("near", c.nearClip, 0.0, 1000.0);
    c.farClip = cameraReader.number("far", c.farClip, 0.0, 10000.0);
    if (c.farClip > 0.0 && c.farClip <= c.nearClip) cameraReader.fail("must be larger than 'near'", "far");
    cameraReader.finish();
  }
  if (const json* render = root.find("render")) {
    ObjectReader renderReader(*render, source, "render");
    RenderSettingsDoc& r = scene.render;
    r.stepVoxels = renderReader.number("step", r.stepVoxels, 0.05, 4.0);
    r.samples = static_cast<int>(renderReader.integer("samples", r.samples, 1, 1024));
    const std::string meshDisplay = renderReader.string("mesh", "off");
    if (meshDisplay == "off") {
      r.meshDisplay = MeshDisplay::Off;
    } else if (meshDisplay == "ghost") {
      r.meshDisplay = MeshDisplay::Ghost;
    } else if (meshDisplay == "silhouette") {
      r.meshDisplay = MeshDisplay::Silhouette;
    } else {
      renderReader.fail("is '" + meshDisplay + "'; expected 'off', 'ghost' or 'silhouette'", "mesh");
    }
    r.meshColor = renderReader.color("mesh_color", r.meshColor);
    r.meshStrength = renderReader.number("mesh_strength", r.meshStrength, 0.0, 10.0);
    if (const json* lighting = renderReader.find("lighting")) {
      if (!lighting->is_boolean()) renderReader.fail("must be true or false", "lighting");
      r.lighting = lighting->get<bool>();
    }
    r.lightAzimuthDeg = renderReader.number("light_azimuth_deg", r.lightAzimuthDeg, -3600.0, 3600.0);
    r.lightElevationDeg = renderReader.number("light_elevation_deg", r.lightElevationDeg, -90.0, 90.0);
    r.lightStrength = renderReader.number("light_strength", r.lightStrength, 0.0, 1.0);
    renderReader.finish();
  }
  scene.seed = static_cast<std::uint64_t>(root.integer("seed", 1, 0, std::int64_t{1} << 53));
  scene.points = static_cast<std::uint64_t>(root.integer("points", 20'000'000, 1'000, std::int64_t{1} << 40));
  root.finish();
  return scene;
}

Scene loadScene(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error("preset file '" + path.string() + "' does not exist");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open preset file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene = sceneFromJson(text.str(), path.string());
  // A builtin: mesh lives inside the binary, wherever the preset file is.
  if (!scene.embedded) scene.baseDirectory = path.parent_path();
  return scene;
}

std::string sceneToJson(const Scene& scene) {
  json root;
  root["schema_version"] = kSchemaVersion;
  root["name"] = scene.name;
  root["mesh"] = {{"path", (scene.embedded ? std::string(kBuiltinMeshPrefix) : std::string()) + scene.meshPath}};
  root["grid"] = {{"resolution", scene.gridResolution}};
  json layers = json::array();
  for (const auto& layer : scene.layers) {
    const AttractorInfo& info = attractorOrThrow(layer.attractor);
    json params = json::object();
    for (std::size_t i = 0; i < info.params.size() && i < layer.params.size(); ++i)
      params[info.params[i].name] = layer.params[i];
    json gradient = json::array();
    for (const auto& stop : layer.color.gradient) gradient.push_back(toHexColor(stop.color));
    const auto vector = [](glm::dvec3 v) { return json::array({v.x, v.y, v.z}); };
    json color = {{"mode", std::string(toString(layer.color.mode))}};
    if (layer.color.palette.empty())
      color["gradient"] = gradient;
    else
      color["palette"] = layer.color.palette;
    const ColorSettings defaults;
    if (layer.color.axis != defaults.axis) color["axis"] = vector(layer.color.axis);
    if (layer.color.period != defaults.period) color["period"] = layer.color.period;
    if (layer.color.scale != defaults.scale) color["scale"] = layer.color.scale;
    json entry = {{"attractor", layer.attractor},
                  {"params", params},
                  {"integrator", std::string(toString(layer.integrator))},
                  {"step", layer.step},
                  {"weight", layer.weight},
                  {"color", color}};
    const LayerTransform& t = layer.transform;
    const LayerTransform none;
    if (t.scale != none.scale || t.rotationDeg != none.rotationDeg || t.offset != none.offset || t.lockFit) {
      json transform = {{"scale", t.scale}, {"rotation_deg", vector(t.rotationDeg)}, {"offset", vector(t.offset)}};
      if (t.lockFit) transform["locked_fit"] = {{"center", vector(t.lockedCenter)}, {"scale", t.lockedScale}};
      entry["transform"] = transform;
    }
    layers.push_back(entry);
  }
  root["layers"] = layers;
  const ToneMapSettings& t = scene.tone;
  root["tone"] = {{"brightness", t.brightness},
                  {"gamma", t.gamma},
                  {"gamma_threshold", t.gammaThreshold},
                  {"vibrancy", t.vibrancy},
                  {"highlight_power", t.highlightPower},
                  {"exposure", t.exposure},
                  {"contrast", t.contrast},
                  {"opacity", t.opacity},
                  {"background", toHexColor(t.background)}};
  const CameraSettings& c = scene.camera;
  root["camera"] = {{"azimuth_deg", c.azimuthDeg},
                    {"elevation_deg", c.elevationDeg},
                    {"roll_deg", c.rollDeg},
                    {"distance", c.distance},
                    {"fov_deg", c.fovDeg},
                    {"ortho_height", c.orthoHeight},
                    {"projection", c.projection == Projection::Orthographic ? "orthographic" : "perspective"},
                    {"target", {c.target.x, c.target.y, c.target.z}},
                    {"near", c.nearClip},
                    {"far", c.farClip}};
  const RenderSettingsDoc& r = scene.render;
  const char* meshNames[] = {"off", "ghost", "silhouette"};
  root["render"] = {{"step", r.stepVoxels},
                    {"samples", r.samples},
                    {"mesh", meshNames[static_cast<int>(r.meshDisplay)]},
                    {"mesh_color", toHexColor(r.meshColor)},
                    {"mesh_strength", r.meshStrength},
                    {"lighting", r.lighting},
                    {"light_azimuth_deg", r.lightAzimuthDeg},
                    {"light_elevation_deg", r.lightElevationDeg},
                    {"light_strength", r.lightStrength}};
  root["seed"] = scene.seed;
  root["points"] = scene.points;
  return root.dump(2) + "\n";
}

}  // namespace voxflame::core
