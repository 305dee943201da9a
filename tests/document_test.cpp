// The explorer's document: edits report what they affect, and the revisions, the unsaved mark and
// the undo history follow the reports rather than comparing whole scenes every frame.
#include <gtest/gtest.h>

#include "core/scene.h"
#include "core/scene_io.h"
#include "document.h"

namespace voxflame {
namespace {

TEST(Document, AnEditCountsOnlyInTheClassesItAffects) {
  app::Document document;
  document.reset(core::defaultScene());
  const app::Document::Revisions start = document.revisions();
  document.scene.tone.gamma += 0.5;
  document.edited(core::Affects::Tone);
  EXPECT_EQ(document.revisions().any, start.any + 1);
  EXPECT_EQ(document.revisions().tone, start.tone + 1);
  EXPECT_EQ(document.revisions().pattern, start.pattern) << "a tone edit must not restart the accumulation";
  EXPECT_EQ(document.revisions().view, start.view) << "nor the march";
  document.scene.name = "renamed";
  document.edited(core::Affects::None);
  EXPECT_EQ(document.revisions().any, start.any + 2) << "a rename is an edit (the title, the unsaved mark)";
  EXPECT_EQ(document.revisions().tone, start.tone + 1);
}

TEST(Document, AReplacementCountsWhatDiffers) {
  app::Document document;
  document.reset(core::defaultScene());
  const app::Document::Revisions start = document.revisions();
  EXPECT_FALSE(document.replace(document.scene)) << "an equal scene changes nothing";
  EXPECT_EQ(document.revisions(), start);
  core::Scene turned = document.scene;
  turned.camera.azimuthDeg += 30.0;
  EXPECT_TRUE(document.replace(turned));
  EXPECT_EQ(document.scene.camera.azimuthDeg, turned.camera.azimuthDeg);
  EXPECT_EQ(document.revisions().view, start.view + 1);
  EXPECT_EQ(document.revisions().pattern, start.pattern) << "undoing a camera move must not restart the accumulation";
  core::Scene other = document.scene;
  other.layers[0].params[0] *= 1.1;
  document.replace(other);
  EXPECT_EQ(document.revisions().pattern, start.pattern + 1);
}

TEST(Document, UnsavedFollowsTheScenesNotTheCount) {
  app::Document document;
  document.reset(core::defaultScene());
  EXPECT_FALSE(document.unsaved()) << "just opened";
  const double gamma = document.scene.tone.gamma;
  document.scene.tone.gamma = gamma + 1.0;
  document.edited(core::Affects::Tone);
  EXPECT_TRUE(document.unsaved());
  document.scene.tone.gamma = gamma;  // dragged back to where it was saved
  document.edited(core::Affects::Tone);
  EXPECT_FALSE(document.unsaved()) << "edits that end where the save was leave nothing unsaved";
  document.scene.name = "mine";
  document.edited(core::Affects::None);
  EXPECT_TRUE(document.unsaved());
  document.markSaved();
  EXPECT_FALSE(document.unsaved());
  EXPECT_EQ(document.savedScene.name, "mine");
}

TEST(Document, TheHistoryRecordsEachEditOnceAndUndoIsAReplacement) {
  app::Document document;
  document.reset(core::defaultScene());
  document.recordInHistory();
  EXPECT_EQ(document.history->size(), 1u) << "nothing edited: nothing recorded";
  document.scene.tone.gamma += 0.5;
  document.edited(core::Affects::Tone);
  document.recordInHistory();
  document.recordInHistory();
  EXPECT_EQ(document.history->size(), 2u);
  const app::Document::Revisions beforeUndo = document.revisions();
  const std::optional<core::Scene> undone = document.history->undo();
  ASSERT_TRUE(undone);
  EXPECT_TRUE(document.replace(*undone));
  EXPECT_EQ(document.revisions().tone, beforeUndo.tone + 1);
  EXPECT_EQ(document.revisions().pattern, beforeUndo.pattern);
  document.recordInHistory();  // the undone scene is the history's current step: no new one
  EXPECT_EQ(document.history->size(), 2u);
  EXPECT_TRUE(document.history->canRedo());
}

}  // namespace
}  // namespace voxflame
