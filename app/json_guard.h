// A guard for JSON files that the user (or anyone) may have edited: nlohmann::json parses and
// frees any nesting without recursion, but dumping recurses, so a hostile file nested a million
// deep would overflow the stack. Files we write nest a few levels; deeper ones are refused before
// parsing.
#pragma once

#include <algorithm>
#include <string_view>

namespace voxflame::app {

// How deeply arrays and objects nest in `text`, outside strings; stops counting past `limit`.
inline int jsonNestingDepth(std::string_view text, int limit) {
  int depth = 0, deepest = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) return deepest;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace voxflame::app
