// The session's takeover (app::ExplorerSession::showProxyVolume, uploadMainVolume,
// mainVolumeUploaded): which grid's volume the live view shows, as a function of what the session
// has had shown. A proxy volume of a newer post goes on screen once it has a picture's worth of
// points; the main grid's replaces it once it shows the proxy's post with the proxy's points (but
// no more than its burst asks for), or a later post; nothing older replaces a newer proxy.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/packed_volume.h"
#include "explorer_session.h"

using namespace voxflame;
using Session = app::ExplorerSession;
using ShownGrid = app::ExplorerSession::ShownGrid;

namespace {

constexpr double kProxyInside = 10'000.0;  // voxels inside the proxy's mask
constexpr double kMainInside = 8 * kProxyInside;

// A volume as a publisher hands it over, with this many points per voxel inside its mask.
core::PackedVolume volumeAt(double pointsPerVoxel, double insideVoxels) {
  core::PackedVolume volume;
  volume.insideVoxels = insideVoxels;
  volume.points = static_cast<std::uint64_t>(pointsPerVoxel * insideVoxels);
  return volume;
}
core::PackedVolume proxyAt(double pointsPerVoxel) {
  return volumeAt(pointsPerVoxel, kProxyInside);
}
// A main grid volume with `points` points (the takeover counts points, not points per voxel).
core::PackedVolume mainWith(std::uint64_t points) {
  core::PackedVolume volume;
  volume.insideVoxels = kMainInside;
  volume.points = points;
  return volume;
}

// No session thread takes part: nothing is posted, and the takeover is the UI thread's.
TEST(Takeover, WithoutAProxyEveryMainVolumeIsShown) {
  Session session(1);
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_EQ(session.takeoverPoints(), 0u);
  for (std::uint64_t post : {0u, 1u, 2u}) {
    EXPECT_TRUE(session.uploadMainVolume(mainWith(1), post)) << post;
    EXPECT_TRUE(session.mainVolumeUploaded(mainWith(1), post)) << post;
  }
  EXPECT_EQ(session.shownMainPost(), 2u);
}

TEST(Takeover, AProxyIsShownOnceItHasEnoughPointsAndShowsANewerPostThanTheMainGrid) {
  Session session(1);
  EXPECT_FALSE(session.showProxyVolume(proxyAt(0.9 * Session::kProxyShownPointsPerVoxel), 1))
      << "hardly any points: it would be all noise";
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_TRUE(session.showProxyVolume(proxyAt(Session::kProxyShownPointsPerVoxel), 1));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Proxy);
  // The main grid shows post 1 in full; a proxy of that post (a fresher one) no longer goes up.
  ASSERT_TRUE(session.mainVolumeUploaded(mainWith(kMainInside * 100), 1));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_FALSE(session.showProxyVolume(proxyAt(Session::kProxyPointsPerVoxel), 1));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_TRUE(session.showProxyVolume(proxyAt(Session::kProxyShownPointsPerVoxel), 2)) << "the next edit's";
  EXPECT_EQ(session.shownGrid(), ShownGrid::Proxy);
}

TEST(Takeover, TheMainGridTakesOverWithTheProxysPointsButNoMoreThanItsBurst) {
  Session session(1);
  ASSERT_TRUE(session.showProxyVolume(proxyAt(10.0), 1));  // a proxy part way through its burst
  const auto proxyPoints = static_cast<std::uint64_t>(10.0 * kProxyInside);
  EXPECT_EQ(session.takeoverPoints(), proxyPoints);
  // A main grid volume of the proxy's post with fewer points would not replace it: not uploaded,
  // and not shown if it was.
  EXPECT_FALSE(session.uploadMainVolume(mainWith(proxyPoints - 1), 1));
  EXPECT_FALSE(session.mainVolumeUploaded(mainWith(proxyPoints - 1), 1));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Proxy);
  EXPECT_TRUE(session.uploadMainVolume(mainWith(proxyPoints), 1));
  EXPECT_TRUE(session.mainVolumeUploaded(mainWith(proxyPoints), 1));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_EQ(session.shownMainPost(), 1u);

  // A proxy whose last batches went a third past its burst: the main grid needs only the burst's
  // count, which its first volume holds (the publisher packs it from then on).
  ASSERT_TRUE(session.showProxyVolume(proxyAt(1.33 * Session::kProxyPointsPerVoxel), 2));
  const auto burst = static_cast<std::uint64_t>(Session::kProxyPointsPerVoxel * kProxyInside);
  EXPECT_EQ(session.takeoverPoints(), burst);
  EXPECT_FALSE(session.uploadMainVolume(mainWith(burst - 1), 2));
  EXPECT_TRUE(session.uploadMainVolume(mainWith(burst), 2));
  EXPECT_TRUE(session.mainVolumeUploaded(mainWith(burst), 2));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
}

TEST(Takeover, NothingOlderReplacesANewerProxyAndALaterPostNeedsNoPoints) {
  Session session(1);
  ASSERT_TRUE(session.showProxyVolume(proxyAt(Session::kProxyPointsPerVoxel), 2));
  // A main grid volume of an earlier post, finishing its upload: recorded, but the proxy stays.
  EXPECT_TRUE(session.uploadMainVolume(mainWith(1), 1)) << "another post than the proxy's: uploaded";
  EXPECT_FALSE(session.mainVolumeUploaded(mainWith(kMainInside * 100), 1));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Proxy);
  EXPECT_EQ(session.shownMainPost(), 1u);
  // One of a pattern older than the newest applied one (post 0) while the proxy shows a newer one:
  // not uploaded, and not shown.
  EXPECT_FALSE(session.uploadMainVolume(mainWith(kMainInside * 100), 0));
  EXPECT_FALSE(session.mainVolumeUploaded(mainWith(kMainInside * 100), 0));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Proxy);
  // A later post than the proxy's (the proxy of that post not shown yet) takes over with any points.
  EXPECT_TRUE(session.uploadMainVolume(mainWith(1), 3));
  EXPECT_TRUE(session.mainVolumeUploaded(mainWith(1), 3));
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_EQ(session.shownMainPost(), 3u);
  // While the main grid is shown, any volume of it is uploaded.
  EXPECT_TRUE(session.uploadMainVolume(mainWith(1), 0));
}

TEST(Takeover, ANewLiveViewStartsWithNothingShown) {
  Session session(1);
  ASSERT_TRUE(session.showProxyVolume(proxyAt(Session::kProxyPointsPerVoxel), 4));
  ASSERT_TRUE(session.mainVolumeUploaded(mainWith(kMainInside * 100), 4));
  session.restartTakeover();
  EXPECT_EQ(session.shownGrid(), ShownGrid::Main);
  EXPECT_EQ(session.shownMainPost(), 0u);
  EXPECT_EQ(session.takeoverPoints(), 0u);
  EXPECT_TRUE(session.showProxyVolume(proxyAt(Session::kProxyShownPointsPerVoxel), 1))
      << "a proxy of any post is newer than nothing";
}

}  // namespace
