#include "chaos_game.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "error.h"
#include "scene.h"

namespace voxflame::core {

namespace {
constexpr double kBadValue = 1e10;  // flam3's limit: a state beyond it has escaped
}

void ChaosLanes::resize(std::size_t lanes) {
  for (auto* v : {&x, &y, &z, &w, &color, &tx, &ty, &tz, &ox, &oy, &oz}) v->assign(lanes, 0.0);
  random.assign(lanes, 1u);
  groupRandom.assign(lanes, 1u);
  visible.assign(lanes, 1);
  choice.assign(lanes, 0);
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
  for (const VariationTerm& term : xform.variations) {
    if (term.weight == 0.0) continue;
    c.terms.push_back({variationOrThrow(term.name).apply, term.weight, term.params});
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
    return;
  }
  if (layer.kind != PatternKind::Flame) throw Error(where + " is not a chaos-game layer");
  validateFlame(layer.flame, where);
  const std::vector<FlameXform> xforms = expandSymmetry(layer.flame);
  double total = 0.0;
  for (const FlameXform& x : xforms) {
    xforms_.push_back(compile(x));
    total += x.weight;
  }
  // The pick table: entry e covers draws in [e, e + 1) / size; each transform owns a run of entries
  // in proportion to its weight (flam3's xform_distrib, finer). A transform of positive weight
  // below one entry's share still gets the entry its cumulative weight lands in.
  const std::size_t size = pick_.size();
  double cumulative = 0.0;
  std::size_t entry = 0;
  for (std::size_t k = 0; k < xforms.size(); ++k) {
    cumulative += xforms[k].weight;
    const auto end =
        k + 1 == xforms.size()
            ? size
            : std::min(size, static_cast<std::size_t>(std::llround(cumulative / total * static_cast<double>(size))));
    for (; entry < end; ++entry) pick_[entry] = static_cast<std::uint8_t>(k);
  }
  hasFinal_ = layer.flame.hasFinal;
  if (hasFinal_) final_ = compile(layer.flame.finalXform);
}

void ChaosGame::seedLane(ChaosLanes& lanes, std::size_t i, SplitMix64& rng) const {
  lanes.x[i] = rng.symmetric();
  lanes.y[i] = rng.symmetric();
  lanes.z[i] = rng.symmetric();
  lanes.w[i] = julia_ ? rng.symmetric() : 0.0;
  lanes.color[i] = rng.uniform();
  lanes.random[i] = static_cast<std::uint32_t>(rng.next() >> 32) | 1u;
  lanes.visible[i] = 0;
}

void ChaosGame::step(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                     std::size_t count) const {
  if (julia_)
    stepJulia(lanes, outX, outY, outZ, outColor, count);
  else
    stepFlame(lanes, outX, outY, outZ, outColor, count);
}

void ChaosGame::applyGroup(const Compiled& xform, ChaosLanes& lanes, std::size_t count) const {
  double* __restrict tx = lanes.tx.data();
  double* __restrict ty = lanes.ty.data();
  double* __restrict tz = lanes.tz.data();
  double* __restrict ox = lanes.ox.data();
  double* __restrict oy = lanes.oy.data();
  double* __restrict oz = lanes.oz.data();
  for (std::size_t j = 0; j < count; ++j) ox[j] = oy[j] = oz[j] = 0.0;
  if (xform.terms.empty()) {
    // No variation acts as linear: the affine map alone.
    for (std::size_t j = 0; j < count; ++j) {
      ox[j] = tx[j];
      oy[j] = ty[j];
      oz[j] = tz[j];
    }
  }
  VariationInput in;
  in.x = tx;
  in.y = ty;
  in.z = tz;
  in.random = lanes.groupRandom.data();
  in.count = count;
  in.affine = xform.affine.data();
  for (const Term& term : xform.terms) {
    in.weight = term.weight;
    in.params = term.params.data();
    term.apply(in, ox, oy, oz);
  }
  if (xform.hasPost) {
    const auto& m = xform.post;
    for (std::size_t j = 0; j < count; ++j) {
      const double px = ox[j], py = oy[j], pz = oz[j];
      ox[j] = m[0] * px + m[1] * py + m[2] * pz + m[3];
      oy[j] = m[4] * px + m[5] * py + m[6] * pz + m[7];
      oz[j] = m[8] * px + m[9] * py + m[10] * pz + m[11];
    }
  }
}

void ChaosGame::stepFlame(ChaosLanes& lanes, double* outX, double* outY, double* outZ, double* outColor,
                          std::size_t count) const {
  // 1. Every lane draws its transform.
  std::uint32_t* __restrict random = lanes.random.data();
  std::uint8_t* __restrict choice = lanes.choice.data();
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t r = laneNext(random[i]);
    random[i] = r;
    choice[i] = pick_[r >> (32 - kPickBits)];
  }
  // 2. Counting sort of the lanes by transform.
  std::array<std::uint32_t, kMaxFlameXforms + kMaxFlameSymmetry + 2> start{};
  for (std::size_t i = 0; i < count; ++i) ++start[choice[i] + 1u];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::array<std::uint32_t, kMaxFlameXforms + kMaxFlameSymmetry + 2> cursor = start;
  std::uint32_t* order = lanes.order.data();
  for (std::size_t i = 0; i < count; ++i) order[cursor[choice[i]]++] = static_cast<std::uint32_t>(i);

  // 3. Each group: gather through the affine map, variations, scatter with the colour blend.
  double* x = lanes.x.data();
  double* y = lanes.y.data();
  double* z = lanes.z.data();
  double* color = lanes.color.data();
  std::int32_t* visible = lanes.visible.data();
  for (std::size_t k = 0; k < xforms_.size(); ++k) {
    const std::uint32_t first = start[k], n = start[k + 1] - start[k];
    if (n == 0) continue;
    const Compiled& xf = xforms_[k];
    const std::uint32_t* group = order + first;
    const auto& a = xf.affine;
    double* __restrict tx = lanes.tx.data();
    double* __restrict ty = lanes.ty.data();
    double* __restrict tz = lanes.tz.data();
    std::uint32_t* __restrict groupRandom = lanes.groupRandom.data();
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t l = group[j];
      const double px = x[l], py = y[l], pz = z[l];
      tx[j] = a[0] * px + a[1] * py + a[2] * pz + a[3];
      ty[j] = a[4] * px + a[5] * py + a[6] * pz + a[7];
      tz[j] = a[8] * px + a[9] * py + a[10] * pz + a[11];
      groupRandom[j] = random[l];
    }
    applyGroup(xf, lanes, n);
    const double keep = 1.0 - xf.colorSpeed, pull = xf.colorSpeed * xf.color;
    const double* ox = lanes.ox.data();
    const double* oy = lanes.oy.data();
    const double* oz = lanes.oz.data();
    if (xf.opacity >= 1.0) {
      for (std::uint32_t j = 0; j < n; ++j) {
        const std::uint32_t l = group[j];
        x[l] = ox[j];
        y[l] = oy[j];
        z[l] = oz[j];
        color[l] = keep * color[l] + pull;
        random[l] = groupRandom[j];
        visible[l] = 1;
      }
    } else {
      for (std::uint32_t j = 0; j < n; ++j) {
        const std::uint32_t l = group[j];
        x[l] = ox[j];
        y[l] = oy[j];
        z[l] = oz[j];
        color[l] = keep * color[l] + pull;
        std::uint32_t r = groupRandom[j];
        visible[l] = laneUniform(r) < xf.opacity ? 1 : 0;
        random[l] = r;
      }
    }
  }

  // 4. What is drawn: the state, or the final transform of it (which never feeds back).
  if (hasFinal_) {
    const auto& a = final_.affine;
    double* __restrict tx = lanes.tx.data();
    double* __restrict ty = lanes.ty.data();
    double* __restrict tz = lanes.tz.data();
    std::uint32_t* __restrict groupRandom = lanes.groupRandom.data();
    for (std::size_t i = 0; i < count; ++i) {
      tx[i] = a[0] * x[i] + a[1] * y[i] + a[2] * z[i] + a[3];
      ty[i] = a[4] * x[i] + a[5] * y[i] + a[6] * z[i] + a[7];
      tz[i] = a[8] * x[i] + a[9] * y[i] + a[10] * z[i] + a[11];
      groupRandom[i] = random[i];
    }
    applyGroup(final_, lanes, count);
    const double keep = 1.0 - final_.colorSpeed, pull = final_.colorSpeed * final_.color;
    for (std::size_t i = 0; i < count; ++i) {
      outX[i] = lanes.ox[i];
      outY[i] = lanes.oy[i];
      outZ[i] = lanes.oz[i];
      outColor[i] = keep * color[i] + pull;
      std::uint32_t r = groupRandom[i];
      if (final_.opacity < 1.0) visible[i] &= laneUniform(r) < final_.opacity ? 1 : 0;
      random[i] = r;
    }
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      outX[i] = x[i];
      outY[i] = y[i];
      outZ[i] = z[i];
      outColor[i] = color[i];
    }
  }
  // 5. A state that left every sensible range (or became NaN) is an escape.
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < count; ++i) {
    const bool good = (std::abs(x[i]) < kBadValue) & (std::abs(y[i]) < kBadValue) & (std::abs(z[i]) < kBadValue);
    outX[i] = good ? outX[i] : kNaN;
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
