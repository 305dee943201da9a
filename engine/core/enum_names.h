// Turning the scene's enumerations into the names presets use and back. Each enum has one table
// of names, in the enum's order, next to its definition (kColorModeNames, ...): the preset
// schema's Choice rows read and write through it, and toString and the ...FromString functions
// derive from it, so a name is spelt in one place.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace voxflame::core {

// The name of `value`; the first name for a value outside the table.
template <class Enum>
std::string_view enumName(std::span<const std::string_view> names, Enum value) {
  const auto index = static_cast<std::size_t>(value);
  return index < names.size() ? names[index] : names.front();
}

// The enumerator `name` names, or nothing for a name the table does not have.
template <class Enum>
std::optional<Enum> enumFromName(std::span<const std::string_view> names, std::string_view name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<Enum>(i);
  return std::nullopt;
}

// "'euler' or 'rk4'", "'off', 'ghost' or 'silhouette'": the names as a message offers them.
inline std::string quotedChoices(std::span<const std::string_view> names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += i == 0 ? "" : i + 1 == names.size() ? " or " : ", ";
    text += '\'';
    text += names[i];
    text += '\'';
  }
  return text;
}

// "speed, curvature, time": the names as a list.
inline std::string joinedNames(std::span<const std::string_view> names) {
  std::string text;
  for (std::string_view name : names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

}  // namespace voxflame::core
