#include "core/flame/image.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/color.h"
#include "core/error.h"
#include "core/task_scheduler.h"

namespace voxflame::core {

namespace {

// k2: maps the normalised density onto the log curve. A ray that crosses a typical pattern has D
// of a few tenths, which brightness 4 (flam3's default) then shows near full intensity, while a
// thousandth of that still shows faintly through gamma.
constexpr double kDensityScale = 1.5;
// flam3's Gaussian: exp(-2 x²) on a support of 1.5 (filters.c), evaluated at 1.5 · r / width.
constexpr double kGaussianSupport = 1.5;
double gaussian(double x) {
  return std::exp(-2.0 * x * x);
}

// Runs fn(begin, end) over [0, count) on the shared task scheduler, at least 16 items (rows or
// bands) a task: fewer cost more to hand off than to do.
void parallelRanges(int count, const std::function<void(int, int)>& fn) {
  parallelFor(static_cast<std::size_t>(std::max(0, count)), 16,
              [&](std::size_t begin, std::size_t end) { fn(static_cast<int>(begin), static_cast<int>(end)); });
}

// One density-estimation kernel: normalised weights over (2r+1)² pixels.
struct Kernel {
  int radius = 0;
  std::vector<float> weights;
};

// `normalHalf`: the half side of the square whose offsets within the width normalise the weights
// (flam3's, FinishSettings::flam3KernelTruncation), or −1 for those the kernel spreads over.
Kernel makeKernel(double width, int normalHalf) {
  Kernel k;
  k.radius = normalHalf < 0 ? static_cast<int>(std::floor(width)) : std::max(0, static_cast<int>(std::ceil(width)) - 1);
  const int side = 2 * k.radius + 1;
  k.weights.assign(static_cast<std::size_t>(side * side), 0.0f);
  double sum = 0.0;
  const int half = normalHalf < 0 ? k.radius : std::max(normalHalf, k.radius);
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx) {
      const double d = std::sqrt(static_cast<double>(dx * dx + dy * dy)) / width;
      if (d > 1.0) continue;
      const double w = gaussian(kGaussianSupport * d);
      sum += w;
      if (std::abs(dx) <= k.radius && std::abs(dy) <= k.radius)
        k.weights[static_cast<std::size_t>((dy + k.radius) * side + dx + k.radius)] = static_cast<float>(w);
    }
  for (float& w : k.weights) w = static_cast<float>(w / sum);
  return k;
}

// Kernel widths follow flam3 (filters.c): (radius · oversample + 1) / count^curve (the count of
// DensityImage::wholeHits), never below minimum · oversample + 1. Widths are quantised in steps of
// 4% so a table of kernels serves every pixel.
class KernelTable {
 public:
  KernelTable(const ToneMapSettings& tone, int oversample, bool flam3Truncation)
      : maxWidth_(tone.estimatorRadius * oversample + 1.0),
        minWidth_(std::min(tone.estimatorMinimum * oversample + 1.0, maxWidth_)),
        curve_(std::max(tone.estimatorCurve, 1e-3)) {
    const int count = index(minWidth_) + 1;
    // flam3 normalises over the square of the widest kernel's spread (filters.c's de_half_size).
    const int normalHalf = flam3Truncation ? std::max(0, static_cast<int>(std::ceil(maxWidth_)) - 1) : -1;
    kernels_.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
      // With flam3's truncation the narrowest is minWidth_ itself (a whole width when the minimum
      // is), as flam3's is; else the table's quantised widths all through, as the GPU finisher has them.
      const double width = flam3Truncation && i + 1 == count ? minWidth_ : maxWidth_ / std::pow(kStep, i);
      kernels_.push_back(makeKernel(width, normalHalf));
    }
  }
  const Kernel& forHits(double hits, bool wholeHits) const {
    const double count = wholeHits ? std::max(1.0, std::ceil(hits)) : hits + 1.0;
    const double width = std::max(minWidth_, maxWidth_ / std::pow(count, curve_));
    return kernels_[static_cast<std::size_t>(std::min<int>(index(width), static_cast<int>(kernels_.size()) - 1))];
  }
  int maxRadius() const { return kernels_.front().radius; }

 private:
  static constexpr double kStep = 1.04;
  int index(double width) const { return static_cast<int>(std::lround(std::log(maxWidth_ / width) / std::log(kStep))); }
  double maxWidth_, minWidth_, curve_;
  std::vector<Kernel> kernels_;
};

// flam3's gamma on opacity, linear below the threshold so faint noise is not amplified.
double gammaAlpha(double density, double g, double threshold) {
  if (density <= 0.0) return 0.0;
  if (density < threshold) {
    const double fraction = density / threshold;
    return (1.0 - fraction) * density * std::pow(threshold, g) / threshold + fraction * std::pow(density, g);
  }
  return std::pow(density, g);
}

glm::dvec3 rgbToHsv(glm::dvec3 c) {
  const double maxC = std::max({c.r, c.g, c.b}), minC = std::min({c.r, c.g, c.b});
  const double delta = maxC - minC;
  double h = 0.0;
  if (delta > 0.0) {
    if (maxC == c.r)
      h = (c.g - c.b) / delta;
    else if (maxC == c.g)
      h = 2.0 + (c.b - c.r) / delta;
    else
      h = 4.0 + (c.r - c.g) / delta;
    h /= 6.0;
    if (h < 0.0) h += 1.0;
  }
  return {h, maxC > 0.0 ? delta / maxC : 0.0, maxC};
}

glm::dvec3 hsvToRgb(glm::dvec3 c) {
  glm::dvec3 rgb;
  for (int i = 0; i < 3; ++i) {
    const double offset = i == 0 ? 1.0 : i == 1 ? 2.0 / 3.0 : 1.0 / 3.0;
    double k = c.x + offset;
    k = std::abs((k - std::floor(k)) * 6.0 - 3.0);
    rgb[i] = c.z * (1.0 + (std::clamp(k - 1.0, 0.0, 1.0) - 1.0) * c.y);
  }
  return rgb;
}

// flam3's calc_newrgb: scales colour by ls; with highlight power ≥ 0, overexposed colours keep
// their brightest channel at 1 and lose saturation instead of clipping to a different hue.
glm::dvec3 scaledColor(glm::dvec3 c, double ls, double highlightPower) {
  const double maxChannel = std::max({c.r, c.g, c.b});
  if (ls <= 0.0 || maxChannel <= 0.0) return glm::dvec3(0.0);
  const double maxScaled = ls * maxChannel;
  if (maxScaled > 1.0 && highlightPower >= 0.0) {
    const double newScale = 1.0 / maxChannel;
    const double saturationKept = std::pow(newScale / ls, highlightPower);
    glm::dvec3 hsv = rgbToHsv(newScale * c);
    hsv.y *= saturationKept;
    return hsvToRgb(hsv);
  }
  const double blend = maxScaled <= 1.0 ? 1.0 : std::min(1.0, -highlightPower);
  return ((1.0 - blend) + blend * ls) * c;
}

// flam3's count for a supersampled pixel's kernel (rect.c): the points of the block of
// (2⌊oversample / 2⌋ + 1)² pixels around it, scaled by (oversample / (oversample + 1))² for an
// even oversample, so the kernel narrows with the density of the output pixel, not of one sample.
double blockDensity(const DensityImage& in, int x, int y, int oversample) {
  const int half = oversample / 2;
  double sum = 0.0;
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx)
      sum += in.at(std::clamp(x + dx, 0, in.width - 1), std::clamp(y + dy, 0, in.height - 1))[3];
  if (oversample % 2 == 0) sum *= std::pow(oversample / (oversample + 1.0), 2.0);
  return sum;
}

}  // namespace

void DensityImage::resize(int w, int h) {
  width = std::max(0, w);
  height = std::max(0, h);
  values.assign(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
}

double hitsPerUnitDensity(const CameraFrame& camera, const GridGeometry& grid, double points, double insideVoxels,
                          int imageHeight) {
  const double side = grid.voxelSize * std::max({grid.size.x, grid.size.y, grid.size.z, 1});
  const glm::dvec3 centre = 0.5 * (grid.box().min + grid.box().max);
  const double depth = std::max(1e-9, glm::dot(centre - camera.eye, camera.forward));
  // projection[1][1] is cot(fov / 2) for a perspective camera and 2 / height for an orthographic one.
  const double scale = std::max(std::abs(camera.projection[1][1]), 1e-12);
  const double pixel = (camera.orthographic ? 2.0 : 2.0 * depth) / (scale * std::max(imageHeight, 1)) / side;
  const double volume = std::max(insideVoxels, 1.0) * std::pow(grid.voxelSize / side, 3.0);
  return std::max(points, 0.0) * pixel * pixel / volume;
}

double logDensity(double density, const ToneMapSettings& tone) {
  return density > 0.0 ? tone.brightness * std::log1p(kDensityScale * density) : 0.0;
}

void estimateDensity(const DensityImage& in, const ToneMapSettings& tone, int oversample, DensityImage& out,
                     bool flam3KernelTruncation) {
  out.resize(in.width, in.height);
  out.hitsPerUnitDensity = in.hitsPerUnitDensity;
  const int width = in.width, height = in.height;
  auto logScale = [&tone](float density) {
    return density > 0.0f ? static_cast<float>(logDensity(density, tone) / density) : 0.0f;
  };
  if (tone.estimatorRadius <= 0.0) {
    parallelRanges(height, [&](int begin, int end) {
      for (int y = begin; y < end; ++y)
        for (int x = 0; x < width; ++x) {
          const float* v = in.at(x, y);
          float* o = out.at(x, y);
          const float scale = logScale(v[3]);
          for (int c = 0; c < 4; ++c) o[c] = v[c] * scale;
        }
    });
    return;
  }
  const KernelTable kernels(tone, std::max(1, oversample), flam3KernelTruncation);
  // Each pixel scatters over its own kernel. Bands at least two kernels tall are done in two
  // rounds (even bands, then odd ones), so bands that run at the same time never write the same row.
  const int band = std::max(16, 2 * kernels.maxRadius() + 2);
  const int bands = (height + band - 1) / band;
  const double hitsPerUnit = in.hitsPerUnitDensity;
  for (int parity = 0; parity < 2; ++parity) {
    std::vector<int> mine;
    for (int b = parity; b < bands; b += 2) mine.push_back(b);
    parallelRanges(static_cast<int>(mine.size()), [&](int begin, int end) {
      for (int i = begin; i < end; ++i) {
        const int y0 = mine[static_cast<std::size_t>(i)] * band, y1 = std::min(height, y0 + band);
        for (int y = y0; y < y1; ++y)
          for (int x = 0; x < width; ++x) {
            const float* v = in.at(x, y);
            if (v[3] <= 0.0f) continue;
            const float scale = logScale(v[3]);
            const float value[4] = {v[0] * scale, v[1] * scale, v[2] * scale, v[3] * scale};
            const double density = in.wholeHits && oversample > 1 ? blockDensity(in, x, y, oversample) : v[3];
            const Kernel& k = kernels.forHits(density * hitsPerUnit, in.wholeHits);
            const int r = k.radius, side = 2 * r + 1;
            if (r == 0) {  // its one weight is 1, or less with flam3's truncation
              float* o = out.at(x, y);
              for (int c = 0; c < 4; ++c) o[c] += k.weights[0] * value[c];
              continue;
            }
            // Weight that would fall outside the image piles on its edge, so the total is kept.
            for (int dy = -r; dy <= r; ++dy) {
              const int yy = std::clamp(y + dy, 0, height - 1);
              const float* w = &k.weights[static_cast<std::size_t>((dy + r) * side)];
              for (int dx = -r; dx <= r; ++dx) {
                const float weight = w[dx + r];
                if (weight == 0.0f) continue;
                float* o = out.at(std::clamp(x + dx, 0, width - 1), yy);
                for (int c = 0; c < 4; ++c) o[c] += weight * value[c];
              }
            }
          }
      }
    });
  }
}

int spatialFilterTaps(int oversample, double radius) {
  oversample = std::max(1, oversample);
  const double fw = 2.0 * kGaussianSupport * oversample * std::max(0.0, radius);
  int taps = static_cast<int>(std::min(fw, 1e6)) + 1;
  if ((taps ^ oversample) & 1) ++taps;
  return taps;
}

void spatialFilter(const DensityImage& in, int oversample, double radius, DensityImage& out) {
  oversample = std::max(1, oversample);
  const int outWidth = in.width / oversample, outHeight = in.height / oversample;
  out.resize(outWidth, outHeight);
  out.hitsPerUnitDensity = in.hitsPerUnitDensity;
  // flam3's filter (filters.c): a kernel of fw = 2 · support · oversample · radius supersampled
  // pixels, rounded to a whole width of the oversample's parity so it stays centred on the pixel.
  const double fw = 2.0 * kGaussianSupport * oversample * std::max(0.0, radius);
  const int taps = spatialFilterTaps(oversample, radius);
  const double adjust = fw > 0.0 ? kGaussianSupport * taps / fw : 1.0;
  std::vector<float> weights(static_cast<std::size_t>(taps * taps));
  double sum = 0.0;
  for (int j = 0; j < taps; ++j)
    for (int i = 0; i < taps; ++i) {
      const double ii = ((2.0 * i + 1.0) / taps - 1.0) * adjust;
      const double jj = ((2.0 * j + 1.0) / taps - 1.0) * adjust;
      const double w = fw > 0.0 ? gaussian(ii) * gaussian(jj) : 1.0;
      weights[static_cast<std::size_t>(j * taps + i)] = static_cast<float>(w);
      sum += w;
    }
  for (float& w : weights) w = static_cast<float>(w / sum);
  const int offset = (taps - oversample) / 2;
  parallelRanges(outHeight, [&](int begin, int end) {
    for (int y = begin; y < end; ++y)
      for (int x = 0; x < outWidth; ++x) {
        float acc[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int j = 0; j < taps; ++j) {
          const int sy = y * oversample - offset + j;
          if (sy < 0 || sy >= in.height) continue;
          for (int i = 0; i < taps; ++i) {
            const int sx = x * oversample - offset + i;
            if (sx < 0 || sx >= in.width) continue;
            const float w = weights[static_cast<std::size_t>(j * taps + i)];
            const float* v = in.at(sx, sy);
            for (int c = 0; c < 4; ++c) acc[c] += w * v[c];
          }
        }
        float* o = out.at(x, y);
        for (int c = 0; c < 4; ++c) o[c] = acc[c];
      }
  });
}

FinishedImage finishImage(const DensityImage& in, const FinishSettings& settings, const MeshOverlay* overlay) {
  const int oversample = std::max(1, settings.oversample);
  if (in.width % oversample || in.height % oversample)
    throw Error("the density image is not a whole number of supersampled pixels");
  DensityImage logImage, filtered;
  estimateDensity(in, settings.tone, oversample, logImage, settings.flam3KernelTruncation);
  spatialFilter(logImage, oversample, settings.filterRadius, filtered);

  const ToneMapSettings& tone = settings.tone;
  const int width = filtered.width, height = filtered.height;
  FinishedImage result;
  result.image.width = width;
  result.image.height = height;
  result.image.pixels.assign(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
  result.alpha.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
  const bool useOverlay = overlay && overlay->mode != MeshDisplay::Off && overlay->width == width &&
                          overlay->height == height && !overlay->rgba.empty();
  const double g = 1.0 / tone.gamma;
  const double exposure = std::exp2(tone.exposure);
  // The background and the outline are colours as chosen (sRGB), whatever the gamma.
  const glm::dvec3 background(linearToSrgb(tone.background));
  const glm::dvec3 lineColor = useOverlay ? glm::dvec3(linearToSrgb(overlay->color)) : glm::dvec3(0.0);
  auto overlayAlpha = [&](int x, int y) {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return static_cast<double>(overlay->at(static_cast<std::size_t>(y) * width + x, 3));
  };
  parallelRanges(height, [&](int begin, int end) {
    for (int y = begin; y < end; ++y)
      for (int x = 0; x < width; ++x) {
        const float* v = filtered.at(x, y);
        const glm::dvec3 c = glm::max(glm::dvec3(v[0], v[1], v[2]), glm::dvec3(0.0)) * exposure;
        const double density = std::max(0.0, static_cast<double>(v[3]) * exposure);
        const double alpha = gammaAlpha(density, g, tone.gammaThreshold);
        const double ls = density > 0.0 ? tone.vibrancy * alpha / density : 0.0;
        glm::dvec3 color = scaledColor(c, ls, tone.highlightPower) + (1.0 - tone.vibrancy) * glm::pow(c, glm::dvec3(g));
        // The contrast is the pattern's, where it covers the pixel; the background shows through
        // where it does not, and the overlay goes on top (finish_tone.glsl).
        const double covered = std::min(alpha, 1.0);
        color = (color - 0.5 * covered) * tone.contrast + 0.5 * covered;
        const std::size_t at = static_cast<std::size_t>(y) * width + x;
        const bool pictured = settings.backgroundPicture && settings.backgroundPicture->size() == result.alpha.size();
        color += (1.0 - covered) * (pictured ? glm::dvec3((*settings.backgroundPicture)[at]) : background);
        if (useOverlay) {
          const std::size_t p = static_cast<std::size_t>(y) * width + x;
          if (overlay->mode == MeshDisplay::Ghost) {
            color += overlay->strength * glm::dvec3(overlay->at(p, 0), overlay->at(p, 1), overlay->at(p, 2));
          } else {
            const double centre = overlayAlpha(x, y);
            double edge = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) edge = std::max(edge, std::abs(overlayAlpha(x + dx, y + dy) - centre));
            color = glm::mix(color, lineColor, std::clamp(edge * overlay->strength * 2.5, 0.0, 1.0));
          }
        }
        if (settings.linearOutput)
          color = glm::pow(glm::max(color, glm::dvec3(0.0)), glm::dvec3(tone.gamma));
        else
          color = glm::clamp(color, 0.0, 1.0);
        float* o = result.image.at(x, y);
        o[0] = static_cast<float>(color.r);
        o[1] = static_cast<float>(color.g);
        o[2] = static_cast<float>(color.b);
        o[3] = 1.0f;
        result.alpha[static_cast<std::size_t>(y) * width + x] = static_cast<float>(std::min(alpha, 1.0));
      }
  });
  return result;
}

double silhouetteCoverage(const FinishedImage& image, const MeshOverlay& silhouette, double threshold) {
  if (silhouette.width != image.image.width || silhouette.height != image.image.height) return 0.0;
  std::size_t inside = 0, covered = 0;
  for (std::size_t p = 0; p < image.alpha.size(); ++p) {
    if (silhouette.rgba[4 * p + 3] <= 127) continue;  // 0.5 in bytes
    ++inside;
    if (image.alpha[p] >= threshold) ++covered;
  }
  return inside ? static_cast<double>(covered) / static_cast<double>(inside) : 0.0;
}

double takeSilhouetteCoverage(ImageRGBA& image, const MeshOverlay& silhouette, double threshold) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  const bool matches = silhouette.width == image.width && silhouette.height == image.height;
  std::size_t inside = 0, covered = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    float& alpha = image.pixels[4 * p + 3];
    if (matches && silhouette.rgba[4 * p + 3] > 127) {
      ++inside;
      if (alpha >= threshold) ++covered;
    }
    alpha = 1.0f;
  }
  return inside ? static_cast<double>(covered) / static_cast<double>(inside) : 0.0;
}

namespace {
std::vector<double> linearLuminance(const ImageRGBA& image, double gamma) {
  std::vector<double> y(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  for (std::size_t p = 0; p < y.size(); ++p) {
    const float* c = &image.pixels[4 * p];
    y[p] = 0.2126 * std::pow(std::max(0.0f, c[0]), gamma) + 0.7152 * std::pow(std::max(0.0f, c[1]), gamma) +
           0.0722 * std::pow(std::max(0.0f, c[2]), gamma);
  }
  return y;
}
}  // namespace

double meanLuminance(const ImageRGBA& image, double gamma) {
  const std::vector<double> y = linearLuminance(image, gamma);
  double sum = 0.0;
  for (double v : y) sum += v;
  return y.empty() ? 0.0 : sum / static_cast<double>(y.size());
}

double relativeLuminanceRmse(const ImageRGBA& image, const ImageRGBA& reference, double gamma) {
  if (image.width != reference.width || image.height != reference.height)
    throw Error("images of different sizes cannot be compared");
  const std::vector<double> a = linearLuminance(image, gamma), b = linearLuminance(reference, gamma);
  double squared = 0.0, sum = 0.0;
  for (std::size_t p = 0; p < a.size(); ++p) {
    squared += (a[p] - b[p]) * (a[p] - b[p]);
    sum += b[p];
  }
  if (a.empty() || sum <= 0.0) return 0.0;
  const double n = static_cast<double>(a.size());
  return std::sqrt(squared / n) / (sum / n);
}

}  // namespace voxflame::core
