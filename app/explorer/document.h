// The explorer's document (see the class). No GL, no ImGui: plain data and counters.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>

#include "core/scene.h"
#include "core/scene_schema.h"
#include "scene_history.h"

namespace voxflame::app {

// The document: the scene, its undo history, what it was last opened or saved as, and the scene the
// Timeline keys against. The only part of the explorer that undo sees and that is saved.
//
// Every change to `scene` is reported, right where it is made, with what it affects (the schema's
// classes, core::Affects): edited() after a change made in place, replace() for a whole new scene.
// The reports bump revisions, and whoever acts on a change (the live view posting a pattern or
// restarting its samples, undo recording a step, the title's unsaved mark, autosave, the flat
// view, the analysis) compares a revision instead of walking the whole scene every frame. Tests
// turn on ExplorerState::frame.checkEditReports, which makes every UI frame check the reports
// against what really changed.
class Document {
 public:
  core::Scene scene;
  std::optional<SceneHistory> history;  // undo/redo over the whole scene
  core::Scene savedScene;               // as last opened or saved: quitting asks while the scene differs from it
  core::Scene keyBase;  // the scene when the time was last shown: the Timeline's "Key" records what differs from it
  core::CameraSettings initialCamera;  // what "reset camera" goes back to

  // What has changed so far, counted per class: a consumer keeps the count it last acted on.
  struct Revisions {
    std::uint64_t any = 0;      // every edit, including those that change nothing drawn (the name)
    std::uint64_t pattern = 0;  // the accumulation must restart
    std::uint64_t view = 0;     // what a ray sees: the march must restart
    std::uint64_t tone = 0;     // the resolve only
    bool operator==(const Revisions&) const = default;
  };
  const Revisions& revisions() const { return revisions_; }

  // `scene` was changed in place, affecting `affects` (Affects::None: nothing drawn, as a rename).
  void edited(core::Affects affects);
  // `scene` becomes `next` (an open, an undo, an import, a keyframe's moment): what it affects is
  // what differs (core::diff, once per replacement). Returns whether anything did.
  bool replace(const core::Scene& next);
  // A fresh document (a preset opened): history, saved scene and key base start here.
  void reset(const core::Scene& opened);

  // Records the scene as undo's newest step when it was edited since the last record (the explorer
  // calls it once an edit settles: no widget or button held).
  void recordInHistory();

  // Whether the scene differs from the saved one; compares the scenes only when either changed
  // since the last call.
  bool unsaved() const;
  void markSaved();  // the scene as it is now has been saved

  // Everything reported since the last call (the UI frame's check of the reports).
  core::Affects takeReported() { return std::exchange(reported_, core::Affects::None); }

 private:
  Revisions revisions_;
  core::Affects reported_ = core::Affects::None;
  std::uint64_t savedRevision_ = 0;                                     // revisions_.any when saved
  std::uint64_t recordedRevision_ = 0;                                  // ... when last recorded in the history
  mutable std::optional<std::pair<std::uint64_t, bool>> unsavedCache_;  // (revisions_.any, unsaved)
};

}  // namespace voxflame::app
