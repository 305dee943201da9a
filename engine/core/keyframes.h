// Keyframes animate any numeric value of a preset. A track names its target with a JSON Pointer
// into the preset document (the complete one, where every key is present; scene_schema.h resolves
// such a pointer to the Scene member it names without making the document) and holds keys at
// increasing times; between keys a value moves linearly or along a Catmull-Rom curve, colours in
// OKLab so that a fade between two saturated colours stays bright. An animated value is checked
// exactly like a typed one: against the range of the schema table and the reader's cross-field
// checks, with the same messages.
//
// Keyframes read, write and check themselves; the preset loader (scene_io.cpp) composes them with
// the scene's reader and writer.
//
// Catmull-Rom with uneven key spacing: the tangent at key i is (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]);
// at the first and last key of an open track it is the one-sided slope to the neighbouring key.
// A looping animation treats each track as periodic over the duration (neighbours wrap, shifted
// by one period), so the curve joins its ends without a kink. Outside its keys an open track holds
// its first or last value.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scene.h"

namespace voxflame::core {

inline constexpr double kMaxAnimationSeconds = 1e6;
inline constexpr std::size_t kMaxKeyframeTracks = 4096;
inline constexpr std::size_t kMaxKeyframes = 100'000;

// The animation's length in seconds: `animation.duration`, or the time of the latest key when
// that is 0 (0 for a scene without keyframes).
double animationDuration(const Scene& scene);
double animationFps(const Scene& scene);
bool animationLoops(const Scene& scene);
// Frames of the whole animation at `fps` (frame i shows time i / fps): a loop has
// round(duration·fps) frames (its end is its first frame again), an open animation one more so
// that its last key is shown. Always at least 1.
int animationFrameCount(const Scene& scene, double fps);

// The scene with every track applied at `seconds` (wrapped to the duration when the animation
// loops). The result keeps the keyframes and animation settings, with animation.time = seconds,
// so evaluating it again at any time gives what evaluating `scene` would. Throws core::Error
// naming the time when an interpolated value leaves its allowed range (a Catmull-Rom overshoot).
Scene sceneAtTime(const Scene& scene, double seconds);

// Records an edit as keys: `edited` is what the user made of sceneAtTime(animated, seconds). Every
// value that already has a track gets a key at `seconds` (replacing one at that exact time) holding
// its value in `edited`; every other numeric value or colour that differs from
// sceneAtTime(animated, seconds) gets a new smooth track with that one key. Everything that is not
// animated (the attractor, the mesh, names) is taken from `edited`. Throws core::Error when a track
// no longer finds its value in `edited` (a layer removed, a gradient shortened).
Scene withKeyframeAt(const Scene& animated, const Scene& edited, double seconds);

// One track's value at `seconds`: a number, an array of numbers or a colour as "#rrggbb".
nlohmann::json evaluateTrack(const KeyframeTrack& track, double seconds, double duration, bool loop);
// A key's value as the preset writes it.
nlohmann::json keyValueToJson(const KeyframeTrack& track, const Keyframe& key);

// Reads a preset's `keyframes` array (nullptr: the preset has none): paths, interpolation, keys of
// one kind at increasing times, none after `animation.duration` when that is set. Throws
// core::Error naming the source and the key path ("keyframes[0].keys[1].time").
std::vector<KeyframeTrack> keyframesFromJson(const nlohmann::json* tracks, const AnimationSettings& animation,
                                             const std::string& sourceName);
// The `keyframes` array as a preset writes it.
nlohmann::json keyframesToJson(const std::vector<KeyframeTrack>& tracks);

// The load-time checks: every track addresses a number, an array of numbers or a colour of the
// right size in the scene, and its values at every key and between keys are within their allowed
// ranges. Throws core::Error naming the source and the track.
void checkKeyframeTracks(const Scene& scene, const std::string& sourceName);

}  // namespace voxflame::core
