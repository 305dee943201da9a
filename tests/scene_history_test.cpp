#include <gtest/gtest.h>

#include "core/scene_io.h"
#include "scene_history.h"

using voxflame::app::SceneHistory;
using voxflame::core::Scene;

TEST(SceneHistory, UndoAndRedoWalkTheRecordedSteps) {
  Scene scene = voxflame::core::defaultScene();
  SceneHistory history(scene);
  EXPECT_FALSE(history.canUndo());
  EXPECT_FALSE(history.record(scene));  // unchanged: no step
  scene.layers[0].params[0] = 1.2;
  EXPECT_TRUE(history.record(scene));
  scene.tone.gamma = 3.0;
  EXPECT_TRUE(history.record(scene));
  auto back = history.undo();
  ASSERT_TRUE(back);
  EXPECT_DOUBLE_EQ(back->tone.gamma, 2.2);
  EXPECT_DOUBLE_EQ(back->layers[0].params[0], 1.2);
  back = history.undo();
  ASSERT_TRUE(back);
  EXPECT_DOUBLE_EQ(back->layers[0].params[0], 1.111);
  EXPECT_FALSE(history.undo());
  auto forward = history.redo();
  ASSERT_TRUE(forward);
  EXPECT_DOUBLE_EQ(forward->layers[0].params[0], 1.2);
  // A new edit after an undo drops the redo branch.
  Scene edited = *forward;
  edited.camera.azimuthDeg = 90.0;
  EXPECT_TRUE(history.record(edited));
  EXPECT_FALSE(history.canRedo());
  EXPECT_EQ(history.size(), 3u);
}

TEST(SceneHistory, KeepsAtMostItsLimit) {
  Scene scene = voxflame::core::defaultScene();
  SceneHistory history(scene, 5);
  for (int i = 1; i <= 20; ++i) {
    scene.camera.azimuthDeg = i;
    history.record(scene);
  }
  EXPECT_EQ(history.size(), 5u);
  int undos = 0;
  while (history.undo()) ++undos;
  EXPECT_EQ(undos, 4);
}
