#include "document.h"

namespace voxflame::app {

void Document::edited(core::Affects affects) {
  ++revisions_.any;
  if (core::any(affects & core::Affects::Pattern)) ++revisions_.pattern;
  if (core::any(affects & core::Affects::View)) ++revisions_.view;
  if (core::any(affects & core::Affects::Tone)) ++revisions_.tone;
  reported_ |= affects;
}

bool Document::replace(const core::Scene& next) {
  const core::SceneDiff changed = core::diff(scene, next);
  if (changed.empty()) return false;
  scene = next;
  edited(changed.affects);
  return true;
}

void Document::reset(const core::Scene& opened) {
  replace(opened);  // counts what the opened scene changes, so the live view posts it
  savedScene = opened;
  keyBase = opened;
  initialCamera = opened.camera;
  history.emplace(opened);
  recordedRevision_ = revisions_.any;
  markSaved();
}

void Document::recordInHistory() {
  if (!history || recordedRevision_ == revisions_.any) return;
  recordedRevision_ = revisions_.any;
  history->record(scene);
}

bool Document::unsaved() const {
  if (revisions_.any == savedRevision_) return false;  // nothing edited since the save
  if (!unsavedCache_ || unsavedCache_->first != revisions_.any)
    unsavedCache_.emplace(revisions_.any, !(scene == savedScene));
  return unsavedCache_->second;
}

void Document::markSaved() {
  savedScene = scene;
  savedRevision_ = revisions_.any;
  unsavedCache_.reset();
}

}  // namespace voxflame::app
