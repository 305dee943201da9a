#include "scene.h"

#include <algorithm>

#include "enum_names.h"
#include "error.h"

namespace voxflame::core {

std::filesystem::path Scene::resolvedMeshPath() const {
  const std::filesystem::path mesh(meshPath);
  if (mesh.is_absolute() || embedded) return mesh;
  return baseDirectory / mesh;
}

namespace {

// `name` as an enumerator of the table, or core::Error "is 'NAME'; the known NOUNS are: a, b, c".
template <class Enum>
Enum fromNameOrThrow(std::span<const std::string_view> names, std::string_view name, std::string_view nouns) {
  if (const std::optional<Enum> value = enumFromName<Enum>(names, name)) return *value;
  std::string message = "is '";
  message.append(name).append("'; the known ").append(nouns).append(" are: ").append(joinedNames(names));
  throw Error(message);
}

}  // namespace

std::string_view toString(RenderMethod method) {
  return enumName(kRenderMethodNames, method);
}

RenderMethod defaultRenderMethod(const std::vector<PatternLayer>& layers) {
  const bool flame = std::any_of(layers.begin(), layers.end(),
                                 [](const PatternLayer& layer) { return layer.kind == PatternKind::Flame; });
  return flame ? RenderMethod::Points : RenderMethod::Volume;
}

std::string_view toString(ColorMode mode) {
  return enumName(kColorModeNames, mode);
}

ColorMode colorModeFromString(std::string_view name) {
  return fromNameOrThrow<ColorMode>(kColorModeNames, name, "colour modes");
}

std::string_view toString(PatternKind kind) {
  return enumName(kPatternKindNames, kind);
}

PatternKind patternKindFromString(std::string_view name) {
  return fromNameOrThrow<PatternKind>(kPatternKindNames, name, "kinds");
}

std::string PatternLayer::patternName() const {
  return kind == PatternKind::Attractor ? attractor : std::string(toString(kind));
}

std::string_view toString(FitMode mode) {
  return enumName(kFitModeNames, mode);
}

FitMode fitModeFromString(std::string_view name) {
  return fromNameOrThrow<FitMode>(kFitModeNames, name, "fit modes");
}

}  // namespace voxflame::core
