// The picture of a line of text as JWildfire's text_wf sees it: JWildfire (TextTransformer) draws
// the text with Java2D, not antialiased, centred in an image as large as the text plus the font
// size on every side, and text_wf lists the painted pixels. Here FreeType draws the glyphs of the
// installed font that fontconfig finds for the name (or the one it offers instead, as Java2D falls
// back to another font when the named one is not installed).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace voxflame::core {

struct TextRaster {
  int width = 0, height = 0;  // the image, in pixels
  // The painted pixels in row order (row i, then column j), as JWildfire lists them.
  std::vector<int> column, row;
  std::string fontFamily;  // the family that drew it: the one asked for, or what stood in
  std::string problem;     // why nothing could be drawn (no font at all), else empty
};

// The image is at most kTextRasterMaxSide pixels a side: a larger font size is drawn smaller (the
// variation scales the picture to its own size anyway), so no file takes unbounded time or memory.
inline constexpr int kTextRasterMaxSide = 2048;

// `text` is UTF-8; lines are cut at '\n', each centred, as JWildfire's rows. `fontSize` is in
// pixels (Java's points at 72 dpi); `baseline` moves every line down by that many pixels.
TextRaster rasteriseText(std::string_view text, std::string_view fontName, int fontSize, int baseline);

// The installed family that stands in for `fontName`, or empty when that family itself is
// installed (compared without case), for the importer's word on a font the flame names.
std::string substituteFontFamily(std::string_view fontName);

}  // namespace voxflame::core
