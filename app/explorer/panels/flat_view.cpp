// The flat view: a flame layer in 2D as flam3 frames it, rendered off the main thread when what it
// shows changed and drawn behind the panels. Reads the scene; changes only the view's own state.
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "core/flame/flat_render.h"
#include "panels.h"

namespace voxflame::app::panels {

// ---------------------------------------------------------------------------------------------
// The flat view: rendered off the main thread when what it shows changed, drawn behind the panels.

// At most this quality and this many samples (those of a 640 × 640 picture at quality 50), so an
// edit shows within about a second: a large view renders at its full size with fewer samples per
// pixel rather than at a small one stretched.
constexpr double kFlatViewMaxQuality = 50.0;
constexpr double kFlatViewMaxSamples = 640.0 * 640.0 * 50.0;

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

// The size the flat view renders at: the flame's aspect fitted into the view's rectangle, in the
// framebuffer's pixels, so the picture is drawn at one texel a pixel. (0, 0) while the view has no
// rectangle yet.
glm::ivec2 flatViewSize(const core::FlatViewSettings& flat, const glm::ivec4& viewRect) {
  if (viewRect.z <= 0 || viewRect.w <= 0 || flat.width < 1 || flat.height < 1) return glm::ivec2(0);
  const double aspect = static_cast<double>(flat.height) / flat.width;
  if (viewRect.z * aspect <= viewRect.w)
    return glm::ivec2(viewRect.z, std::max(1, static_cast<int>(std::lround(viewRect.z * aspect))));
  return glm::ivec2(std::max(1, static_cast<int>(std::lround(viewRect.w / aspect))), viewRect.w);
}

void updateFlatView(const Document& document, FlatViewState& flat, Services& services, FrameOutputs& frame) {
  if (!flat.on) {
    // Runs every frame while the view is off: costs nothing unless a render was under way or kept.
    if (services.flatRender.busy()) services.flatRender.cancel();
    flat.rendered.layers.clear();  // so that turning the view on renders afresh
    flat.checkedRevision = ~std::uint64_t{0};
    flat.renderedSize = glm::ivec2(0);
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
  // Only an edit or a new size of the view can change what the flat view shows: no copy of the
  // layer is made on the frames between.
  const glm::ivec2 size = flatViewSize(document.scene.flat, frame.viewRect);
  if (flat.checkedRevision == document.revisions().any && size == flat.renderedSize) return;
  flat.checkedRevision = document.revisions().any;
  const core::Scene shown = flatViewScene(document.scene);
  if (shown.layers.empty()) {
    flat.message = "the flat view shows flame layers; this scene has none";
    return;
  }
  if (size.x <= 0 || size.y <= 0) return;  // the first frame places the view
  if (shown == flat.rendered && size == flat.renderedSize) return;
  flat.rendered = shown;
  flat.renderedSize = size;
  core::FlatRenderOptions options;
  // One side alone: the other follows the flame's aspect, as flatViewSize fitted it.
  if (size.x == frame.viewRect.z)
    options.width = size.x;
  else
    options.height = size.y;
  const double pixels = static_cast<double>(size.x) * size.y;
  options.quality = std::min({shown.flat.quality, kFlatViewMaxQuality, kFlatViewMaxSamples / pixels});
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

// The flat image in the view's rectangle between the panels, over the volume: one texel a
// framebuffer pixel, centred, on black; its caption in the rectangle's lower left corner.
void drawFlatView(const FlatViewState& flat, const Services& services, FrameOutputs& frame) {
  if (!flat.on || frame.viewRect.z <= 0 || frame.viewRect.w <= 0) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec4 view = viewRectInWindow(frame, glm::dvec4(0.0, 0.0, frame.viewRect.z, frame.viewRect.w));
  const ImVec2 viewMin(view.x, view.y), viewMax(view.z, view.w);
  draw->PushClipRect(viewMin, viewMax);
  draw->AddRectFilled(viewMin, viewMax, IM_COL32(0, 0, 0, 255));
  if (frame.flatTexture && frame.flatTextureWidth > 0 && frame.flatTextureHeight > 0) {
    // Centred on whole pixels, so that each texel lands on one pixel (an older image, of another
    // size, shows the same way until the new one comes, cut to the view).
    const int x = frame.viewRect.x + (frame.viewRect.z - frame.flatTextureWidth) / 2;
    const int y = frame.viewRect.y + (frame.viewRect.w - frame.flatTextureHeight) / 2;
    const ImVec4 r = viewRectInWindow(
        frame, glm::dvec4(x - frame.viewRect.x, y - frame.viewRect.y, frame.flatTextureWidth, frame.flatTextureHeight));
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(frame.flatTexture)), ImVec2(r.x, r.y),
                   ImVec2(r.z, r.w));
    if (frame.probe) frame.probe->items["flat/image"] = UiProbe::Rect{r.x, r.y, r.z, r.w};
  }
  const char* text = !flat.message.empty()        ? flat.message.c_str()
                     : services.flatRender.busy() ? "flat view: rendering…"
                                                  : "flat view (as flam3 renders it)";
  const ImVec2 textSize = ImGui::CalcTextSize(text);
  const float margin = ImGui::GetStyle().WindowPadding.x;
  const ImVec2 at(viewMin.x + margin, viewMax.y - margin - textSize.y);
  draw->AddText(at, IM_COL32(220, 220, 220, 255), text);
  draw->PopClipRect();
  if (frame.probe) {
    frame.probe->items["flat/caption"] = UiProbe::Rect{at.x, at.y, at.x + textSize.x, at.y + textSize.y};
    frame.probe->texts["flat/caption"] = text;
  }
}

}  // namespace voxflame::app::panels
