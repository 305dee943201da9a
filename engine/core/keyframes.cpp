#include "keyframes.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "color.h"
#include "error.h"
#include "json_reader.h"
#include "scene_schema.h"

namespace voxflame::core {

using nlohmann::json;

namespace {

using Point = std::vector<double>;

std::string formatSeconds(double seconds) {
  std::ostringstream text;
  text << seconds;
  return text.str();
}

// The space a track interpolates in: numbers as they are, colours in OKLab.
Point interpolationPoint(const KeyframeTrack& track, const Keyframe& key) {
  if (track.kind != KeyKind::Color) return key.values;
  const glm::vec3 lab = linearToOklab(glm::vec3(static_cast<float>(key.values[0]), static_cast<float>(key.values[1]),
                                                static_cast<float>(key.values[2])));
  return {lab.x, lab.y, lab.z};
}

double wrapTime(double seconds, double period) {
  const double wrapped = seconds - period * std::floor(seconds / period);
  return wrapped >= period ? 0.0 : wrapped;  // rounding can land exactly on the period
}

// Keys on a time line: an open track is extended by a reflected key at each end (so its end
// tangents are one-sided slopes); a looping one repeats every period, each repeat shifted by
// `drift` (a turntable's 360° per turn), so key j + n is key j one period and one drift later.
class KeyLine {
 public:
  KeyLine(std::vector<double> times, std::vector<Point> points, bool loop, double period, Point drift)
      : times_(std::move(times)), points_(std::move(points)), loop_(loop), period_(period), drift_(std::move(drift)) {}

  long count() const { return static_cast<long>(times_.size()); }

  double time(long j) const {
    if (loop_) return times_[wrapIndex(j)] + period_ * static_cast<double>(floorDiv(j));
    if (j < 0) return 2.0 * times_.front() - times_[1];
    if (j >= count()) return 2.0 * times_.back() - times_[times_.size() - 2];
    return times_[static_cast<std::size_t>(j)];
  }

  Point point(long j) const {
    if (loop_) {
      Point p = points_[wrapIndex(j)];
      const double turns = static_cast<double>(floorDiv(j));
      for (std::size_t c = 0; c < p.size(); ++c) p[c] += turns * drift_[c];
      return p;
    }
    if (j < 0) return reflect(points_.front(), points_[1]);
    if (j >= count()) return reflect(points_.back(), points_[points_.size() - 2]);
    return points_[static_cast<std::size_t>(j)];
  }

  // The segment [time(i), time(i + 1)) holding t (already wrapped for a loop, inside the keys otherwise).
  long segment(double t) const {
    const long upper = static_cast<long>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
    if (loop_) return upper - 1;  // -1: between the last key of the previous period and the first
    return std::clamp(upper - 1, 0L, count() - 2);
  }

 private:
  static Point reflect(const Point& end, const Point& inner) {
    Point p(end.size());
    for (std::size_t c = 0; c < p.size(); ++c) p[c] = 2.0 * end[c] - inner[c];
    return p;
  }
  long floorDiv(long j) const { return j >= 0 ? j / count() : -((-j + count() - 1) / count()); }
  std::size_t wrapIndex(long j) const { return static_cast<std::size_t>(j - floorDiv(j) * count()); }

  std::vector<double> times_;
  std::vector<Point> points_;
  bool loop_;
  double period_;
  Point drift_;
};

// A track's keys laid out on their time line once, then evaluated at any time in O(log keys).
// Building the line for every evaluation made checking a track of n keys (at each key, and between
// them) O(n²): a preset of 5000 keys took a minute to load, one of 100 000 hours.
class TrackCurve {
 public:
  TrackCurve(const KeyframeTrack& track, double duration, bool loop)
      : interpolation_(track.interpolation),
        periodic_(loop && duration > 0.0),
        duration_(duration),
        line_(lineOf(track, periodic_, duration)) {}

  Point at(double seconds) const {
    const KeyLine& line = line_;
    const long last = line.count() - 1;
    if (last == 0 && !periodic_) return line.point(0);
    double t = seconds;
    if (periodic_) {
      t = wrapTime(seconds, duration_);
    } else {
      if (t <= line.time(0)) return line.point(0);
      if (t >= line.time(last)) return line.point(last);
    }
    const long i = line.segment(t);
    const double t0 = line.time(i), t1 = line.time(i + 1);
    const Point p0 = line.point(i), p1 = line.point(i + 1);
    const double h = t1 - t0;
    const double s = h > 0.0 ? std::clamp((t - t0) / h, 0.0, 1.0) : 0.0;
    Point result(p0.size());
    if (interpolation_ == Interpolation::Linear) {
      for (std::size_t c = 0; c < result.size(); ++c) result[c] = p0[c] + s * (p1[c] - p0[c]);
      return result;
    }
    // Cubic Hermite with Catmull-Rom tangents for uneven spacing.
    const Point before = line.point(i - 1), after = line.point(i + 2);
    const double spanBefore = t1 - line.time(i - 1), spanAfter = line.time(i + 2) - t0;
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s, h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
    for (std::size_t c = 0; c < result.size(); ++c) {
      const double m0 = (p1[c] - before[c]) / spanBefore;
      const double m1 = (after[c] - p0[c]) / spanAfter;
      result[c] = h00 * p0[c] + h10 * h * m0 + h01 * p1[c] + h11 * h * m1;
    }
    return result;
  }

 private:
  static KeyLine lineOf(const KeyframeTrack& track, bool periodic, double duration) {
    std::vector<double> times;
    std::vector<Point> points;
    Point drift(track.keys.front().values.size(), 0.0);
    for (const Keyframe& key : track.keys) {
      // A key at the duration of a loop whose first key is at 0 closes the loop: the next period
      // starts there. When its value differs from the first key's (0° and 360°), every period is
      // shifted by the difference, so a turntable turns on without a jump or a change of speed.
      if (periodic && key.time >= duration && !times.empty() && times.front() == 0.0) {
        if (track.kind != KeyKind::Color) {
          const Point closing = interpolationPoint(track, key);
          for (std::size_t c = 0; c < drift.size(); ++c) drift[c] = closing[c] - points.front()[c];
        }
        continue;
      }
      times.push_back(key.time);
      points.push_back(interpolationPoint(track, key));
    }
    return KeyLine(std::move(times), std::move(points), periodic, duration, std::move(drift));
  }

  Interpolation interpolation_;
  bool periodic_;
  double duration_;
  KeyLine line_;
};

Point interpolate(const KeyframeTrack& track, double seconds, double duration, bool loop) {
  return TrackCurve(track, duration, loop).at(seconds);
}

bool kindFits(const KeyframeTrack& track, const ValueRef& target) {
  switch (track.kind) {
    case KeyKind::Number:
      return target.kind == ValueRef::Kind::Number;
    case KeyKind::Array:
      return target.kind == ValueRef::Kind::Array && target.numbers.size() == track.keys.front().values.size();
    case KeyKind::Color:
      return target.kind == ValueRef::Kind::Color;
  }
  return false;
}

std::string describe(const KeyframeTrack& track) {
  switch (track.kind) {
    case KeyKind::Number:
      return "numbers";
    case KeyKind::Array:
      return "arrays of " + std::to_string(track.keys.front().values.size()) + " numbers";
    case KeyKind::Color:
      return "colours";
  }
  return "values";
}

// A colour as a preset holds it: 8 bits per sRGB channel, so an animated colour is exactly what
// writing the scene and reading it back would give.
glm::vec3 presetColor(glm::vec3 linear) {
  return parseHexColor(toHexColor(linear));
}

// Writes the track's value at `seconds` into `target` (resolved in the scene being animated),
// checked against the target's range.
void applyTrack(const ValueRef& target, const KeyframeTrack& track, const TrackCurve& curve, double seconds,
                const std::string& sourceName) {
  const Point p = curve.at(seconds);
  if (track.kind == KeyKind::Color) {
    *target.color = presetColor(
        oklabToLinear(glm::vec3(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]))));
    return;
  }
  setNumbers(target, p, sourceName);
}

// The values a target holds now, to put back after trying a track's values in it.
struct Saved {
  std::vector<double> numbers;
  glm::vec3 color{0.0f};
};

Saved save(const ValueRef& target) {
  Saved saved;
  for (const NumberSlot& slot : target.numbers) saved.numbers.push_back(slot.get());
  if (target.color) saved.color = *target.color;
  return saved;
}

void restore(const ValueRef& target, const Saved& saved) {
  for (std::size_t i = 0; i < target.numbers.size(); ++i)
    std::visit([&](auto* p) { *p = static_cast<std::remove_pointer_t<decltype(p)>>(saved.numbers[i]); },
               target.numbers[i].target);
  if (target.color) *target.color = saved.color;
}

Keyframe keyFrom(const KeyframeTrack& track, const ValueRef& value, double seconds) {
  Keyframe key;
  key.time = seconds;
  if (!kindFits(track, value))
    throw Error("the keyframe track '" + track.path + "' holds " + describe(track) + " but the edited scene has " +
                describe(value) + " there");
  if (track.kind == KeyKind::Color) {
    const glm::vec3 linear = presetColor(*value.color);
    key.values = {linear.r, linear.g, linear.b};
  } else {
    for (const NumberSlot& slot : value.numbers) key.values.push_back(slot.get());
  }
  return key;
}

void insertKey(KeyframeTrack& track, Keyframe key) {
  constexpr double kSameTime = 1e-9;
  auto at = std::lower_bound(track.keys.begin(), track.keys.end(), key.time - kSameTime,
                             [](const Keyframe& k, double time) { return k.time < time; });
  if (at != track.keys.end() && std::abs(at->time - key.time) <= kSameTime)
    *at = std::move(key);
  else
    track.keys.insert(at, std::move(key));
}

// Opens a track for every animatable value of `edited` that differs from `current`. Values the
// current scene does not have (a new layer) are structure, not motion.
void collectChanges(const Scene& edited, const Scene& current, const std::set<std::string>& tracked, double seconds,
                    std::vector<KeyframeTrack>& tracks) {
  const auto open = [&](const std::string& path, KeyKind kind, const ValueRef& value) {
    KeyframeTrack track;
    track.path = path;
    track.kind = kind;
    track.interpolation = Interpolation::Smooth;
    // An array track's size comes from its first key; keyFrom checks the value against it.
    if (kind == KeyKind::Array) track.keys.push_back({seconds, std::vector<double>(value.numbers.size())});
    Keyframe key = keyFrom(track, value, seconds);
    track.keys = {std::move(key)};  // one key: the value holds everywhere until more keys follow
    tracks.push_back(std::move(track));
  };
  for (const std::string& path : animatablePaths(edited)) {
    if (tracked.count(path)) continue;
    const ValueRef now = resolveValue(edited, path), before = resolveValue(current, path);
    if (now.kind != before.kind || now.numbers.size() != before.numbers.size()) continue;  // structure changed
    switch (now.kind) {
      case ValueRef::Kind::Number:
        if (now.numbers[0].get() != before.numbers[0].get()) open(path, KeyKind::Number, now);
        break;
      case ValueRef::Kind::Color:
        if (toHexColor(*now.color) != toHexColor(*before.color)) open(path, KeyKind::Color, now);
        break;
      case ValueRef::Kind::Array: {
        bool elementTracked = false;
        for (std::size_t i = 0; i < now.numbers.size(); ++i)
          elementTracked |= tracked.count(path + "/" + std::to_string(i)) > 0;
        if (!elementTracked) {
          for (std::size_t i = 0; i < now.numbers.size(); ++i)
            if (now.numbers[i].get() != before.numbers[i].get()) {
              open(path, KeyKind::Array, now);
              break;
            }
          break;
        }
        // Some elements have tracks of their own: the others are keyed one by one.
        for (std::size_t i = 0; i < now.numbers.size(); ++i) {
          const std::string element = path + "/" + std::to_string(i);
          if (tracked.count(element) || now.numbers[i].get() == before.numbers[i].get()) continue;
          open(element, KeyKind::Number, resolveValue(edited, element));
        }
        break;
      }
      default:
        break;
    }
  }
}

// The keyframe value as the track's kind: a number, an array of numbers or a colour string.
Keyframe readKey(const json& value, const std::string& source, const std::string& path, KeyframeTrack& track,
                 bool first) {
  ObjectReader reader(value, source, path);
  Keyframe key;
  const json* time = reader.find("time");
  if (!time) reader.fail("is missing", "time");
  key.time = reader.checkNumber(*time, "time", 0.0, kMaxAnimationSeconds);
  const json* v = reader.find("value");
  if (!v) reader.fail("is missing", "value");
  KeyKind kind = KeyKind::Number;
  if (v->is_number()) {
    key.values = {reader.checkNumber(*v, "value", -1e12, 1e12)};
  } else if (v->is_string()) {
    kind = KeyKind::Color;
    try {
      const glm::vec3 linear = parseHexColor(v->get<std::string>());
      key.values = {linear.r, linear.g, linear.b};
    } catch (const Error& e) {
      reader.fail(e.what(), "value");
    }
  } else if (v->is_array() && !v->empty() && v->size() <= 64) {
    kind = KeyKind::Array;
    for (const json& element : *v) key.values.push_back(reader.checkNumber(element, "value", -1e12, 1e12));
  } else {
    reader.fail("must be a number, an array of 1 to 64 numbers or a colour string like \"#ff8800\"", "value");
  }
  if (first) {
    track.kind = kind;
  } else if (kind != track.kind || key.values.size() != track.keys.front().values.size()) {
    reader.fail(
        "must be of the same kind as the track's first key (a number, an array of as many numbers, or a colour)",
        "value");
  }
  reader.finish();
  return key;
}

}  // namespace

double animationDuration(const Scene& scene) {
  if (scene.animation.duration > 0.0) return scene.animation.duration;
  double last = 0.0;
  for (const KeyframeTrack& track : scene.keyframes)
    if (!track.keys.empty()) last = std::max(last, track.keys.back().time);
  return last;
}

double animationFps(const Scene& scene) {
  return scene.animation.fps;
}

bool animationLoops(const Scene& scene) {
  return scene.animation.loop;
}

int animationFrameCount(const Scene& scene, double fps) {
  const double duration = animationDuration(scene);
  if (duration <= 0.0 || fps <= 0.0) return 1;
  const double frames = duration * fps;
  const double count = scene.animation.loop ? std::round(frames) : std::floor(frames + 1e-9) + 1.0;
  return static_cast<int>(std::clamp(count, 1.0, 2e9));
}

json evaluateTrack(const KeyframeTrack& track, double seconds, double duration, bool loop) {
  const Point p = interpolate(track, seconds, duration, loop);
  switch (track.kind) {
    case KeyKind::Number:
      return p.front();
    case KeyKind::Array:
      return json(p);
    case KeyKind::Color: {
      const glm::vec3 linear =
          oklabToLinear(glm::vec3(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])));
      return toHexColor(linear);
    }
  }
  return nullptr;
}

json keyValueToJson(const KeyframeTrack& track, const Keyframe& key) {
  switch (track.kind) {
    case KeyKind::Number:
      return key.values.front();
    case KeyKind::Array:
      return json(key.values);
    case KeyKind::Color:
      return toHexColor(glm::vec3(static_cast<float>(key.values[0]), static_cast<float>(key.values[1]),
                                  static_cast<float>(key.values[2])));
  }
  return nullptr;
}

std::vector<KeyframeTrack> keyframesFromJson(const json* value, const AnimationSettings& animation,
                                             const std::string& sourceName) {
  std::vector<KeyframeTrack> tracks;
  if (!value) return tracks;
  if (!value->is_array() || value->size() > kMaxKeyframeTracks)
    throw Error(sourceName + ": 'keyframes' must be an array of at most " + std::to_string(kMaxKeyframeTracks) +
                " tracks");
  for (std::size_t i = 0; i < value->size(); ++i) {
    const std::string path = "keyframes[" + std::to_string(i) + "]";
    ObjectReader reader((*value)[i], sourceName, path);
    KeyframeTrack track;
    track.path = reader.requiredString("path");
    if (track.path.empty() || track.path[0] != '/')
      reader.fail(
          "is '" + track.path + "'; a JSON Pointer into the preset starts with '/', like \"/camera/azimuth_deg\"",
          "path");
    const std::string interpolation = reader.string("interpolation", "smooth");
    if (interpolation == "linear") {
      track.interpolation = Interpolation::Linear;
    } else if (interpolation == "smooth") {
      track.interpolation = Interpolation::Smooth;
    } else {
      reader.fail("is '" + interpolation + "'; expected 'linear' or 'smooth'", "interpolation");
    }
    const json* keys = reader.find("keys");
    if (!keys) reader.fail("is missing", "keys");
    if (!keys->is_array() || keys->empty() || keys->size() > kMaxKeyframes)
      reader.fail("must be an array of 1 to " + std::to_string(kMaxKeyframes) + " keys", "keys");
    for (std::size_t k = 0; k < keys->size(); ++k) {
      const std::string keyPath = reader.keyPath("keys") + "[" + std::to_string(k) + "]";
      Keyframe key = readKey((*keys)[k], sourceName, keyPath, track, k == 0);
      if (k > 0 && key.time <= track.keys.back().time) {
        std::ostringstream reason;
        reason << "is " << key.time << ", not after the previous key's " << track.keys.back().time
               << "; key times must increase";
        throw Error(sourceName + ": '" + keyPath + ".time' " + reason.str());
      }
      if (animation.duration > 0.0 && key.time > animation.duration) {
        std::ostringstream reason;
        reason << "is " << key.time << ", after the animation's duration " << animation.duration;
        throw Error(sourceName + ": '" + keyPath + ".time' " + reason.str());
      }
      track.keys.push_back(std::move(key));
    }
    for (const KeyframeTrack& other : tracks)
      if (other.path == track.path) reader.fail("'" + track.path + "' already has a track", "path");
    reader.finish();
    tracks.push_back(std::move(track));
  }
  return tracks;
}

json keyframesToJson(const std::vector<KeyframeTrack>& tracks) {
  json out = json::array();
  for (const KeyframeTrack& track : tracks) {
    json keys = json::array();
    for (const Keyframe& key : track.keys) keys.push_back({{"time", key.time}, {"value", keyValueToJson(track, key)}});
    out.push_back({{"path", track.path},
                   {"interpolation", track.interpolation == Interpolation::Linear ? "linear" : "smooth"},
                   {"keys", keys}});
  }
  return out;
}

void checkKeyframeTracks(const Scene& scene, const std::string& sourceName) {
  if (scene.keyframes.empty()) return;
  Scene work = scene;  // each track's values are tried in it, then put back
  const double duration = animationDuration(scene);
  const bool loop = scene.animation.loop;
  for (std::size_t i = 0; i < scene.keyframes.size(); ++i) {
    const KeyframeTrack& track = scene.keyframes[i];
    const std::string name = "keyframes[" + std::to_string(i) + "]";
    const std::string where = sourceName + ": '" + name + ".path' ";
    const ValueRef target = resolveValue(work, track.path);
    if (target.kind == ValueRef::Kind::Missing)
      throw Error(where + "is '" + track.path +
                  "', which names no value of the preset (paths are JSON Pointers such as \"/camera/azimuth_deg\", "
                  "\"/layers/0/params/a\" or \"/layers/0/color/gradient/1\"; a layer with a palette has no gradient)");
    if (target.kind == ValueRef::Kind::Other)
      throw Error(where + "is '" + track.path + "', which is " + target.what +
                  "; only numbers, arrays of numbers and colours can be animated");
    if (!kindFits(track, target))
      throw Error(sourceName + ": '" + name + ".keys' hold " + describe(track) + " but '" + track.path + "' is " +
                  describe(target));

    // Every key, and for curves points between keys (where Catmull-Rom can overshoot), must give
    // a valid preset: found now, not on frame 900 of a render.
    // The keys first: a bad key is named at its own time rather than where the curve leads to it.
    std::vector<double> times;
    for (const Keyframe& key : track.keys) times.push_back(key.time);
    const bool between = track.interpolation == Interpolation::Smooth && track.keys.size() <= 2000;
    constexpr int kSamplesBetween = 8;
    for (std::size_t k = 0; between && k < track.keys.size(); ++k) {
      const double t0 = track.keys[k].time;
      const double t1 = k + 1 < track.keys.size() ? track.keys[k + 1].time : (loop ? duration : t0);
      for (int s = 1; s < kSamplesBetween && t1 > t0; ++s) times.push_back(t0 + (t1 - t0) * s / kSamplesBetween);
      if (k == 0 && loop && t0 > 0.0)
        for (int s = 1; s < kSamplesBetween; ++s) times.push_back(t0 * s / kSamplesBetween);
    }
    const Saved original = save(target);
    const TrackCurve curve(track, duration, loop);
    for (double t : times) {
      const std::string at = sourceName + ": " + name + " ('" + track.path + "') at " + formatSeconds(t) + " s";
      applyTrack(target, track, curve, t, at);
      checkSceneConstraints(work, at);
    }
    restore(target, original);
  }
}

Scene sceneAtTime(const Scene& scene, double seconds) {
  Scene result = scene;
  if (!scene.keyframes.empty()) {
    const std::string source = "keyframes of '" + scene.name + "' at " + formatSeconds(seconds) + " s";
    const double duration = animationDuration(scene);
    for (const KeyframeTrack& track : scene.keyframes) {
      const ValueRef target = resolveValue(result, track.path);
      if (!kindFits(track, target))
        throw Error(source + ": the keyframe track '" + track.path + "' finds " +
                    (target.kind == ValueRef::Kind::Missing ? std::string("no value") : describe(target)) +
                    " there (a layer removed, a gradient shortened?)");
      applyTrack(target, track, TrackCurve(track, duration, scene.animation.loop), seconds, source);
    }
    checkSceneConstraints(result, source);
  }
  result.animation.time = std::clamp(seconds, 0.0, kMaxAnimationSeconds);
  return result;
}

Scene withKeyframeAt(const Scene& animated, const Scene& edited, double seconds) {
  const Scene current = sceneAtTime(animated, seconds);
  const double duration = animationDuration(animated);
  double keyTime = std::clamp(seconds, 0.0, kMaxAnimationSeconds);
  if (animated.animation.loop && duration > 0.0) keyTime = wrapTime(keyTime, duration);

  std::vector<KeyframeTrack> tracks = animated.keyframes;
  std::set<std::string> tracked;
  for (KeyframeTrack& track : tracks) {
    const ValueRef value = resolveValue(edited, track.path);
    if (value.kind == ValueRef::Kind::Missing)
      throw Error("the keyframe track '" + track.path + "' addresses a value the edited scene no longer has");
    insertKey(track, keyFrom(track, value, keyTime));
    tracked.insert(track.path);
  }
  collectChanges(edited, current, tracked, keyTime, tracks);

  Scene result = edited;
  result.keyframes = std::move(tracks);
  result.animation = animated.animation;
  if (result.animation.duration > 0.0) result.animation.duration = std::max(result.animation.duration, keyTime);
  result.animation.time = std::clamp(seconds, 0.0, kMaxAnimationSeconds);
  // The new keys are checked like keys typed into a preset.
  checkKeyframeTracks(result, "keyframes added at " + formatSeconds(seconds) + " s");
  return result;
}

}  // namespace voxflame::core
