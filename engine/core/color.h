// Colours and gradients. Presets write colours as sRGB hex ("#ff8800"); everything downstream
// works in linear RGB. Gradients interpolate in OKLab so that the middle of a gradient between
// two saturated colours stays as bright and saturated as its ends (plain RGB mixing darkens it).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace voxflame::core {

glm::vec3 srgbToLinear(glm::vec3 srgb);
glm::vec3 linearToSrgb(glm::vec3 linear);
glm::vec3 linearToOklab(glm::vec3 linear);
glm::vec3 oklabToLinear(glm::vec3 lab);

// Parses "#rrggbb" into linear RGB; throws core::Error naming the text otherwise.
glm::vec3 parseHexColor(std::string_view text);
std::string toHexColor(glm::vec3 linear);

struct GradientStop {
  float position = 0.0f;  // 0..1
  glm::vec3 color{0.0f};  // linear RGB
  bool operator==(const GradientStop&) const = default;
};

class Gradient {
 public:
  Gradient() = default;
  explicit Gradient(std::vector<GradientStop> stops);  // sorted by position; needs ≥ 1 stop

  glm::vec3 at(float t) const;  // linear RGB; t is clamped to [0, 1]
  const std::vector<GradientStop>& stops() const { return stops_; }

 private:
  std::vector<GradientStop> stops_;
  std::vector<glm::vec3> labs_;  // the stops in OKLab, computed once
};

// Named palettes a preset can refer to ("palette": "ember"): evenly spaced sRGB hex stops,
// interpolated in OKLab like any gradient.
struct NamedPalette {
  std::string name;
  std::vector<std::string> hexStops;
};
const std::vector<NamedPalette>& namedPalettes();
// The palette's stops in linear RGB; throws core::Error listing the known names.
std::vector<GradientStop> paletteStops(std::string_view name);

}  // namespace voxflame::core
