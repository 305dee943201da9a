// JWildfire's subflame variations (subflame_wf, glynns3subfl; variations_subflame.cpp) draw points of
// a whole flame embedded in their text parameter (VariationInfo::textParams). Each embedded flame is
// imported and iterated once, to a cloud of points that every call draws from; these functions let
// the flame import check an embedded flame and decode JWildfire's encoding of it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxflame::core {

struct VariationInfo;

// What becomes of an embedded flame (the text of a subflame term; empty: the variation's default).
struct EmbeddedFlameCheck {
  // Why it cannot be read or iterated (not a flame, no transforms, ...): the term then adds nothing.
  std::string error;
  // What its own import left out (ImportedFlame::leftOut).
  std::vector<std::string> leftOut;
  // It holds subflame terms itself: those are left out of it, so an embedding never recurses.
  bool nested = false;
  // Its chaos game gave no finite point at all (every orbit escapes): the term adds nothing.
  bool escapes = false;
  // A check made while an embedded flame is being imported (one nested in another) is not made:
  // the nested term is left out anyway.
  bool skipped = false;
};

// Imports and iterates `text` (the same cloud the variation draws from, kept for it). Never throws.
EmbeddedFlameCheck checkEmbeddedFlame(std::string_view text);

// Whether `info` is a variation that embeds a flame in its text parameter `flame` (subflame_wf,
// glynns3subfl).
bool embedsFlame(const VariationInfo& info);

// JWildfire writes a variation's text resource as the hexadecimal digits of its bytes. nullopt when
// `value` is not such digits (an odd count, another character).
std::optional<std::string> decodeJwildfireResource(std::string_view value);

}  // namespace voxflame::core
