// Importing flame files: the XML genomes that flam3, Apophysis, Fractorium and JWildfire write
// (.flame, .flam3). A file holds one or many <flame> elements under any root; each becomes a
// FlameGenome plus what a scene needs besides: a name, a 256-colour palette (inline <color>
// entries, a hex <palette>/<colors> block, or flam3's built-in palette number resolved from the
// palette table of Debian's flam3 package) and the tone keys flam3 and voxflame share.
//
// flam3 writes an affine map as coefs="a d b e c f", meaning x' = a x + b y + c, y' = d x + e y + f;
// the reader puts a, b, c, d, e, f into Affine3's first two rows (flame.h). Variations are the
// attributes of an <xform> that name a variation of the catalogue (flame/variations.h), their
// parameters `<variation>_<parameter>` attributes (julian_power, ngon_sides); `chaos` is the
// transform's xaos. An attribute that names a catalogue variation is that variation, never a
// parameter of a shorter one (blur_square beside blur); one that extends a known variation's name
// without being one of its parameters is an unknown variation. Files that are not well-formed
// XML (JWildfire's attribute names with spaces or `#`, stray closing tags) are read again
// tolerantly. What voxflame does not know (a variation, a background transform) is left out,
// reported as a warning (the unknown variations all in one) and listed in ImportedFlame::leftOut;
// what would make the flame meaningless (no transforms, only zero weights, coefficients that are
// not finite or beyond ±1e6) is a core::Error naming the file and the transform.
//
// Motion becomes keyframes (ImportedFlame::keyframes): flam3's <motion> elements (periodic
// offsets, motion_function sin, triangle, hill or Fractorium's saw, over a loop of 128 frames at
// 30 fps) and JWildfire's motion curves (points frame → value of a transform's weight, colour,
// colour symmetry, opacity, xy coefficients, a variation's amount or parameter, a layer's weight),
// each with its interpolation as near as keyframes come (JWildfire's SPLINE and BEZIER are played
// as Catmull-Rom curves through the same points); the warnings say what was approximated.
//
// Flames are 2D. A flat one (no 3D variation, no z coefficient) gains depth on import
// (addFlameDepth): the z row of every transform becomes z' = ½ z + depth · s, with s from −1 for
// the transform of lowest colour to +1 for the highest, so a point's depth is a binary-fraction-like
// record of the transforms it went through: a fractal stack of layers, coloured like the flame,
// that fills a volume. It is nothing but affine coefficients, so it stays editable after import.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/color.h"
#include "core/flame/flame.h"
#include "core/scene.h"

namespace voxflame::core {

// Where Debian's flam3 package keeps flam3's 701 built-in palettes (palette="N" in a flame file).
inline constexpr const char* kFlam3PaletteTable = "/usr/share/flam3/flam3-palettes.xml";
inline constexpr double kDefaultFlameDepth = 0.5;
inline constexpr double kMaxFlameDepth = 10.0;
inline constexpr std::size_t kFlamePaletteSize = 256;
inline constexpr double kMaxImportedLayerWeight = 1000.0;  // a scene layer's largest weight

struct FlameImportOptions {
  std::filesystem::path paletteTable = kFlam3PaletteTable;
  double depth = kDefaultFlameDepth;  // addFlameDepth's depth for flat flames; 0 keeps them flat
  std::size_t index = 0;              // which <flame> of the file (0-based), unless `name` is set
  std::string name;                   // pick the flame with this name attribute instead
};

// One more layer of a layered flame (JWildfire's <layer>s after the first visible one).
struct ImportedFlameLayer {
  FlameGenome genome;
  std::vector<GradientStop> palette;  // as ImportedFlame::palette
  double weight = 1.0;                // relative to ImportedFlame::weight
  bool depthAdded = false;
};

struct ImportedFlame {
  std::string name;
  // The flame's genome and palette; for a JWildfire flame of several layers, its first visible
  // layer's, the others in otherLayers.
  FlameGenome genome;
  std::vector<GradientStop> palette;  // kFlamePaletteSize stops at i/255, linear RGB
  double weight = 1.0;                // the layer weight (JWildfire's layer weight × density²)
  std::vector<ImportedFlameLayer> otherLayers;
  ToneMapSettings tone;     // flam3's defaults, then the file's keys
  FlatViewSettings flat;    // flam3's 2D framing: size, center, scale, zoom, quality, ...
  bool depthAdded = false;  // addFlameDepth changed the genome
  // flam3's <motion> and JWildfire's motion curves as keyframes of the scene sceneFromImportedFlame
  // makes (paths /layers/L/flame/xforms/J/...: L 0 for the flame, 1... for otherLayers), with
  // their timing; empty when the flame does not move.
  std::vector<KeyframeTrack> keyframes;
  AnimationSettings animation;
  std::vector<std::string> warnings;  // what was left out or replaced, for the user
  // What the file asks for that the import could not keep, one short name each, sorted
  // ("variation crackle", "xaos", "<motion>"): empty when the flame was imported whole. The
  // corpus tally counts these; `warnings` says the same in sentences.
  std::vector<std::string> leftOut;
};

struct FlameFileContents {
  std::vector<std::string> names;  // every <flame> of the file, in order (name or "flame N")
  std::size_t index = 0;           // the one imported
  ImportedFlame flame;
};

// Reads the flame selected by `options` from the XML `text`; `sourceName` (a path) is what
// messages call it. Throws core::Error.
FlameFileContents readFlameXml(std::string_view text, const std::string& sourceName,
                               const FlameImportOptions& options = {});
FlameFileContents loadFlameFile(const std::filesystem::path& path, const FlameImportOptions& options = {});

// True for the extensions flame files use: .flame, .flam3 (any case).
bool isFlameFilePath(const std::filesystem::path& path);

// Whether no transform (the final one included) has a 3D variation or a z coefficient: such a
// genome iterates in the plane z = const.
bool isFlatFlame(const FlameGenome& genome);

// Gives a flat genome depth as described above (depth ≥ 0; 0 collapses it onto z = 0); with depth
// > 0 it drops flatten terms, which would set z back to 0. Returns
// false, changing nothing, for a genome that is not flat.
bool addFlameDepth(FlameGenome& genome, double depth);

// A complete scene showing the imported flame: `base` with its layers replaced by one flame layer
// (colour index mode over the flame's palette) and one more per layer of otherLayers, each with
// its weight, the others fitted with the first (FitMode::Previous) so they stay in register; the
// flame's tone keys and 2D framing, its name, the points method (defaultRenderMethod), and the
// flame's motion as keyframes (none when it does not move).
// The first layer's locked fit and every layer's rotation put the flat view's frame in the mesh,
// facing base's camera (presets/SCHEMA.md, "Imported flames"), from a short chaos game of the
// flame for the depth of what it draws inside the frame.
Scene sceneFromImportedFlame(const ImportedFlame& flame, const Scene& base);

}  // namespace voxflame::core
