#include "chaos_game.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <utility>

#include <glm/common.hpp>

#include "color.h"
#include "error.h"
#include "scene.h"

namespace voxflame::core {

namespace {

constexpr double kBadValue = 1e10;  // flam3's limit: a state beyond it has escaped
static_assert(kMaxFlameXforms + kMaxFlameSymmetry < 256, "ChaosLanes::choice holds a transform index in a byte");

// The step's loops as functions of restrict-qualified parameters (GCC vectorises loops over
// those, not over restrict locals), each built for AVX2 and for any x86-64 and picked when the
// program loads: an always-inline body and a thin multiversioned wrapper around it.
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__SANITIZE_THREAD__)
#define VOXFLAME_CHAOS_TARGETS [[gnu::target_clones("avx2", "default")]]
#else
#define VOXFLAME_CHAOS_TARGETS
#endif

// Each lane draws its transform: the top bits of its next random number index the pick table (with
// xaos, the row of the transform it took last, and it remembers its choice). Counted as drawn, four
// ways (lane i in count i mod 4): lanes that follow each other often choose the same transform, and
// with one count per transform each increment would wait for the one before it.
constexpr std::size_t kCountWays = 4;
using GroupCounts = std::array<std::array<std::uint32_t, kMaxFlameXforms + kMaxFlameSymmetry>, kCountWays>;
template <bool kXaos>
void drawAndCount(std::uint32_t* __restrict random, std::uint8_t* __restrict choice, std::uint8_t* __restrict previous,
                  const std::uint8_t* __restrict pick, int shift, int rowBits, std::size_t count, GroupCounts& counts) {
  const auto draw = [&](std::size_t i) {
    const std::uint32_t r = laneNext(random[i]);
    random[i] = r;
    const std::size_t row = kXaos ? static_cast<std::size_t>(previous[i]) << rowBits : 0;
    const std::uint8_t k = pick[row | (r >> shift)];
    choice[i] = k;
    if constexpr (kXaos) previous[i] = static_cast<std::uint8_t>(k + 1);
    return k;
  };
  std::size_t lane = 0;
  for (; lane + kCountWays <= count; lane += kCountWays)
    for (std::size_t way = 0; way < kCountWays; ++way) ++counts[way][draw(lane + way)];
  for (; lane < count; ++lane) ++counts[lane % kCountWays][draw(lane)];
}

// Fills one row of the pick table: entry e covers draws in [e, e + 1) / size; each transform owns
// a run of entries in proportion to its weight (flam3's xform_distrib); the last transform of
// positive weight takes the rounding remainder, so one of weight 0 is never drawn. All weights 0:
// false, and the row is left to the caller.
bool fillPickRow(std::uint8_t* row, std::size_t size, const std::vector<double>& weights) {
  double total = 0.0;
  for (const double w : weights) total += w;
  if (!(total > 0.0)) return false;
  double cumulative = 0.0;
  std::size_t entry = 0;
  std::size_t last = 0;
  for (std::size_t k = 0; k < weights.size(); ++k)
    if (weights[k] > 0.0) last = k;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    cumulative += weights[k];
    const auto end =
        k == last
            ? size
            : std::min(size, static_cast<std::size_t>(std::llround(cumulative / total * static_cast<double>(size))));
    for (; entry < end; ++entry) row[entry] = static_cast<std::uint8_t>(k);
    if (k == last) break;
  }
  return true;
}

// The lanes of one group gathered through the affine map into contiguous arrays, with their
// random states unless the group draws none (kWithRandom false: a group of fixed variations).
template <bool kWithRandom>
[[gnu::always_inline]] inline void gatherBody(const std::uint32_t* __restrict group, std::size_t n,
                                              const double* __restrict x, const double* __restrict y,
                                              const double* __restrict z, const std::uint32_t* __restrict random,
                                              const double* __restrict a, double* __restrict tx, double* __restrict ty,
                                              double* __restrict tz, std::uint32_t* __restrict groupRandom) {
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint32_t l = group[j];
    const double px = x[l], py = y[l], pz = z[l];
    tx[j] = a[0] * px + a[1] * py + a[2] * pz + a[3];
    ty[j] = a[4] * px + a[5] * py + a[6] * pz + a[7];
    tz[j] = a[8] * px + a[9] * py + a[10] * pz + a[11];
    if constexpr (kWithRandom) groupRandom[j] = random[l];
  }
}
VOXFLAME_CHAOS_TARGETS void gatherAffine(const std::uint32_t* group, std::size_t n, const double* x, const double* y,
                                         const double* z, const std::uint32_t* random, const double* a, double* tx,
                                         double* ty, double* tz, std::uint32_t* groupRandom, bool withRandom = true) {
  if (withRandom)
    gatherBody<true>(group, n, x, y, z, random, a, tx, ty, tz, groupRandom);
  else
    gatherBody<false>(group, n, x, y, z, random, a, tx, ty, tz, groupRandom);
}

// The group's results back into their lanes, with flam3's colour blend and the opacity draw.
// Without kWithRandom the lanes' random states stay as they were (the group drew none, see
// gatherBody); without kWritesVisible an opaque group leaves visible to the caller (stepFlame sets
// all of it at once in a game where nothing hides points).
template <bool kOpaque, bool kWithRandom, bool kWritesVisible>
[[gnu::always_inline]] inline void scatterBody(const std::uint32_t* __restrict group, std::size_t n,
                                               const double* __restrict ox, const double* __restrict oy,
                                               const double* __restrict oz, std::uint32_t* __restrict groupRandom,
                                               double* __restrict x, double* __restrict y, double* __restrict z,
                                               double* __restrict color, std::uint32_t* __restrict random,
                                               std::int32_t* __restrict visible, double keep, double pull,
                                               double opacity) {
  static_assert(kOpaque || (kWithRandom && kWritesVisible), "a translucent group draws for its opacity");
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint32_t l = group[j];
    x[l] = ox[j];
    y[l] = oy[j];
    z[l] = oz[j];
    color[l] = keep * color[l] + pull;
    if constexpr (kWithRandom) {
      std::uint32_t r = groupRandom[j];
      // Only a translucent transform draws for its opacity.
      if constexpr (kWritesVisible) visible[l] = kOpaque ? 1 : (laneUniform(r) < opacity ? 1 : 0);
      random[l] = r;
    } else if constexpr (kWritesVisible) {
      visible[l] = 1;
    }
  }
}
// drawsRandom: the group's variations may have drawn random numbers; setsVisible: write each
// lane's visible flag (a translucent group always does, and draws for it).
VOXFLAME_CHAOS_TARGETS void scatterGroup(const std::uint32_t* group, std::size_t n, const double* ox, const double* oy,
                                         const double* oz, std::uint32_t* groupRandom, double* x, double* y, double* z,
                                         double* color, std::uint32_t* random, std::int32_t* visible, double keep,
                                         double pull, double opacity, bool drawsRandom, bool setsVisible) {
  // Copies of the loop, so the common opaque case has no draw and no compare in it, and a group of
  // fixed variations moves no random state.
  if (opacity < 1.0)
    scatterBody<false, true, true>(group, n, ox, oy, oz, groupRandom, x, y, z, color, random, visible, keep, pull,
                                   opacity);
  else if (drawsRandom && setsVisible)
    scatterBody<true, true, true>(group, n, ox, oy, oz, groupRandom, x, y, z, color, random, visible, keep, pull, 1.0);
  else if (drawsRandom)
    scatterBody<true, true, false>(group, n, ox, oy, oz, groupRandom, x, y, z, color, random, visible, keep, pull, 1.0);
  else if (setsVisible)
    scatterBody<true, false, true>(group, n, ox, oy, oz, groupRandom, x, y, z, color, random, visible, keep, pull, 1.0);
  else
    scatterBody<true, false, false>(group, n, ox, oy, oz, groupRandom, x, y, z, color, random, visible, keep, pull,
                                    1.0);
}

// p ← M p + t in place (the post-affine).
[[gnu::always_inline]] inline void affineBody(double* __restrict x, double* __restrict y, double* __restrict z,
                                              const double* __restrict m, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    const double px = x[j], py = y[j], pz = z[j];
    x[j] = m[0] * px + m[1] * py + m[2] * pz + m[3];
    y[j] = m[4] * px + m[5] * py + m[6] * pz + m[7];
    z[j] = m[8] * px + m[9] * py + m[10] * pz + m[11];
  }
}
VOXFLAME_CHAOS_TARGETS void affineInPlace(double* x, double* y, double* z, const double* m, std::size_t n) {
  affineBody(x, y, z, m, n);
}

// What is drawn, when there is no final transform: the state itself, or NaN where the state has
// left every sensible range (the caller reseeds those lanes).
[[gnu::always_inline]] inline void emitBody(const double* __restrict x, const double* __restrict y,
                                            const double* __restrict z, const double* __restrict color,
                                            double* __restrict outX, double* __restrict outY, double* __restrict outZ,
                                            double* __restrict outColor, std::size_t count) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < count; ++i) {
    const bool good = (std::abs(x[i]) < kBadValue) & (std::abs(y[i]) < kBadValue) & (std::abs(z[i]) < kBadValue);
    outX[i] = good ? x[i] : kNaN;
    outY[i] = y[i];
    outZ[i] = z[i];
    outColor[i] = color[i];
  }
}
VOXFLAME_CHAOS_TARGETS void emitPoints(const double* x, const double* y, const double* z, const double* color,
                                       double* outX, double* outY, double* outZ, double* outColor, std::size_t count) {
  emitBody(x, y, z, color, outX, outY, outZ, outColor, count);
}

#undef VOXFLAME_CHAOS_TARGETS

}  // namespace

void ChaosLanes::resize(std::size_t lanes) {
  for (auto* v : {&x, &y, &z, &w, &color, &tx, &ty, &tz, &ox, &oy, &oz, &sx, &sy, &sz, &gc, &gs}) v->assign(lanes, 0.0);
  rgb.assign(lanes, 0u);
  groupRgb.assign(lanes, 0u);
  hidden.assign(lanes, 0u);
  groupHidden.assign(lanes, 0u);
  field.assign(lanes, 1.0);
  fieldNoise.assign(lanes, 0.0);
  random.assign(lanes, 1u);
  groupRandom.assign(lanes, 1u);
  termState.clear();
  visible.assign(lanes, 1);
  choice.assign(lanes, 0);
  previous.assign(lanes, 0);
  order.assign(lanes, 0);
}

ChaosGame::Compiled ChaosGame::compile(const FlameXform& xform) {
  Compiled c;
  c.affine = xform.affine.m;
  c.hasPost = xform.hasPost && !xform.post.isIdentity();
  c.post = xform.post.m;
  c.color = xform.color;
  c.colorSpeed = xform.colorSpeed;
  c.opacity = xform.opacity;
  c.directColor = xform.directColor;
  if (xform.hasWeightField()) {
    c.hasField = true;
    c.fieldFromPosition = xform.fieldInput == WeightFieldInput::Position;
    c.fieldColor = 0.1 * xform.fieldColor;
    c.fieldJitter = 0.1 * xform.fieldJitter;
    c.field = xform;
    c.field.variations.clear();
    c.field.xaos.clear();
  }
  for (const VariationStage stage : {VariationStage::Pre, VariationStage::Normal, VariationStage::Post})
    for (const VariationTerm& term : xform.variations) {
      if (term.weight == 0.0 || variationStage(term.name) != stage) continue;
      const VariationInfo& info = variationOrThrow(term.name);
      c.terms.push_back({info.apply,
                         term.weight,
                         term.params,
                         stage,
                         info.mapsXY,
                         info.threeD,
                         info.additive,
                         info.name == "flatten",
                         info.replaces,
                         info.readsSum,
                         {}});
      c.terms.back().texts = info.textsFor(term.texts);
      c.terms.back().laneState = info.laneState;
      if (c.hasField) c.terms.back().field = weightFieldTerm(xform, term, info);
      c.hasNormalTerms = c.hasNormalTerms || stage == VariationStage::Normal;
      c.drawsRandom = c.drawsRandom || info.random;
      c.directColour = c.directColour || info.directColour;
      c.paintsRgb = c.paintsRgb || info.paintsRgb;
      c.hidesByTerm = c.hidesByTerm || info.hidesPoints;
    }
  return c;
}

ChaosGame::ChaosGame(const PatternLayer& layer, const std::string& where) {
  if (layer.kind == PatternKind::QuaternionJulia) {
    validateQuaternionJulia(layer.julia, where);
    julia_ = true;
    juliaSettings_ = layer.julia;
    const double turn = layer.julia.turnDeg * std::numbers::pi / 180.0;
    turnCos_ = std::cos(turn);
    turnSin_ = std::sin(turn);
    hidesPoints_ = layer.julia.view == QuaternionView::Slice;
    return;
  }
  if (layer.kind != PatternKind::Flame) throw Error(where + " is not a chaos-game layer");
  validateFlame(layer.flame, where);
  const std::vector<FlameXform> xforms = expandSymmetry(layer.flame);
  std::vector<double> weights;
  for (const FlameXform& x : xforms) {
    xforms_.push_back(compile(x));
    weights.push_back(x.weight);
  }
  xaos_ = hasXaos(layer.flame);
  const std::size_t rows = xaos_ ? xforms.size() + 1 : 1;
  pick_.assign(rows * kPickSize, 0);
  fillPickRow(pick_.data(), kPickSize, weights);  // validateFlame saw a positive total
  // Row k + 1: after transform k. Symmetry transforms (past the genome's) neither have nor get
  // factors other than 1, as in flam3, where they are transforms with default xaos.
  for (std::size_t k = 0; k + 1 < rows; ++k) {
    std::vector<double> after = weights;
    if (k < layer.flame.xforms.size()) {
      const std::vector<double>& factors = layer.flame.xforms[k].xaos;
      for (std::size_t j = 0; j < std::min(factors.size(), layer.flame.xforms.size()); ++j) after[j] *= factors[j];
    }
    std::uint8_t* row = pick_.data() + (k + 1) * kPickSize;
    if (!fillPickRow(row, kPickSize, after)) std::copy_n(pick_.data(), kPickSize, row);  // a dead end: plain weights
  }
  if (layer.flame.symmetry.rotational > 1 || layer.flame.symmetry.mirror)
    for (const Affine3& g : symmetryGroup(layer.flame.symmetry)) group_.push_back(g.m);
  for (const Affine3& g : postSymmetryMaps(layer.flame.postSymmetry)) postSymmetry_.push_back(g.m);
  hasFinal_ = layer.flame.hasFinal;
  if (hasFinal_) {
    final_ = compile(layer.flame.finalXform);
    for (const FlameXform& chained : layer.flame.chainedFinals) chainedFinals_.push_back(compile(chained));
  }
  // Each term that keeps per-lane memory gets its own array of it.
  std::size_t slots = 0;
  const auto assignSlots = [&](Compiled& c) {
    for (Term& term : c.terms)
      if (term.laneState > 0) term.stateSlot = slots++;
  };
  for (Compiled& x : xforms_) assignSlots(x);
  if (hasFinal_) assignSlots(final_);
  for (Compiled& x : chainedFinals_) assignSlots(x);
  for (const Compiled& x : xforms_) hidesPoints_ = hidesPoints_ || x.opacity < 1.0;
  hidesPoints_ = hidesPoints_ || (hasFinal_ && final_.opacity < 1.0);
  for (const Compiled& x : chainedFinals_) hidesPoints_ = hidesPoints_ || x.opacity < 1.0;
  for (const Compiled& x : xforms_) hidesByTerm_ = hidesByTerm_ || x.hidesByTerm;
  hidesByTerm_ = hidesByTerm_ || (hasFinal_ && final_.hidesByTerm);
  for (const Compiled& x : chainedFinals_) hidesByTerm_ = hidesByTerm_ || x.hidesByTerm;
  hidesPoints_ = hidesPoints_ || hidesByTerm_;
  for (const Compiled& x : xforms_) paintsRgb_ = paintsRgb_ || x.paintsRgb;
  paintsRgb_ = paintsRgb_ || (hasFinal_ && final_.paintsRgb);
  for (const Compiled& x : chainedFinals_) paintsRgb_ = paintsRgb_ || x.paintsRgb;
  if (paintsRgb_) {
    // The palette as the file writes it (the import keeps it as linear stops), in bytes: what
    // JWildfire's nearest-colour searches compare a painted colour with.
    const std::vector<GradientStop> stops = layer.color.gradient.empty() && !layer.color.palette.empty()
                                                ? paletteStops(layer.color.palette)
                                                : layer.color.gradient;
    if (!stops.empty()) {
      const Gradient gradient(stops);
      for (std::size_t i = 0; i < palette_.size(); ++i) {
        const glm::vec3 c =
            glm::clamp(linearToSrgb(gradient.at(static_cast<float>(i) / 255.0f)), 0.0f, 1.0f) * 255.0f + 0.5f;
        palette_[i] = static_cast<std::uint32_t>(c.r) | static_cast<std::uint32_t>(c.g) << 8 |
                      static_cast<std::uint32_t>(c.b) << 16;
      }
    }
  }
}

void ChaosGame::seedLane(ChaosLanes& lanes, std::size_t i, SplitMix64& rng) const {
  lanes.x[i] = rng.symmetric();
  lanes.y[i] = rng.symmetric();
  lanes.z[i] = rng.symmetric();
  lanes.w[i] = julia_ ? rng.symmetric() : 0.0;
  lanes.color[i] = rng.uniform();
  lanes.random[i] = static_cast<std::uint32_t>(rng.next() >> 32) | 1u;
  lanes.visible[i] = 0;
  lanes.previous[i] = 0;
  if (i < lanes.hidden.size()) lanes.hidden[i] = 0;
}

void ChaosGame::step(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                     std::size_t count) const {
  if (julia_)
    stepJulia(lanes, outX, outY, outZ, outColor, count);
  else
    stepFlame(lanes, outX, outY, outZ, outColor, count);
}

namespace {

// A pre_ or post_ term's result into the point p: each coordinate the variation maps is replaced
// by the result (or, for an additive variation, has it added); the others are kept.
void combineStage(double* __restrict px, double* __restrict py, double* __restrict pz, const double* __restrict rx,
                  const double* __restrict ry, const double* __restrict rz, bool mapsXY, bool mapsZ, bool additive,
                  std::size_t count) {
  const double keep = additive ? 1.0 : 0.0;
  if (mapsXY)
    for (std::size_t j = 0; j < count; ++j) {
      px[j] = keep * px[j] + rx[j];
      py[j] = keep * py[j] + ry[j];
    }
  if (mapsZ)
    for (std::size_t j = 0; j < count; ++j) pz[j] = keep * pz[j] + rz[j];
}

}  // namespace

void ChaosGame::fillField(const Compiled& xform, const std::uint32_t* group, std::size_t count, const double* x,
                          const double* y, const double* z, ChaosLanes& lanes) {
  double* field = lanes.field.data();
  double* noise = lanes.fieldNoise.data();
  const double amount = xform.field.fieldAmount;
  for (std::size_t j = 0; j < count; ++j) {
    const std::uint32_t i = group[j];
    const double n = xform.fieldFromPosition ? weightFieldNoise(xform.field, x[i], y[i], z[i])
                                             : weightFieldNoise(xform.field, lanes.tx[j], lanes.ty[j], lanes.tz[j]);
    noise[j] = n;
    field[j] = 1.0 + amount * n;
  }
  // The lanes applyGroup rounds the group up to.
  for (std::size_t j = count; j < std::min((count + 3) & ~std::size_t{3}, lanes.size()); ++j) {
    field[j] = 1.0;
    noise[j] = 0.0;
  }
}

void ChaosGame::jitterByField(const Compiled& xform, ChaosLanes& lanes, std::size_t count) {
  // JWildfire's TransformationApplyWeightMapJitter: each coordinate in turn, the noise read at the
  // point as moved so far with that coordinate first.
  double* ox = lanes.ox.data();
  double* oy = lanes.oy.data();
  double* oz = lanes.oz.data();
  const double jitter = xform.fieldJitter;
  for (std::size_t j = 0; j < count; ++j) {
    ox[j] += jitter * weightFieldNoise(xform.field, ox[j], oy[j], oz[j]);
    oy[j] += jitter * weightFieldNoise(xform.field, oy[j], ox[j], oz[j]);
    oz[j] += jitter * weightFieldNoise(xform.field, oz[j], ox[j], oy[j]);
  }
}

void ChaosGame::colourByField(const Compiled& xform, const ChaosLanes& lanes, const std::uint32_t* order,
                              std::size_t count, double* colour) {
  // JWildfire's TransformationApplyWeightMapToColorStep, after the colour blend; the index is not
  // clamped here (the palette lookup clamps it), as in JWildfire.
  const double* noise = lanes.fieldNoise.data();
  for (std::size_t j = 0; j < count; ++j) colour[order[j]] *= 1.0 + xform.fieldColor * noise[j];
}

void ChaosGame::applyGroup(const Compiled& xform, ChaosLanes& lanes, const std::uint32_t* group,
                           std::size_t count) const {
  // Whole vectors only: the lanes past the group (to the next multiple of 4) are worked on too and
  // never read back, so no lane falls to a loop's scalar tail, where a sin or atan2 costs four
  // times what it costs in a vector call (vector_math.h). A group of a 20-transform flame has about
  // a dozen lanes.
  const std::size_t groupSize = count;
  count = std::min((count + 3) & ~std::size_t{3}, lanes.size());
  double* __restrict tx = lanes.tx.data();
  double* __restrict ty = lanes.ty.data();
  double* __restrict tz = lanes.tz.data();
  double* __restrict ox = lanes.ox.data();
  double* __restrict oy = lanes.oy.data();
  double* __restrict oz = lanes.oz.data();
  double* __restrict sx = lanes.sx.data();
  double* __restrict sy = lanes.sy.data();
  double* __restrict sz = lanes.sz.data();
  const auto clear = [&](double* a, double* b, double* c) {
    for (std::size_t j = 0; j < count; ++j) a[j] = b[j] = c[j] = 0.0;
  };
  const double* __restrict field = lanes.field.data();
  const double* __restrict noise = lanes.fieldNoise.data();
  // A term's factor in lane j: the field's, times its own weight's (the field's `amount` parameter).
  const auto factor = [&](const Term& term, std::size_t j) {
    return term.field.weight == 0.0 ? field[j] : field[j] * (1.0 + noise[j] * term.field.weight);
  };
  const auto scaleByField = [&](const Term& term, double* a, double* b, double* c) {
    for (std::size_t j = 0; j < count; ++j) {
      const double f = factor(term, j);
      a[j] *= f;
      b[j] *= f;
      c[j] *= f;
    }
  };
  VariationInput in;
  in.random = lanes.groupRandom.data();
  in.colour = lanes.gc.data();  // read and set only by direct-colour terms (startDirectColour fills it)
  if (xform.paintsRgb) {
    // JWildfire clears a point's rgbColor flag as each transform starts: nothing painted yet.
    in.rgb = lanes.groupRgb.data();
    std::fill_n(in.rgb, count, 0u);
    in.palette = palette_.data();
  }
  if (xform.hidesByTerm) {
    // The group's doHide flags as the points bring them; written back after the terms.
    in.hidden = lanes.groupHidden.data();
    for (std::size_t j = 0; j < count; ++j) in.hidden[j] = j < groupSize ? lanes.hidden[group[j]] : 0u;
  }
  in.count = count;
  in.affine = xform.affine.data();
  in.tx = tx;
  in.ty = ty;
  in.tz = tz;
  const auto run = [&](const Term& term, const double* x, const double* y, const double* z, double* rx, double* ry,
                       double* rz) {
    in.x = x;
    in.y = y;
    in.z = z;
    in.weight = term.weight;
    in.params = term.params.data();
    in.stage = term.stage;
    in.texts = term.texts.empty() ? nullptr : term.texts.data();
    in.count = count;
    in.state = nullptr;
    in.lanes = nullptr;
    if (term.laneState > 0) {
      if (lanes.termState.size() <= term.stateSlot) lanes.termState.resize(term.stateSlot + 1);
      std::vector<double>& memory = lanes.termState[term.stateSlot];
      if (memory.size() != lanes.size() * term.laneState) memory.assign(lanes.size() * term.laneState, 0.0);
      in.state = memory.data();
      in.lanes = group;
      // The lanes past the group that the others work on belong to other groups: this one's own only.
      in.count = groupSize;
    }
    // An ordinary term maps t itself, which crob may move for the terms after it.
    const bool ordinary = term.stage == VariationStage::Normal;
    in.movableX = ordinary ? tx : nullptr;
    in.movableY = ordinary ? ty : nullptr;
    if (term.field.params.empty()) {
      term.apply(in, rx, ry, rz);
      return;
    }
    // Parameters the field scales differ from lane to lane (JWildfire sets them, re-initialises the
    // variation, and restores them): lane j's at params[j · size, (j + 1) · size).
    const std::size_t size = term.params.size();
    std::vector<double>& params = lanes.fieldParams;
    params.resize(groupSize * size);
    bool alike = true;
    for (std::size_t j = 0; j < groupSize; ++j) {
      double* const own = params.data() + j * size;
      std::copy(term.params.begin(), term.params.end(), own);
      for (const WeightFieldTerm::Param& p : term.field.params) {
        const double scaled = own[p.index] * (1.0 + noise[j] * p.intensity);
        own[p.index] = p.integer ? std::round(scaled) : scaled;  // JWildfire's FTOI for an int parameter
      }
      alike = alike && std::memcmp(own, params.data(), size * sizeof(double)) == 0;
    }
    if (alike && groupSize > 0) {
      // Every lane's the same (a whole number the field moved past no rounding step): the group
      // in one call, as without the field. Lane by lane, a variation computes in libm's scalar
      // functions where the group's call uses libmvec's vector ones (vector_math.h), whose results
      // differ in the last bits; this way the same parameters give the same points, and the speed.
      in.params = params.data();
      term.apply(in, rx, ry, rz);
      return;
    }
    for (std::size_t j = 0; j < groupSize; ++j) {
      VariationInput one = in;
      one.params = params.data() + j * size;
      one.count = 1;
      one.x = x + j;
      one.y = y + j;
      one.z = z + j;
      one.tx = tx + j;
      one.ty = ty + j;
      one.tz = tz + j;
      one.random = in.random + j;
      one.colour = in.colour + j;
      one.rgb = in.rgb ? in.rgb + j : nullptr;
      one.hidden = in.hidden ? in.hidden + j : nullptr;
      one.lanes = in.lanes ? in.lanes + j : nullptr;
      one.movableX = ordinary ? tx + j : nullptr;
      one.movableY = ordinary ? ty + j : nullptr;
      term.apply(one, rx + j, ry + j, rz + j);
    }
  };
  std::size_t k = 0;
  // pre_ terms: each maps the affine point t in place (o is their scratch).
  for (; k < xform.terms.size() && xform.terms[k].stage == VariationStage::Pre; ++k) {
    clear(ox, oy, oz);
    run(xform.terms[k], tx, ty, tz, ox, oy, oz);
    if (xform.hasField) scaleByField(xform.terms[k], ox, oy, oz);
    combineStage(tx, ty, tz, ox, oy, oz, xform.terms[k].mapsXY, xform.terms[k].mapsZ, xform.terms[k].additive, count);
    if (xform.terms[k].flattens)
      for (std::size_t j = 0; j < count; ++j) tz[j] = 0.0;
  }
  clear(ox, oy, oz);
  if (!xform.hasNormalTerms) {
    // No variation acts as linear: the affine map (and pre_ terms) alone.
    for (std::size_t j = 0; j < count; ++j) {
      ox[j] = tx[j];
      oy[j] = ty[j];
      oz[j] = tz[j];
    }
  }
  bool flatten = false;
  for (; k < xform.terms.size() && xform.terms[k].stage == VariationStage::Normal; ++k) {
    // A term that assigns instead of adding (JWildfire's shredlin, Fractorium's mirror_x) discards
    // the sum so far.
    if (xform.terms[k].replaces != VariationInfo::Replaces::Nothing) {
      const bool xy = xform.terms[k].replaces != VariationInfo::Replaces::Z;
      const bool z = xform.terms[k].replaces != VariationInfo::Replaces::XY;
      for (std::size_t j = 0; j < count; ++j) {
        ox[j] = xy ? 0.0 : ox[j];
        oy[j] = xy ? 0.0 : oy[j];
        oz[j] = z ? 0.0 : oz[j];
      }
    }
    if (xform.hasField && xform.terms[k].readsSum) {
      // A term that reads (and may rewrite) the sum before it gets that sum; its change is scaled.
      for (std::size_t j = 0; j < count; ++j) {
        sx[j] = ox[j];
        sy[j] = oy[j];
        sz[j] = oz[j];
      }
      run(xform.terms[k], tx, ty, tz, sx, sy, sz);
      for (std::size_t j = 0; j < count; ++j) {
        const double f = factor(xform.terms[k], j);
        ox[j] += f * (sx[j] - ox[j]);
        oy[j] += f * (sy[j] - oy[j]);
        oz[j] += f * (sz[j] - oz[j]);
      }
    } else if (xform.hasField) {
      // The term's result scaled per lane (variations are linear in their weight), then summed.
      clear(sx, sy, sz);
      run(xform.terms[k], tx, ty, tz, sx, sy, sz);
      for (std::size_t j = 0; j < count; ++j) {
        const double f = factor(xform.terms[k], j);
        ox[j] += f * sx[j];
        oy[j] += f * sy[j];
        oz[j] += f * sz[j];
      }
    } else {
      run(xform.terms[k], tx, ty, tz, ox, oy, oz);
    }
    flatten = flatten || xform.terms[k].flattens;
  }
  if (flatten)
    for (std::size_t j = 0; j < count; ++j) oz[j] = 0.0;
  // post_ terms: each maps the sum o in place (s is their scratch; t stays for those that read it).
  for (; k < xform.terms.size(); ++k) {
    clear(sx, sy, sz);
    run(xform.terms[k], ox, oy, oz, sx, sy, sz);
    if (xform.hasField) scaleByField(xform.terms[k], sx, sy, sz);
    combineStage(ox, oy, oz, sx, sy, sz, xform.terms[k].mapsXY, xform.terms[k].mapsZ, xform.terms[k].additive, count);
    if (xform.terms[k].flattens)
      for (std::size_t j = 0; j < count; ++j) oz[j] = 0.0;
  }
  if (xform.hasPost) affineInPlace(ox, oy, oz, xform.post.data(), count);
  if (xform.fieldJitter != 0.0) jitterByField(xform, lanes, groupSize);
  if (xform.hidesByTerm)
    for (std::size_t j = 0; j < groupSize; ++j) lanes.hidden[group[j]] = lanes.groupHidden[j];
}

void ChaosGame::startDirectColour(const Compiled& xform, ChaosLanes& lanes, const std::uint32_t* group, std::size_t n) {
  const double keep = 1.0 - xform.colorSpeed, pull = xform.colorSpeed * xform.color;
  const double* color = lanes.color.data();
  double* gc = lanes.gc.data();
  double* gs = lanes.gs.data();
  for (std::size_t j = 0; j < n; ++j) gs[j] = gc[j] = keep * color[group[j]] + pull;
}

void ChaosGame::finishDirectColour(const Compiled& xform, ChaosLanes& lanes, std::size_t n) {
  // Fractorium's Xform::Apply: saved + direct_color · (set − saved), and NaN (a variation's 0/0,
  // an escaped point's) as 0.
  double* gc = lanes.gc.data();
  const double* gs = lanes.gs.data();
  for (std::size_t j = 0; j < n; ++j) {
    const double c = gs[j] + xform.directColor * (gc[j] - gs[j]);
    gc[j] = std::isnan(c) ? 0.0 : c;
  }
}

void ChaosGame::keepPaintedRgb(const Compiled& xform, ChaosLanes& lanes, const std::uint32_t* group, std::size_t n,
                               bool final) {
  // A transform's true colour replaces the point's. Where it paints none, a transform leaves the
  // point to its colour index (JWildfire gives a transform the colour type DIFFUSION unless the file
  // says otherwise, whose colour step takes the palette's colour unless rgbColor is set), and a
  // final transform keeps the colour the point came with (JWildfire's final transforms default to
  // the colour type NONE, which has no colour step).
  std::uint32_t* rgb = lanes.rgb.data();
  const std::uint32_t* painted = lanes.groupRgb.data();
  if (!xform.paintsRgb) {
    if (!final)
      for (std::size_t j = 0; j < n; ++j) rgb[group[j]] = 0u;
    return;
  }
  for (std::size_t j = 0; j < n; ++j) rgb[group[j]] = painted[j] != 0u || !final ? painted[j] : rgb[group[j]];
}

void ChaosGame::stepFlame(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                          std::size_t count) const {
  // 1. Every lane draws its transform, counted by transform for 2.
  std::uint32_t* random = lanes.random.data();
  std::uint8_t* choice = lanes.choice.data();
  constexpr std::size_t kWays = kCountWays;
  const std::size_t xformCount = xforms_.size();
  GroupCounts cursor;
  for (auto& way : cursor) std::fill_n(way.begin(), xformCount, 0u);
  if (xaos_)
    drawAndCount<true>(random, choice, lanes.previous.data(), pick_.data(), 32 - kPickBits, kPickBits, count, cursor);
  else
    drawAndCount<false>(random, choice, lanes.previous.data(), pick_.data(), 32 - kPickBits, kPickBits, count, cursor);
  // 2. Counting sort of the lanes by transform.
  std::size_t lane = 0;
  // start[k]: group k's first place in `order`; cursor[w][k]: the next place for way w's lanes of it.
  std::array<std::uint32_t, kMaxFlameXforms + kMaxFlameSymmetry + 1> start;
  std::uint32_t place = 0;
  for (std::size_t k = 0; k < xformCount; ++k) {
    start[k] = place;
    for (auto& way : cursor) place += std::exchange(way[k], place);
  }
  start[xformCount] = place;
  std::uint32_t* order = lanes.order.data();
  for (lane = 0; lane + kWays <= count; lane += kWays)
    for (std::size_t way = 0; way < kWays; ++way)
      order[cursor[way][choice[lane + way]]++] = static_cast<std::uint32_t>(lane + way);
  for (; lane < count; ++lane) order[cursor[lane % kWays][choice[lane]]++] = static_cast<std::uint32_t>(lane);

  // 3. Each group: gathered through the affine map, its variations, scattered back.
  double* x = lanes.x.data();
  double* y = lanes.y.data();
  double* z = lanes.z.data();
  double* color = lanes.color.data();
  std::int32_t* visible = lanes.visible.data();
  // Where no transform hides points every drawn point is shown: set here in one pass, not lane by
  // lane in each group's scatter.
  if (!hidesPoints_) std::fill_n(visible, count, 1);
  for (std::size_t k = 0; k < xforms_.size(); ++k) {
    const std::uint32_t first = start[k], n = start[k + 1] - start[k];
    if (n == 0) continue;
    const Compiled& xf = xforms_[k];
    const std::uint32_t* group = order + first;
    const bool drawsRandom = xf.drawsRandom || xf.opacity < 1.0;
    gatherAffine(group, n, x, y, z, random, xf.affine.data(), lanes.tx.data(), lanes.ty.data(), lanes.tz.data(),
                 lanes.groupRandom.data(), drawsRandom);
    if (xf.directColour) startDirectColour(xf, lanes, group, n);
    if (xf.hasField) fillField(xf, group, n, x, y, z, lanes);
    applyGroup(xf, lanes, group, n);
    scatterGroup(group, n, lanes.ox.data(), lanes.oy.data(), lanes.oz.data(), lanes.groupRandom.data(), x, y, z, color,
                 random, visible, 1.0 - xf.colorSpeed, xf.colorSpeed * xf.color, xf.opacity, drawsRandom, hidesPoints_);
    if (xf.directColour) {
      // The plain blend scatterGroup wrote is replaced by the direct-colour one.
      finishDirectColour(xf, lanes, n);
      const double* gc = lanes.gc.data();
      for (std::uint32_t j = 0; j < n; ++j) color[group[j]] = gc[j];
    }
    if (xf.fieldColor != 0.0) colourByField(xf, lanes, group, n, color);
    if (paintsRgb_) keepPaintedRgb(xf, lanes, group, n, false);
  }

  // 4. What is drawn: the state, or the final transform of it (which never feeds back). A point a
  // variation hid (JWildfire's doHide) is not drawn, though it goes on moving.
  const auto maskHidden = [&] {
    if (hidesByTerm_)
      for (std::size_t i = 0; i < count; ++i) visible[i] &= lanes.hidden[i] ? 0 : 1;
  };
  if (!hasFinal_) {
    maskHidden();
    emitPoints(x, y, z, color, outX, outY, outZ, outColor, count);
    if (!group_.empty()) throughOneOf(group_, lanes, outX, outY, outZ, count);
    if (!postSymmetry_.empty()) throughOneOf(postSymmetry_, lanes, outX, outY, outZ, count);
    return;
  }
  for (std::size_t i = 0; i < count; ++i) order[i] = static_cast<std::uint32_t>(i);
  gatherAffine(order, count, x, y, z, random, final_.affine.data(), lanes.tx.data(), lanes.ty.data(), lanes.tz.data(),
               lanes.groupRandom.data());
  if (final_.directColour) startDirectColour(final_, lanes, order, count);
  if (final_.hasField) fillField(final_, order, count, x, y, z, lanes);
  applyGroup(final_, lanes, order, count);
  if (final_.directColour) finishDirectColour(final_, lanes, count);
  if (paintsRgb_) keepPaintedRgb(final_, lanes, order, count, true);
  const double keep = 1.0 - final_.colorSpeed, pull = final_.colorSpeed * final_.color;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < count; ++i) {
    const bool good = (std::abs(x[i]) < kBadValue) & (std::abs(y[i]) < kBadValue) & (std::abs(z[i]) < kBadValue);
    outX[i] = good ? lanes.ox[i] : kNaN;
    outY[i] = lanes.oy[i];
    outZ[i] = lanes.oz[i];
    outColor[i] = final_.directColour ? lanes.gc[i] : keep * color[i] + pull;
    std::uint32_t r = lanes.groupRandom[i];
    visible[i] &= laneUniform(r) < final_.opacity ? 1 : 0;
    random[i] = r;
  }
  if (final_.fieldColor != 0.0) colourByField(final_, lanes, order, count, outColor);
  // JWildfire's further final transforms, each bending what the one before drew.
  for (const Compiled& chained : chainedFinals_) {
    gatherAffine(order, count, outX, outY, outZ, random, chained.affine.data(), lanes.tx.data(), lanes.ty.data(),
                 lanes.tz.data(), lanes.groupRandom.data());
    const double chainedKeep = 1.0 - chained.colorSpeed, chainedPull = chained.colorSpeed * chained.color;
    if (chained.directColour)  // as startDirectColour, from the colour the final before it drew
      for (std::size_t i = 0; i < count; ++i) lanes.gs[i] = lanes.gc[i] = chainedKeep * outColor[i] + chainedPull;
    if (chained.hasField) fillField(chained, order, count, outX, outY, outZ, lanes);
    applyGroup(chained, lanes, order, count);
    if (chained.directColour) finishDirectColour(chained, lanes, count);
    if (paintsRgb_) keepPaintedRgb(chained, lanes, order, count, true);
    for (std::size_t i = 0; i < count; ++i) {
      outX[i] = std::isnan(outX[i]) ? kNaN : lanes.ox[i];
      outY[i] = lanes.oy[i];
      outZ[i] = lanes.oz[i];
      outColor[i] = chained.directColour ? lanes.gc[i] : chainedKeep * outColor[i] + chainedPull;
      std::uint32_t r = lanes.groupRandom[i];
      visible[i] &= laneUniform(r) < chained.opacity ? 1 : 0;
      random[i] = r;
    }
    if (chained.fieldColor != 0.0) colourByField(chained, lanes, order, count, outColor);
  }
  maskHidden();
  if (!group_.empty()) throughOneOf(group_, lanes, outX, outY, outZ, count);
  if (!postSymmetry_.empty()) throughOneOf(postSymmetry_, lanes, outX, outY, outZ, count);
}

void ChaosGame::throughOneOf(const std::vector<std::array<double, 12>>& maps, ChaosLanes& lanes, double* outX,
                             double* outY, double* outZ, std::size_t count) {
  const auto elements = static_cast<std::uint64_t>(maps.size());
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t r = laneNext(lanes.random[i]);
    lanes.random[i] = r;
    const auto& m = maps[static_cast<std::size_t>((std::uint64_t{r} * elements) >> 32)];
    const double px = outX[i], py = outY[i], pz = outZ[i];
    outX[i] = m[0] * px + m[1] * py + m[2] * pz + m[3];
    outY[i] = m[4] * px + m[5] * py + m[6] * pz + m[7];
    outZ[i] = m[8] * px + m[9] * py + m[10] * pz + m[11];
  }
}

void ChaosGame::stepJulia(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                          std::size_t count) const {
  const glm::dvec4 c = juliaSettings_.c;
  const bool slice = juliaSettings_.view == QuaternionView::Slice;
  double* __restrict x = lanes.x.data();
  double* __restrict y = lanes.y.data();
  double* __restrict z = lanes.z.data();
  double* __restrict w = lanes.w.data();
  double* __restrict color = lanes.color.data();
  std::uint32_t* __restrict random = lanes.random.data();
  std::int32_t* __restrict visible = lanes.visible.data();
  for (std::size_t i = 0; i < count; ++i) {
    // q − c, then its principal square root: for q = a + v (v the vector part), √q has real part
    // √((|q| + a) / 2) and vector part v/|v| · √((|q| − a) / 2).
    const double a = x[i] - c.x, b = y[i] - c.y, d = z[i] - c.z, e = w[i] - c.w;
    const double vector = std::sqrt(b * b + d * d + e * e);
    const double norm = std::sqrt(a * a + vector * vector);
    const double real = std::sqrt(std::max(0.0, 0.5 * (norm + a)));
    const double imaginary = std::sqrt(std::max(0.0, 0.5 * (norm - a)));
    // On the negative real axis every unit vector is a square root's direction; i is one of them.
    const bool axis = vector < 1e-300;
    const double scale = axis ? 0.0 : imaginary / (axis ? 1.0 : vector);
    const std::uint32_t r = laneNext(random[i]);
    random[i] = r;
    const double sign = (r >> 31) ? -1.0 : 1.0;
    x[i] = sign * real;
    y[i] = sign * (axis ? imaginary : b * scale);
    z[i] = sign * d * scale;
    w[i] = sign * e * scale;
    // The colour follows the sequence of roots taken, so it shows the set's self-similar address.
    color[i] = 0.5 * color[i] + ((r >> 31) ? 0.5 : 0.0);
    const double turnedZ = turnCos_ * z[i] - turnSin_ * w[i];
    const double turnedW = turnSin_ * z[i] + turnCos_ * w[i];
    outX[i] = x[i];
    outY[i] = y[i];
    outZ[i] = turnedZ;
    outColor[i] = color[i];
    visible[i] = slice ? (std::abs(turnedW - juliaSettings_.sliceW) < juliaSettings_.thickness ? 1 : 0) : 1;
  }
}

}  // namespace voxflame::core
