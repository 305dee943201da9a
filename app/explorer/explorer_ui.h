// The explorer's panels and input handling: plain ImGui over plain data. Nothing here calls GL or
// GLFW, so the whole UI logic runs in a headless ImGui context in tests (drive io.MousePos and
// friends, call explorerUiFrame, look at the Scene). The window loop in explorer.cpp owns GL, the
// session and the files; panels ask it for things through UiRequests.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <atomic>
#include <utility>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/image_io.h"
#include "core/lyapunov.h"
#include "core/progress_signal.h"
#include "core/scene.h"
#include "document.h"
#include "explorer_session.h"
#include "autosave.h"
#include "background_job.h"
#include "export_job.h"
#include "preset_library.h"
#include "settings.h"

namespace voxflame::app {

// Where widgets were drawn in the last frame, by a stable name ("tone/gamma"), so tests can click
// and drag them like a user.
struct UiProbe {
  struct Rect {
    float minX = 0, minY = 0, maxX = 0, maxY = 0;
    float centerX() const { return 0.5f * (minX + maxX); }
    float centerY() const { return 0.5f * (minY + maxY); }
  };
  std::map<std::string, Rect> items;
  // The words some of them show, by the same names, where a test reads them (a label, a caption).
  std::map<std::string, std::string> texts;
};

// What panels ask of the window loop, which owns files, GL and the session; cleared each frame.
struct UiRequests {
  std::optional<std::filesystem::path> open;  // a preset, a voxflame PNG or a mesh
  std::optional<std::string> saveAs;          // save the scene as a user preset with this name
  bool saveReplacing = false;                 // ... replacing a user preset of that name (Save)
  std::optional<ExportRequest> exportStill;   // render a still in a child process (the Export panel)
  bool refineFurther = false;                 // refine a resting volume on to twice its points
  bool quit = false;
};

// Timings the status line shows and scripted runs report.
struct FrameMetrics {
  double frameMs = 0.0;
  double fps = 0.0;
  double worstFrameMs = 0.0;      // since the last change of pattern
  double uploadMs = 0.0;          // GL upload time spent in the last frame
  double changeToFrameMs = -1.0;  // the last pattern change until the first frame showing it
  double worstChangeToFrameMs = 0.0;
  int changeToFrameFrames = 0;   // ... in frames
  double changeToFullMs = -1.0;  // the last pattern change until the full grid (not the proxy) shows it
  float marchScale = 1.0f;       // fraction of the window's pixels the last frame marched (frame budget)
};

// What each panel keeps between frames besides the document: filters, fields being typed, handles
// being dragged, messages. A panel changes its own part.
struct PatternPanelState {
  char attractorFilter[64] = "";
  char variationFilter[64] = "";             // the "add variation" list's filter (one list is open at a time)
  bool focusAttractorFilter = false;         // Ctrl+F: the next frame puts the keyboard in the attractor filter
  std::map<std::size_t, int> selectedXform;  // per layer: the flame transform being edited (-1: the final one)
  // Per layer: the page of "to" columns the xaos matrix shows (ImGui tables hold 64 columns at most).
  std::map<std::size_t, std::size_t> xaosColumnPage;
  // A rotate handle turns the matrix it was pressed on by the angles dragged so far, so the
  // angles start at 0 on every press and the drag never accumulates rounding.
  std::string rotatingId;
  std::array<double, 12> rotateStart{};
  double rotateAngles[3] = {0.0, 0.0, 0.0};
  // What the last rotate drag turned, said under the handle (which is back at 0 after it) while the
  // map is still the one that drag left.
  std::string turnedId;
  std::array<double, 3> turnedAngles{};
  std::array<double, 12> turnedResult{};
};

struct ScenePanelState {
  char meshPath[512] = "";
  int gridDraft = 0;         // the grid slider's value while it is held
  float renderScale = 1.0f;  // fraction of the window's pixels a still view is refined at
  // While the view or pattern changes, the march scale drops below renderScale to keep frames
  // within this many milliseconds (app::FrameBudget).
  float frameBudgetMs = 33.0f;
  // Presets section.
  char saveName[128] = "";
  std::string presetMessage;
  // Export section. The path it made for the document's name (it follows the name until typed
  // over), and an export waiting for "replace the existing file?".
  char exportPath[512] = "";
  std::string exportPathMade;
  std::optional<ExportRequest> exportToConfirm;
};

struct ExplorePanelState {
  std::uint64_t searchSeed = 1;
  double mutateStrength = 0.1;
  std::string searchMessage;
  // Where Search and Mutate have been: back and forward walk it like a browser's history. Each
  // entry is a whole layer, so it holds the kind and the genome or constant of chaos layers too.
  std::vector<core::PatternLayer> visited;
  std::size_t visitedIndex = 0;
  std::vector<std::string> visitedMessages;            // what the search said of each, so it follows Back/Forward
  std::string analysedKey;                             // the layer the last analysis was started for
  std::uint64_t analysedRevision = ~std::uint64_t{0};  // ... checked at this pattern revision
  std::string lyapunovText = "Lyapunov: …";
};

struct TimelinePanelState {
  bool playing = false;  // the shown scene is the animation at scene.animation.time
  std::string timelineMessage;
};

// A flame file with several flames, opened: which one to import (the "Which flame?" list). Declared
// outside PromptsState: clang, which the include check (scripts/check_includes.py) parses with,
// finds a nested struct with member initialisers not default-constructible inside the enclosing
// class, so std::optional of it cannot emplace() (LLVM issue 36032).
struct FlameChoicePrompt {
  std::filesystem::path path;
  std::vector<std::string> names;  // every flame of the file, in order
  char filter[64] = "";
  // The next frame gives the filter the keyboard: when the list opens, and after an Enter that
  // took nothing (ImGui lets go of a field on Enter).
  bool focusFilter = true;
};

struct PromptsState {
  using FlameChoice = FlameChoicePrompt;
  std::string notice;  // an error or a message shown in the window until dismissed
  std::optional<FlameChoice> flameChoice;
  bool quitPrompt = false;     // the Save / Discard / Cancel prompt is open
  bool quitAfterSave = false;  // Save was chosen there: quit once the save has worked
};

// The flat view (issue 25): the first flame layer rendered in 2D as flam3 frames it
// (core/flame/flat_render.h), shown in the view's rectangle between the panels while `on`, at that
// rectangle's pixel size. It renders off the main thread whenever the layer, the tone, the framing
// or the rectangle's size change.
struct FlatViewState {
  bool on = false;
  core::Scene rendered;        // what the job renders or rendered: the flame layer, tone and framing
  glm::ivec2 renderedSize{0};  // ... and at what size, in pixels
  std::uint64_t checkedRevision = ~std::uint64_t{0};  // the document revision `rendered` was last checked at
  std::string message;
};

// The view being dragged with the mouse (shortcuts.cpp): left orbits, right or middle pans.
struct ViewDragState {
  bool orbiting = false, panning = false;
};

struct StatusBarState {
  bool showStats = false;  // the status line shows its technical figures (else as a tooltip)
};

struct PanelState {
  PatternPanelState pattern;
  ScenePanelState scene;
  ExplorePanelState explore;
  TimelinePanelState timeline;
  PromptsState prompts;
  FlatViewState flat;
  ViewDragState drag;
  StatusBarState status;
  float uiScale = 1.0f;  // panel and font scale (DPI), as given to applyUiScale
};

// The work that runs beside the frames and what it needs: background jobs, the preset library, the
// export child, the settings kept between sessions.
struct Services {
  // Search (F3) and Mutate run off the main thread; their result replaces layer 0's pattern
  // (an attractor's parameters, a flame's genome or a Julia set's constant).
  struct SearchOutcome {
    std::optional<core::PatternLayer> found;  // the pattern part of layer 0 (applyVisited copies it)
    std::string message;                      // what was found, or why nothing was
  };
  BackgroundJob<SearchOutcome> search;
  // The running search's progress: candidates tried, and the strength it tries now (it widens by
  // itself while it finds nothing).
  std::shared_ptr<std::atomic<int>> searchTried;
  std::shared_ptr<std::atomic<double>> searchStrength;
  // Notified with each try counted in searchTried: what a caller waiting for the search's progress
  // (a test) sleeps on; the frames only read the count.
  std::shared_ptr<core::ProgressSignal> searchProgress;
  // The Lyapunov spectrum of layer 0, analysed off the main thread whenever the pattern changes.
  BackgroundJob<core::OrbitAnalysis> analysis;
  BackgroundJob<core::ImageRGBA> flatRender;  // the flat view's image
  PresetLibrary* presets = nullptr;           // owned by the window loop
  ExportJob* exportJob = nullptr;             // the child rendering a still, owned by the window loop
  std::filesystem::path executable;           // the voxflame binary exports run; empty: this process
  ExportStatus exportStatus;                  // polled once per UI frame
  Settings settings;                          // recent files, export settings, preset folder: kept between sessions
  std::vector<Recoverable> recoverable;  // autosaves of sessions that crashed or were killed, offered back at start
};

// What a frame produces and the window loop, the live view and the tests read: timings, the
// session's status, the panels' requests, where the picture goes, and the GL textures the window
// loop uploads for the panels.
// What the live view shows and whether it still refines it (LiveView::refinement), for the status
// line: "at rest" is said only once the session and the view both rest.
struct ViewRefinement {
  bool resting = false;      // the picture is final: no sample or point of the view's is being made
  bool points = false;       // the scene's still method is points
  bool pointsShown = false;  // ... and the points picture has replaced the volume picture
  std::uint64_t pointsDone = 0, pointsTarget = 0;
  std::string pointsError;  // why the points picture stopped (the volume picture is shown), else empty
  int samples = 0;          // of the volume picture
  // The view only waits for the points thread's next picture: frames may wait a little for input
  // instead of drawing the same pixels (frameWaitSeconds).
  bool waitingForPoints = false;
};

struct FrameOutputs {
  FrameMetrics metrics;
  SessionStatus session;  // copied from the session once per frame
  int samples = 0;        // the live view's samples of the picture shown
  ViewRefinement view;
  UiRequests requests;
  // The user holds a widget (a slider being dragged, a field being typed in) or drags the view:
  // an edit made now is one of a run of them, so the large grid holds from the first (LiveView).
  bool interacting = false;
  // A panel asked for the keyboard in this frame (panels::takeKeyboard): the next frame's typed
  // characters wait a frame more (InputQueue::applyTo's holdCharacters).
  bool keyboardFocusMoved = false;
  // Where the picture goes: the space between the docked panels, in framebuffer pixels (x, y from
  // the bottom, width, height), set by each UI frame; empty: the whole framebuffer. The live view
  // frames its camera to it, widened to hold all of the export's picture (viewCamera).
  glm::ivec4 viewRect{0};
  // The docked panels' edges in window coordinates, from this frame's panels: the Pattern panel's
  // right edge, the Scene panel's left one, the Timeline's top.
  struct PanelEdges {
    float left = 0.0f, right = 0.0f, bottom = 0.0f;
  } layout;
  // Text fields' changes this frame, as (field, text), kept only when recordTyping is set (the
  // explorer's --input-log writes them once the frame that shows them is drawn).
  bool recordTyping = false;
  std::vector<std::pair<std::string, std::string>> typedThisFrame;
  UiProbe* probe = nullptr;  // set by tests
  // Set by tests: each UI frame checks that every change to the scene was reported with what it
  // affects (Document), and throws std::logic_error naming the first that was not.
  bool checkEditReports = false;
  // GL textures, uploaded by the window loop: the presets' thumbnails, and the flat view's image
  // (the window loop uploads `flatImage` before the next UI frame while flatImagePending).
  std::map<std::filesystem::path, unsigned> thumbnailTextures;
  core::ImageRGBA flatImage;
  bool flatImagePending = false;
  unsigned flatTexture = 0;
  int flatTextureWidth = 0, flatTextureHeight = 0;
};

struct ExplorerState {
  Document document;
  PanelState panels;
  Services services;
  FrameOutputs frame;
};

// Sets up the state for a scene just opened (history, camera reset point, search history).
void resetExplorerState(ExplorerState& state, const core::Scene& scene);

// One UI frame between ImGui::NewFrame and ImGui::Render: input, panels, background jobs.
void explorerUiFrame(ExplorerState& state);

// Whether the scene has changes that were not saved (it differs from the last opened or saved).
bool hasUnsavedChanges(const ExplorerState& state);

// The user asked to quit (Ctrl+Q, the window's close button): quits at once when nothing is
// unsaved, else opens the Save / Discard / Cancel prompt.
void askToQuit(ExplorerState& state);

// "voxflame — NAME", with a mark while changes are unsaved.
std::string windowTitle(const ExplorerState& state);

// The camera the view shows the scene with: the scene's, widened when the export's picture is
// wider than the view so that all of it shows, inside the export frame (core::viewCameraFor). An
// export uses the scene's camera itself, as `voxflame render` does.
core::CameraSettings viewCamera(const ExplorerState& state);

// Opens a preset, a voxflame PNG (a fresh scene and history) or a mesh (the pattern stays; one
// undoable edit) and puts it first in the recent files. On failure the scene is untouched and
// the notice says why; returns whether it opened.
bool openFile(ExplorerState& state, const std::filesystem::path& path);

// Starts the export the Export panel asked for (the frame loop calls it with the window's job) and
// remembers its folder; a refused request leaves a notice.
void startExport(ExplorerState& state, ExportJob& job, const ExportRequest& request);

// The status line's convergence meter: "noise 1.2% → 0.5%" while refining towards a target,
// "noise 1.2%" when refinement never stops, "converged (noise 0.48%)", "paused for the export".
std::string convergenceText(const SessionStatus& status);
// The same with the live view's own refinement: "at rest" only once the view rests too, and the
// points picture's progress while it builds ("points: 38 M of 60 M").
std::string convergenceText(const SessionStatus& status, const ViewRefinement& view);

// How long the window loop may wait for input before its next frame: 0 while anything moves (an
// edit, refinement, an upload, samples, a job, playback); a long wait when the session and the
// picture rest, so the explorer uses almost no CPU while nothing changes; a short one while an
// export runs, so its progress shows without taking cores from it. `restingFrames` counts the
// frames in a row that found everything at rest (ImGui needs a couple to settle after input).
double frameWaitSeconds(const ExplorerState& state, bool viewResting, int restingFrames);

// Applies the UI scale (DPI): fonts and spacing. Call before the first frame.
void applyUiScale(float scale);

}  // namespace voxflame::app
