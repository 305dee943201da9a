// The Timeline: play, scrub and key the animation, its tracks with their keys. Changes the scene's
// keyframes and shows the scene at the current time.
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <sstream>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/keyframes.h"
#include "core/scene_schema.h"
#include "panels.h"
#include "widgets.h"

namespace voxflame::app::panels {

// ---------------------------------------------------------------------------------------------
// Timeline: the scene shown is the animation at the current time; "Key" records what the user
// changed there as keyframes; scrubbing and playing re-evaluate the animation.

double timelineLength(const core::Scene& scene) {
  const double duration = core::animationDuration(scene);
  return duration > 0.0 ? duration : 5.0;  // room to place the first keys
}

void showTime(Document& document, TimelinePanelState& timeline, PromptsState& prompts, double seconds) {
  try {
    // The moment's values differ from the last one's wherever a track is: what they affect is found
    // by comparing the two (Document::replace).
    document.replace(core::sceneAtTime(document.scene, seconds));
    document.keyBase = document.scene;
  } catch (const core::Error& e) {
    prompts.notice = e.what();
    timeline.playing = false;
  }
}

std::vector<double> keyTimes(const core::Scene& scene) {
  std::vector<double> times;
  for (const core::KeyframeTrack& track : scene.keyframes)
    for (const core::Keyframe& key : track.keys) times.push_back(key.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }),
              times.end());
  return times;
}

void advancePlayback(Document& document, TimelinePanelState& timeline, PromptsState& prompts) {
  if (!timeline.playing) return;
  const double length = timelineLength(document.scene);
  double next = document.scene.animation.time + static_cast<double>(ImGui::GetIO().DeltaTime);
  if (next > length) {
    // Play stops at the end unless the animation loops (its loop box).
    if (core::animationLoops(document.scene) && length > 0.0)
      next = std::fmod(next, length);
    else
      next = length, timeline.playing = false;
  }
  showTime(document, timeline, prompts, next);
}

// An animated value's name for people: "/layers/0/params/a" reads "layer 1 a",
// "/camera/azimuth_deg" reads "camera azimuth deg".
std::string trackName(const std::string& path) {
  std::vector<std::string> parts;
  std::istringstream split(path);
  for (std::string part; std::getline(split, part, '/');)
    if (!part.empty()) parts.push_back(part);
  std::string name;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::string part = parts[i];
    if (part == "params" || part == "tone" || part == "render") continue;
    if (part == "layers" && i + 1 < parts.size() && std::all_of(parts[i + 1].begin(), parts[i + 1].end(), ::isdigit)) {
      part = "layer " + std::to_string(std::stoi(parts[++i]) + 1);
    }
    std::replace(part.begin(), part.end(), '_', ' ');
    name += (name.empty() ? "" : " ") + part;
  }
  return name.empty() ? path : name;
}

// What Key did: the values that got a key at `time` ("keyed layer 1 a, camera azimuth deg at 1.50 s").
std::string keyedText(const std::vector<core::KeyframeTrack>& before, const std::vector<core::KeyframeTrack>& after,
                      double time) {
  std::vector<std::string> keyed;
  for (const core::KeyframeTrack& track : after) {
    const auto old =
        std::find_if(before.begin(), before.end(), [&](const core::KeyframeTrack& t) { return t.path == track.path; });
    const bool keyedNow = std::any_of(track.keys.begin(), track.keys.end(),
                                      [&](const core::Keyframe& key) { return std::abs(key.time - time) < 1e-6; });
    if (keyedNow && (old == before.end() || !(old->keys == track.keys))) keyed.push_back(trackName(track.path));
  }
  char at[32];
  std::snprintf(at, sizeof at, " at %.2f s", time);
  if (keyed.empty()) return std::string("nothing changed to key") + at;
  std::string text = "keyed ";
  for (std::size_t i = 0; i < keyed.size() && i < 4; ++i) text += (i ? ", " : "") + keyed[i];
  if (keyed.size() > 4) text += " and " + std::to_string(keyed.size() - 4) + " more";
  return text + at;
}

void timelineWindow(Ui& ui, TimelinePanelState& timeline, PromptsState& prompts, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  // Docked under the picture, between the side panels, above the status line.
  const float statusHeight = statusBarHeight(scale);
  const float left = ui.frame.layout.left, right = std::max(ui.frame.layout.right, left + 1.0f);
  // Room for up to four animated values' rows; more scroll. The scrubber's key ticks have a strip
  // of their own under it.
  const auto rows = static_cast<float>(std::min<std::size_t>(ui.document.scene.keyframes.size(), 4) + 1);
  const float tickHeight = 6 * scale;
  const float height = 2 * ImGui::GetFrameHeightWithSpacing() + rows * ImGui::GetTextLineHeightWithSpacing() +
                       ImGui::GetFrameHeight() + 2 * ImGui::GetStyle().WindowPadding.y +
                       ImGui::GetTextLineHeightWithSpacing() + tickHeight + ImGui::GetStyle().ItemSpacing.y;
  ImGui::SetNextWindowPos(ImVec2(left, io.DisplaySize.y - statusHeight), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(right - left, height), ImGuiCond_Always);
  ImGui::Begin("Timeline", nullptr,
               ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  ui.frame.layout.bottom = ImGui::GetWindowPos().y;
  core::Scene& scene = ui.document.scene;
  const double length = timelineLength(scene);
  if (button(ui, "timeline/", timeline.playing ? "Pause" : "Play")) {
    timeline.playing = !timeline.playing;
    // Play at the end starts over.
    if (timeline.playing && scene.animation.time >= length - 1e-9) showTime(ui.document, timeline, prompts, 0.0);
  }
  ImGui::SameLine();
  const std::vector<double> times = keyTimes(scene);
  const double now = scene.animation.time;
  if (button(ui, "timeline/", "|<")) {
    double target = 0.0;
    for (double t : times)
      if (t < now - 1e-6) target = t;
    showTime(ui.document, timeline, prompts, target);
  }
  ImGui::SameLine();
  if (button(ui, "timeline/", ">|")) {
    double target = length;
    for (auto t = times.rbegin(); t != times.rend(); ++t)
      if (*t > now + 1e-6) target = *t;
    showTime(ui.document, timeline, prompts, target);
  }
  ImGui::SameLine();
  if (button(ui, "timeline/", "Key")) {
    try {
      // What changed since the time was last shown becomes keys; animated values always get one.
      core::Scene animated = ui.document.keyBase;
      animated.keyframes = scene.keyframes;
      animated.animation = scene.animation;
      const std::vector<core::KeyframeTrack> before = scene.keyframes;
      ui.document.replace(core::withKeyframeAt(animated, scene, now));
      ui.document.keyBase = scene;
      timeline.timelineMessage = keyedText(before, scene.keyframes, now);
    } catch (const core::Error& e) {
      prompts.notice = e.what();
    }
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("keyframe every value you changed here (and every animated one)");
  ImGui::SameLine();
  const bool keyHere = std::any_of(times.begin(), times.end(), [&](double t) { return std::abs(t - now) < 1e-6; });
  ImGui::BeginDisabled(!keyHere);
  if (button(ui, "timeline/", "Delete key")) {
    core::Scene without = scene;
    for (core::KeyframeTrack& track : without.keyframes)
      std::erase_if(track.keys, [&](const core::Keyframe& key) { return std::abs(key.time - now) < 1e-6; });
    std::erase_if(without.keyframes, [](const core::KeyframeTrack& track) { return track.keys.empty(); });
    ui.document.replace(without);
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90 * scale);
  const core::Field<core::AnimationSettings>& durationField = core::field(core::animationFields(), "duration");
  double duration = scene.animation.duration;
  if (ImGui::DragScalar("duration", ImGuiDataType_Double, &duration, 0.05f, &durationField.ui.min,
                        &durationField.ui.max, duration > 0.0 ? std::string(durationField.ui.format).c_str() : "auto",
                        ImGuiSliderFlags_AlwaysClamp)) {
    scene.animation.duration = duration;
    ui.document.edited(durationField.affects);
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70 * scale);
  const core::Field<core::AnimationSettings>& fpsField = core::field(core::animationFields(), "fps");
  double fps = scene.animation.fps;
  if (ImGui::DragScalar("fps", ImGuiDataType_Double, &fps, 0.2f, &fpsField.ui.min, &fpsField.ui.max,
                        std::string(fpsField.ui.format).c_str(), ImGuiSliderFlags_AlwaysClamp)) {
    scene.animation.fps = fps;
    ui.document.edited(fpsField.affects);
  }
  ImGui::SameLine();
  reportEdit(ui, ImGui::Checkbox("loop", &scene.animation.loop), core::field(core::animationFields(), "loop").affects);

  // The scrubber, with a tick for every key time in a strip under it: inside it they covered the
  // time it shows.
  double time = now;
  const double zero = 0.0;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderScalar("##time", ImGuiDataType_Double, &time, &zero, &length, "%.2f s")) {
    timeline.playing = false;
    showTime(ui.document, timeline, prompts, time);
  }
  probe(ui, "timeline/time");
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  const float grab = ImGui::GetStyle().GrabMinSize;
  ImGui::Dummy(ImVec2(max.x - min.x, tickHeight));
  probe(ui, "timeline/ticks");
  const float tickTop = ImGui::GetItemRectMin().y;
  for (double t : times) {
    const float x = min.x + grab * 0.5f + static_cast<float>(t / length) * (max.x - min.x - grab);
    ImGui::GetWindowDrawList()->AddTriangleFilled(ImVec2(x - 4 * scale, tickTop + tickHeight),
                                                  ImVec2(x + 4 * scale, tickTop + tickHeight), ImVec2(x, tickTop),
                                                  IM_COL32(255, 190, 90, 255));
  }
  if (scene.keyframes.empty()) {
    dimText("no keyframes: move the time, change something, press Key");
  } else {
    if (!timeline.timelineMessage.empty()) dimText("%s", timeline.timelineMessage.c_str());
    // One row per animated value: its name, then its keys as ticks over the animation's length,
    // in a column right of every name (the longest sets it, up to half the row; a name longer than
    // that is shortened, whole in its tooltip); a value with one key holds still.
    const char* holdsText = "(one key: holds still)";
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float mark = 4 * scale;  // a key's half width
    float namesWidth = 0.0f;
    for (const core::KeyframeTrack& track : scene.keyframes)
      namesWidth = std::max(namesWidth, ImGui::CalcTextSize(trackName(track.path).c_str()).x +
                                            (track.keys.size() == 1 ? spacing + ImGui::CalcTextSize(holdsText).x : 0));
    const float nameWidth = std::min(std::max(namesWidth, 160 * scale), 0.5f * (max.x - min.x));
    const float rowLeft = min.x + nameWidth + spacing + mark;
    const float rowRight = std::max(rowLeft + 1.0f, max.x - grab * 0.5f);
    for (const core::KeyframeTrack& track : scene.keyframes) {
      const bool holds = track.keys.size() == 1;
      // Where both do not fit, the name and "holds still" share the column.
      const float holdsWidth = holds ? std::min(spacing + ImGui::CalcTextSize(holdsText).x, 0.5f * nameWidth) : 0.0f;
      const std::string name = fittedText(trackName(track.path), nameWidth - holdsWidth);
      const ImVec2 row = ImGui::GetCursorScreenPos();
      ImGui::TextUnformatted(name.c_str());
      probe(ui, "timeline/track/" + track.path);
      probeText(ui, "timeline/track/" + track.path, name);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s%s", track.path.c_str(), holds ? "\none key: holds still" : "");
      const std::string holdsShown =
          holds ? fittedText(holdsText, nameWidth - ImGui::CalcTextSize(name.c_str()).x - spacing) : std::string();
      if (!holdsShown.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(kDimColor, "%s", holdsShown.c_str());
        probe(ui, "timeline/track/" + track.path + "/holds");
      }
      const float rowHeight = ImGui::GetTextLineHeight();
      ImDrawList* draw = ImGui::GetWindowDrawList();
      draw->AddLine(ImVec2(rowLeft, row.y + 0.5f * rowHeight), ImVec2(rowRight, row.y + 0.5f * rowHeight),
                    IM_COL32(110, 115, 130, 255));
      for (const core::Keyframe& key : track.keys) {
        const float x = rowLeft + static_cast<float>(key.time / std::max(length, 1e-9)) * (rowRight - rowLeft);
        draw->AddQuadFilled(ImVec2(x, row.y + 1), ImVec2(x + mark, row.y + 0.5f * rowHeight),
                            ImVec2(x, row.y + rowHeight - 1), ImVec2(x - mark, row.y + 0.5f * rowHeight),
                            IM_COL32(255, 190, 90, 255));
      }
      if (ui.frame.probe)
        ui.frame.probe->items["timeline/track/" + track.path + "/keys"] =
            UiProbe::Rect{rowLeft - mark, row.y, rowRight + mark, row.y + rowHeight};
    }
  }
  ImGui::End();
}

}  // namespace voxflame::app::panels
