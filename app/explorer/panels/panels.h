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

#include "core/flame/flame.h"
#include "core/flame/search.h"
#include "core/flame/xml.h"
#include "explorer_ui.h"

namespace voxflame::app {

// Puts a flame just imported from `path` in place of the pattern (openFile, flameChoiceWindow):
// one undoable edit, the import's warnings in the notice, the file first in the recent files.
void applyImportedFlame(Document& document, PromptsState& prompts, Settings& settings,
                        const std::filesystem::path& path, const core::FlameFileContents& contents,
                        const core::Scene& scene);

}  // namespace voxflame::app

namespace voxflame::app::panels {

struct Ui;

// Each panel's parameters say what it may change: `Ui&` (the document, whose edits it reports,
// and the frame's outputs) for panels that edit the scene, `const Document&` for those that only
// read it, its own part of PanelState, and the services it starts or polls.

// flat_view.cpp
core::Scene flatViewScene(const core::Scene& scene);
void updateFlatView(const Document& document, FlatViewState& flat, Services& services, FrameOutputs& frame);
glm::ivec2 flatViewSize(const core::FlatViewSettings& flat, const glm::ivec4& viewRect);
void drawFlatView(const FlatViewState& flat, const Services& services, FrameOutputs& frame);

// explore_panel.cpp
std::string analysisKey(const core::PatternLayer& layer);
void updateAnalysis(const Document& document, ExplorePanelState& explore, Services& services);
void applyVisited(core::PatternLayer& layer, const core::PatternLayer& visited);
std::string fillText(const core::FillReport& fill);
void startSearch(const Document& document, ExplorePanelState& explore, Services& services, double strength, bool fresh);
void collectSearch(Document& document, ExplorePanelState& explore, Services& services);
void goVisited(Document& document, ExplorePanelState& explore, int direction);

// shortcuts.cpp
void handleHistory(Document& document);
glm::dvec3 clampedTarget(const glm::dvec3& target);
void handleCamera(Document& document, ViewDragState& drag, bool quitPromptOpen);
void handleShortcuts(ExplorerState& state);  // the keyboard's shortcuts reach every part

// pattern_panel.cpp
void attractorPicker(Ui& ui, PatternPanelState& pattern, core::PatternLayer& layer, const core::AttractorInfo& info);
void gradientPreview(const std::vector<core::GradientStop>& stops, float width, float height);
void colourEditor(Ui& ui, const std::string& scope, core::ColorSettings& color, bool chaosGame);
void juliaEditor(Ui& ui, const std::string& scope, core::QuaternionJuliaSettings& julia);
void attractorEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::PatternLayer& layer);
void layerEditor(Ui& ui, PatternPanelState& pattern, ExplorePanelState& explore, FlatViewState& flat, std::size_t index,
                 bool& removeThis);
void patternWindow(Ui& ui, PatternPanelState& pattern, ExplorePanelState& explore, FlatViewState& flat,
                   Services& services, float scale);

// flame_panel.cpp
void patternKindChoice(Ui& ui, PatternPanelState& pattern, std::size_t index, const std::string& scope,
                       core::PatternLayer& layer);
double columnLength(const std::array<double, 12>& m, int col);
std::array<double, 9> eulerRotation(const double degrees[3]);
void affineEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::Affine3& affine);
void variationsEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::FlameXform& xform);
double xaosFactor(const core::FlameXform& from, std::size_t to);
ImU32 xaosCellColor(double factor);
std::pair<std::size_t, std::size_t> xaosColumnPage(Ui& ui, PatternPanelState& pattern, std::size_t index,
                                                   const std::string& scope, std::size_t count);
void xaosMatrix(Ui& ui, PatternPanelState& pattern, std::size_t index, const std::string& scope,
                core::FlameGenome& flame, int selected);
void xformEditor(Ui& ui, PatternPanelState& pattern, const std::string& scope, core::FlameXform& xform, bool isFinal);
void flameEditor(Ui& ui, PatternPanelState& pattern, ExplorePanelState& explore, std::size_t index,
                 const std::string& scope, core::FlameGenome& flame);

// scene_panel.cpp
std::string formatBytes(double bytes);
void meshSection(Ui& ui, ScenePanelState& scenePanel, const Services& services);
void renderSection(Ui& ui, ScenePanelState& scenePanel, Services& services);
void cameraSection(Ui& ui);
void presetsSection(FrameOutputs& frame, ScenePanelState& scenePanel, PromptsState& prompts, Services& services,
                    float scale);
void exportSection(const Document& document, FrameOutputs& frame, ScenePanelState& scenePanel, Services& services,
                   float scale);
ImVec4 viewRectInWindow(const FrameOutputs& frame, glm::dvec4 rect);
void dimLastBoundedPicture(const FrameOutputs& frame);
void drawExportFrame(const FrameOutputs& frame, const Services& services);
void placeView(FrameOutputs& frame, float scale);
void viewWindow(Ui& ui, ScenePanelState& scenePanel, PromptsState& prompts, Services& services, float scale);

// prompts.cpp
void recoveryWindow(Ui& ui, std::vector<Recoverable>& offered, float scale);
void flameChoiceWindow(Ui& ui, PromptsState& prompts, Settings& settings, float scale);
void quitPromptWindow(const Document& document, FrameOutputs& frame, PromptsState& prompts, float scale);
void noticeWindow(FrameOutputs& frame, PromptsState& prompts, float scale);

// status_bar.cpp
void statusBar(FrameOutputs& frame, const ExplorePanelState& explore, StatusBarState& status, float scale);

// timeline_panel.cpp
double timelineLength(const core::Scene& scene);
void showTime(Document& document, TimelinePanelState& timeline, PromptsState& prompts, double seconds);
std::vector<double> keyTimes(const core::Scene& scene);
void advancePlayback(Document& document, TimelinePanelState& timeline, PromptsState& prompts);
std::string trackName(const std::string& path);
std::string keyedText(const std::vector<core::KeyframeTrack>& before, const std::vector<core::KeyframeTrack>& after,
                      double time);
void timelineWindow(Ui& ui, TimelinePanelState& timeline, PromptsState& prompts, float scale);

}  // namespace voxflame::app::panels
