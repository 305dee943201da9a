// Files compiled into the binary at build time (the default preset and its mesh), looked up by
// their path relative to the repository root, e.g. "presets/default.json".
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace voxflame::core {

std::optional<std::span<const std::byte>> embeddedFile(std::string_view name);

}  // namespace voxflame::core
