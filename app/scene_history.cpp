#include "scene_history.h"

namespace voxflame::app {

SceneHistory::SceneHistory(const core::Scene& initial, std::size_t limit) : limit_(std::max<std::size_t>(limit, 2)) {
  steps_.push_back(initial);
}

bool SceneHistory::record(const core::Scene& scene) {
  if (scene == steps_[current_]) return false;
  steps_.resize(current_ + 1);
  steps_.push_back(scene);
  if (steps_.size() > limit_) steps_.erase(steps_.begin());
  current_ = steps_.size() - 1;
  return true;
}

std::optional<core::Scene> SceneHistory::undo() {
  if (!canUndo()) return std::nullopt;
  return steps_[--current_];
}

std::optional<core::Scene> SceneHistory::redo() {
  if (!canRedo()) return std::nullopt;
  return steps_[++current_];
}

}  // namespace voxflame::app
