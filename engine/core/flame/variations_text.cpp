// JWildfire's text_wf: points of a line of text. JWildfire (TextWFFunc) draws its `text` resource
// in the font `font_name` at font_size pixels into an image as large as the text plus the font size
// on every side, lists the painted pixels, and each call adds one of them at random, centred and
// divided by the image's width and height, then slightly blurred. The drawing is done once per
// parameter set and shared (text_raster.h draws it); the kernel below only picks pixels.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/flame/text_raster.h"
#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// JWildfire's defaults: its own name, in Arial.
constexpr const char* kDefaultText = "JWildfire";
constexpr const char* kDefaultFont = "Arial";
// JWildfire's DFLT_SCALE: the unit picture is drawn three units wide.
constexpr double kTextScale = 3.0;

// The painted pixels as text_wf adds them: ((j − w/2) / w, (i − h/2) / h), w × h the image.
struct TextPoints {
  std::string text, font;
  int size = 0, baseline = 0;
  std::vector<double> x, y;
};

std::shared_ptr<TextPoints> buildPoints(const std::string& text, const std::string& font, int size, int baseline) {
  auto points = std::make_shared<TextPoints>();
  points->text = text;
  points->font = font;
  points->size = size;
  points->baseline = baseline;
  const TextRaster raster = rasteriseText(text, font, size, baseline);
  const double w = raster.width, h = raster.height;
  points->x.reserve(raster.column.size());
  points->y.reserve(raster.column.size());
  for (std::size_t k = 0; k < raster.column.size(); ++k) {
    points->x.push_back((raster.column[k] - w / 2.0) / w);
    points->y.push_back((raster.row[k] - h / 2.0) / h);
  }
  return points;
}

// The points for these parameters: each thread keeps the last set it used, and a few recent ones
// are kept for all threads, so a render draws the text once.
std::shared_ptr<const TextPoints> textPoints(const std::string& text, const std::string& font, int size, int baseline) {
  const auto same = [&](const TextPoints& p) {
    return p.size == size && p.baseline == baseline && p.text == text && p.font == font;
  };
  thread_local std::shared_ptr<const TextPoints> last;
  static RecentBuilds<TextPoints> pictures(4);
  return pictures.get(last, same, [&] { return buildPoints(text, font, size, baseline); });
}

// Tools.FTOI of a parameter, held where Java's int (and the raster's size cap) leave it meaningful.
int wholePixels(double value, int low, int high) {
  return std::isnan(value) ? low : static_cast<int>(std::clamp(std::round(value), double(low), double(high)));
}

// text_wf: 3 (scale_x X + offset_x, scale_y Y + offset_y) with (X, Y) a painted pixel (Ψ₁ picks it)
// moved by the blur (e^{antialias √(−ln(1 − Ψ₂))} − 1) / 1000 along 2πΨ₃ when antialias > 0.01; z
// carried. As in JWildfire the weight does not scale x and y, and with fewer than two painted pixels
// the result is (Ψ₁, Ψ₂) (JWildfire paints those points black, which a colour index cannot carry).
VOXFLAME_VARIATION_TARGETS void textWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const int size = wholePixels(P[0], 0, kTextRasterMaxSide);
  const double blurRadius = P[1];
  const double scaleX = P[2], scaleY = P[3], offsetX = P[4], offsetY = P[5];
  const int baseline = wholePixels(P[6], -kTextRasterMaxSide, kTextRasterMaxSide);
  // A single evaluation without the term's texts (the catalogue probes every variation once as it is
  // built) draws no text: the chaos game always passes them (the defaults where a preset has none), and
  // drawing here would start fontconfig in every process that looks a variation up.
  std::shared_ptr<const TextPoints> points;
  if (in.texts) points = textPoints(in.texts[0], in.texts[1], size, baseline);
  const std::size_t count = points ? points->x.size() : 0;
  const double* __restrict px = points ? points->x.data() : nullptr;
  const double* __restrict py = points ? points->y.data() : nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    if (count > 1) {
      double rawX, rawY;
      pickBlurredPixel(px, py, count, blurRadius, rnd[i], rawX, rawY);
      outX[i] += (rawX * scaleX + offsetX) * kTextScale;
      outY[i] += (rawY * scaleY + offsetY) * kTextScale;
    } else {
      outX[i] += laneUniform(rnd[i]);
      outY[i] += laneUniform(rnd[i]);
    }
    outZ[i] += w * z[i];
  }
}

// text_wf's pixels for a backend of its own: (X, Y) pairs; none without texts, as the kernel.
std::vector<double> textTable(const double* params, const std::string* texts) {
  if (!texts) return {};
  const std::shared_ptr<const TextPoints> points =
      textPoints(texts[0], texts[1], wholePixels(params[0], 0, kTextRasterMaxSide),
                 wholePixels(params[6], -kTextRasterMaxSide, kTextRasterMaxSide));
  std::vector<double> table(2 * points->x.size());
  for (std::size_t k = 0; k < points->x.size(); ++k) {
    table[2 * k] = points->x[k];
    table[2 * k + 1] = points->y[k];
  }
  return table;
}

}  // namespace

void variation_kernels::addTextVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, kRandom = CatalogueAdder::kRandom;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;
  add("text_wf",
      "3 (scale_x X + offset_x, scale_y Y + offset_y), z: (X, Y) a pixel (Ψ) of `text` drawn in `font_name` at "
      "font_size pixels (not antialiased, moved down by baseline) in an image of the text's size plus font_size on "
      "every side, centred and divided by the image's width and height, blurred by (e^{antialias √(−ln Ψ)} − 1)/1000 "
      "along 2πΨ when antialias > 0.01; the weight does not scale x and y (JWildfire's); with no picture (Ψ, Ψ). A "
      "font that is not installed is drawn in the one fontconfig offers instead",
      k2D, kRandom, &textWf,
      {count("font_size", 320.0, 10.0, 500.0),
       {"antialias", 0.5, 0.0, 1.0},
       {"scale_x", 1.0, -2.0, 2.0},
       {"scale_y", 1.0, -2.0, 2.0},
       {"offset_x", 0.0, -1.0, 1.0},
       {"offset_y", 0.0, -1.0, 1.0},
       count("baseline", 0.0, 0.0, 100.0)});
  catalogue.back().textParams = {{"text", kDefaultText}, {"font_name", kDefaultFont}};
  catalogue.back().table = &textTable;
}

}  // namespace voxflame::core
