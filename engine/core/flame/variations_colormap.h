// JWildfire's colormap_wf (variations_colormap.cpp): what the importer asks of its inlined picture.
#pragma once

#include <cstdint>
#include <string>

namespace voxflame::core {

// The most pixels an inlined picture may have (JWildfire's pictures are photographs, a few million at most).
inline constexpr std::uint64_t kMaxColormapPixels = std::uint64_t{1} << 24;

// Why colormap_wf cannot draw the picture its inlined_image text holds (the hex of a file's bytes), or empty
// when it can (an empty text: the default picture).
std::string colormapPictureProblem(const std::string& inlinedHex);

}  // namespace voxflame::core
