// The explorer's engine side: the mesh, its inside mask, the Accumulator and the snapshot thread
// for the scene being edited, with every slow step (loading a mesh, building a mask, clearing a
// large grid for a new generation) done on a control thread of its own. The UI thread only posts
// the newest scene and takes what is ready, so a frame never waits on refinement. No GL here.
//
// Grids larger than a proxy have a second, small Accumulator (longest side kProxyResolution, its
// own mask of the same mesh) that runs a short burst of each new pattern before the large grid
// is even cleared: its volume is ready within a frame or two, so an edit shows at once, coarse,
// until the large grid has caught up.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/mesh.h"
#include "core/packed_volume.h"
#include "core/progress_signal.h"
#include "core/scene.h"
#include "refinement_backends.h"

namespace voxflame::app {

// What the status line and the panels show; a copy, taken without waiting.
struct SessionStatus {
  bool buildingShape = false;  // a mesh load or mask build is running in the background
  std::string shapeStage;      // what it is doing ("loading mesh …", "inside mask 256³ …")
  double shapeSeconds = 0.0;   // how long it has been at it
  std::string error;           // the last thing that went wrong (bad mesh, bad parameters), or empty
  core::AccumulatorStats stats;
  std::uint64_t requestedGeneration = 0;  // pattern requests posted so far
  std::uint64_t appliedGeneration = 0;    // of those, the newest the Accumulator runs
  bool hasShape = false;
  core::GridGeometry grid;  // the current shape's grid (when hasShape)
  // Convergence (core/refinement/convergence.h): the estimated noise left in the volume (a fraction; NaN
  // until measured), the target that stops refining (0: never), and why refinement rests.
  double noise = std::numeric_limits<double>::quiet_NaN();
  double noiseTarget = 0.0;
  // The last two measurements themselves, newest first (ConvergenceMeter), NaN until taken.
  double lastMeasurement = std::numeric_limits<double>::quiet_NaN();
  double previousMeasurement = std::numeric_limits<double>::quiet_NaN();
  bool converged = false;  // the noise reached the target: the workers sleep until the next edit
  bool capped = false;     // the points reached the grid's cap (restCapPointsPerVoxel) first
  bool paused = false;     // refinement is held while an export runs
  // Points per voxel inside the mask now, and the cap that ends refinement whatever the noise.
  double pointsPerVoxel = 0.0;
  double capPointsPerVoxel = 0.0;
  std::uint64_t insideVoxels = 0;  // of the refining grid's mask
  // Nothing will change until the user does something: refinement is held and finished, and the
  // last volume has been taken. The window loop may then wait for events instead of drawing.
  bool resting = false;
  // The newest pattern applied escapes (or collapses): what to tell the user, in one line, e.g.
  // "escapes at a = 1.0948; showing the last bounded value". Empty while it stays bounded.
  std::string escapeNote;
  bool showingLastBounded = false;  // the picture is still the last bounded pattern's (dimmed)
  // What refines the large grid (setBackendChoice), and why it is not what was chosen, or empty.
  core::BackendKind backend = core::BackendKind::Cpu;
  std::string backendNote;
  // The GPU backend hands its grid to the renderer on the GPU (PackedVolume::device); else the grid
  // is read back and uploaded (a window whose context is not EGL's cannot share it).
  bool gridOnDevice = false;
};

class ExplorerSession {
 public:
  // threads: accumulation threads (0: one per hardware thread). snapshotInterval: how often the
  // refining grid is copied and packed for upload.
  explicit ExplorerSession(int threads = 0,
                           std::chrono::milliseconds snapshotInterval = std::chrono::milliseconds(100));
  ~ExplorerSession();  // stops and joins every thread it owns
  ExplorerSession(const ExplorerSession&) = delete;
  ExplorerSession& operator=(const ExplorerSession&) = delete;

  // Posts the scene being edited. Returns at once; only the newest posted scene is applied. A new
  // mesh or grid resolution rebuilds the shape in the background (the old volume stays on screen
  // meanwhile); any other change to the pattern starts a new generation. `interacting` begins the
  // hold of setRefinement's `interacting` with the post (only setRefinement ends it), so the edit
  // that starts a drag already finds the large grid held: set after the post, the control thread
  // could have applied the edit to the large grid first.
  void post(const core::Scene& scene, bool interacting = false);

  // Posts the scene when its pattern (what core::diff() classes as Affects::Pattern: mesh, grid,
  // layers, seed) differs from the last one posted this way; returns whether it did. For callers
  // without a document's revisions (the session's tests): the explorer's live view posts on the
  // document's pattern revision instead, with no diff per frame.
  bool postIfPatternChanged(const core::Scene& scene, bool interacting = false);

  // Swaps the newest packed volume into `out` when one newer than it is ready. Never waits.
  // `reflectsPost` gets the number of the post (counting from 1) whose pattern the volume shows,
  // or 0 when it still shows an older one.
  bool takeVolumeIfNewer(core::PackedVolume& out, std::uint64_t* reflectsPost = nullptr);
  // The same for the proxy's volume; false when the shape has no proxy (a small grid).
  bool takeProxyIfNewer(core::PackedVolume& out, std::uint64_t* reflectsPost = nullptr);

  // The takeover: which grid's volume the live view shows, the proxy's or the main grid's. The
  // live view asks as volumes arrive (UI thread only, like the take calls) and does what it is
  // told; the session keeps what is on screen for the answers. A proxy volume goes on screen as
  // soon as it shows a newer post than the main grid's last whole volume with at least
  // kProxyShownPointsPerVoxel (one with hardly any points yet would be all noise). The main grid's
  // volume replaces it once it shows the proxy's post with takeoverPoints(), or a later post; a
  // volume that could not do that is not even uploaded (at 512³ the upload alone costs frames).
  enum class ShownGrid { Main, Proxy };
  // A proxy volume just taken (takeProxyIfNewer), of post `reflectsPost`: true when it is to be
  // shown now, in place of whatever is shown.
  bool showProxyVolume(const core::PackedVolume& proxy, std::uint64_t reflectsPost);
  // A main grid volume just taken (takeVolumeIfNewer): false when it is not worth uploading, as
  // the proxy on screen would stay (too few points for the proxy's post, or an older pattern while
  // the proxy shows a newer one).
  bool uploadMainVolume(const core::PackedVolume& volume, std::uint64_t reflectsPost) const;
  // A main grid volume of post `reflectsPost` (0: an older one than the newest applied) is whole in
  // the renderer: true when it is shown now, in place of the proxy.
  bool mainVolumeUploaded(const core::PackedVolume& volume, std::uint64_t reflectsPost);
  // The points a main grid volume of the proxy's post needs to replace the proxy on screen.
  std::uint64_t takeoverPoints() const;
  ShownGrid shownGrid() const { return takeover_.shown; }
  // The post of the main grid's last whole volume (0: none, or one older than any proxy shown).
  std::uint64_t shownMainPost() const { return takeover_.mainPost; }
  // A new live view on this session: nothing is on screen yet.
  void restartTakeover() { takeover_ = Takeover{}; }

  // The proxy grid's longest side, and the grids that get one: those whose longest side is more
  // than half as long again (smaller ones fill and upload about as fast as the proxy).
  static constexpr int kProxyResolution = 64;
  static constexpr int kProxyAbove = kProxyResolution * 3 / 2;
  // A proxy burst stops at this many points per voxel inside the mesh: enough for a smooth coarse
  // picture, few enough to take tens of milliseconds.
  static constexpr double kProxyPointsPerVoxel = 24.0;
  // While the user drags, a third of that: each burst is thrown away by the next edit, and its
  // workers take the cores the frame needs (a full burst made drag frames half as long again as
  // orbit frames). When the drag ends the last pattern's burst goes on to the full count.
  static constexpr double kProxyDragPointsPerVoxel = 8.0;
  // A proxy is shown once it holds this many; its publisher packs none with fewer (one of nearly
  // no points, packed the moment a pattern is set, would only keep the next one waiting).
  static constexpr double kProxyShownPointsPerVoxel = 2.0;
  // The memory a session on this grid holds with the live view that shows it: the inside mask,
  // the accumulator, the packed volume being filled and the one being shown, the renderer's
  // textures, the proxy's share and the shadows. What the grid slider shows beside it.
  static std::size_t estimatedBytes(const core::GridGeometry& grid);
  // The mesh of a shape that became current since the last call (for the renderer), else empty.
  std::optional<core::TriangleMesh> takeNewMesh();
  // The grid of the current shape (for the camera), or empty before the first shape is ready.
  std::optional<core::GridGeometry> geometry() const;
  SessionStatus status() const;
  void clearError();
  // Blocks until the posted scene is applied (for tests and scripted runs); false on timeout.
  bool waitUntilApplied(double timeoutSeconds);
  // Counts what the session's threads did that status() or the take calls could show: a look or a
  // pack of either grid's snapshot thread, a post applied, a steer. A caller that waits for the
  // session (tests, scripted runs; the window loop never waits) notes news(), checks what it waits
  // for, then sleeps in waitForNews until the count moves past what it noted (false once
  // `timeoutSeconds` pass).
  std::uint64_t news() const { return news_.count(); }
  bool waitForNews(std::uint64_t seen, double timeoutSeconds) const;
  // What such a caller may wait for besides the status (the window loop never asks): the proxy's
  // refinement (empty without a proxy; `done` once its burst is over), and whether the large grid's
  // backend is idle (RefinementBackend::idle: the batches under way when it was held have landed).
  std::optional<core::AccumulatorStats> proxyStats() const;
  bool gridIdle() const;

  // Refinement stops once the noise estimate reaches noiseTarget (a fraction; 0: refine until
  // the next edit), and is held while `paused` (an export runs: the two would fight over the
  // cores; a pattern edited meanwhile still refines to a small preview). A stopped or held
  // accumulator's workers sleep; a new pattern or a lower target starts them again. Cheap when
  // nothing changed: the explorer calls it every frame.
  // `interacting`: the user is dragging a slider or orbiting. The large grid then holds too (its
  // work would be thrown away by the next edit, and the cores are the renderer's): the proxy shows
  // each edit, and the large grid refines the pattern the user stops on. `viewMoving`: only the
  // view changes (an orbit, a pan), so any grid, one without a proxy too, holds: the pattern
  // stays, and the cores are the frame's until the view is still (a post ends it).
  // `gridPointCap` (0: none) ends refinement at that many points when fewer than the rest cap:
  // under the points method the grid only dims the projected points, and an export's grid stops at
  // kGridPointsForPointsMethod, so the live view's stops there too and leaves the cores to the
  // points picture (LivePoints).
  void setRefinement(double noiseTarget, bool paused, bool interacting = false, bool viewMoving = false,
                     std::uint64_t gridPointCap = 0);
  // What refines the large grid from the next pattern on (the explorer's setting, default Cpu):
  // Auto takes the GPU backend where the GL renderer is a hardware one and it runs the pattern;
  // Gpu takes it wherever it runs the pattern. A pattern it does not run (a flame) refines on the
  // CPU, and the status says why. A change of backend rebuilds the grid (the mask comes from the
  // cache); the proxy always refines on the CPU. Cheap when nothing changed: call it every frame.
  // `method`: under the points method the points are dimmed by the grid in host memory, so a GPU
  // backend then reads its grid back instead of handing it to the renderer on the GPU.
  void setBackendChoice(BackendChoice choice, core::RenderMethod method = core::RenderMethod::Volume);
  // The context of the renderer that draws this session's volumes (gl::currentShareGroup() on the
  // thread that draws): a GPU backend made from then on shares it and hands its grid over on the
  // GPU, with no read-back or upload (PackedVolume::device). Empty (the default): through host memory.
  void setRendererShareGroup(gl::ShareGroup renderer) {
    std::lock_guard lock(mutex_);
    renderer_ = renderer;
  }

  // The inside mask of the current shape (null before the first shape is ready): the points
  // picture iterates the pattern over it.
  std::shared_ptr<const core::InsideMask> mask() const;

  // How often the noise is measured while the volume refines.
  static constexpr std::chrono::milliseconds kMeterInterval{250};

  // Refinement ends at this many points per voxel inside the mask even when the noise never
  // reaches its target (a flow whose estimate levels off above it, or a target of "never"), so
  // the explorer always comes to rest. What the picture shows is points per pixel: a pixel sums a
  // column through the mesh, about as many voxels long as the mesh is thick, through a footprint
  // of about (resolution / pixels)² voxel faces. So the cap falls with the square of the grid's
  // longest side from kRestCapPointsPerVoxel at 192 (the default grid), and with the mesh's
  // thickness (the cube root of its inside voxels) against the bunny's at the same grid: a sphere,
  // thicker, needs fewer points per voxel for the same picture, a thin dragon more. Within
  // [kRestCapMinimum, kRestCapMaximum], the thickness factor within [½, 2].
  static constexpr double kRestCapPointsPerVoxel = 192.0;
  static constexpr double kRestCapMinimum = 32.0;
  static constexpr double kRestCapMaximum = 2048.0;
  // The bunny's thickness in voxels at 192: the cube root of its 1.37 M inside voxels.
  static constexpr double kReferenceThicknessAt192 = 111.0;
  static double restCapPointsPerVoxel(const core::GridGeometry& grid, std::uint64_t insideVoxels);

  // "Refine further": refinement goes on from the points already there to twice as many, past
  // the noise target and the cap (the cap doubles with it). Returns at once.
  void refineFurther();
  // The points a pattern edited during an export refines to before it is held.
  static constexpr std::uint64_t kPausedPreviewPoints = 5'000'000;

 private:
  struct Engine;  // the shape plus the Accumulator and publisher running on it
  struct Proxy;   // the small Accumulator that runs each pattern first
  void controlLoop(std::stop_token stop);
  void steer(Engine& engine);  // control thread: measures the noise, holds or releases the workers
  // Control thread: sets a posted pattern on the large grid and steers it.
  void applyPattern(Engine& engine, const core::Scene& scene, std::uint64_t post);
  // Whether the engine's large grid holds for a drag: the user interacts and a proxy shows the edits.
  bool holdsForInteraction(const Engine& engine) const;
  // Control thread, after `accumulator` took `scene`'s pattern: what the status says of an escape.
  void noteEscape(const core::RefinementBackend& accumulator, const core::Scene& scene);

  // What the live view shows (the takeover's calls; UI thread only, so no lock).
  struct Takeover {
    ShownGrid shown = ShownGrid::Main;
    std::uint64_t proxyPost = 0;    // the post of the proxy volume last shown (0: none yet)
    std::uint64_t proxyPoints = 0;  // ... its points, and the voxels inside its mask
    double proxyInsideVoxels = 0.0;
    std::uint64_t mainPost = 0;  // shownMainPost()
  };
  Takeover takeover_;

  const int threads_;
  const std::chrono::milliseconds snapshotInterval_;
  // Before the engine: its snapshot threads notify it until they are joined.
  mutable core::EventCounter news_;

  mutable std::mutex mutex_;  // guards everything below except the control thread's locals
  std::condition_variable_any wake_;
  std::condition_variable appliedSignal_;
  std::optional<core::Scene> postedPattern_;  // UI thread only: what postIfPatternChanged posted last
  std::optional<core::Scene> pending_;        // the newest posted scene not yet picked up
  std::uint64_t requested_ = 0, applied_ = 0;
  bool working_ = false;            // the control thread is applying a scene
  std::unique_ptr<Engine> engine_;  // replaced and destroyed only by the control thread
  std::optional<core::TriangleMesh> newMesh_;
  bool buildingShape_ = false;
  std::string shapeStage_;
  std::chrono::steady_clock::time_point shapeStart_;
  std::string error_;
  double noiseTarget_ = 0.0;
  bool paused_ = false;
  bool interacting_ = false;
  bool viewMoving_ = false;
  std::uint64_t gridPointCap_ = 0;
  bool steerRequested_ = false;  // setRefinement changed something for the control thread
  double noise_ = std::numeric_limits<double>::quiet_NaN();
  bool converged_ = false;
  bool capped_ = false;
  double pointsPerVoxel_ = 0.0, capPointsPerVoxel_ = 0.0;
  std::uint64_t insideVoxels_ = 0;
  double lastMeasurement_ = std::numeric_limits<double>::quiet_NaN(), previousMeasurement_ = lastMeasurement_;
  bool refineFurtherRequested_ = false;
  bool holding_ = false;  // the accumulator's target is held (converged, capped or paused)
  // Control thread only: the layers of the last pattern applied that stays bounded.
  std::optional<std::vector<core::PatternLayer>> lastBounded_;
  std::string escapeNote_;
  bool showingLastBounded_ = false;
  BackendChoice backendChoice_ = BackendChoice::Cpu;
  core::RenderMethod backendMethod_ = core::RenderMethod::Volume;
  gl::ShareGroup renderer_;  // setRendererShareGroup
  gl::ShareGroup rendererShareGroup() const {
    std::lock_guard lock(mutex_);
    return renderer_;
  }
  std::optional<core::Scene> lastPosted_;  // posted again when the backend choice changes
  std::string backendNote_;
  std::jthread control_;  // last: started after everything it uses exists
};

}  // namespace voxflame::app
