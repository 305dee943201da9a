// The flat view: a scene's flame layer rendered in 2D the way flam3 frames and renders it
// (flam3's rect.c), so an imported flame can be compared with what its author saw. No mesh, no
// depth: the chaos game runs over the genome's transforms in the plane (x, y); the camera maps
// flame units to pixels at scale · 2^zoom pixels per unit, turned by `rotate` about the centre;
// points fall into an oversampled histogram with a gutter around the image; the sample count is
// flam3's: quality · 4^zoom per output pixel. The histogram is then finished by the same flam3
// finisher the 3D renders use (flame/image.h): density estimation, log density, the spatial
// filter, gamma, vibrancy, highlight power and the background.
//
// The palette and the background are used as flam3 uses them: the file's colour values averaged
// as they are (the import stored them as linear RGB; they are encoded back), with gamma applied
// to the density only.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image_io.h"
#include "core/flame/variations.h"
#include "core/scene.h"

namespace voxflame::core {

struct FlatRenderOptions {
  // The output size; 0 takes the flat view's. One side alone keeps the flame's aspect ratio, and
  // the framing scales with the image, as flam3-render's size scale (ss) does.
  int width = 0, height = 0;
  std::optional<double> quality;  // samples per output pixel; none: the flat view's
  std::uint64_t seed = 1;
  // The PNG bit depth the image is for (8 or 16): its values are put on flam3's levels for it
  // (flatPixelLevel), so the file holds what flam3-render's would.
  int bitDepth = 8;
  const std::atomic<bool>* cancel = nullptr;  // when set to true, renderFlat throws RenderCancelled
};

struct FlatRenderResult {
  ImageRGBA image;  // display-encoded, rows top to bottom
  std::uint64_t samples = 0;
  double quality = 0.0;
};

struct FlatRenderCancelled {};

// The output size for these options: the flat view's, or as asked (see FlatRenderOptions).
// Throws core::Error for a size that is not positive or too large.
void flatRenderSize(const FlatViewSettings& flat, const FlatRenderOptions& options, int& width, int& height);

// Renders the scene's first flame layer flat. Throws core::Error when the scene has none, or for a
// size or quality out of range (not positive, not finite, beyond 65536 pixels a side or 10¹²
// samples).
// The colour flam3 deposits for a colour index (rect.c): in step mode the entry ⌊index · 256⌋, in
// linear mode entries i and i + 1 around index · 256 blended by its fraction; an index below 0
// takes entry 0 and one at or past 255/256 entry 255 in both modes.
glm::vec3 flatPaletteColour(const std::array<glm::vec3, 256>& palette, double index, PaletteMode mode);
// A drawn point's colour: the true colour a variation painted it (ChaosLanes::rgb, VariationInput::rgb's
// packing, when kRgbPainted is set), else its colour index's as above.
glm::vec3 flatPointColour(const std::array<glm::vec3, 256>& palette, double index, PaletteMode mode, std::uint32_t rgb);

// flam3's output levels (rect.c): a channel value v (1 standing for its 256) becomes
// a = min(256 v, 255), written as ⌊a⌋ in 8 bits and ⌊256 a⌋ in 16; returned as the fraction of
// the largest value that a PNG writer rounds back to exactly that level. Truncating rather than
// rounding makes a dim flame's mean half a level darker: a tenth at a mean of five levels.
float flatPixelLevel(float value, int bitDepth);

FlatRenderResult renderFlat(const Scene& scene, const FlatRenderOptions& options = {});

// The flat view's 3D camera (FlatViewSettings), projecting a drawn point (x, y, z) into the plane.
// angle01 and blur01 are uniform draws in [0, 1) for depth of field. With R_a the turn by a about
// an axis (right-handed: R_z(a) takes (1, 0, 0) to (cos a, sin a, 0)):
//  * Apophysis 3D's and Fractorium's (Ember::ProjectPitchYaw and its depth blur): q = R_x(pitch)
//    R_z(−yaw) (p − (0, 0, z₀)); with depth of field (x, y) first moves by blur01 · 0.1 dof · q_z
//    towards angle01 · 2π; then divided by 1 − perspective · q_z.
//  * JWildfire's (FlameRendererView's camera matrix and project): q = R_z(rotate) R_x(pitch)
//    R_y(bank) R_z(−yaw) p + c, c the camera position; zr = 1 − perspective · q_z + c_z, a point
//    with zr below 10⁻⁸ is not drawn (NaN). With depth of field the point moves by a blur of
//    radius ρ = 0.1 dof · scale · D before the division, where D is
//      - legacy: the depth in front of the depth in focus, z₀ − q_z, for points with D > 0;
//      - new_dof: d = (|q − focus|²)^(1/exponent): D = d beyond `area`, D = S(t) d between
//        area − area/2.25 and area with t the place in that band and S the smootherstep
//        t³(6t² − 15t + 10), none nearer (sharp).
//    The blur is its shape's (JWildfire's DOFBlurShape) with f = JWildfire's fade draw: Ψ for
//    fade ≥ 1, 1 for fade 0, and between them a fresh Ψ for the share `fade` of the points, else 1:
//      bubble: f ρ towards a random angle (f drawn from blur01, the angle from angle01);
//      rect: f ρ (Ψ₁ − ½, Ψ₂ − ½), x times width (param1);
//      cloverleaf, cannabiscurve: |f₂ ρ| V(s), V the catalogue's filled (filled = 1) curve at
//        s = f₁ (1 − 2Ψ₁, 1 − 2Ψ₂);
//      heart: |f ρ| xheart(2 − 4Ψ₁, 2 − 4Ψ₂) with angle, ratio (param1, 2);
//      flower: 2 |f ρ| flower(1 − 2Ψ₁, 1 − 2Ψ₂) with holes, petals (param1, 2);
//      nblur, perlin_noise, sineblur, starblur: f ρ V(q) of the catalogue's nBlur, dc_perlin,
//        sineblur, starblur with their parameters (camera_dof_shape's help lists them);
//      taurus: ¼ |f ρ| taurus(f (2π − 4πΨ₁), f (2π − 4πΨ₂)) with r, n, inv, sor;
//    each offset but bubble's and sineblur's turned by the shape's rotate. The draws after angle01
//    and blur01 come from a generator seeded by those two. The picture's `rotate` is part of this
//    camera (about the origin), so the flat view does not turn the picture again.
struct FlatCamera {
  explicit FlatCamera(const FlatViewSettings& flat);
  glm::dvec2 project(double x, double y, double z, double angle01, double blur01) const;
  // The point without depth of field: JWildfire's solid rendering moves points by the camera only.
  glm::dvec2 projectSharp(double x, double y, double z) const;
  // The turned point's depth (larger is nearer the eye), as JWildfire's z-buffer keeps it.
  double depth(double x, double y, double z) const;
  // The blur's offset (before the perspective division) for a turned point (px, py) at blur
  // distance D (JWildfire's dofDist), as above.
  glm::dvec2 dofOffset(double px, double py, double distance, double angle01, double blur01) const;
  bool jwildfire = false;
  std::array<std::array<double, 3>, 3> turn{};  // rows: the turned point's x, y and depth
  glm::dvec3 position{0.0};                     // JWildfire's c
  double z0 = 0.0, perspective = 0.0, dofScale = 0.0, dofFade = 1.0;
  // JWildfire's new_dof (FlatViewSettings::cameraDofNew).
  bool newDof = false;
  glm::dvec3 focus{0.0};
  double area = 0.5, fadeBand = 0.5 / 2.25, inverseExponent = 0.5;
  FlatDofShape shape = FlatDofShape::Bubble;
  bool shapeTurned = false;
  double shapeCos = 1.0, shapeSin = 0.0;
  double rectWidth = 0.0;
  const VariationInfo* shapeVariation = nullptr;  // the catalogue's variation the shape draws with
  std::vector<double> shapeParams;                // its parameters, in the catalogue's order

 private:
  glm::dvec2 projectTurned(double x, double y, double z, bool blurred, double angle01, double blur01) const;
};

}  // namespace voxflame::core
