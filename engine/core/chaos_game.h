// The chaos game that iterates flame and quaternion Julia layers (flame.h) for the Accumulator,
// many independent lanes at a time.
//
// Every lane draws its own transform at every step from its own random generator: lanes that
// shared one draw would all apply the same map and, the maps being contractive, converge onto one
// point. To still vectorise, a step sorts the lanes by the transform they drew (a counting sort),
// gathers each group's points into contiguous arrays, runs the group's affine map and each of its
// variations as one loop over the group (flame/variations.h), and scatters the results back.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/flame/flame.h"
#include "core/flame/variations.h"
#include "random.h"

namespace voxflame::core {

struct PatternLayer;

// The state of a set of chaos-game lanes, structure of arrays, plus the scratch a step needs.
struct ChaosLanes {
  std::vector<double> x, y, z, w;     // the iterated point (w: a quaternion's fourth component)
  std::vector<double> color;          // flam3's colour index, 0–1
  std::vector<std::uint32_t> random;  // each lane's xorshift32 state (never 0)
  std::vector<std::int32_t> visible;  // 1 when this step's point is drawn (opacity, slice)
  // Scratch for one step.
  std::vector<std::uint8_t> choice;  // a transform index: the genome's and symmetry's fit in a byte
  // With xaos: 1 + the transform each lane took last (0 before its first step), which picks the
  // row of the pick table its next choice is drawn from.
  std::vector<std::uint8_t> previous;
  std::vector<std::uint32_t> order;
  std::vector<double> tx, ty, tz, ox, oy, oz;
  std::vector<double> sx, sy, sz;  // a post_ term's result (t is still read then)
  // A direct-colour transform's group: the colour index its variations read and set, and what the
  // colour blend made of it before them (flame.h's directColor blends between the two).
  std::vector<double> gc, gs;
  // Only for a game whose paintsRgb() is true: each lane's drawn point's true colour (what its
  // transform, or a final transform after it, painted: VariationInput::rgb's packing; 0 where none
  // painted it, and the colour index's palette entry stands), and a group's scratch of the same.
  std::vector<std::uint32_t> rgb, groupRgb;
  // Only for a game with a variation that hides points: each lane's JWildfire doHide flag (it lasts from
  // step to step; 0 at a fresh start), and a group's scratch of the same.
  std::vector<std::uint8_t> hidden, groupHidden;
  std::vector<double> field;        // 1 + amount · noise: a weighting field's factor of the variation weights
  std::vector<double> fieldNoise;   // the weighting field's noise n itself (colour and parameters read it)
  std::vector<double> fieldParams;  // scratch: each lane's parameters of a term as the field changes them
  std::vector<std::uint32_t> groupRandom;
  // Memory of the variations that keep some per lane (VariationInfo::laneState), one array per such
  // term of the game (Term::stateSlot), laneState doubles per lane; made on first use, 0 at first.
  std::vector<std::vector<double>> termState;
  void resize(std::size_t lanes);
  std::size_t size() const { return x.size(); }
};

class ChaosGame {
 public:
  // Prepares a flame or quaternion Julia layer; throws core::Error for an invalid one (flame.h's
  // validate functions name the layer as `where`).
  ChaosGame(const PatternLayer& layer, const std::string& where);

  // Puts lane i at a fresh start: a uniform point in [-1, 1]³ (and w), a uniform colour, as
  // flam3 does; the caller lets the lane run through its transient before it draws.
  void seedLane(ChaosLanes& lanes, std::size_t i, SplitMix64& rng) const;

  // One step for lanes [0, count): the state moves; the point to draw (after the final transform,
  // or the quaternion's projection) goes to out, its colour index to outColor, and lanes.visible
  // says whether it is drawn. A lane whose state is no longer finite (or beyond 1e10) gets NaN in
  // out, which the caller treats as an escape and reseeds.
  void step(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor, std::size_t count) const;

  std::size_t transformCount() const { return xforms_.size(); }  // symmetry transforms included
  // Whether lanes.visible can ever be 0 (a translucent transform, a quaternion slice); when not,
  // the caller may skip reading it.
  bool hidesPoints() const { return hidesPoints_; }
  // Whether a variation may paint points a true colour (VariationInfo::paintsRgb): then step fills
  // lanes.rgb, which whoever colours the drawn points reads before the colour index.
  bool paintsRgb() const { return paintsRgb_; }
  // Whether a variation may hide points (VariationInfo::hidesPoints), JWildfire's doHide kept per lane.
  bool hidesPointsByTerm() const { return hidesByTerm_; }

  // What another backend needs to run the same game (the GPU's generated kernel): the pick table
  // (rows of pickSize() entries, each a transform index: one row without xaos, 1 + transforms
  // with it, row 0 for a lane's first step and row k + 1 after transform k), and the maps every
  // drawn point goes through at random (the symmetry group, then JWildfire's post symmetry).
  static constexpr int pickBits() { return kPickBits; }
  static constexpr std::size_t pickSize() { return kPickSize; }
  const std::vector<std::uint8_t>& pickTable() const { return pick_; }
  // The file's palette in bytes (VariationInput::palette), filled for flames whose variations paint
  // true colours: what they compare a painted colour with.
  const std::array<std::uint32_t, 256>& variationPalette() const { return palette_; }
  bool usesXaos() const { return xaos_; }
  const std::vector<std::array<double, 12>>& symmetryGroupMaps() const { return group_; }
  const std::vector<std::array<double, 12>>& postSymmetryImages() const { return postSymmetry_; }

 private:
  struct Term {
    VariationFn apply = nullptr;
    double weight = 1.0;
    std::vector<double> params;
    VariationStage stage = VariationStage::Normal;
    bool mapsXY = true, mapsZ = false, additive = false;                  // how a pre_/post_ form combines
    bool flattens = false;                                                // flatten: z is 0 after this stage
    VariationInfo::Replaces replaces = VariationInfo::Replaces::Nothing;  // as an ordinary term
    bool readsSum = false;                                                // as an ordinary term
    // What the transform's weighting field does to this term besides `field` (weightFieldTerm).
    WeightFieldTerm field;
    std::vector<std::string> texts{};  // its text parameters, all of them
    std::size_t laneState = 0;         // VariationInfo::laneState
    std::size_t stateSlot = 0;         // its array in ChaosLanes::termState when laneState > 0
  };
  struct Compiled {
    std::array<double, 12> affine{};
    bool hasPost = false;
    std::array<double, 12> post{};
    std::vector<Term> terms;  // pre_ terms first, then the others, then post_ ones (each in file order)
    bool hasNormalTerms = false;
    bool drawsRandom = false;  // has a term that draws random numbers (VariationInfo::random)
    double color = 0.0, colorSpeed = 0.5, opacity = 1.0;
    bool directColour = false;  // has a term that reads or sets the colour index (VariationInfo::directColour)
    double directColor = 1.0;
    bool paintsRgb = false;    // has a term that may paint a true colour (VariationInfo::paintsRgb)
    bool hidesByTerm = false;  // has a term that may hide the point (VariationInfo::hidesPoints)
    // A weighting field (flame.h): `field` keeps the transform's field settings (no variations).
    bool hasField = false;
    bool fieldFromPosition = false;
    double fieldColor = 0.0, fieldJitter = 0.0;  // JWildfire's intensities times its 0.1
    FlameXform field;
  };
  // lanes.field for a group: the factor each lane's variation weights take.
  static void fillField(const Compiled& xform, const std::uint32_t* group, std::size_t count, const double* x,
                        const double* y, const double* z, ChaosLanes& lanes);
  // The weighting field's jitter of a group's results o (after the post map), lanes [0, count).
  static void jitterByField(const Compiled& xform, ChaosLanes& lanes, std::size_t count);
  // colour[order[j]] · (1 + fieldColor · n) for the group's lanes: the field's colour.
  static void colourByField(const Compiled& xform, const ChaosLanes& lanes, const std::uint32_t* order,
                            std::size_t count, double* colour);
  static Compiled compile(const FlameXform& xform);
  // Runs one compiled transform's affine map, variations and post map on a contiguous group, whose
  // entry j is lane group[j] (what variations that keep per-lane memory index it by).
  void applyGroup(const Compiled& xform, ChaosLanes& lanes, const std::uint32_t* group, std::size_t count) const;
  // A direct-colour transform's colour: lanes.gc as the colour blend of `color` makes it (and gs a copy)
  // before applyGroup; after it, gc blended back towards gs by directColor.
  static void startDirectColour(const Compiled& xform, ChaosLanes& lanes, const std::uint32_t* group, std::size_t n);
  static void finishDirectColour(const Compiled& xform, ChaosLanes& lanes, std::size_t n);
  void stepFlame(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                 std::size_t count) const;
  // Each drawn point through one of `maps` (Affine3's layout), drawn at random from its lane.
  static void throughOneOf(const std::vector<std::array<double, 12>>& maps, ChaosLanes& lanes, double* outX,
                           double* outY, double* outZ, std::size_t count);
  void stepJulia(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                 std::size_t count) const;

  // A group after applyGroup, in a game with true colours: what its transform painted into the
  // lanes' rgb (lane j of the group is lane group[j]); where it painted nothing, 0 (the colour
  // index's colour) after an ordinary transform and the colour the point had after a final one.
  static void keepPaintedRgb(const Compiled& xform, ChaosLanes& lanes, const std::uint32_t* group, std::size_t n,
                             bool final);

  bool julia_ = false;
  bool hidesPoints_ = false;
  bool paintsRgb_ = false;
  bool hidesByTerm_ = false;                  // a term may hide points: lanes.hidden is kept and masks lanes.visible
  std::array<std::uint32_t, 256> palette_{};  // the file's palette, VariationInput::palette
  std::vector<Compiled> xforms_;
  bool hasFinal_ = false;
  Compiled final_;
  std::vector<Compiled> chainedFinals_;  // applied after final_, in order (FlameGenome::chainedFinals)
  static constexpr int kPickBits = 12;
  static constexpr std::size_t kPickSize = std::size_t{1} << kPickBits;
  // Top bits of a draw → transform. Without xaos one row of kPickSize entries; with xaos (flam3's
  // chaos) one row for a lane's first step (the plain weights) and one after each transform k (row
  // k + 1: the weights times transform k's xaos factors).
  std::vector<std::uint8_t> pick_;
  bool xaos_ = false;
  std::vector<std::array<double, 12>> group_;  // the symmetry group each drawn point goes through (flame.h)
  // JWildfire's post symmetry (flame.h's postSymmetryMaps), after the group: one image of each point.
  std::vector<std::array<double, 12>> postSymmetry_;
  QuaternionJuliaSettings juliaSettings_;
  double turnCos_ = 1.0, turnSin_ = 0.0;
};

}  // namespace voxflame::core
