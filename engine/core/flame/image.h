// The last stage of a fractal flame, made the way flam3 makes it in 2D (Draves & Reckase, "The
// Fractal Flame Algorithm"), shared by both render methods and by the explorer:
//   1. A supersampled *density image* holds what was summed into each pixel: a density D and the
//      colour-weighted density. The volume method integrates D along each pixel's ray through the
//      grid; the points method adds every point that projects into the pixel.
//   2. Log density and density estimation: each pixel's value becomes k1 · log(1 + k2 · D) and is
//      spread over a Gaussian kernel whose radius shrinks as the pixel's hits grow (wide where few
//      points fell, none where many did), so sparse regions turn smooth instead of grainy.
//   3. The spatial filter (a Gaussian of `filter_radius` output pixels) takes the supersampled
//      image down to the output pixels.
//   4. Gamma with a linear threshold, vibrancy and highlight power make the display colour.
// Nothing is log-scaled before it is summed: that is what keeps filaments silky.
//
// D is normalised so an image's brightness does not depend on the number of points, the grid
// resolution, the image size, the supersampling or the number of sub-samples: D is the column
// density of points along the pixel's ray relative to the mean density inside the mesh, with
// lengths in units of the grid's longest side (a ray crossing a uniformly filled mesh over a
// length d has D = d). `hitsPerUnitDensity` converts D back to points per pixel for step 2.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/camera.h"
#include "core/grid.h"
#include "core/image_io.h"
#include "core/scene.h"

namespace voxflame::core {

// Extinction per unit of column density D at tone.opacity 1: a ray through a typical filled mesh
// (D of a few tenths) keeps a third to a half of what lies behind.
inline constexpr double kAbsorptionPerDensity = 4.0;

struct DensityImage {
  int width = 0, height = 0;        // pixels (supersampled)
  std::vector<float> values;        // 4 per pixel, rows top to bottom: red·D, green·D, blue·D, D (linear)
  double hitsPerUnitDensity = 1.0;  // points that a pixel with D = 1 holds
  // How density estimation counts a pixel's points when it picks the pixel's kernel. The renders
  // of the volume (fractional sums along rays): hits + 1. The flat view (whole points, as flam3's
  // filters.c counts them): ⌈hits⌉, so a pixel with one point gets the widest kernel, and with
  // an oversample above 1 the hits of the block of supersampled pixels around it (rect.c).
  bool wholeHits = false;

  void resize(int w, int h);  // zero-filled
  float* at(int x, int y) {
    return &values[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
  }
  const float* at(int x, int y) const {
    return &values[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x))];
  }
};

// The mesh drawn over the pattern (ghost or silhouette), at the output size, rows top to bottom:
// RGBA, rgb the rim colour in linear light, alpha 1 where the mesh covers the pixel.
struct MeshOverlay {
  MeshDisplay mode = MeshDisplay::Off;
  glm::vec3 color{1.0f};  // linear RGB of a silhouette line
  double strength = 0.35;
  int width = 0, height = 0;
  // 4 bytes per pixel, rows top to bottom: the layer is drawn into an 8-bit target, so bytes hold
  // it exactly (a supersampled one averaged down is rounded to them), at a quarter of the memory
  // of floats, which a 16K print needs.
  std::vector<std::uint8_t> rgba;
  float at(std::size_t pixel, int channel) const { return static_cast<float>(rgba[4 * pixel + channel]) / 255.0f; }
};

struct FinishSettings {
  ToneMapSettings tone;
  int oversample = 1;         // supersampled pixels per output pixel along each axis
  double filterRadius = 0.5;  // spatial filter, in output pixels
  bool linearOutput = false;  // linear light (for EXR) instead of display-encoded and clamped
  // Density estimation as flam3-render does it (the flat view, compared with flam3): a kernel of
  // width h spreads over the offsets of at most ⌈h⌉ − 1 pixels along each axis, while its weights
  // are normalised over every offset within h, so a kernel of whole width (the narrowest, 1, where
  // the density is highest) keeps only 1 / (1 + 4 e^(−4.5)) ≈ 96% of its pixel's value.
  bool flam3KernelTruncation = false;
  // A background per output pixel (display values 0–1, rows top to bottom, the output's size) in place of
  // tone.background: JWildfire's background transforms paint one. nullptr: tone.background everywhere.
  const std::vector<glm::vec3>* backgroundPicture = nullptr;
};

struct FinishedImage {
  ImageRGBA image;           // output size, rows top to bottom
  std::vector<float> alpha;  // per output pixel: the pattern's opacity after gamma (0 where empty)
};

// The points a pixel of an image `imageHeight` pixels tall holds where its D is 1, measured at the
// grid's centre: points × (pixel footprint area) / (volume inside the mesh), lengths in grid sides.
double hitsPerUnitDensity(const CameraFrame& camera, const GridGeometry& grid, double points, double insideVoxels,
                          int imageHeight);

// k1 · log(1 + k2 · D): the log density of a pixel, k1 from the tone's brightness.
double logDensity(double density, const ToneMapSettings& tone);

// Step 2 on every pixel: log density, spread by density estimation when tone.estimatorRadius > 0
// (radii in output pixels, scaled by `oversample`). Output: red·L, green·L, blue·L, L per pixel.
void estimateDensity(const DensityImage& in, const ToneMapSettings& tone, int oversample, DensityImage& out,
                     bool flam3KernelTruncation = false);

// Step 3: the Gaussian spatial filter of `radius` output pixels, from the supersampled image to
// width / oversample × height / oversample pixels.
// The width of that filter in supersampled pixels (flam3's filters.c: ⌊2 · support · oversample ·
// radius⌋ + 1, made of the oversample's parity so it stays centred on the pixel).
int spatialFilterTaps(int oversample, double radius);
void spatialFilter(const DensityImage& in, int oversample, double radius, DensityImage& out);

// Steps 2–4 and the mesh overlay (may be null). `in`'s size must be a multiple of the oversample.
FinishedImage finishImage(const DensityImage& in, const FinishSettings& settings, const MeshOverlay* overlay = nullptr);

// The share of the mesh's silhouette (overlay alpha > 0.5) where the pattern shows (alpha at
// least `threshold`); 0 when the mesh covers no pixel.
double silhouetteCoverage(const FinishedImage& image, const MeshOverlay& silhouette, double threshold = 0.1);
// The same for an image that carries the opacity in its fourth channel (finishImageOnGpu's
// alphaInImage), which then becomes opaque (1).
double takeSilhouetteCoverage(ImageRGBA& imageWithAlpha, const MeshOverlay& silhouette, double threshold = 0.1);

// Mean linear luminance (Rec. 709) of a display-encoded image with this gamma.
double meanLuminance(const ImageRGBA& image, double gamma);
// RMS difference of linear luminance between `image` and `reference`, relative to the reference's
// mean luminance: how far a render is from a converged one (0 identical).
double relativeLuminanceRmse(const ImageRGBA& image, const ImageRGBA& reference, double gamma);

}  // namespace voxflame::core
