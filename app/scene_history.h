// Undo and redo over the whole scene. The explorer records the scene whenever an edit settles
// (a slider released, a button pressed), so a whole drag is one step; undo and redo hand back
// earlier or later versions. Scenes are compared with == (every member), so an edit that changes
// anything, and nothing else, is a step.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/scene.h"

namespace voxflame::app {

class SceneHistory {
 public:
  explicit SceneHistory(const core::Scene& initial, std::size_t limit = 200);

  // Records `scene` as the newest step when it differs from the current one; drops any redo.
  // Returns whether a step was added.
  bool record(const core::Scene& scene);
  std::optional<core::Scene> undo();  // the previous step, or nothing at the oldest
  std::optional<core::Scene> redo();  // the next step, or nothing at the newest
  bool canUndo() const { return current_ > 0; }
  bool canRedo() const { return current_ + 1 < steps_.size(); }
  std::size_t size() const { return steps_.size(); }

 private:
  std::vector<core::Scene> steps_;
  std::size_t current_ = 0;
  std::size_t limit_;
};

}  // namespace voxflame::app
