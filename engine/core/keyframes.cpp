#include "keyframes.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "color.h"
#include "error.h"

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

Point interpolate(const KeyframeTrack& track, double seconds, double duration, bool loop) {
  std::vector<double> times;
  std::vector<Point> points;
  const bool periodic = loop && duration > 0.0;
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
  if (times.size() == 1 && !periodic) return points.front();
  double t = seconds;
  if (periodic) {
    t = wrapTime(seconds, duration);
  } else {
    if (t <= times.front()) return points.front();
    if (t >= times.back()) return points.back();
  }
  const KeyLine line(std::move(times), std::move(points), periodic, duration, std::move(drift));
  const long i = line.segment(t);
  const double t0 = line.time(i), t1 = line.time(i + 1);
  const Point p0 = line.point(i), p1 = line.point(i + 1);
  const double h = t1 - t0;
  const double s = h > 0.0 ? std::clamp((t - t0) / h, 0.0, 1.0) : 0.0;
  Point result(p0.size());
  if (track.interpolation == Interpolation::Linear) {
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

bool isHexColor(const json& value) {
  if (!value.is_string()) return false;
  try {
    parseHexColor(value.get<std::string>());
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool isNumberArray(const json& value) {
  return value.is_array() && !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const json& element) { return element.is_number(); });
}

// The value a pointer names in `document`, or nullptr (also for a malformed array index).
const json* resolve(const json& document, const std::string& path) {
  try {
    const json::json_pointer pointer(path);
    if (!document.contains(pointer)) return nullptr;
    return &document.at(pointer);
  } catch (const json::exception&) {
    return nullptr;
  }
}

std::string describe(const json& value) {
  if (value.is_number()) return "a number";
  if (isHexColor(value)) return "a colour";
  if (isNumberArray(value)) return "an array of " + std::to_string(value.size()) + " numbers";
  if (value.is_string()) return "the text " + value.dump();
  if (value.is_boolean()) return "true or false";
  if (value.is_array()) return "an array";
  return "an object";
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

bool kindFits(const KeyframeTrack& track, const json& target) {
  switch (track.kind) {
    case KeyKind::Number:
      return target.is_number();
    case KeyKind::Array:
      return isNumberArray(target) && target.size() == track.keys.front().values.size();
    case KeyKind::Color:
      return isHexColor(target);
  }
  return false;
}

void applyTrack(json& document, const KeyframeTrack& track, double seconds, double duration, bool loop) {
  json& target = document.at(json::json_pointer(track.path));
  json value = evaluateTrack(track, seconds, duration, loop);
  // Whole-number keys (seed, points, grid resolution) step to the nearest whole number.
  if (target.is_number_integer() && value.is_number())
    value = static_cast<std::int64_t>(std::llround(value.get<double>()));
  target = std::move(value);
}

Keyframe keyFromJson(const KeyframeTrack& track, const json& value, double seconds) {
  Keyframe key;
  key.time = seconds;
  if (!kindFits(track, value))
    throw Error("the keyframe track '" + track.path + "' holds " + describe(track) + " but the edited scene has " +
                describe(value) + " there");
  if (track.kind == KeyKind::Color) {
    const glm::vec3 linear = parseHexColor(value.get<std::string>());
    key.values = {linear.r, linear.g, linear.b};
  } else if (track.kind == KeyKind::Array) {
    for (const json& element : value) key.values.push_back(element.get<double>());
  } else {
    key.values = {value.get<double>()};
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

std::string escapePointerToken(const std::string& token) {
  std::string escaped;
  for (char c : token) {
    if (c == '~')
      escaped += "~0";
    else if (c == '/')
      escaped += "~1";
    else
      escaped += c;
  }
  return escaped;
}

// Walks the edited document and opens a track for every numeric value or colour that differs from
// the current one. Values the current scene does not have (a new layer) are structure, not motion.
void collectChanges(const json& edited, const json* current, const std::string& path,
                    const std::set<std::string>& tracked, double seconds, std::vector<KeyframeTrack>& tracks) {
  if (tracked.count(path) || path == "/schema_version") return;
  if (!current) return;
  const auto open = [&](KeyKind kind) {
    KeyframeTrack track;
    track.path = path;
    track.kind = kind;
    track.interpolation = Interpolation::Smooth;
    // An array track's size comes from its first key; keyFromJson then checks the value against it.
    if (kind == KeyKind::Array) track.keys.push_back({seconds, std::vector<double>(edited.size())});
    Keyframe key = keyFromJson(track, edited, seconds);
    // One key: the value holds everywhere until more keys follow.
    track.keys = {std::move(key)};
    tracks.push_back(std::move(track));
  };
  if (edited.is_number()) {
    if (!current->is_number() || current->get<double>() != edited.get<double>()) open(KeyKind::Number);
  } else if (edited.is_string()) {
    if (isHexColor(edited) && *current != edited) open(KeyKind::Color);
  } else if (edited.is_array()) {
    bool elementTracked = false;
    for (std::size_t i = 0; i < edited.size(); ++i) elementTracked |= tracked.count(path + "/" + std::to_string(i)) > 0;
    if (isNumberArray(edited) && !elementTracked) {
      if (!isNumberArray(*current) || current->size() != edited.size()) return;  // structure changed
      for (std::size_t i = 0; i < edited.size(); ++i)
        if ((*current)[i].get<double>() != edited[i].get<double>()) {
          open(KeyKind::Array);
          return;
        }
      return;
    }
    for (std::size_t i = 0; i < edited.size(); ++i)
      collectChanges(edited[i], current->is_array() && i < current->size() ? &(*current)[i] : nullptr,
                     path + "/" + std::to_string(i), tracked, seconds, tracks);
  } else if (edited.is_object()) {
    for (auto it = edited.begin(); it != edited.end(); ++it) {
      const json* inner = nullptr;
      if (current->is_object()) {
        const auto found = current->find(it.key());
        if (found != current->end()) inner = &*found;
      }
      collectChanges(it.value(), inner, path + "/" + escapePointerToken(it.key()), tracked, seconds, tracks);
    }
  }
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

void checkKeyframeTracks(const Scene& scene, const std::string& sourceName) {
  if (scene.keyframes.empty()) return;
  const json document = sceneToDocument(scene, false);
  const double duration = animationDuration(scene);
  const bool loop = scene.animation.loop;
  for (std::size_t i = 0; i < scene.keyframes.size(); ++i) {
    const KeyframeTrack& track = scene.keyframes[i];
    const std::string name = "keyframes[" + std::to_string(i) + "]";
    const std::string where = sourceName + ": '" + name + ".path' ";
    const json* target = track.path == "/schema_version" ? nullptr : resolve(document, track.path);
    if (!target)
      throw Error(where + "is '" + track.path +
                  "', which names no value of the preset (paths are JSON Pointers such as \"/camera/azimuth_deg\", "
                  "\"/layers/0/params/a\" or \"/layers/0/color/gradient/1\"; a layer with a palette has no gradient)");
    if (!target->is_number() && !isHexColor(*target) && !isNumberArray(*target))
      throw Error(where + "is '" + track.path + "', which is " + describe(*target) +
                  "; only numbers, arrays of numbers and colours can be animated");
    if (!kindFits(track, *target))
      throw Error(sourceName + ": '" + name + ".keys' hold " + describe(track) + " but '" + track.path + "' is " +
                  describe(*target));

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
    for (double t : times) {
      json animated = document;
      applyTrack(animated, track, t, duration, loop);
      sceneFromDocument(animated, sourceName + ": " + name + " ('" + track.path + "') at " + formatSeconds(t) + " s",
                        false);
    }
  }
}

Scene sceneAtTime(const Scene& scene, double seconds) {
  Scene result;
  if (scene.keyframes.empty()) {
    result = scene;
  } else {
    json document = sceneToDocument(scene, false);
    const double duration = animationDuration(scene);
    for (const KeyframeTrack& track : scene.keyframes)
      applyTrack(document, track, seconds, duration, scene.animation.loop);
    result =
        sceneFromDocument(document, "keyframes of '" + scene.name + "' at " + formatSeconds(seconds) + " s", false);
    result.embedded = scene.embedded;
    result.baseDirectory = scene.baseDirectory;
    result.keyframes = scene.keyframes;
  }
  result.animation = scene.animation;
  result.animation.time = std::clamp(seconds, 0.0, kMaxAnimationSeconds);
  return result;
}

Scene withKeyframeAt(const Scene& animated, const Scene& edited, double seconds) {
  const Scene current = sceneAtTime(animated, seconds);
  const json currentDocument = sceneToDocument(current, false);
  const json editedDocument = sceneToDocument(edited, false);
  const double duration = animationDuration(animated);
  double keyTime = std::clamp(seconds, 0.0, kMaxAnimationSeconds);
  if (animated.animation.loop && duration > 0.0) keyTime = wrapTime(keyTime, duration);

  std::vector<KeyframeTrack> tracks = animated.keyframes;
  std::set<std::string> tracked;
  for (KeyframeTrack& track : tracks) {
    const json* value = resolve(editedDocument, track.path);
    if (!value) throw Error("the keyframe track '" + track.path + "' addresses a value the edited scene no longer has");
    insertKey(track, keyFromJson(track, *value, keyTime));
    tracked.insert(track.path);
  }
  collectChanges(editedDocument, &currentDocument, "", tracked, keyTime, tracks);

  Scene result = edited;
  result.keyframes = std::move(tracks);
  result.animation = animated.animation;
  if (result.animation.duration > 0.0) result.animation.duration = std::max(result.animation.duration, keyTime);
  result.animation.time = std::clamp(seconds, 0.0, kMaxAnimationSeconds);
  // Through the document once more, so the new keys are checked like keys typed into a preset.
  Scene checked = sceneFromDocument(sceneToDocument(result), "keyframes added at " + formatSeconds(seconds) + " s");
  checked.embedded = result.embedded;
  checked.baseDirectory = result.baseDirectory;
  return checked;
}

}  // namespace voxflame::core
