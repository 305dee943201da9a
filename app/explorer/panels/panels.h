// The explorer's panels, one file each (app/explorer/panels/): what explorerUiFrame calls, and what
// the panels call of one another. Internal to voxflame_explorer; tests drive the panels through
// explorerUiFrame (explorer_ui.h).
#pragma once

#include <imgui.h>

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/flame.h"
#include "core/flame_search.h"
#include "core/flame_xml.h"
#include "explorer_ui.h"

namespace voxflame::app {

// Puts a flame just imported from `path` in place of the pattern (openFile, flameChoiceWindow).
void applyImportedFlame(ExplorerState& state, const std::filesystem::path& path,
                        const core::FlameFileContents& contents, const core::Scene& scene);

}  // namespace voxflame::app

namespace voxflame::app::panels {

// flat_view.cpp
core::Scene flatViewScene(const core::Scene& scene);
void updateFlatView(ExplorerState& state);
void drawFlatView(const ExplorerState& state);

// explore_panel.cpp
std::string analysisKey(const core::PatternLayer& layer);
void updateAnalysis(ExplorerState& state);
void applyVisited(core::PatternLayer& layer, const core::PatternLayer& visited);
std::string fillText(const core::FillReport& fill);
void startSearch(ExplorerState& state, double strength, bool fresh);
void collectSearch(ExplorerState& state);
void goVisited(ExplorerState& state, int direction);

// shortcuts.cpp
void handleHistory(ExplorerState& state);
glm::dvec3 clampedTarget(const glm::dvec3& target);
void handleCamera(ExplorerState& state);
void handleShortcuts(ExplorerState& state);

// pattern_panel.cpp
void attractorPicker(ExplorerState& state, core::PatternLayer& layer, const core::AttractorInfo& info);
void gradientPreview(const std::vector<core::GradientStop>& stops, float width, float height);
void colourEditor(ExplorerState& state, const std::string& scope, core::ColorSettings& color, bool chaosGame);
void juliaEditor(ExplorerState& state, const std::string& scope, core::QuaternionJuliaSettings& julia);
void attractorEditor(ExplorerState& state, const std::string& scope, core::PatternLayer& layer);
void layerEditor(ExplorerState& state, std::size_t index, bool& removeThis);
void patternWindow(ExplorerState& state, float scale);

// flame_panel.cpp
void patternKindChoice(ExplorerState& state, std::size_t index, const std::string& scope, core::PatternLayer& layer);
double columnLength(const std::array<double, 12>& m, int col);
std::array<double, 9> eulerRotation(const double degrees[3]);
void affineEditor(ExplorerState& state, const std::string& scope, core::Affine3& affine);
void variationsEditor(ExplorerState& state, const std::string& scope, core::FlameXform& xform);
double xaosFactor(const core::FlameXform& from, std::size_t to);
ImU32 xaosCellColor(double factor);
std::pair<std::size_t, std::size_t> xaosColumnPage(ExplorerState& state, std::size_t index, const std::string& scope,
                                                   std::size_t count);
void xaosMatrix(ExplorerState& state, std::size_t index, const std::string& scope, core::FlameGenome& flame,
                int selected);
void xformEditor(ExplorerState& state, const std::string& scope, core::FlameXform& xform, bool isFinal);
void flameEditor(ExplorerState& state, std::size_t index, const std::string& scope, core::FlameGenome& flame);

// scene_panel.cpp
std::string formatBytes(double bytes);
void meshSection(ExplorerState& state);
void renderSection(ExplorerState& state);
void cameraSection(ExplorerState& state);
void presetsSection(ExplorerState& state, float scale);
void exportSection(ExplorerState& state);
ImVec4 viewRectInWindow(const ExplorerState& state, glm::dvec4 rect);
void dimLastBoundedPicture(const ExplorerState& state);
void drawExportFrame(const ExplorerState& state);
void placeView(ExplorerState& state, float scale);
void viewWindow(ExplorerState& state, float scale);

// prompts.cpp
void recoveryWindow(ExplorerState& state, float scale);
void flameChoiceWindow(ExplorerState& state, float scale);
void quitPromptWindow(ExplorerState& state, float scale);
void noticeWindow(ExplorerState& state, float scale);

// status_bar.cpp
void statusBar(ExplorerState& state, float scale);

// timeline_panel.cpp
double timelineLength(const core::Scene& scene);
void showTime(ExplorerState& state, double seconds);
std::vector<double> keyTimes(const core::Scene& scene);
void advancePlayback(ExplorerState& state);
std::string trackName(const std::string& path);
std::string keyedText(const std::vector<core::KeyframeTrack>& before, const std::vector<core::KeyframeTrack>& after,
                      double time);
void timelineWindow(ExplorerState& state, float scale);

}  // namespace voxflame::app::panels
