// The flat view: a flame layer in 2D as flam3 frames it, rendered off the main thread when what it
// shows changed and drawn behind the panels. Reads the scene; changes only the view's own state.
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <sstream>
#include <cstdarg>
#include <cctype>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "core/attractor.h"
#include "core/camera.h"
#include "core/color.h"
#include "core/error.h"
#include "core/flame.h"
#include "core/flame_search.h"
#include "core/flame_variations.h"
#include "core/flame_xml.h"
#include "core/flat_render.h"
#include "core/grid.h"
#include "core/keyframes.h"
#include "core/scene_schema.h"
#include "commands.h"
#include "pipeline.h"
#include "panels.h"
#include "widgets.h"

namespace voxflame::app::panels {

// ---------------------------------------------------------------------------------------------
// The flat view: rendered off the main thread when what it shows changed, drawn behind the panels.

// At most this wide and this quality, so an edit shows within about a second.
constexpr int kFlatViewMaxWidth = 640;
constexpr double kFlatViewMaxQuality = 50.0;

const core::PatternLayer* firstFlameLayer(const core::Scene& scene) {
  for (const core::PatternLayer& layer : scene.layers)
    if (layer.kind == core::PatternKind::Flame) return &layer;
  return nullptr;
}

// The part of the scene the flat view shows: the first flame layer, the tone and the framing.
core::Scene flatViewScene(const core::Scene& scene) {
  core::Scene shown;
  shown.name = scene.name;
  if (const core::PatternLayer* layer = firstFlameLayer(scene)) shown.layers = {*layer};
  shown.tone = scene.tone;
  shown.flat = scene.flat;
  return shown;
}

void updateFlatView(const Document& document, FlatViewState& flat, Services& services, FrameOutputs& frame) {
  if (!flat.on) {
    // Runs every frame while the view is off: costs nothing unless a render was under way or kept.
    if (services.flatRender.busy()) services.flatRender.cancel();
    flat.rendered.layers.clear();  // so that turning the view on renders afresh
    flat.checkedRevision = ~std::uint64_t{0};
    return;
  }
  if (services.flatRender.ready()) {
    try {
      frame.flatImage = *services.flatRender.take();
      frame.flatImagePending = true;
      flat.message.clear();
    } catch (const std::exception& e) {
      flat.message = e.what();
    }
  }
  // Only an edit can change what the flat view shows: no copy of the layer is made on the frames between.
  if (flat.checkedRevision == document.revisions().any) return;
  flat.checkedRevision = document.revisions().any;
  const core::Scene shown = flatViewScene(document.scene);
  if (shown.layers.empty()) {
    flat.message = "the flat view shows flame layers; this scene has none";
    return;
  }
  if (shown == flat.rendered) return;
  flat.rendered = shown;
  core::FlatRenderOptions options;
  options.width = std::min(shown.flat.width, kFlatViewMaxWidth);
  options.quality = std::min(shown.flat.quality, kFlatViewMaxQuality);
  services.flatRender.start([shown, options](std::stop_token stop) mutable {
    std::atomic<bool> cancel{false};
    const std::stop_callback onStop(stop, [&cancel] { cancel = true; });
    options.cancel = &cancel;
    try {
      return core::renderFlat(shown, options).image;
    } catch (const core::FlatRenderCancelled&) {
      return core::ImageRGBA{};
    }
  });
}

// The flat image over the whole window behind the panels, letterboxed to its aspect.
void drawFlatView(const FlatViewState& flat, const Services& services, const FrameOutputs& frame) {
  if (!flat.on) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  draw->AddRectFilled(ImVec2(0.0f, 0.0f), display, IM_COL32(0, 0, 0, 255));
  if (frame.flatTexture && frame.flatTextureWidth > 0 && frame.flatTextureHeight > 0) {
    const float fit = std::min(display.x / static_cast<float>(frame.flatTextureWidth),
                               display.y / static_cast<float>(frame.flatTextureHeight));
    const ImVec2 size(fit * static_cast<float>(frame.flatTextureWidth),
                      fit * static_cast<float>(frame.flatTextureHeight));
    const ImVec2 corner(0.5f * (display.x - size.x), 0.5f * (display.y - size.y));
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(frame.flatTexture)), corner,
                   ImVec2(corner.x + size.x, corner.y + size.y));
  }
  const char* text = !flat.message.empty()        ? flat.message.c_str()
                     : services.flatRender.busy() ? "flat view: rendering…"
                                                  : "flat view (as flam3 renders it)";
  draw->AddText(ImVec2(12.0f, display.y - 48.0f), IM_COL32(220, 220, 220, 255), text);
}

}  // namespace voxflame::app::panels
