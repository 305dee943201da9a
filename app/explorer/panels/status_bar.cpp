// The status line: what is happening, in words, with the figures under Stats; and how long the
// window loop may wait for events. Changes nothing but the Stats toggle and "refine further".
#include "explorer_ui.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "panels.h"
#include "widgets.h"

namespace voxflame::app {

std::string convergenceText(const SessionStatus& status) {
  if (!status.hasShape) return "";
  if (!status.escapeNote.empty()) return status.escapeNote;  // nothing refines: this is the news
  char text[200];
  const double noise = 100.0 * status.noise, target = 100.0 * status.noiseTarget;
  const double millions = static_cast<double>(status.stats.points) * 1e-6;
  // The GPU backend says so: the user chose it in the Scene panel, and a flame falls back to the CPU.
  // Where its grid reaches the view through host memory, the status says that too (it costs frames).
  const char* refining = status.backend != core::BackendKind::Gpu ? "refining"
                         : status.gridOnDevice                    ? "refining on the GPU"
                                                                  : "refining on the GPU (grid read back)";
  if (status.paused)
    std::snprintf(text, sizeof text, "refining paused for the export");
  else if (status.converged)
    std::snprintf(text, sizeof text, "at rest: the noise reached its target (%.2g%% of %.2g%%)", noise, target);
  else if (status.capped)
    std::snprintf(text, sizeof text, "at rest: the cap of %.0f points per voxel (noise %.2g%%)",
                  status.capPointsPerVoxel, noise);
  else if (!std::isfinite(noise))
    std::snprintf(text, sizeof text, "%s: %.0f M points, measuring the noise", refining, millions);
  else if (status.noiseTarget > 0.0)
    std::snprintf(text, sizeof text, "%s: %.0f M points, noise %.2g%% of %.2g%%", refining, millions, noise, target);
  else
    std::snprintf(text, sizeof text, "%s: %.0f M points, noise %.2g%%", refining, millions, noise);
  return text;
}

std::string convergenceText(const SessionStatus& status, const ViewRefinement& view) {
  std::string text = convergenceText(status);
  if (text.empty() || !status.escapeNote.empty() || status.paused) return text;
  char line[200];
  const bool sessionRests = text.rfind("at rest", 0) == 0;
  if (!view.pointsError.empty() && (sessionRests || view.resting))
    return "the points picture stopped (" + view.pointsError + "): " + (view.resting ? text : "refining the view");
  if (view.points && (view.pointsDone > 0 || sessionRests) && !view.resting) {
    std::snprintf(line, sizeof line, "points: %.0f M of %.0f M%s", static_cast<double>(view.pointsDone) * 1e-6,
                  static_cast<double>(view.pointsTarget) * 1e-6,
                  view.pointsShown ? "" : " (the volume preview until the first picture is in)");
    return line;
  }
  if (view.points && view.pointsShown && view.resting && sessionRests) {
    std::snprintf(line, sizeof line, "at rest: the points picture holds its %.0f M points",
                  static_cast<double>(view.pointsDone) * 1e-6);
    return line;
  }
  if (sessionRests && !view.resting) {
    std::snprintf(line, sizeof line, "refining the view: %d samples", view.samples);
    return line;
  }
  return text;
}

double frameWaitSeconds(const ExplorerState& state, bool viewResting, int restingFrames) {
  if (state.services.exportStatus.state == ExportState::Running) return 0.1;
  const bool busy = state.panels.timeline.playing || state.services.search.busy() || state.services.analysis.busy() ||
                    state.services.flatRender.busy() || state.frame.flatImagePending || state.panels.drag.orbiting ||
                    state.panels.drag.panning;
  if (busy) return 0.0;
  // The points picture comes a few times in its build-up: the frames between would draw the same
  // pixels and take a core from the points. Input ends the wait at once.
  if (state.frame.view.waitingForPoints) return 0.05;
  if (!viewResting || !state.frame.session.resting || restingFrames < 3) return 0.0;
  // Other threads do not wake the loop; this bounds how late it notices one that finished.
  return 0.5;
}

}  // namespace voxflame::app

namespace voxflame::app::panels {

void statusBar(FrameOutputs& frame, const ExplorePanelState& explore, StatusBarState& status, float scale) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = statusBarHeight(scale);
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const core::AccumulatorStats& stats = frame.session.stats;
  const FrameMetrics& m = frame.metrics;
  // Words first: what is happening. The technical figures are one click (Stats) or a hover away.
  if (frame.session.buildingShape)
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "%s %.1f s", frame.session.shapeStage.c_str(),
                       frame.session.shapeSeconds);
  else if (const std::string convergence = convergenceText(frame.session, frame.view); !convergence.empty())
    ImGui::TextUnformatted(convergence.c_str());
  char figures[400];
  std::snprintf(figures, sizeof figures,
                "%.1f M points  %.1f M/s  inside %.1f%%  reseeded %llu  |  %.0f fps  %.1f ms (worst %.0f)  upload "
                "%.1f ms  %d samples",
                static_cast<double>(stats.points) * 1e-6, stats.pointsPerSecond * 1e-6, 100.0 * stats.insideFraction(),
                static_cast<unsigned long long>(stats.escapes), m.fps, m.frameMs, m.worstFrameMs, m.uploadMs,
                frame.samples);
  // While the pattern escapes, the figures are the last bounded pattern's (or none): say so.
  std::string details = frame.session.showingLastBounded ? std::string("last bounded pattern: ") + figures : figures;
  if (m.changeToFrameMs >= 0.0) {
    std::snprintf(figures, sizeof figures, "  |  edit→frame %.0f ms (%d frames)", m.changeToFrameMs,
                  m.changeToFrameFrames);
    details += figures;
  }
  // The analysis of an orbit that escapes may read as a fixed point: the escape is what is true.
  if (!frame.session.escapeNote.empty())
    details += "  |  escapes";
  else if (!explore.lyapunovText.empty())
    details += "  |  " + explore.lyapunovText;
  if (ImGui::IsItemHovered() && !status.showStats) ImGui::SetTooltip("%s", details.c_str());
  if ((frame.session.converged || frame.session.capped) && !frame.session.buildingShape) {
    ImGui::SameLine();
    if (ImGui::SmallButton("Refine further")) frame.requests.refineFurther = true;
    probe(frame, "status/refine_further");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("go on from the %.0f points per voxel already there to twice as many",
                        frame.session.pointsPerVoxel);
  }
  ImGui::SameLine();
  if (ImGui::SmallButton(status.showStats ? "Hide stats###stats" : "Stats###stats"))
    status.showStats = !status.showStats;
  probe(frame, "status/stats");
  if (status.showStats) {
    ImGui::SameLine();
    ImGui::TextColored(kDimColor, "%s", details.c_str());
  }
  ImGui::End();
}

}  // namespace voxflame::app::panels
