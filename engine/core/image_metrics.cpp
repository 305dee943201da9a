#include "image_metrics.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include <glm/common.hpp>

#include "color.h"
#include "error.h"

namespace voxflame::core {

namespace {

constexpr double kLumaWeights[3] = {0.2126, 0.7152, 0.0722};

std::vector<double> luma(const ImageRGBA& image) {
  std::vector<double> y(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  for (std::size_t p = 0; p < y.size(); ++p) {
    const float* c = &image.pixels[4 * p];
    y[p] = kLumaWeights[0] * c[0] + kLumaWeights[1] * c[1] + kLumaWeights[2] * c[2];
  }
  return y;
}

// One pass of a separable filter along rows (horizontal) or columns, the kernel clipped and
// renormalised at the image's edges.
std::vector<double> blur(const std::vector<double>& in, int width, int height, const std::vector<double>& kernel,
                         bool horizontal) {
  const int radius = static_cast<int>(kernel.size() / 2);
  std::vector<double> out(in.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum = 0.0, weight = 0.0;
      for (int k = -radius; k <= radius; ++k) {
        const int sx = horizontal ? x + k : x, sy = horizontal ? y : y + k;
        if (sx < 0 || sy < 0 || sx >= width || sy >= height) continue;
        const double w = kernel[static_cast<std::size_t>(k + radius)];
        sum += w * in[static_cast<std::size_t>(sy) * width + sx];
        weight += w;
      }
      out[static_cast<std::size_t>(y) * width + x] = sum / weight;
    }
  return out;
}

std::vector<double> gaussianBlur(const std::vector<double>& in, int width, int height) {
  constexpr int kRadius = 5;
  constexpr double kSigma = 1.5;
  std::vector<double> kernel;
  for (int k = -kRadius; k <= kRadius; ++k) kernel.push_back(std::exp(-0.5 * k * k / (kSigma * kSigma)));
  return blur(blur(in, width, height, kernel, true), width, height, kernel, false);
}

void checkSizes(const ImageRGBA& a, const ImageRGBA& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error("images of different sizes cannot be compared (" + std::to_string(a.width) + "×" +
                std::to_string(a.height) + " and " + std::to_string(b.width) + "×" + std::to_string(b.height) + ")");
  if (a.width <= 0 || a.height <= 0) throw Error("an empty image cannot be compared");
}

}  // namespace

double ssimLuma(const ImageRGBA& a, const ImageRGBA& b) {
  checkSizes(a, b);
  const int width = a.width, height = a.height;
  const std::vector<double> x = luma(a), y = luma(b);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (std::size_t p = 0; p < x.size(); ++p) {
    xx[p] = x[p] * x[p];
    yy[p] = y[p] * y[p];
    xy[p] = x[p] * y[p];
  }
  const std::vector<double> mx = gaussianBlur(x, width, height), my = gaussianBlur(y, width, height);
  const std::vector<double> sxx = gaussianBlur(xx, width, height), syy = gaussianBlur(yy, width, height),
                            sxy = gaussianBlur(xy, width, height);
  constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
  constexpr int kMargin = 5;  // the window's radius: pixels whose window fits
  const bool small = width <= 2 * kMargin || height <= 2 * kMargin;
  const int x0 = small ? 0 : kMargin, y0 = small ? 0 : kMargin;
  const int x1 = small ? width : width - kMargin, y1 = small ? height : height - kMargin;
  double sum = 0.0;
  for (int py = y0; py < y1; ++py)
    for (int px = x0; px < x1; ++px) {
      const std::size_t p = static_cast<std::size_t>(py) * width + px;
      const double varX = std::max(0.0, sxx[p] - mx[p] * mx[p]), varY = std::max(0.0, syy[p] - my[p] * my[p]);
      const double cov = sxy[p] - mx[p] * my[p];
      sum += (2.0 * mx[p] * my[p] + kC1) * (2.0 * cov + kC2) /
             ((mx[p] * mx[p] + my[p] * my[p] + kC1) * (varX + varY + kC2));
    }
  return sum / (static_cast<double>(x1 - x0) * (y1 - y0));
}

double meanLinearLuminance(const ImageRGBA& image) {
  const std::size_t count = static_cast<std::size_t>(std::max(0, image.width)) * std::max(0, image.height);
  if (count == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t p = 0; p < count; ++p) {
    const float* c = &image.pixels[4 * p];
    const glm::vec3 linear = srgbToLinear(glm::clamp(glm::vec3(c[0], c[1], c[2]), 0.0f, 1.0f));
    sum += kLumaWeights[0] * linear.r + kLumaWeights[1] * linear.g + kLumaWeights[2] * linear.b;
  }
  return sum / static_cast<double>(count);
}

glm::dvec3 meanColor(const ImageRGBA& image) {
  const std::size_t count = static_cast<std::size_t>(std::max(0, image.width)) * std::max(0, image.height);
  if (count == 0) return glm::dvec3(0.0);
  glm::dvec3 sum(0.0);
  for (std::size_t p = 0; p < count; ++p)
    for (int c = 0; c < 3; ++c) sum[c] += image.pixels[4 * p + static_cast<std::size_t>(c)];
  return sum / static_cast<double>(count);
}

}  // namespace voxflame::core
