// The picture of an SVG document as JWildfire's svg_wf sees it: the document drawn into an image of
// its own size times a resolution multiplier, and the painted pixels' places. JWildfire draws it
// with the svgSalamander library and Java2D; this is a small rasteriser of the same shapes (path,
// rect, circle, ellipse, line, polyline, polygon, in groups with transforms), their fills and
// strokes, for svg_wf (variations_svg.cpp) and the importer's check of a flame's SVG.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace voxflame::core {

struct SvgRaster {
  int width = 0, height = 0;  // the image, in pixels
  // The painted pixels in row order (row i, then column j), as JWildfire lists them.
  std::vector<std::uint16_t> column, row;
  // What of the document could not be drawn (a parse error, an unknown path command, text, an
  // image too large), each once; empty when nothing was lost.
  std::vector<std::string> problems;
};

// The image is at most kSvgRasterMaxSide pixels a side (a larger one is drawn smaller, said in
// problems), so that no document or multiplier takes unbounded time or memory.
inline constexpr int kSvgRasterMaxSide = 2048;

// `resolution` multiplies the document's size (JWildfire's resolution_multiplier); `antialias`
// counts pixels that a shape only touches, as Java2D's antialiased drawing paints them.
SvgRaster rasteriseSvg(std::string_view document, double resolution, bool antialias);

}  // namespace voxflame::core
