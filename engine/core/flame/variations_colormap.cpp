// JWildfire's colormap_wf (AbstractColorMapWFFunc): the point is not moved; it takes its colour (and,
// with scale_z, its height) from a picture laid over the plane. JWildfire reads the picture from an image
// the flame inlines (the hex of the file's bytes, kept as that hex text here), else from a file it names;
// with neither it paints from its default picture, GradientCreator's 256 × 256 four-corner gradient (red
// top left, yellow top right, cyan bottom left, blue bottom right), drawn here exactly as GradientCreator
// draws it (10-bit fixed point steps). An inlined PNG is decoded; a file the flame only names (which is
// not in the flame) and an inlined picture that is not a PNG cannot be followed: the import names them
// lost and the default picture stands in (xml.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/flame/subflame.h"
#include "core/flame/variation_kernels.h"
#include "core/flame/variations_colormap.h"
#include "core/image_io.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

constexpr std::int32_t kSide = 256;  // the default picture's width and height

// GradientCreator.fillImage for a width × height picture of four corner colours: each row's ends are
// interpolated down the left and right edges, then the row between them, all in steps of 1/1024 that
// are truncated (Java's integer division and arithmetic shift, which C++20's >> is too); the first and
// last rows and columns take the corners' colours exactly. Pixels are r | g << 8 | b << 16.
std::array<std::uint32_t, kSide * kSide> buildDefaultPicture() {
  constexpr std::int32_t kCorner[4][3] = {{255, 0, 0}, {255, 255, 0}, {0, 255, 255}, {0, 0, 255}};  // UL UR LL LR
  constexpr int kPrecision = 10;
  std::array<std::uint32_t, kSide * kSide> picture{};
  const auto put = [&](std::int32_t column, std::int32_t row, const std::int32_t(&c)[3]) {
    picture[static_cast<std::size_t>(row * kSide + column)] = static_cast<std::uint32_t>(c[0] & 255) |
                                                              static_cast<std::uint32_t>(c[1] & 255) << 8 |
                                                              static_cast<std::uint32_t>(c[2] & 255) << 16;
  };
  std::int32_t leftStep[3], rightStep[3];
  for (int c = 0; c < 3; ++c) {
    leftStep[c] = ((kCorner[2][c] - kCorner[0][c]) << kPrecision) / (kSide - 1);
    rightStep[c] = ((kCorner[3][c] - kCorner[1][c]) << kPrecision) / (kSide - 1);
  }
  for (std::int32_t i = 0; i < kSide; ++i) {
    std::int32_t left[3], right[3];
    for (int c = 0; c < 3; ++c) {
      if (i == 0) {
        left[c] = kCorner[0][c];
        right[c] = kCorner[1][c];
      } else if (i == kSide - 1) {
        left[c] = kCorner[2][c];
        right[c] = kCorner[3][c];
      } else {
        left[c] = ((i * leftStep[c]) >> kPrecision) + kCorner[0][c];
        right[c] = ((i * rightStep[c]) >> kPrecision) + kCorner[1][c];
      }
    }
    std::int32_t step[3], sum[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) step[c] = ((right[c] - left[c]) << kPrecision) / (kSide - 1);
    put(0, i, left);
    for (std::int32_t j = 1; j < kSide - 1; ++j) {
      std::int32_t value[3];
      for (int c = 0; c < 3; ++c) {
        sum[c] += step[c];
        value[c] = (sum[c] >> kPrecision) + left[c];
      }
      put(j, i, value);
    }
    put(kSide - 1, i, right);
  }
  return picture;
}

const std::array<std::uint32_t, kSide * kSide>& defaultPicture() {
  static const std::array<std::uint32_t, kSide* kSide> picture = buildDefaultPicture();
  return picture;
}

// A picture colormap_wf reads: width × height pixels, rows top to bottom, each r | g << 8 | b << 16 | a << 24.
struct Picture {
  std::int32_t width = kSide, height = kSide;
  std::vector<std::uint32_t> pixels;
  const std::string* source = nullptr;  // the inlined hex it was decoded from (nullptr: the default picture)
  std::size_t sourceSize = 0;
  std::string sample;  // bytes of that text at fixed places, which tell two texts of one size apart cheaply
};

std::string sampleOf(const std::string& text) {
  std::string sample;
  for (std::size_t k = 0; k < 64 && !text.empty(); ++k) sample += text[k * (text.size() - 1) / 63];
  return sample;
}

std::shared_ptr<Picture> defaultPictureOnly() {
  auto picture = std::make_shared<Picture>();
  const auto& pixels = defaultPicture();
  picture->pixels.reserve(pixels.size());
  for (std::uint32_t p : pixels) picture->pixels.push_back(p | 0xff000000u);
  return picture;
}

// The picture for colormap_wf's inlined image (its hex text), or the default one when there is none or it is
// not a PNG (the import names that).
std::shared_ptr<Picture> buildPicture(const std::string& inlined) {
  std::shared_ptr<Picture> picture;
  try {
    const std::optional<std::string> bytes = decodeJwildfireResource(inlined);
    if (bytes) {
      const PngInfo png = readPngBytes(*bytes, "colormap_wf's inlined picture", kMaxColormapPixels);
      picture = std::make_shared<Picture>();
      picture->width = png.image.width;
      picture->height = png.image.height;
      picture->pixels.resize(png.image.pixels.size() / 4);
      for (std::size_t k = 0; k < picture->pixels.size(); ++k) {
        std::uint32_t packed = 0;
        for (int c = 0; c < 4; ++c)
          packed |=
              static_cast<std::uint32_t>(std::lround(std::clamp(png.image.pixels[4 * k + c], 0.0f, 1.0f) * 255.0f))
              << (8 * c);
        picture->pixels[k] = packed;
      }
    }
  } catch (const Error&) {
    picture.reset();
  }
  if (!picture || picture->pixels.empty()) picture = defaultPictureOnly();
  picture->source = &inlined;
  picture->sourceSize = inlined.size();
  picture->sample = sampleOf(inlined);
  return picture;
}

// The picture for these texts: each thread keeps the last one it used, and a few are kept for all threads,
// so a render decodes an inlined picture once. A picture is known by the text object it came from, its size
// and a sample of its bytes, which spares comparing a large text at every call.
std::shared_ptr<const Picture> pictureFor(const std::string* inlined) {
  static const std::shared_ptr<const Picture> fallback = defaultPictureOnly();
  if (!inlined || inlined->empty()) return fallback;
  const auto same = [&](const Picture& p) {
    return p.source == inlined && p.sourceSize == inlined->size() && p.sample == sampleOf(*inlined);
  };
  thread_local std::shared_ptr<const Picture> last;
  static RecentBuilds<Picture> pictures(4);
  return pictures.get(last, same, [&] { return buildPicture(*inlined); });
}

// JWildfire's Tools.FTOI: rounds half away from zero, through Java's saturating (int); NaN gives 0.
inline std::int32_t ftoi(double value) {
  if (value > 0.0) return javaInt(value + 0.5);
  if (value < 0.0) return javaInt(0.0 - (std::abs(value) + 0.5));
  return 0;
}

// JWildfire's tiling of a pixel index into [0, side): an index below 0 is moved up by (index / side − 1)
// sides (Java's truncating division, wrapping int arithmetic), one at or past side down by index / side
// sides. The first lands a multiple of side exactly one side too far (−256 becomes 256), which then
// falls outside the picture as in JWildfire.
inline std::int32_t tiled(std::int32_t index, std::int32_t side) {
  if (index < 0) return wrapAdd(index, -wrapMul(wrapAdd(index / side, -1), side));
  if (index >= side) return wrapAdd(index, -wrapMul(index / side, side));
  return index;
}

struct Channels {
  double r = 0.0, g = 0.0, b = 0.0, a = 0.0;
};

inline Channels pixel(const Picture& picture, std::int32_t column, std::int32_t row) {
  const std::uint32_t p = picture.pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(picture.width) +
                                         static_cast<std::size_t>(column)];
  return {static_cast<double>(p & 255u), static_cast<double>(p >> 8 & 255u), static_cast<double>(p >> 16 & 255u),
          static_cast<double>(p >> 24)};
}

// colormap_wf (see the catalogue's formula below). Parameters: scale_x, scale_y, scale_z, offset_x,
// offset_y, offset_z, tile_x, tile_y, reset_z, dc_color, blend_colormap, with_alpha, is_sequence,
// sequence_start, sequence_digits (the last three only pick a file of an image sequence).
VOXFLAME_VARIATION_TARGETS void colormapWf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double scaleX = P[0], scaleY = P[1], scaleZ = P[2], offsetX = P[3], offsetY = P[4], offsetZ = P[5];
  const bool tileX = ftoi(P[6]) == 1, tileY = ftoi(P[7]) == 1, resetZ = ftoi(P[8]) != 0;
  const std::int32_t dcColor = ftoi(P[9]);
  const bool blend = ftoi(P[10]) > 0, withAlpha = ftoi(P[11]) > 0;
  std::uint8_t* __restrict hidden = in.hidden;
  std::uint32_t* __restrict rgb = dcColor == 0 ? in.rgb : nullptr;
  const std::uint32_t* palette = dcColor > 0 ? in.palette : nullptr;
  // In place for a pre_ or post_ term (JWildfire changes the point it is handed, and keeps x and y); an
  // ordinary term adds nothing to the sum's x and y.
  const bool inPlace = in.stage != VariationStage::Normal;
  const std::shared_ptr<const Picture> held = pictureFor(in.texts ? &in.texts[1] : nullptr);
  const Picture& picture = *held;
  const std::int32_t width = picture.width, height = picture.height;
  const bool resets = resetZ;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = (x[i] - (offsetX + 0.5) + 1.0) / scaleX * static_cast<double>(width - 2);
    const double v = (y[i] - (offsetY + 0.5) + 1.0) / scaleY * static_cast<double>(height - 2);
    std::int32_t column = blend ? javaInt(std::trunc(u)) : ftoi(u);
    std::int32_t row = blend ? javaInt(std::trunc(v)) : ftoi(v);
    if (tileX) column = tiled(column, width);
    if (tileY) row = tiled(row, height);
    Channels c;
    if (column >= 0 && column < width && row >= 0 && row < height) {
      if (blend) {
        // Bilinear between the pixel and its right, lower and lower-right neighbours (transparent black
        // past the last column or row) by the fractions u − trunc u, v − trunc v, which are negative for
        // negative u, v: JWildfire extrapolates there, and so does this.
        const double fu = u - std::trunc(u), fv = v - std::trunc(v);
        const Channels lu = pixel(picture, column, row);
        const Channels ru = column < width - 1 ? pixel(picture, column + 1, row) : Channels{};
        const Channels lb = row < height - 1 ? pixel(picture, column, row + 1) : Channels{};
        const Channels rb = column < width - 1 && row < height - 1 ? pixel(picture, column + 1, row + 1) : Channels{};
        const auto blerp = [&](double a, double b, double c2, double d) {
          const double top = a + (b - a) * fu, bottom = c2 + (d - c2) * fu;
          return top + (bottom - top) * fv;
        };
        c = {blerp(lu.r, ru.r, lb.r, rb.r), blerp(lu.g, ru.g, lb.g, rb.g), blerp(lu.b, ru.b, lb.b, rb.b),
             blerp(lu.a, ru.a, lb.a, rb.a)};
      } else {
        c = pixel(picture, column, row);
      }
    }
    // dc_color 0: the point is painted the picture's colour (black outside it); JWildfire keeps the
    // blended channels unrounded, a painted colour here holds bytes, so they are rounded and held in 0–255.
    if (rgb) {
      const auto byte = [](double value) {
        return static_cast<std::uint32_t>(std::clamp(static_cast<double>(ftoi(value)), 0.0, 255.0));
      };
      rgb[i] = paintedRgb(byte(c.r), byte(c.g), byte(c.b));
    }
    // dc_color > 0: the colour index of the render palette's entry nearest to it; below 0 neither.
    // JWildfire's getColorIdx matches against its render palette: the gradient scaled by 200/256.
    if (palette)
      colour[i] =
          static_cast<double>(nearestPaletteEntry(palette, ftoi(c.r), ftoi(c.g), ftoi(c.b), 200.0 / 256.0)) / 255.0;
    // JWildfire's doHide: with_alpha hides the point on a pixel of alpha at most 0.1 (outside the picture, or a
    // transparent pixel of an inlined one; the default picture is opaque), and without it a colormap_wf term
    // shows the point again.
    if (hidden) hidden[i] = withAlpha && c.a <= 0.1 ? 1u : 0u;
    double dz = offsetZ;
    if (std::abs(scaleZ) > kJwfEpsilon) dz += scaleZ * (0.299 * c.r + 0.588 * c.g + 0.113 * c.b) / 255.0;
    outX[i] += inPlace ? x[i] : 0.0;  // not 0 · x, which a NaN point would make NaN
    outY[i] += inPlace ? y[i] : 0.0;
    // reset_z replaces the z of the terms before it (an ordinary term rewrites the running sum,
    // VariationInfo::readsSum; a pre_/post_ term's own z); otherwise dz is added to it.
    outZ[i] = resets ? dz : outZ[i] + (inPlace ? z[i] : 0.0) + dz;
  }
}

// colormap_wf's picture for a backend of its own: its width and height, then each pixel's red,
// green, blue and alpha (0–255), row by row.
std::vector<double> colormapTable(const double*, const std::string* texts) {
  const std::shared_ptr<const Picture> held = pictureFor(texts ? &texts[1] : nullptr);
  const Picture& picture = *held;
  std::vector<double> table = {static_cast<double>(picture.width), static_cast<double>(picture.height)};
  table.reserve(2 + 4 * picture.pixels.size());
  for (const std::uint32_t p : picture.pixels)
    for (int channel = 0; channel < 4; ++channel) table.push_back(static_cast<double>(p >> (8 * channel) & 255u));
  return table;
}

}  // namespace

std::string colormapPictureProblem(const std::string& inlinedHex) {
  if (inlinedHex.empty()) return {};
  const std::optional<std::string> bytes = decodeJwildfireResource(inlinedHex);
  if (!bytes) return "its inlined picture is not JWildfire's hex of a file";
  try {
    readPngBytes(*bytes, "the inlined picture", kMaxColormapPixels);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

void variation_kernels::addColormapVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k3D = CatalogueAdder::k3D, kFixed = CatalogueAdder::kFixed;
  const auto count = &CatalogueAdder::count;
  add("colormap_wf",
      "adds nothing to x and y (a pre_/post_ term keeps them); samples JWildfire's default picture (the 256 × "
      "256 four-corner gradient red, yellow / cyan, blue) at pixel (u, v) = ((p − offset − ½ + 1)/scale · 254), "
      "rounded (blend_colormap: truncated and bilinearly blended), tiled with tile_x/y = 1 (else black outside); "
      "dc_color 1: colour index of the nearest entry of the palette scaled by 200/256, 0: paints the point that "
      "colour; with_alpha hides points on transparent pixels (outside the picture), which stay hidden until a "
      "colormap_wf term shows them; z = dz (reset_z) or z + dz, dz = offset_z + scale_z (0.299 R + 0.588 G + 0.113 "
      "B)/255. An inlined PNG (inlined_image, the hex of its bytes) replaces the default picture, scaled by its "
      "size − 2; a picture file only named is not read (the import names it lost)",
      k3D, kFixed, &colormapWf,
      {{"scale_x", 1.0, 0.5, 2.5},
       {"scale_y", 1.0, 0.5, 2.5},
       {"scale_z", 0.0, -0.3, 0.3},
       {"offset_x", 0.0, 0.0, 1.0},
       {"offset_y", 0.0, 0.0, 1.0},
       {"offset_z", 0.0, 0.0, 1.0},
       count("tile_x", 1.0, 0.0, 1.0),
       count("tile_y", 1.0, 0.0, 1.0),
       count("reset_z", 1.0, 0.0, 1.0),
       count("dc_color", 1.0, 0.0, 1.0),
       count("blend_colormap", 0.0, 0.0, 1.0),
       count("with_alpha", 0.0, 0.0, 1.0),
       count("is_sequence", 0.0, 0.0, 1.0),
       count("sequence_start", 1.0, 0.0, 10000.0),
       count("sequence_digits", 4.0, 1.0, 8.0)});
  catalogue.back().textParams = {
      {"image_filename", ""}, {"inlined_image", ""}, {"image_desc_src", ""}, {"image_src", ""}};
  catalogue.back().directColour = true;
  catalogue.back().readsSum = true;
  catalogue.back().paintsRgb = true;
  catalogue.back().hidesPoints = true;
  catalogue.back().table = &colormapTable;
}

}  // namespace voxflame::core
