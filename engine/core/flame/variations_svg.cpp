// JWildfire's svg_wf: points of an SVG drawing. JWildfire (SVGWFFunc) draws the SVG document given
// as its `svg` resource into an image of the document's size times resolution_multiplier, lists the
// painted pixels, and each call adds one of them at random, centred and scaled by the painted
// area's larger side, then slightly blurred. The drawing is done once per parameter set and shared
// (svg_raster.h draws it); the kernel below only picks pixels.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/flame/svg_raster.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// The picture when a file gives no SVG: a square's outline (JWildfire's own default is an Inkscape
// sketch too long to carry here; every file that uses svg_wf writes its SVG).
constexpr const char* kDefaultSvg =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"100\">"
    "<rect x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\"/></svg>";

// The painted pixels as svg_wf adds them: ((j − xMin) − xSize/2, (i − yMin) − ySize/2) / maxSize.
struct SvgPoints {
  double resolution = 0.0;
  bool antialias = false;
  std::string document;
  std::vector<double> x, y;
};

// JWildfire's extent of the painted pixels, with its quirk kept: it tests j > xMax only when
// j < xMin failed (and likewise for rows), which matters only for the first pixel it sees, so
// that a picture whose first painted pixel lies furthest right or down measures as JWildfire's does.
std::shared_ptr<SvgPoints> buildPoints(double resolution, bool antialias, const std::string& document) {
  auto points = std::make_shared<SvgPoints>();
  points->resolution = resolution;
  points->antialias = antialias;
  points->document = document;
  const SvgRaster raster = rasteriseSvg(document, resolution, antialias);
  int xMin = raster.width - 1, xMax = 0, yMin = raster.height - 1, yMax = 0;
  for (std::size_t k = 0; k < raster.column.size(); ++k) {
    const int j = raster.column[k], i = raster.row[k];
    if (j < xMin)
      xMin = j;
    else if (j > xMax)
      xMax = j;
    if (i < yMin)
      yMin = i;
    else if (i > yMax)
      yMax = i;
  }
  const int xSize = xMax - xMin, ySize = yMax - yMin, maxSize = std::max(xSize, ySize);
  if (maxSize <= 0) return points;
  points->x.reserve(raster.column.size());
  points->y.reserve(raster.column.size());
  for (std::size_t k = 0; k < raster.column.size(); ++k) {
    points->x.push_back(((raster.column[k] - xMin) - xSize / 2.0) / maxSize);
    points->y.push_back(((raster.row[k] - yMin) - ySize / 2.0) / maxSize);
  }
  return points;
}

// The points for these parameters: each thread keeps the last set it used, and a few recent ones
// are kept for all threads (as hopalong keeps its orbits), so a render draws the SVG once.
std::shared_ptr<const SvgPoints> svgPoints(double resolution, bool antialias, const std::string& document) {
  const auto same = [&](const SvgPoints& p) {
    return p.resolution == resolution && p.antialias == antialias && p.document == document;
  };
  thread_local std::shared_ptr<const SvgPoints> last;
  static RecentBuilds<SvgPoints> pictures(4);
  return pictures.get(last, same, [&] { return buildPoints(resolution, antialias, document); });
}

// svg_wf: (s_x X + o_x, s_y Y + o_y) with (X, Y) a painted pixel (Ψ₁ picks it) moved by the blur
// (e^{radius √(−ln(1 − Ψ₂))} − 1) / 1000 along 2πΨ₃ when antialias_radius > 0.01; z carried. As in
// JWildfire the weight does not scale x and y, and with fewer than two painted pixels the result
// is (Ψ₁, Ψ₂). JWildfire draws Ψ₂ in [0, 1) and takes −ln Ψ₂, infinite at 0; 1 − Ψ₂ has the same
// distribution and is never 0. Its colour (the palette's entry nearest to the pixel's colour, or
// the pixel's own with true_color) is not followed: voxflame's variations see no palette.
VOXFLAME_VARIATION_TARGETS void svgWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double blurRadius = P[0];
  // setParameter clamps the multiplier into [0.1, 100]; pre_antialias is an int (Tools.FTOI).
  const double resolution = std::isnan(P[1]) ? 0.1 : std::clamp(P[1], 0.1, 100.0);
  const bool antialias = std::round(P[3]) != 0.0;
  const double scaleX = P[4], scaleY = P[5], offsetX = P[6], offsetY = P[7];
  static const std::string kDefault = kDefaultSvg;
  const std::string& document = in.texts ? in.texts[0] : kDefault;
  const std::shared_ptr<const SvgPoints> points = svgPoints(resolution, antialias, document);
  const std::size_t count = points->x.size();
  const double* __restrict px = points->x.data();
  const double* __restrict py = points->y.data();
  for (std::size_t i = 0; i < n; ++i) {
    if (count > 1) {
      double rawX, rawY;
      pickBlurredPixel(px, py, count, blurRadius, rnd[i], rawX, rawY);
      outX[i] += rawX * scaleX + offsetX;
      outY[i] += rawY * scaleY + offsetY;
    } else {
      outX[i] += laneUniform(rnd[i]);
      outY[i] += laneUniform(rnd[i]);
    }
    outZ[i] += w * z[i];
  }
}

// svg_wf's pixels for a backend of its own: (X, Y) pairs.
std::vector<double> svgTable(const double* params, const std::string* texts) {
  const double resolution = std::isnan(params[1]) ? 0.1 : std::clamp(params[1], 0.1, 100.0);
  const std::shared_ptr<const SvgPoints> points =
      svgPoints(resolution, std::round(params[3]) != 0.0, texts ? texts[0] : std::string(kDefaultSvg));
  std::vector<double> table(2 * points->x.size());
  for (std::size_t k = 0; k < points->x.size(); ++k) {
    table[2 * k] = points->x[k];
    table[2 * k + 1] = points->y[k];
  }
  return table;
}

}  // namespace

void variation_kernels::addSvgVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, kRandom = CatalogueAdder::kRandom;
  add("svg_wf",
      "(scale_x X + offset_x, scale_y Y + offset_y), z: (X, Y) a pixel (Ψ) of the SVG `svg` drawn at "
      "resolution_multiplier times its size (pre_antialias: antialiased), centred and divided by the painted "
      "area's larger side, blurred by (e^{antialias_radius √(−ln Ψ)} − 1)/1000 along 2πΨ when antialias_radius > "
      "0.01; the weight does not scale x and y (JWildfire's); with no picture (Ψ, Ψ)",
      k2D, kRandom, &svgWf,
      {{"antialias_radius", 0.5, 0.0, 2.0},
       {"resolution_multiplier", 2.0, 0.1, 3.0},
       {"true_color", 1.0, 0.0, 1.0},
       {"pre_antialias", 1.0, 0.0, 1.0},
       {"scale_x", 1.0, -2.5, 2.5},
       {"scale_y", 1.0, -2.5, 2.5},
       {"offset_x", 0.0, -2.5, 2.5},
       {"offset_y", 0.0, -2.5, 2.5}});
  catalogue.back().textParams = {{"svg", kDefaultSvg}};
  catalogue.back().table = &svgTable;
}

}  // namespace voxflame::core
