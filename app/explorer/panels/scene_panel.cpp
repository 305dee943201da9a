// The Scene panel and the view: mesh and grid, render and tone, camera, presets and export, and the
// picture's place between the docked panels (with the export's frame). Changes the mesh, grid,
// tone, render and camera; saves presets and starts exports.
#include "explorer_ui.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "core/camera.h"
#include "core/error.h"
#include "core/grid.h"
#include "core/scene_schema.h"
#include "panels.h"
#include "widgets.h"

namespace voxflame::app {

void startExport(ExplorerState& state, ExportJob& job, const ExportRequest& request) {
  try {
    state.services.settings.lastExportFolder = std::filesystem::absolute(request.output).parent_path();
    job.start(request);
    state.services.exportStatus = job.poll();
  } catch (const core::Error& e) {
    state.panels.prompts.notice = e.what();
  }
}

}  // namespace voxflame::app

namespace voxflame::app::panels {

std::string formatBytes(double bytes) {
  char text[32];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.1f GB", bytes * 1e-9);
  else
    std::snprintf(text, sizeof text, "%.0f MB", bytes * 1e-6);
  return text;
}

void meshSection(Ui& ui, ScenePanelState& scenePanel, const Services& services) {
  const std::string file = std::filesystem::path(ui.document.scene.meshPath).filename().string();
  ImGui::Text("mesh: %s%s", file.c_str(), ui.document.scene.embedded ? " (built in)" : "");
  ImGui::InputTextWithHint("##meshpath", "path to a mesh, preset or image", scenePanel.meshPath,
                           sizeof scenePanel.meshPath);
  noteTyped(ui, "mesh path", scenePanel.meshPath);
  probe(ui, "mesh/path");
  ImGui::SameLine();
  if (button(ui, "mesh/", "Open") && scenePanel.meshPath[0] != '\0') ui.frame.requests.open = scenePanel.meshPath;
  if (!services.settings.recent.empty() && ImGui::BeginCombo("recent", "recent files")) {
    for (const RecentFile& recent : services.settings.recent) {
      const std::string label = recent.path.filename().string() + "  (" + recent.path.parent_path().string() + ")";
      if (ImGui::Selectable(label.c_str())) ui.frame.requests.open = recent.path;
    }
    ImGui::EndCombo();
  }
  dimText("or drop a mesh, preset or PNG onto the window");

  // The grid only changes when the slider is let go: each change rebuilds the mask.
  int& draft = scenePanel.gridDraft;
  if (!ImGui::IsAnyItemActive() || draft == 0) draft = ui.document.scene.gridResolution;
  const core::Field<core::Scene>& grid = core::field(core::sceneFields(), "grid.resolution");
  ImGui::SliderInt(std::string(grid.ui.label).c_str(), &draft, static_cast<int>(grid.ui.min),
                   static_cast<int>(grid.ui.max), std::string(grid.ui.format).c_str(), ImGuiSliderFlags_AlwaysClamp);
  probe(ui, "mesh/grid");
  if (ImGui::IsItemDeactivatedAfterEdit() && draft != ui.document.scene.gridResolution) {
    ui.document.scene.gridResolution = draft;
    ui.document.edited(grid.affects);
  }
  // What a session on the grid over this mesh holds (a cube before the first shape is ready).
  core::GridGeometry draftGrid;
  try {
    const core::Box box =
        ui.frame.session.hasShape ? ui.frame.session.grid.box() : core::Box{glm::dvec3(0.0), glm::dvec3(1.0)};
    draftGrid = core::gridOverBox(box, std::clamp(draft, core::kMinGridResolution, core::kMaxGridResolution));
  } catch (const core::Error&) {
    draftGrid.size = glm::ivec3(std::max(draft, 1));
  }
  dimText("about %s of memory", formatBytes(static_cast<double>(ExplorerSession::estimatedBytes(draftGrid))).c_str());

  core::RenderSettingsDoc& render = ui.document.scene.render;
  fieldWidget(ui, "mesh/", render, core::renderFields(), "mesh");
  fieldWidget(ui, "mesh/", render, core::renderFields(), "mesh_color");
  fieldWidget(ui, "mesh/", render, core::renderFields(), "mesh_strength");
}

void renderSection(Ui& ui, ScenePanelState& scenePanel, Services& services) {
  core::ToneMapSettings& tone = ui.document.scene.tone;
  for (std::string_view key :
       {"brightness", "gamma", "gamma_threshold", "vibrancy", "highlight_power", "exposure", "contrast", "opacity",
        "estimator_radius", "estimator_minimum", "estimator_curve", "background"})
    fieldWidget(ui, "tone/", tone, core::toneFields(), key);
  core::RenderSettingsDoc& render = ui.document.scene.render;
  fieldWidget(ui, "render/", render, core::renderFields(), "step");
  fieldWidget(ui, "render/", render, core::renderFields(), "method", "render/method");
  fieldWidget(ui, "render/", render, core::renderFields(), "oversample");
  fieldWidget(ui, "render/", render, core::renderFields(), "filter_radius");
  if (render.method == core::RenderMethod::Points)
    for (std::string_view key : {"dof.aperture", "dof.focus_distance", "fog"})
      fieldWidget(ui, "render/", render, core::renderFields(), key);
  fieldWidget(ui, "render/", render, core::renderFields(), "lighting");
  if (render.lighting)
    for (std::string_view key : {"light_azimuth_deg", "light_elevation_deg", "light_strength"})
      fieldWidget(ui, "render/", render, core::renderFields(), key);
  ImGui::SliderFloat("preview scale", &scenePanel.renderScale, 0.25f, 1.0f, "%.2f");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "fraction of the window's pixels marched while the view is still (playback goes as sharp as "
        "the frame budget allows)");
  ImGui::SliderFloat("frame budget", &scenePanel.frameBudgetMs, 8.0f, 200.0f, "%.0f ms");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("while you edit, orbit or play, as many pixels are marched as keep frames this quick");
  // 0 reads "never": the slider's left end is refining until the next edit.
  double& stopAt = services.settings.refineUntilNoisePercent;
  const double low = 0.0, high = 10.0;
  const char* stopLabel = "stop refining at noise";
  const bool stopBeside = labelFitsBeside(ui, stopLabel, "render/stop_refining_at_noise");
  if (!stopBeside) labelAbove(ui, stopLabel, "render/stop_refining_at_noise");
  ImGui::SliderScalar(stopBeside ? stopLabel : "##stop refining at noise", ImGuiDataType_Double, &stopAt, &low, &high,
                      stopAt <= 0.0 ? "at the cap" : "%.2f%%", ImGuiSliderFlags_Logarithmic);
  probe(ui, "render/stop_refining_at_noise");
  stopAt = std::clamp(stopAt, 0.0, 100.0);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "the volume stops refining (and the explorer rests) once two measurements of its noise in a row are this\n"
        "low, or at the grid's cap of points per voxel, whichever comes first; a lower target refines on from\n"
        "the points already there");
  // What refines the volume: a setting of the explorer, kept with the others, not in the preset.
  BackendChoice& backend = services.settings.refinementBackend;
  int backendIndex = static_cast<int>(backend);
  const char* backendNames[] = {"cpu", "gpu", "auto"};
  if (ImGui::Combo("refine on", &backendIndex, backendNames, 3)) backend = static_cast<BackendChoice>(backendIndex);
  probe(ui, "render/refine_on");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "cpu: every core; gpu: compute shaders (attractors, quaternion Julia sets, and flames of the\n"
        "variations it has; other flames refine on the CPU);\n"
        "auto: the GPU where it is a hardware one. A change refines the volume again from nothing");
  const SessionStatus& session = ui.frame.session;
  dimText("refining on the %s backend%s%s", std::string(core::toString(session.backend)).c_str(),
          session.backendNote.empty() ? "" : ": ", session.backendNote.c_str());
}

void cameraSection(Ui& ui) {
  core::CameraSettings& camera = ui.document.scene.camera;
  for (std::string_view key : {"azimuth_deg", "elevation_deg", "roll_deg", "distance", "fov_deg"})
    fieldWidget(ui, "camera/", camera, core::cameraFields(), key);
  bool orthographic = camera.projection == core::Projection::Orthographic;
  if (reportEdit(ui, ImGui::Checkbox("orthographic", &orthographic), core::Affects::View))
    camera.projection = orthographic ? core::Projection::Orthographic : core::Projection::Perspective;
  auto view = [&](const char* label, double azimuth, double elevation) {
    if (reportEdit(ui, button(ui, "camera/", label), core::Affects::View)) {
      camera.azimuthDeg = azimuth, camera.elevationDeg = elevation, camera.rollDeg = 0.0;
      camera.target = glm::dvec3(0.0);
    }
  };
  view("Front", 0.0, 0.0);
  ImGui::SameLine();
  view("Side", 90.0, 0.0);
  ImGui::SameLine();
  view("Top", 0.0, 90.0);
  ImGui::SameLine();
  if (reportEdit(ui, button(ui, "camera/", "Reset"), core::Affects::View)) camera = ui.document.initialCamera;
  dimText("drag: orbit · right/middle drag: pan · wheel: zoom · W/A/S/D/Q/E: fly");
}

void presetsSection(FrameOutputs& frame, ScenePanelState& scenePanel, PromptsState& prompts, Services& services,
                    float scale) {
  if (!services.presets) return;
  const PresetLibrary::Entries entries = services.presets->entries();
  // Saving comes first, so it stays in reach however long the library grows.
  ImGui::InputTextWithHint("##savename", "name of your preset", scenePanel.saveName, sizeof scenePanel.saveName);
  noteTyped(frame, "preset name", scenePanel.saveName);
  probe(frame, "preset/name");
  ImGui::SameLine();
  if (button(frame, "preset/", "Save as") && scenePanel.saveName[0] != '\0')
    frame.requests.saveAs = scenePanel.saveName;
  ImGui::SameLine();
  if (button(frame, "preset/", "Refresh")) services.presets->refresh();
  if (!scenePanel.presetMessage.empty()) ImGui::TextWrapped("%s", scenePanel.presetMessage.c_str());
  if (services.presets->busy()) dimText("reading presets…");
  if (entries) {
    const float size = 92 * scale;
    const int columns = std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / (size + 8 * scale)));
    int column = 0;
    PresetSource lastSource = PresetSource::Shipped;
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const PresetEntry& entry = (*entries)[i];
      if (i == 0 || entry.source != lastSource) {
        dimText(entry.source == PresetSource::Shipped ? "shipped" : "yours (%s)",
                services.presets->userFolder().string().c_str());
        column = 0;
      }
      lastSource = entry.source;
      if (column++ % columns != 0) ImGui::SameLine();
      ImGui::PushID(static_cast<int>(i));
      ImGui::BeginGroup();
      const auto texture = frame.thumbnailTextures.find(entry.path);
      bool clicked = false;
      if (texture != frame.thumbnailTextures.end() && entry.thumbnail) {
        const float aspect = static_cast<float>(entry.thumbnail->height) / static_cast<float>(entry.thumbnail->width);
        clicked = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture->second)),
                                     ImVec2(size, size * aspect));
      } else {
        clicked = ImGui::Button(entry.loads ? "no image" : "broken", ImVec2(size, size * 0.625f));
      }
      probe(frame, "preset/" + entry.path.stem().string());
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s\n%s", entry.displayName.c_str(),
                          entry.loads ? entry.attractor.c_str() : entry.error.c_str());
      if (clicked) {
        if (entry.loads)
          frame.requests.open = entry.path;
        else
          prompts.notice = entry.error;
      }
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size);
      ImGui::TextUnformatted(entry.displayName.c_str());
      ImGui::PopTextWrapPos();
      ImGui::EndGroup();
      ImGui::PopID();
    }
  }
}

void exportSection(const Document& document, FrameOutputs& frame, ScenePanelState& scenePanel, Services& services,
                   float scale) {
  if (!services.exportJob) return;
  ExportSettings& settings = services.settings.lastExport;
  int size[2] = {settings.width, settings.height};
  if (ImGui::InputInt2("size", size)) {
    settings.width = std::clamp(size[0], 16, 65536);
    settings.height = std::clamp(size[1], 16, 65536);
  }
  ImGui::SliderInt("samples", &settings.samples, 1, 64, "%d", ImGuiSliderFlags_Logarithmic);
  double millions = static_cast<double>(settings.points ? settings.points : document.scene.points) * 1e-6;
  const double minPoints = 0.1, maxPoints = 10000.0;
  if (ImGui::SliderScalar("M points", ImGuiDataType_Double, &millions, &minPoints, &maxPoints, "%.1f",
                          ImGuiSliderFlags_Logarithmic))
    settings.points = static_cast<std::uint64_t>(millions * 1e6);
  dimText("method: %s (Render panel)", std::string(core::toString(document.scene.render.method)).c_str());
  int format = static_cast<int>(settings.format);
  if (ImGui::Combo("format", &format, "PNG 8-bit\0PNG 16-bit\0EXR (linear float)\0"))
    settings.format = static_cast<ExportFormat>(format);
  // The file is named after the document, and follows it (a save-as renames it) until typed over.
  if (scenePanel.exportPath[0] == '\0' || scenePanel.exportPathMade == scenePanel.exportPath) {
    const std::filesystem::path folder = services.settings.lastExportFolder.empty()
                                             ? std::filesystem::current_path()
                                             : services.settings.lastExportFolder;
    const std::string path =
        (folder / (sanitizePresetName(document.scene.name) + extensionOf(settings.format))).string();
    std::snprintf(scenePanel.exportPath, sizeof scenePanel.exportPath, "%s", path.c_str());
    scenePanel.exportPathMade = scenePanel.exportPath;
  }
  ImGui::InputText("file", scenePanel.exportPath, sizeof scenePanel.exportPath);
  noteTyped(frame, "export file", scenePanel.exportPath);
  probe(frame, "export/file");
  if (frame.viewRect.z > 0 && frame.viewRect.w > 0) {
    ImGui::SameLine();
    if (button(frame, "export/", "view size")) {
      settings.width = std::clamp(frame.viewRect.z, 16, 65536);
      settings.height = std::clamp(frame.viewRect.w, 16, 65536);
    }
  }
  const ExportStatus& status = services.exportStatus;
  if (status.state == ExportState::Running) {
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%s %.0f%%", status.stage.c_str(), 100.0 * status.overall);
    ImGui::ProgressBar(static_cast<float>(status.overall), ImVec2(-80 * scale, 0), overlay);
    ImGui::SameLine();
    if (button(frame, "export/", "Cancel")) services.exportJob->cancel();
    return;
  }
  if (button(frame, "export/", "Export now")) {  // not "Export": the header above has that id
    ExportRequest request;
    request.scene = document.scene;
    request.settings = settings;
    request.output = withExtensionFor(scenePanel.exportPath, settings.format);
    request.executable = services.executable;
    const bool madePath = scenePanel.exportPathMade == scenePanel.exportPath;
    std::snprintf(scenePanel.exportPath, sizeof scenePanel.exportPath, "%s", request.output.string().c_str());
    if (madePath) scenePanel.exportPathMade = scenePanel.exportPath;
    std::error_code error;
    if (std::filesystem::exists(request.output, error))
      scenePanel.exportToConfirm = std::move(request);  // asked below first
    else
      frame.requests.exportStill = std::move(request);
  }
  if (scenePanel.exportToConfirm) {
    ImGui::TextColored(kErrorColor, "%s exists.", scenePanel.exportToConfirm->output.filename().string().c_str());
    ImGui::SameLine();
    if (button(frame, "export/", "Replace it")) {
      frame.requests.exportStill = std::move(*scenePanel.exportToConfirm);
      scenePanel.exportToConfirm.reset();
    }
    ImGui::SameLine();
    if (scenePanel.exportToConfirm && button(frame, "export/", "Keep it")) scenePanel.exportToConfirm.reset();
  }
  if (status.state == ExportState::Done) ImGui::TextWrapped("wrote %s", status.output.string().c_str());
  if (status.state == ExportState::Failed) ImGui::TextColored(kErrorColor, "%s", status.error.c_str());
  if (status.state == ExportState::Cancelled) dimText("cancelled; nothing was written");
}

// The view's rectangle in window coordinates (from the top), from framebuffer pixels from the bottom.
ImVec4 viewRectInWindow(const FrameOutputs& frame, glm::dvec4 rect) {
  const ImGuiIO& io = ImGui::GetIO();
  const ImVec2 scale = io.DisplayFramebufferScale;
  return ImVec4(static_cast<float>(frame.viewRect.x + rect.x) / scale.x,
                io.DisplaySize.y - static_cast<float>(frame.viewRect.y + rect.y + rect.w) / scale.y,
                static_cast<float>(frame.viewRect.x + rect.x + rect.z) / scale.x,
                io.DisplaySize.y - static_cast<float>(frame.viewRect.y + rect.y) / scale.y);
}

// While the pattern escapes the view keeps the last bounded picture, dimmed: it is not the
// pattern the sliders say.
void dimLastBoundedPicture(const FrameOutputs& frame) {
  if (!frame.session.showingLastBounded || frame.viewRect.z <= 0 || frame.viewRect.w <= 0) return;
  const ImVec4 r = viewRectInWindow(frame, glm::dvec4(0.0, 0.0, frame.viewRect.z, frame.viewRect.w));
  ImGui::GetBackgroundDrawList()->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.z, r.w), IM_COL32(0, 0, 0, 140));
}

// Where the export's picture lies in the view, when its aspect is not the view's: a thin frame.
void drawExportFrame(const FrameOutputs& frame, const Services& services) {
  const ExportSettings& settings = services.settings.lastExport;
  if (frame.viewRect.z <= 0 || frame.viewRect.w <= 0 || settings.width <= 0 || settings.height <= 0) return;
  const double viewAspect = static_cast<double>(frame.viewRect.z) / frame.viewRect.w;
  const double aspect = static_cast<double>(settings.width) / settings.height;
  if (std::abs(aspect / viewAspect - 1.0) < 0.005) return;
  const ImVec4 r = viewRectInWindow(frame, core::exportFrame(glm::dvec2(frame.viewRect.z, frame.viewRect.w), aspect));
  ImGui::GetBackgroundDrawList()->AddRect(ImVec2(r.x, r.y), ImVec2(r.z, r.w), IM_COL32(255, 255, 255, 110));
}

// The picture's rectangle: between the side panels, above the Timeline, in framebuffer pixels.
void placeView(FrameOutputs& frame, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float left = std::clamp(frame.layout.left, 0.0f, io.DisplaySize.x);
  const float right =
      std::clamp(frame.layout.right > left ? frame.layout.right : io.DisplaySize.x, left, io.DisplaySize.x);
  const float bottom =
      std::clamp(frame.layout.bottom > 0.0f ? frame.layout.bottom : io.DisplaySize.y - statusBarHeight(scale), 0.0f,
                 io.DisplaySize.y);
  const ImVec2 toPixels = io.DisplayFramebufferScale;
  const int x = static_cast<int>(std::lround(left * toPixels.x));
  const int width = static_cast<int>(std::lround(right * toPixels.x)) - x;
  const int height = static_cast<int>(std::lround(bottom * toPixels.y));
  const int fromBottom = static_cast<int>(std::lround(io.DisplaySize.y * toPixels.y)) - height;
  frame.viewRect = width > 0 && height > 0 ? glm::ivec4(x, fromBottom, width, height) : glm::ivec4(0);
}

void viewWindow(Ui& ui, ScenePanelState& scenePanel, PromptsState& prompts, Services& services, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  // Docked at the right, full height above the status line; only its width is the user's.
  const float height = io.DisplaySize.y - statusBarHeight(scale);
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x, 0), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(320 * scale, height), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(260 * scale, height), ImVec2(0.4f * io.DisplaySize.x, height));
  ImGui::Begin("Scene", nullptr, ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoMove);
  ui.frame.layout.right = ImGui::IsWindowCollapsed() ? io.DisplaySize.x : ImGui::GetWindowPos().x;
  ImGui::PushItemWidth(-120 * scale);
  if (ImGui::CollapsingHeader("Mesh", ImGuiTreeNodeFlags_DefaultOpen)) meshSection(ui, scenePanel, services);
  if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) renderSection(ui, scenePanel, services);
  const bool cameraOpen = ImGui::CollapsingHeader("Camera");
  probe(ui, "header/Camera");
  if (cameraOpen) cameraSection(ui);
  const bool presetsOpen = ImGui::CollapsingHeader("Presets");
  probe(ui, "header/Presets");
  if (presetsOpen) presetsSection(ui.frame, scenePanel, prompts, services, scale);
  const bool exportOpen = ImGui::CollapsingHeader("Export");
  probe(ui, "header/Export");
  if (exportOpen) exportSection(ui.document, ui.frame, scenePanel, services, scale);
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace voxflame::app::panels
