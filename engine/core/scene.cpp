#include "scene.h"

#include "error.h"

namespace voxflame::core {

std::filesystem::path Scene::resolvedMeshPath() const {
  const std::filesystem::path mesh(meshPath);
  if (mesh.is_absolute() || embedded) return mesh;
  return baseDirectory / mesh;
}

std::string_view toString(RenderMethod method) {
  return method == RenderMethod::Points ? "points" : "volume";
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
    case ColorMode::Index:
      return "index";
  }
  return "speed";
}

ColorMode colorModeFromString(std::string_view name) {
  for (ColorMode mode : {ColorMode::Speed, ColorMode::Curvature, ColorMode::Time, ColorMode::Axis, ColorMode::Distance,
                         ColorMode::Index})
    if (toString(mode) == name) return mode;
  throw Error("is '" + std::string(name) +
              "'; the known colour modes are: speed, curvature, time, axis, distance, index");
}

std::string_view toString(PatternKind kind) {
  switch (kind) {
    case PatternKind::Attractor:
      return "attractor";
    case PatternKind::Flame:
      return "flame";
    case PatternKind::QuaternionJulia:
      return "quaternion_julia";
  }
  return "attractor";
}

PatternKind patternKindFromString(std::string_view name) {
  for (PatternKind kind : {PatternKind::Attractor, PatternKind::Flame, PatternKind::QuaternionJulia})
    if (toString(kind) == name) return kind;
  throw Error("is '" + std::string(name) + "'; the known kinds are: attractor, flame, quaternion_julia");
}

std::string PatternLayer::patternName() const {
  return kind == PatternKind::Attractor ? attractor : std::string(toString(kind));
}

std::string_view toString(FitMode mode) {
  switch (mode) {
    case FitMode::Contain:
      return "contain";
    case FitMode::Cover:
      return "cover";
    case FitMode::Stretch:
      return "stretch";
    case FitMode::Previous:
      return "previous";
  }
  return "contain";
}

FitMode fitModeFromString(std::string_view name) {
  for (FitMode mode : {FitMode::Contain, FitMode::Cover, FitMode::Stretch, FitMode::Previous})
    if (toString(mode) == name) return mode;
  throw Error("is '" + std::string(name) + "'; the known fit modes are: contain, cover, stretch, previous");
}

}  // namespace voxflame::core
