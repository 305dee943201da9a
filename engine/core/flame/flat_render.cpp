#include "core/flame/flat_render.h"

#include <algorithm>
#include <array>
#include <bit>
#include <initializer_list>
#include <string_view>
#include <utility>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/chaos_game.h"
#include "core/color.h"
#include "core/error.h"
#include "core/flame/flat_solid.h"
#include "core/flame/image.h"
#include "core/flame/variations.h"
#include "core/random.h"
#include "core/task_scheduler.h"

namespace voxflame::core {

namespace {

constexpr double kMaxSide = 65536.0;
constexpr double kMaxSamples = 1e12;
constexpr std::size_t kLanes = 1024;
// flam3's chaos game (rect.c, iter_thread and flam3_iterate), which the flat view follows so that
// a flame is as bright as flam3-render draws it: an orbit starts from a random point and draws
// kSubBatch samples after discarding kFuse steps (flam3-render's fuse without early clipping),
// then starts again. A flame whose orbits collapse onto a point is drawn mostly by those
// restarts. A bad value (NaN or beyond 10¹⁰) restarts the orbit at a random point without fuse and
// does not count as a sample, unless it is the kBadRetries-th in a row.
constexpr int kFuse = 15;
constexpr std::uint64_t kSubBatch = 10000;
constexpr int kBadRetries = 5;
// The histograms of all chaos-game tasks together stay below this, whatever the core count.
constexpr double kMaxHistogramBytes = 1.5e9;
// flam3's k1 carries 268/256 (rect.c): flam3 brightness 4 is 4 · 268/256 on the log curve.
constexpr double kFlam3BrightnessFactor = 268.0 / 256.0;
// The finisher's log is brightness · log(1 + kFinisherDensityScale · D) (image.cpp's k2).
constexpr double kFinisherDensityScale = 1.5;

const PatternLayer& flameLayer(const Scene& scene) {
  for (const PatternLayer& layer : scene.layers)
    if (layer.kind == PatternKind::Flame) return layer;
  throw Error("the scene '" + scene.name + "' has no flame layer; the flat view shows flame layers only");
}

// The layer made planar: the z row of every affine map becomes 0, so the depth an import adds
// (flame_xml.h) and any z coefficient drop out and the variations see z = 0, as in flam3.
PatternLayer planarLayer(const PatternLayer& layer) {
  PatternLayer planar = layer;
  const auto flatten = [](FlameXform& x) {
    for (int i = 8; i < 12; ++i) {
      x.affine.m[static_cast<std::size_t>(i)] = 0.0;
      x.post.m[static_cast<std::size_t>(i)] = 0.0;
    }
  };
  for (FlameXform& x : planar.flame.xforms) flatten(x);
  flatten(planar.flame.finalXform);
  for (FlameXform& x : planar.flame.chainedFinals) flatten(x);
  return planar;
}

// flam3's palette as the file has it: 256 entries of the values the file wrote (the import keeps
// them as linear RGB; flam3 averages the written values as they are).
std::array<glm::vec3, 256> filePalette(const ColorSettings& color) {
  const std::vector<GradientStop> stops =
      color.gradient.empty() && !color.palette.empty() ? paletteStops(color.palette) : color.gradient;
  if (stops.empty()) throw Error("the flame layer has no colours (an empty gradient)");
  const Gradient gradient(stops);
  std::array<glm::vec3, 256> palette;
  for (std::size_t i = 0; i < palette.size(); ++i)
    palette[i] = glm::clamp(linearToSrgb(gradient.at(static_cast<float>(i) / 255.0f)), 0.0f, 1.0f);
  return palette;
}

// JWildfire's background transforms (FlameGenome::backgroundXforms, LogDensityFilter's background): the
// picture's background, per output pixel in display values 0–1, rows top to bottom; empty when the first
// flame layer has none (JWildfire then paints none, whatever the other layers hold). The background colour
// (as bytes) starts each pixel; for every flame layer, each of its background transforms maps the pixel's
// place ((column − (width − 1)/2, row − (height − 1)/2) / half the diagonal · 1.41 / zoom, z = 0, colour
// index 0) once, and its colour times the transform's weight is added, truncated to a whole byte each time
// as JWildfire's int does: a true colour a variation painted, else the render palette's entry ⌊254 c + ½⌋
// (held in 0–255) scaled by 200/256. The sum is held in 0–255 at the end. JWildfire makes its DC variations
// sample the point itself there (prepareBackgroundRendering sets ColorOnly), and so does this.
// Java's (int) of a double, kept a double: truncated towards 0, saturating, NaN as 0.
double javaTruncated(double value) {
  return std::isnan(value) ? 0.0 : std::trunc(std::clamp(value, -2147483648.0, 2147483647.0));
}

std::vector<glm::vec3> backgroundPicture(const Scene& scene, int width, int height, std::uint64_t seed) {
  std::vector<const PatternLayer*> layers;
  for (const PatternLayer& layer : scene.layers)
    if (layer.kind == PatternKind::Flame) layers.push_back(&layer);
  if (layers.empty() || layers.front()->flame.backgroundXforms.empty()) return {};
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<std::array<double, 3>> bytes(pixels);
  const glm::vec3 base = glm::clamp(linearToSrgb(scene.tone.background), glm::vec3(0.0f), glm::vec3(1.0f));
  for (auto& b : bytes)
    for (int c = 0; c < 3; ++c) b[static_cast<std::size_t>(c)] = std::round(base[c] * 255.0);
  const double halfDiagonal =
      std::sqrt(static_cast<double>(width) * width + static_cast<double>(height) * height) * 0.5;
  for (const PatternLayer* source : layers) {
    const FlameGenome& genome = source->flame;
    if (genome.backgroundXforms.empty()) continue;
    const double scale = 1.41 / genome.backgroundZoom / halfDiagonal;
    const std::array<glm::vec3, 256> palette = filePalette(source->color);
    for (const FlameXform& xform : genome.backgroundXforms) {
      // The transform alone, as a game of one transform of weight 1 (its weight scales its colour).
      PatternLayer layer = *source;
      layer.flame = FlameGenome{};
      layer.flame.xforms.push_back(xform);
      layer.flame.xforms.back().weight = 1.0;
      layer.flame.xforms.back().opacity = 1.0;
      for (VariationTerm& term : layer.flame.xforms.back().variations)
        if (const VariationInfo* info = findVariation(term.name))
          if (const int k = info->paramIndex("ColorOnly"); k >= 0 && static_cast<std::size_t>(k) < term.params.size())
            term.params[static_cast<std::size_t>(k)] = 1.0;
      const ChaosGame game(layer, "a background transform");
      const bool painted = game.paintsRgb();
      const double amount = xform.weight;
      parallelFor(static_cast<std::size_t>(height), 8, [&](std::size_t begin, std::size_t end) {
        ChaosLanes lanes;
        lanes.resize(static_cast<std::size_t>(width));
        std::vector<double> ox(static_cast<std::size_t>(width)), oy(ox.size()), oz(ox.size()), oc(ox.size());
        for (std::size_t row = begin; row < end; ++row) {
          SplitMix64 rng(seed * 0x9e3779b97f4a7c15ULL + row + 1);
          for (std::size_t i = 0; i < ox.size(); ++i) {
            game.seedLane(lanes, i, rng);
            lanes.x[i] = (static_cast<double>(i) - (width - 1) * 0.5) * scale;
            lanes.y[i] = (static_cast<double>(row) - (height - 1) * 0.5) * scale;
            lanes.z[i] = 0.0;
            lanes.color[i] = 0.0;
          }
          game.step(lanes, ox.data(), oy.data(), oz.data(), oc.data(), ox.size());
          for (std::size_t i = 0; i < ox.size(); ++i) {
            double rgb[3];
            const std::uint32_t paint = painted ? lanes.rgb[i] : 0u;
            if (paint & kRgbPainted) {
              for (int c = 0; c < 3; ++c) rgb[c] = static_cast<double>(paint >> (8 * c) & 255u);
            } else {
              const double index = std::clamp(javaTruncated(oc[i] * 254.0 + 0.5), 0.0, 255.0);
              const glm::vec3& entry = palette[static_cast<std::size_t>(index)];
              for (int c = 0; c < 3; ++c) rgb[c] = std::round(entry[c] * 255.0) * 200.0 / 256.0;
            }
            std::array<double, 3>& b = bytes[row * ox.size() + i];
            for (int c = 0; c < 3; ++c)
              b[static_cast<std::size_t>(c)] = javaTruncated(b[static_cast<std::size_t>(c)] + rgb[c] * amount);
          }
        }
      });
    }
  }
  std::vector<glm::vec3> picture(pixels);
  for (std::size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      picture[p][c] = static_cast<float>(std::clamp(bytes[p][static_cast<std::size_t>(c)], 0.0, 255.0) / 255.0);
  return picture;
}

bool finitePositive(double v) {
  return std::isfinite(v) && v > 0.0;
}

}  // namespace

void flatRenderSize(const FlatViewSettings& flat, const FlatRenderOptions& options, int& width, int& height) {
  if (options.width < 0 || options.height < 0)
    throw Error("the flat view's size must be positive, not " + std::to_string(options.width) + "×" +
                std::to_string(options.height));
  if (flat.width < 1 || flat.height < 1) throw Error("the flame's size (flat.width, flat.height) must be positive");
  const double aspect = static_cast<double>(flat.height) / flat.width;
  width = options.width ? options.width
                        : (options.height ? static_cast<int>(std::lround(options.height / aspect)) : flat.width);
  height =
      options.height ? options.height : (options.width ? static_cast<int>(std::lround(width * aspect)) : flat.height);
  width = std::max(width, 1);
  height = std::max(height, 1);
  if (width > kMaxSide || height > kMaxSide)
    throw Error("the flat view of " + std::to_string(width) + "×" + std::to_string(height) +
                " pixels is too large (at most 65536 a side)");
}

glm::vec3 flatPaletteColour(const std::array<glm::vec3, 256>& palette, double index, PaletteMode mode) {
  const double scaled = index * 256.0;
  if (!(scaled > 0.0)) return palette[0];  // NaN too
  if (scaled >= 255.0) return palette[255];
  const auto entry = static_cast<std::size_t>(scaled);
  if (mode == PaletteMode::Step) return palette[entry];
  const auto fraction = static_cast<float>(scaled - static_cast<double>(entry));
  return palette[entry] * (1.0f - fraction) + palette[entry + 1] * fraction;
}

glm::vec3 flatPointColour(const std::array<glm::vec3, 256>& palette, double index, PaletteMode mode,
                          std::uint32_t rgb) {
  if (!(rgb & kRgbPainted)) return flatPaletteColour(palette, index, mode);
  // A painted colour's bytes are display values, as the palette's entries are (filePalette).
  return glm::vec3(static_cast<float>(rgb & 255u), static_cast<float>(rgb >> 8 & 255u),
                   static_cast<float>(rgb >> 16 & 255u)) /
         255.0f;
}

float flatPixelLevel(float value, int bitDepth) {
  const float a = std::clamp(value * 256.0f, 0.0f, 255.0f);  // NaN: 0
  if (!(a > 0.0f)) return 0.0f;
  return bitDepth == 16 ? std::floor(a * 256.0f) / 65535.0f : std::floor(a) / 255.0f;
}

namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

Matrix3 operator*(const Matrix3& a, const Matrix3& b) {
  Matrix3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
  return m;
}

// The turn by `degrees` about coordinate axis `axis` (0: x, 1: y, 2: z), right-handed.
Matrix3 turnAbout(int axis, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Matrix3 m{};
  m[axis][axis] = 1.0;
  m[u][u] = c;
  m[u][v] = -s;
  m[v][u] = s;
  m[v][v] = c;
  return m;
}

}  // namespace

namespace {

// A variation of the catalogue that a depth of field shape draws with, and its parameters: the
// catalogue's defaults (JWildfire's, for those the shape leaves alone), then the shape's by name.
void useShapeVariation(FlatCamera& camera, std::string_view name,
                       std::initializer_list<std::pair<std::string_view, double>> params) {
  const VariationInfo& info = variationOrThrow(name);
  camera.shapeVariation = &info;
  camera.shapeParams = info.defaultParams();
  for (const auto& [param, value] : params) {
    const int index = info.paramIndex(param);
    if (index >= 0) camera.shapeParams[static_cast<std::size_t>(index)] = value;
  }
}

// Ken Perlin's smootherstep (JWildfire's GfxMathLib.smootherstep from 0 to 1): t clamped into
// [0, 1], then t³(6t² − 15t + 10).
double smootherstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

// The generator of a shape's further draws, seeded by the point's two draws (never 0).
std::uint32_t shapeSeed(double angle01, double blur01) {
  std::uint64_t h = std::bit_cast<std::uint64_t>(angle01) * 0x9e3779b97f4a7c15ULL ^
                    std::bit_cast<std::uint64_t>(blur01) * 0xc2b2ae3d27d4eb4fULL;
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 29;
  const auto seed = static_cast<std::uint32_t>(h >> 32) ^ static_cast<std::uint32_t>(h);
  return seed == 0 ? 0x6d2b79f5U : seed;
}

}  // namespace

FlatCamera::FlatCamera(const FlatViewSettings& flat)
    : jwildfire(flat.cameraModel == FlatCameraModel::Jwildfire),
      z0(flat.cameraZ),
      perspective(flat.cameraPerspective),
      dofScale(0.1 * flat.cameraDof),
      dofFade(flat.cameraDofFade) {
  const Matrix3 yaw = turnAbout(2, -flat.cameraYawDeg), pitch = turnAbout(0, flat.cameraPitchDeg);
  if (!jwildfire) {
    turn = pitch * yaw;
    return;
  }
  turn = turnAbout(2, flat.rotateDeg) * pitch * turnAbout(1, flat.cameraBankDeg) * yaw;
  position = flat.cameraPosition;
  dofScale *= flat.cameraDofScale;
  newDof = flat.cameraDofNew;
  focus = flat.cameraDofFocus;
  area = flat.cameraDofArea;
  fadeBand = area / 2.25;
  inverseExponent = 1.0 / flat.cameraDofExponent;
  shape = flat.cameraDofShape;
  // JWildfire turns the offset only for a rotate above its EPSILON.
  const double rotate = flat.cameraDofRotateDeg * std::numbers::pi / 180.0;
  shapeTurned = std::abs(flat.cameraDofRotateDeg) > 1e-8;
  shapeCos = std::cos(rotate);
  shapeSin = std::sin(rotate);
  const double p1 = flat.cameraDofParam1, p2 = flat.cameraDofParam2, p3 = flat.cameraDofParam3;
  const double p4 = flat.cameraDofParam4, p5 = flat.cameraDofParam5;
  switch (shape) {
    case FlatDofShape::Bubble:
      break;
    case FlatDofShape::Rect:
      rectWidth = flat.cameraDofParam1;
      useShapeVariation(*this, "square", {});
      break;
    case FlatDofShape::Cloverleaf:
      useShapeVariation(*this, "cloverleaf_wf", {{"filled", 1.0}});
      break;
    case FlatDofShape::CannabisCurve:
      useShapeVariation(*this, "cannabiscurve_wf", {{"filled", 1.0}});
      break;
    case FlatDofShape::Heart:  // JWildfire's xheart_blur_wf: xheart of a random point
      useShapeVariation(*this, "xheart", {{"angle", p1}, {"ratio", p2}});
      break;
    case FlatDofShape::Flower:
      useShapeVariation(*this, "flower", {{"holes", p1}, {"petals", p2}});
      break;
    case FlatDofShape::NBlur:
      useShapeVariation(
          *this, "nBlur",
          {{"numEdges", p1}, {"numStripes", p2}, {"ratioStripes", p3}, {"ratioHole", p4}, {"circumCircle", p5}});
      break;
    case FlatDofShape::PerlinNoise:
      useShapeVariation(*this, "dc_perlin",
                        {{"shape", p1}, {"amps", p2}, {"freqs", p3}, {"centre", p4}, {"range", p5}});
      break;
    case FlatDofShape::SineBlur:
      useShapeVariation(*this, "sineblur", {{"power", p1}});
      break;
    case FlatDofShape::StarBlur:
      useShapeVariation(*this, "starblur", {{"power", p1}, {"range", p2}});
      break;
    case FlatDofShape::Taurus:
      useShapeVariation(*this, "taurus", {{"r", p1}, {"n", p2}, {"inv", p3}, {"sor", p4}});
      break;
  }
}

double FlatCamera::depth(double x, double y, double z) const {
  if (!jwildfire) z -= z0;
  return turn[2][0] * x + turn[2][1] * y + turn[2][2] * z + position.z;
}

glm::dvec2 FlatCamera::project(double x, double y, double z, double angle01, double blur01) const {
  return projectTurned(x, y, z, true, angle01, blur01);
}

glm::dvec2 FlatCamera::projectSharp(double x, double y, double z) const {
  return projectTurned(x, y, z, false, 0.0, 0.0);
}

glm::dvec2 FlatCamera::dofOffset(double px, double py, double distance, double angle01, double blur01) const {
  const double radius = dofScale * distance;
  if (shape == FlatDofShape::Bubble) {
    const double fade = dofFade <= 1e-8         ? 1.0
                        : dofFade >= 1.0 - 1e-8 ? blur01
                        : blur01 <= dofFade     ? blur01 / dofFade
                                                : 1.0;
    // In this order, so the legacy bubble draws exactly as it did before the other shapes came.
    const double angle = 2.0 * std::numbers::pi * angle01, r = fade * dofScale * distance;
    return {r * std::cos(angle), r * std::sin(angle)};
  }
  std::uint32_t random = shapeSeed(angle01, blur01);
  const auto draw = [&] { return laneUniform(random); };
  // JWildfire's AbstractDOFBlurShape.doFade.
  const auto fadeDraw = [&] {
    if (dofFade <= 1e-8) return 1.0;
    if (dofFade >= 1.0 - 1e-8) return draw();
    return draw() <= dofFade ? draw() : 1.0;
  };
  double sx = px, sy = py, weight = 0.0;
  switch (shape) {
    case FlatDofShape::Cloverleaf:
    case FlatDofShape::CannabisCurve: {
      const double fade = fadeDraw();
      weight = std::abs(radius * (shape == FlatDofShape::Cloverleaf ? fadeDraw() : fade));
      sx = (1.0 - 2.0 * draw()) * fade;
      sy = (1.0 - 2.0 * draw()) * fade;
      break;
    }
    case FlatDofShape::Heart:
      weight = std::abs(radius * fadeDraw());
      sx = 2.0 - 4.0 * draw();
      sy = 2.0 - 4.0 * draw();
      break;
    case FlatDofShape::Flower:
      weight = 2.0 * std::abs(radius * fadeDraw());
      sx = 1.0 - 2.0 * draw();
      sy = 1.0 - 2.0 * draw();
      break;
    case FlatDofShape::Taurus: {
      const double fade = fadeDraw();
      weight = 0.25 * std::abs(radius * fade);
      sx = (2.0 - 4.0 * draw()) * std::numbers::pi * fade;
      sy = (2.0 - 4.0 * draw()) * std::numbers::pi * fade;
      break;
    }
    default:  // rect, nblur, perlin_noise, sineblur, starblur: the variation of the point itself
      weight = radius * fadeDraw();
      break;
  }
  double sz = 0.0, ox = 0.0, oy = 0.0, oz = 0.0, colour = 0.0;
  static constexpr double kIdentity[12] = {1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0};
  VariationInput in;
  in.x = in.tx = &sx;
  in.y = in.ty = &sy;
  in.z = in.tz = &sz;
  in.random = &random;
  in.count = 1;
  in.weight = weight;
  in.params = shapeParams.data();
  in.affine = kIdentity;
  in.colour = &colour;  // dc_perlin colours the point; JWildfire plots the colour it had before
  shapeVariation->apply(in, &ox, &oy, &oz);
  if (shape == FlatDofShape::Rect) ox *= rectWidth;
  if (shapeTurned && shape != FlatDofShape::SineBlur) {
    const double rx = ox * shapeCos - oy * shapeSin, ry = ox * shapeSin + oy * shapeCos;
    ox = rx;
    oy = ry;
  }
  return {ox, oy};
}

glm::dvec2 FlatCamera::projectTurned(double x, double y, double z, bool blurred, double angle01, double blur01) const {
  if (!jwildfire) z -= z0;
  const auto row = [&](int i) { return turn[i][0] * x + turn[i][1] * y + turn[i][2] * z; };
  double px = row(0) + position.x, py = row(1) + position.y;
  const double depth = row(2) + position.z;
  if (!jwildfire) {
    if (blurred && dofScale != 0.0) {
      const double angle = 2.0 * std::numbers::pi * angle01, r = blur01 * dofScale * depth;
      px += r * std::cos(angle);
      py += r * std::sin(angle);
    }
    double zr = 1.0 - perspective * depth;
    if (zr == 0.0) zr = std::numeric_limits<double>::epsilon();  // Fractorium's Zeps
    return {px / zr, py / zr};
  }
  const double zr = 1.0 - perspective * depth + position.z;
  if (!(zr >= 1e-8)) return glm::dvec2(std::numeric_limits<double>::quiet_NaN());  // behind the eye
  if (blurred && dofScale != 0.0) {
    double distance = 0.0;  // JWildfire's dofDist; 0: sharp
    if (!newDof) {
      distance = std::max(z0 - depth, 0.0);
    } else {
      const glm::dvec3 d = glm::dvec3(px, py, depth) - focus;
      const double dist = std::pow(glm::dot(d, d), inverseExponent);
      if (dist > area)
        distance = dist;
      else if (dist > area - fadeBand)
        distance = smootherstep((dist - (area - fadeBand)) / fadeBand) * dist;
    }
    if (distance > 0.0) {
      const glm::dvec2 offset = dofOffset(px, py, distance, angle01, blur01);
      px += offset.x;
      py += offset.y;
    }
  }
  return {px / zr, py / zr};
}

namespace {

bool hasDepthVariation(const FlameGenome& genome) {
  const auto threeD = [](const FlameXform& x) {
    return std::any_of(x.variations.begin(), x.variations.end(), [](const VariationTerm& term) {
      const VariationInfo* info = findVariation(term.name);
      return info && info->threeD && info->name != "flatten";
    });
  };
  return std::any_of(genome.xforms.begin(), genome.xforms.end(), threeD) ||
         (genome.hasFinal && threeD(genome.finalXform)) ||
         std::any_of(genome.chainedFinals.begin(), genome.chainedFinals.end(), threeD);
}

// One task of the flat view's chaos game: kLanes orbits, each fused for kFuse steps, restarted
// after kSubBatch points (flam3's sub-batches) and after a bad value (kBadRetries tries, then the
// sample counts as drawn); `quota` points are drawn. seeded(i) runs after every seedLane of lane i
// (the solid view draws a lane's material there), chosen(i) after each good step of lane i before
// its fuse is counted, and draw(i, x, y, z, colour) for every visible point. Returns false when the
// render was cancelled. The glowing and the solid view share it, so they draw the same orbits.
template <typename Seeded, typename Chosen, typename Draw>
bool runFlatTask(const ChaosGame& game, SplitMix64& rng, std::uint64_t quota, const FlatRenderOptions& options,
                 std::atomic<bool>& cancelled, ChaosLanes& lanes, Seeded&& seeded, Chosen&& chosen, Draw&& draw) {
  lanes.resize(kLanes);
  std::vector<int> fuse(kLanes, kFuse), bad(kLanes, 0);
  std::vector<std::uint64_t> orbitSamples(kLanes, 0);
  const auto seed = [&](std::size_t i) {
    game.seedLane(lanes, i, rng);
    seeded(i);
  };
  for (std::size_t i = 0; i < kLanes; ++i) seed(i);
  std::vector<double> outX(kLanes), outY(kLanes), outZ(kLanes), outColor(kLanes);
  std::uint64_t drawn = 0, steps = 0;
  while (drawn < quota) {
    if ((++steps & 255) == 0 &&
        (cancelled.load(std::memory_order_relaxed) || (options.cancel && options.cancel->load()))) {
      cancelled = true;
      return false;
    }
    game.step(lanes, outX.data(), outY.data(), outZ.data(), outColor.data(), kLanes);
    for (std::size_t i = 0; i < kLanes && drawn < quota; ++i) {
      if (std::isnan(outX[i])) {  // a bad value: on from a random point, as flam3 goes on
        seed(i);
        if (fuse[i] > 0 || ++bad[i] < kBadRetries) continue;
        bad[i] = 0;
        ++drawn;
        continue;
      }
      bad[i] = 0;
      chosen(i);
      if (fuse[i] > 0) {
        --fuse[i];
        continue;
      }
      ++drawn;
      const bool visible = lanes.visible[i] != 0;
      if (++orbitSamples[i] == kSubBatch) {  // this orbit's sub-batch is drawn: the next starts afresh
        orbitSamples[i] = 0;
        seed(i);
        fuse[i] = kFuse;
      }
      if (visible) draw(i, outX[i], outY[i], outZ[i], outColor[i]);
    }
  }
  return true;
}

// JWildfire's solid rendering (flat_solid.h): the chaos game as in renderFlat, but each
// supersampled pixel keeps its nearest point, which is then shaded; the image is the shaded
// colour filtered by the spatial filter over the background, as JWildfire's filter and gamma
// stages draw it: colour Σ w·c plus the background times 1 − (Σ w)^(1 + 1/gamma).
FlatRenderResult renderFlatSolid(const Scene& scene, const FlatRenderOptions& options, int width, int height,
                                 double quality) {
  const FlatViewSettings& flat = scene.flat;
  const FlatSolidSettings& solid = flat.solid;
  const PatternLayer& source = flameLayer(scene);
  // A JWildfire flame with 3D variations keeps its depth: JWildfire's affine maps pass z through.
  // One without them is flat there too (the z rows are the import's added depth).
  PatternLayer layer = hasDepthVariation(source.flame) ? source : planarLayer(source);
  std::vector<Affine3> postSymmetry = postSymmetryMaps(layer.flame.postSymmetry);
  if (postSymmetry.empty()) postSymmetry.emplace_back();
  layer.flame.postSymmetry.kind = PostSymmetryKind::None;
  const ChaosGame game(layer, "the flame layer");
  const std::array<glm::vec3, 256> palette = filePalette(layer.color);
  const bool paintsRgb = game.paintsRgb();
  const std::size_t genomeXforms = layer.flame.xforms.size();

  const double sizeScale = options.width || !options.height ? static_cast<double>(width) / flat.width
                                                            : static_cast<double>(height) / flat.height;
  const double zoomScale = std::exp2(flat.zoom);
  const double pixelsPerUnit = flat.scale * zoomScale * sizeScale;
  const double samples = quality * zoomScale * zoomScale * width * height;
  if (!(samples <= kMaxSamples))
    throw Error("the flat view would draw " + std::to_string(samples) + " samples; at most 10¹² are allowed");
  const int oversample = std::clamp(flat.oversample, 1, 4);
  const int gutter = static_cast<int>(std::ceil(1.5 * flat.filterRadius)) + 1;
  const int rasterWidth = (width + 2 * gutter) * oversample, rasterHeight = (height + 2 * gutter) * oversample;
  const double bucketsPerUnit = pixelsPerUnit * oversample;
  const double left = flat.centerX - (0.5 * width + gutter) / pixelsPerUnit;
  const double top = flat.centerY - (0.5 * height + gutter) / pixelsPerUnit;
  const bool hasCamera = flat.hasCamera();
  const FlatCamera camera(flat);
  const double turn = flat.rotateDeg * std::numbers::pi / 180.0;
  const double cosTurn = std::cos(turn), sinTurn = std::sin(turn);
  const bool turned = flat.rotateDeg != 0.0 && !(hasCamera && camera.jwildfire);

  // The shadow maps are framed by the first points of an orbit, as JWildfire frames them.
  std::vector<SolidShadowMap> shadowMaps;
  if (solid.shadowType != SolidShadowType::Off &&
      std::any_of(solid.lights.begin(), solid.lights.end(), [](const SolidLight& l) { return l.castShadows; })) {
    constexpr std::size_t kFramingPoints = 40960;
    std::vector<glm::dvec3> framing;
    SplitMix64 rng(options.seed * 0x2545f4914f6cdd1dULL + 7);
    ChaosLanes lanes;
    lanes.resize(kLanes);
    for (std::size_t i = 0; i < kLanes; ++i) game.seedLane(lanes, i, rng);
    std::vector<double> outX(kLanes), outY(kLanes), outZ(kLanes), outColor(kLanes);
    for (int step = 0; framing.size() < kFramingPoints && step < 1000; ++step) {
      game.step(lanes, outX.data(), outY.data(), outZ.data(), outColor.data(), kLanes);
      if (step < kFuse) continue;
      for (std::size_t i = 0; i < kLanes; ++i) {
        if (std::isnan(outX[i])) {
          game.seedLane(lanes, i, rng);
          continue;
        }
        if (!lanes.visible[i]) continue;
        for (const Affine3& image : postSymmetry) framing.push_back(image.apply({outX[i], outY[i], outZ[i]}));
      }
    }
    shadowMaps = makeSolidShadowMaps(solid, framing);
  }

  const double rasterBytes = static_cast<double>(sizeof(SolidTexel)) * rasterWidth * rasterHeight;
  const int tasks = static_cast<int>(std::clamp(std::floor(kMaxHistogramBytes / rasterBytes), 1.0,
                                                static_cast<double>(std::max(1, taskConcurrency()))));
  std::vector<SolidRaster> rasters(static_cast<std::size_t>(tasks));
  const auto total = static_cast<std::uint64_t>(std::llround(samples));
  std::atomic<bool> cancelled{false};
  parallelFor(static_cast<std::size_t>(tasks), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t task = begin; task < end; ++task) {
      SolidRaster& raster = rasters[task];
      raster.resize(rasterWidth, rasterHeight);
      const std::uint64_t quota = total / tasks + (task < total % tasks ? 1 : 0);
      SplitMix64 rng(options.seed * 0x9e3779b97f4a7c15ULL + task + 1);
      ChaosLanes lanes;
      // Each lane's material index, blended by the transform it takes as its colour is
      // (JWildfire starts it at random).
      std::vector<double> material(kLanes);
      const auto seeded = [&](std::size_t i) { material[i] = rng.uniform(); };
      const auto chosen = [&](std::size_t i) {
        if (const std::size_t k = lanes.choice[i]; k < genomeXforms) {
          const FlameXform& x = layer.flame.xforms[k];
          material[i] = material[i] * (1.0 + x.materialSpeed) * 0.5 + x.material * (1.0 - x.materialSpeed) * 0.5;
        }
      };
      const auto draw = [&](std::size_t i, double x, double y, double z, double colour) {
        const glm::vec3 c = paintsRgb ? flatPointColour(palette, colour, flat.paletteMode, lanes.rgb[i])
                                      : flatPaletteColour(palette, colour, flat.paletteMode);
        for (const Affine3& image : postSymmetry) {
          const glm::dvec3 q = image.apply({x, y, z});
          for (SolidShadowMap& map : shadowMaps)
            if (map.active) map.deposit(q);
          double px = q.x, py = q.y, depth = q.z;
          if (hasCamera) {
            // JWildfire's solid rendering moves points by the camera only; its depth of field
            // is a blur after shading, which the flat view leaves out.
            const glm::dvec2 p = camera.projectSharp(q.x, q.y, q.z);
            px = p.x;
            py = p.y;
            depth = camera.depth(q.x, q.y, q.z);
          }
          if (turned) {
            const double dx = px - flat.centerX, dy = py - flat.centerY;
            px = dx * cosTurn - dy * sinTurn + flat.centerX;
            py = dx * sinTurn + dy * cosTurn + flat.centerY;
          }
          const double bx = (px - left) * bucketsPerUnit, by = (py - top) * bucketsPerUnit;
          if (!(bx >= 0.0 && by >= 0.0 && bx < rasterWidth && by < rasterHeight) || !std::isfinite(depth)) continue;
          raster.deposit(static_cast<int>(bx), static_cast<int>(by),
                         {static_cast<float>(depth), static_cast<float>(q.x), static_cast<float>(q.y),
                          static_cast<float>(q.z), c.r, c.g, c.b, static_cast<float>(material[i])});
        }
      };
      if (!runFlatTask(game, rng, quota, options, cancelled, lanes, seeded, chosen, draw)) return;
    }
  });
  if (cancelled) throw FlatRenderCancelled{};
  SolidRaster& nearest = rasters.front();
  parallelFor(static_cast<std::size_t>(rasterHeight), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y)
      for (int x = 0; x < rasterWidth; ++x)
        for (std::size_t t = 1; t < rasters.size(); ++t)
          nearest.deposit(x, static_cast<int>(y), rasters[t].at(x, static_cast<int>(y)));
  });

  const glm::dvec3 background(glm::clamp(linearToSrgb(scene.tone.background), glm::vec3(0.0f), glm::vec3(1.0f)));
  const std::vector<glm::vec3> picture = backgroundPicture(scene, width, height, options.seed);
  const DensityImage shaded = shadeSolidRaster(solid, nearest, shadowMaps, bucketsPerUnit, background);
  DensityImage filtered;
  spatialFilter(shaded, oversample, flat.filterRadius, filtered);
  const double gamma = scene.tone.gamma > 0.0 ? scene.tone.gamma : 1.0;

  FlatRenderResult result;
  result.samples = total;
  result.quality = quality;
  result.image.width = width;
  result.image.height = height;
  result.image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* v = filtered.at(x + gutter, y + gutter);
      const double coverage = std::clamp(static_cast<double>(v[3]), 0.0, 1.0);
      const double alpha = std::pow(coverage, 1.0 + 1.0 / gamma);
      float* pixel = result.image.at(x, y);
      const glm::dvec3 behind =
          picture.empty() ? background : glm::dvec3(picture[static_cast<std::size_t>(y) * width + x]);
      for (int channel = 0; channel < 3; ++channel) {
        const double value = std::clamp(static_cast<double>(v[channel]), 0.0, 1.0) + behind[channel] * (1.0 - alpha);
        pixel[channel] = flatPixelLevel(static_cast<float>(value), options.bitDepth);
      }
      pixel[3] = 1.0f;
    }
  return result;
}

}  // namespace

FlatRenderResult renderFlat(const Scene& scene, const FlatRenderOptions& options) {
  const FlatViewSettings& flat = scene.flat;
  int width = 0, height = 0;
  flatRenderSize(flat, options, width, height);
  const double quality = options.quality.value_or(flat.quality);
  if (!finitePositive(quality)) throw Error("the flat view's quality must be a positive number");
  if (!finitePositive(flat.scale) || !std::isfinite(flat.zoom) || !std::isfinite(flat.centerX) ||
      !std::isfinite(flat.centerY) || !std::isfinite(flat.rotateDeg) || !(flat.filterRadius >= 0.0))
    throw Error("the flame's framing (flat) holds a value that is not a finite number");
  if (flat.solid.enabled) return renderFlatSolid(scene, options, width, height, quality);
  PatternLayer layer = planarLayer(flameLayer(scene));
  // JWildfire's post symmetry draws every point through each of its maps, as JWildfire does (the
  // chaos game alone would draw each through one of them).
  std::vector<Affine3> postSymmetry = postSymmetryMaps(layer.flame.postSymmetry);
  if (postSymmetry.empty()) postSymmetry.emplace_back();
  layer.flame.postSymmetry.kind = PostSymmetryKind::None;
  const ChaosGame game(layer, "the flame layer");
  const std::array<glm::vec3, 256> palette = filePalette(layer.color);
  const bool paintsRgb = game.paintsRgb();

  // flam3's camera (rect.c): pixels per unit scale · 2^zoom, scaled with the image when its size
  // differs from the flame's (as flam3-render's ss does); samples quality · 4^zoom per pixel.
  const double sizeScale = options.width || !options.height ? static_cast<double>(width) / flat.width
                                                            : static_cast<double>(height) / flat.height;
  const double zoomScale = std::exp2(flat.zoom);
  const double pixelsPerUnit = flat.scale * zoomScale * sizeScale;
  const double sampleDensity = quality * zoomScale * zoomScale;
  const double samples = sampleDensity * width * height;
  if (!(samples <= kMaxSamples))
    throw Error("the flat view would draw " + std::to_string(samples) + " samples; at most 10¹² are allowed");
  const int oversample = std::clamp(flat.oversample, 1, 4);
  const ToneMapSettings& sceneTone = scene.tone;
  // A gutter around the image, as flam3 has: points just outside still spread into it through
  // density estimation and the filter.
  const int gutter = static_cast<int>(std::ceil(sceneTone.estimatorRadius + 1.5 * flat.filterRadius)) + 1;
  const int histWidth = (width + 2 * gutter) * oversample, histHeight = (height + 2 * gutter) * oversample;
  const double bucketsPerUnit = pixelsPerUnit * oversample;
  const double left = flat.centerX - (0.5 * width + gutter) / pixelsPerUnit;
  const double top = flat.centerY - (0.5 * height + gutter) / pixelsPerUnit;
  const bool hasCamera = flat.hasCamera();
  const FlatCamera camera(flat);
  const double turn = flat.rotateDeg * std::numbers::pi / 180.0;
  const double cosTurn = std::cos(turn), sinTurn = std::sin(turn);
  // JWildfire's camera turns by `rotate` itself (about the origin).
  const bool turned = flat.rotateDeg != 0.0 && !(hasCamera && camera.jwildfire);
  // flam3's histogram (rect.c) reaches beyond the image by the spatial filter's gutter or, when
  // larger, the density estimator's radius: points further out are not drawn, so neither filter
  // spreads anything from them into the picture.
  const int filterGutter = (spatialFilterTaps(oversample, flat.filterRadius) - oversample) / 2;
  const int estimatorGutter =
      sceneTone.estimatorRadius > 0.0
          ? static_cast<int>(std::ceil(std::min(sceneTone.estimatorRadius, 1e6))) * oversample + oversample - 1
          : 0;
  const double drawnGutter = std::max(filterGutter, estimatorGutter);
  const double drawnLeft = gutter * oversample - drawnGutter, drawnRight = (gutter + width) * oversample + drawnGutter;
  const double drawnTop = gutter * oversample - drawnGutter, drawnBottom = (gutter + height) * oversample + drawnGutter;

  // The chaos game in independent tasks, each into its own histogram (hits, then red, green and
  // blue weighted by hits), summed afterwards; the task count is fixed by the core count and a
  // memory cap, so a render is the same on every run of one machine.
  const double histogramBytes = 16.0 * histWidth * histHeight;
  const int tasks = static_cast<int>(std::clamp(std::floor(kMaxHistogramBytes / histogramBytes), 1.0,
                                                static_cast<double>(std::max(1, taskConcurrency()))));
  std::vector<DensityImage> histograms(static_cast<std::size_t>(tasks));
  const auto total = static_cast<std::uint64_t>(std::llround(samples));
  std::atomic<bool> cancelled{false};
  parallelFor(static_cast<std::size_t>(tasks), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t task = begin; task < end; ++task) {
      DensityImage& histogram = histograms[task];
      histogram.resize(histWidth, histHeight);
      const std::uint64_t quota = total / tasks + (task < total % tasks ? 1 : 0);
      SplitMix64 rng(options.seed * 0x9e3779b97f4a7c15ULL + task + 1);
      ChaosLanes lanes;
      const auto draw = [&](std::size_t i, double x, double y, double z, double colour) {
        const glm::vec3 c = paintsRgb ? flatPointColour(palette, colour, flat.paletteMode, lanes.rgb[i])
                                      : flatPaletteColour(palette, colour, flat.paletteMode);
        for (const Affine3& image : postSymmetry) {
          const glm::dvec3 q = image.apply({x, y, z});
          double px = q.x, py = q.y;
          if (hasCamera) {
            const double angle = camera.dofScale != 0.0 ? rng.uniform() : 0.0;
            const double blur = camera.dofScale != 0.0 ? rng.uniform() : 0.0;
            const glm::dvec2 p = camera.project(px, py, q.z, angle, blur);
            px = p.x;
            py = p.y;
          }
          if (turned) {
            const double dx = px - flat.centerX, dy = py - flat.centerY;
            px = dx * cosTurn - dy * sinTurn + flat.centerX;
            py = dx * sinTurn + dy * cosTurn + flat.centerY;
          }
          const double bx = (px - left) * bucketsPerUnit, by = (py - top) * bucketsPerUnit;
          if (!(bx >= drawnLeft && by >= drawnTop && bx < drawnRight && by < drawnBottom)) continue;
          float* v = histogram.at(static_cast<int>(bx), static_cast<int>(by));
          v[0] += c.r;
          v[1] += c.g;
          v[2] += c.b;
          v[3] += 1.0f;
        }
      };
      const auto nothing = [](std::size_t) {};
      if (!runFlatTask(game, rng, quota, options, cancelled, lanes, nothing, nothing, draw)) return;
    }
  });
  if (cancelled) throw FlatRenderCancelled{};

  // flam3's k2 (rect.c): log(1 + k2 · hits) with k2 = oversample² / (area · sample density), the
  // area in flame units². The finisher's log takes D = k2 · hits / its own density scale.
  const double area = static_cast<double>(width) * height / (pixelsPerUnit * pixelsPerUnit);
  const double k2 = static_cast<double>(oversample * oversample) / (area * sampleDensity);
  DensityImage& sum = histograms.front();
  const auto toDensity = static_cast<float>(k2 / kFinisherDensityScale);
  parallelFor(static_cast<std::size_t>(histHeight), 16, [&](std::size_t begin, std::size_t end) {
    const std::size_t row = 4 * static_cast<std::size_t>(histWidth);
    for (std::size_t y = begin; y < end; ++y)
      for (std::size_t p = y * row; p < (y + 1) * row; ++p) {
        float value = sum.values[p];
        for (std::size_t t = 1; t < histograms.size(); ++t) value += histograms[t].values[p];
        sum.values[p] = value * toDensity;
      }
  });
  sum.hitsPerUnitDensity = kFinisherDensityScale / k2;
  sum.wholeHits = true;

  FinishSettings finish;
  finish.tone = sceneTone;
  finish.tone.brightness *= kFlam3BrightnessFactor;
  finish.oversample = oversample;
  finish.filterRadius = flat.filterRadius;
  finish.flam3KernelTruncation = true;
  // JWildfire's background transforms: the picture sits under the output pixels, not the gutter.
  const std::vector<glm::vec3> picture = backgroundPicture(scene, width, height, options.seed);
  std::vector<glm::vec3> behind;
  if (!picture.empty()) {
    behind.assign(static_cast<std::size_t>(sum.width / oversample) * (sum.height / oversample),
                  glm::clamp(linearToSrgb(sceneTone.background), glm::vec3(0.0f), glm::vec3(1.0f)));
    const std::size_t finishedWidth = static_cast<std::size_t>(sum.width / oversample);
    for (int y = 0; y < height; ++y)
      std::copy_n(picture.begin() + static_cast<std::ptrdiff_t>(y) * width, width,
                  behind.begin() + static_cast<std::ptrdiff_t>((y + gutter) * finishedWidth + gutter));
    finish.backgroundPicture = &behind;
  }
  const FinishedImage finished = finishImage(sum, finish);

  FlatRenderResult result;
  result.samples = total;
  result.quality = quality;
  result.image.width = width;
  result.image.height = height;
  result.image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    std::copy_n(finished.image.at(gutter, y + gutter), 4 * static_cast<std::size_t>(width), result.image.at(0, y));
    for (int x = 0; x < width; ++x) {
      float* pixel = result.image.at(x, y);
      for (int channel = 0; channel < 3; ++channel) pixel[channel] = flatPixelLevel(pixel[channel], options.bitDepth);
    }
  }
  return result;
}

}  // namespace voxflame::core
