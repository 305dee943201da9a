#include "color.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "error.h"

namespace voxflame::core {

namespace {
float toLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float toSrgb(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
}  // namespace

glm::vec3 srgbToLinear(glm::vec3 s) {
  return {toLinear(s.r), toLinear(s.g), toLinear(s.b)};
}
glm::vec3 linearToSrgb(glm::vec3 l) {
  return {toSrgb(l.r), toSrgb(l.g), toSrgb(l.b)};
}

// Björn Ottosson's OKLab (2020), from linear sRGB.
glm::vec3 linearToOklab(glm::vec3 c) {
  const float l = std::cbrt(0.4122214708f * c.r + 0.5363325363f * c.g + 0.0514459929f * c.b);
  const float m = std::cbrt(0.2119034982f * c.r + 0.6806995451f * c.g + 0.1073969566f * c.b);
  const float s = std::cbrt(0.0883024619f * c.r + 0.2817188376f * c.g + 0.6299787005f * c.b);
  return {0.2104542553f * l + 0.7936177850f * m - 0.0040720468f * s,
          1.9779984951f * l - 2.4285922050f * m + 0.4505937099f * s,
          0.0259040371f * l + 0.7827717662f * m - 0.8086757660f * s};
}

glm::vec3 oklabToLinear(glm::vec3 lab) {
  const float l = lab.x + 0.3963377774f * lab.y + 0.2158037573f * lab.z;
  const float m = lab.x - 0.1055613458f * lab.y - 0.0638541728f * lab.z;
  const float s = lab.x - 0.0894841775f * lab.y - 1.2914855480f * lab.z;
  const float l3 = l * l * l, m3 = m * m * m, s3 = s * s * s;
  return glm::max(glm::vec3(4.0767416621f * l3 - 3.3077115913f * m3 + 0.2309699292f * s3,
                            -1.2684380046f * l3 + 2.6097574011f * m3 - 0.3413193965f * s3,
                            -0.0041960863f * l3 - 0.7034186147f * m3 + 1.7076147010f * s3),
                  glm::vec3(0.0f));
}

glm::vec3 parseHexColor(std::string_view text) {
  auto hex = [&](char ch) -> int {
    if (ch >= '0' && ch <= '9') return ch - '0';
    if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
    return -1;
  };
  if (text.size() != 7 || text[0] != '#') throw Error("colour '" + std::string(text) + "' is not of the form #rrggbb");
  glm::vec3 srgb;
  for (int c = 0; c < 3; ++c) {
    const int hi = hex(text[1 + 2 * c]);
    const int lo = hex(text[2 + 2 * c]);
    if (hi < 0 || lo < 0) throw Error("colour '" + std::string(text) + "' is not of the form #rrggbb");
    srgb[c] = static_cast<float>(hi * 16 + lo) / 255.0f;
  }
  return srgbToLinear(srgb);
}

std::string toHexColor(glm::vec3 linear) {
  const glm::vec3 s = linearToSrgb(linear);
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", static_cast<int>(std::lround(s.r * 255.0f)),
                static_cast<int>(std::lround(s.g * 255.0f)), static_cast<int>(std::lround(s.b * 255.0f)));
  return buffer;
}

Gradient::Gradient(std::vector<GradientStop> stops) : stops_(std::move(stops)) {
  if (stops_.empty()) throw Error("a gradient needs at least one colour stop");
  std::stable_sort(stops_.begin(), stops_.end(),
                   [](const GradientStop& a, const GradientStop& b) { return a.position < b.position; });
  for (const auto& stop : stops_) labs_.push_back(linearToOklab(stop.color));
}

glm::vec3 Gradient::at(float t) const {
  if (stops_.empty()) return glm::vec3(1.0f);
  t = std::clamp(t, 0.0f, 1.0f);
  if (t <= stops_.front().position) return stops_.front().color;
  if (t >= stops_.back().position) return stops_.back().color;
  std::size_t upper = 1;
  while (stops_[upper].position < t) ++upper;
  const float span = stops_[upper].position - stops_[upper - 1].position;
  const float w = span > 0.0f ? (t - stops_[upper - 1].position) / span : 1.0f;
  return oklabToLinear(labs_[upper - 1] + w * (labs_[upper] - labs_[upper - 1]));
}

const std::vector<NamedPalette>& namedPalettes() {
  static const std::vector<NamedPalette> palettes = {
      {"ember", {"#1a0500", "#8c1c03", "#ff6a00", "#ffd27a", "#fff8e7"}},
      {"glacier", {"#020a1a", "#0b3d91", "#2aa7d6", "#a8ecff", "#ffffff"}},
      {"aurora", {"#06131f", "#11694d", "#3ee08f", "#b8ff6a", "#f3f7ff"}},
      {"dusk", {"#1d0b36", "#6b1f73", "#d9436b", "#ffa552", "#ffe9a8"}},
      {"reef", {"#001b2e", "#006d77", "#83c5be", "#ffddd2", "#e29578"}},
      {"nebula", {"#0b0221", "#4b1d8f", "#c23bd4", "#ff7eb6", "#ffe3f1"}},
      {"moss", {"#0d1b0a", "#355e1f", "#8db83a", "#e3e87a", "#fffbe0"}},
      {"steel", {"#0a0d12", "#3a4756", "#8597ad", "#d8e1ea", "#ffffff"}},
      {"seed", {"#1e4dff", "#ffb13b"}},  // the default preset's two stops
  };
  return palettes;
}

std::vector<GradientStop> paletteStops(std::string_view name) {
  for (const auto& palette : namedPalettes()) {
    if (palette.name != name) continue;
    std::vector<GradientStop> stops;
    const std::size_t count = palette.hexStops.size();
    for (std::size_t i = 0; i < count; ++i)
      stops.push_back({static_cast<float>(i) / static_cast<float>(count - 1), parseHexColor(palette.hexStops[i])});
    return stops;
  }
  std::string known;
  for (const auto& palette : namedPalettes()) known += (known.empty() ? "" : ", ") + palette.name;
  throw Error("unknown palette '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace voxflame::core
