// What the files of the preset schema share and its callers do not need: short names for what a
// change affects (the tables' rows are read more easily with them), splitting a nested key,
// comparing one field of two objects, and escaping a JSON Pointer token.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "scene_schema.h"

namespace voxflame::core::schema_internal {

inline constexpr Affects kPattern = Affects::Pattern;
inline constexpr Affects kView = Affects::View;
inline constexpr Affects kTone = Affects::Tone;
inline constexpr Affects kStill = Affects::Still;
inline constexpr Affects kNothing = Affects::None;

// "dof.aperture" → {"dof", "aperture"}; "gamma" → {"", "gamma"}.
inline std::pair<std::string, std::string> splitKey(std::string_view key) {
  const auto dot = key.find('.');
  if (dot == std::string_view::npos) return {"", std::string(key)};
  return {std::string(key.substr(0, dot)), std::string(key.substr(dot + 1))};
}

template <class Owner>
bool fieldEqual(const Owner& a, const Owner& b, const Field<Owner>& f) {
  return std::visit(
      [&]<class M>(const M& member) {
        if constexpr (std::is_same_v<M, std::monostate>) {
          return true;
        } else if constexpr (std::is_same_v<M, Choice<Owner>>) {
          return member.get(a) == member.get(b);
        } else {
          return a.*member == b.*member;
        }
      },
      f.member);
}

// A key as a JSON Pointer token: '~' becomes "~0" and '/' becomes "~1" (RFC 6901).
std::string escapeToken(std::string_view token);

}  // namespace voxflame::core::schema_internal
