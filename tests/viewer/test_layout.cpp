// Where the viewer frames the scene: the part of the window the panel and the overlay
// leave free, chosen by how large the scene would be drawn there.
#include "layout.hpp"

#include <gtest/gtest.h>

namespace draught::viewer {
namespace {

bool inside(const Rect& r, const Rect& outer) {
  return r.x0 >= outer.x0 && r.y0 >= outer.y0 && r.x1 <= outer.x1 && r.y1 <= outer.y1;
}

TEST(FreeRect, NothingCoveredIsTheWholeWindow) {
  const Rect r = free_rect(1280, 800, {}, 0.6);
  EXPECT_EQ(r.x0, 0);
  EXPECT_EQ(r.y0, 0);
  EXPECT_EQ(r.x1, 1280);
  EXPECT_EQ(r.y1, 800);
}

TEST(FreeRect, BesideThePanelAndClearOfTheOverlay) {
  // The default layout: the panel down the left, the overlay in the top right corner.
  const Rect panel{10, 10, 410, 790}, overlay{960, 10, 1270, 150};
  const std::vector<Rect> covers{panel, overlay};
  // A tall glass: the full height between panel and overlay beats the wider part below it.
  const Rect glass = free_rect(1280, 800, covers, 0.6);
  EXPECT_FALSE(glass.overlaps(panel));
  EXPECT_FALSE(glass.overlaps(overlay));
  EXPECT_EQ(glass.x0, 410);
  EXPECT_EQ(glass.x1, 960);
  EXPECT_EQ(glass.height(), 800);
  // A wide flight: the width below the overlay matters more.
  const Rect flight = free_rect(1280, 800, covers, 3.0);
  EXPECT_FALSE(flight.overlaps(panel));
  EXPECT_FALSE(flight.overlaps(overlay));
  EXPECT_EQ(flight.x0, 410);
  EXPECT_EQ(flight.x1, 1280);
  EXPECT_EQ(flight.y0, 150);
}

TEST(FreeRect, CoversOutsideTheWindowAreIgnored) {
  const Rect r = free_rect(800, 600, {{-300, 0, -10, 600}, {0, 700, 800, 900}}, 1.0);
  EXPECT_EQ(r.width(), 800);
  EXPECT_EQ(r.height(), 600);
}

TEST(FreeRect, TooLittleRoomFallsBackToTheWholeWindow) {
  // A tiny window the panel nearly fills: the scene is drawn behind it rather than in a sliver.
  const Rect r = free_rect(320, 240, {{0, 0, 300, 240}}, 0.6);
  EXPECT_EQ(r.width(), 320);
  EXPECT_EQ(r.height(), 240);
}

TEST(FreeRect, AlwaysFreeOfEveryCover) {
  const std::vector<Rect> covers{{10, 10, 300, 500}, {500, 0, 640, 120}, {200, 400, 640, 480}};
  for (double aspect : {0.3, 0.6, 1.0, 2.0, 5.0}) {
    const Rect r = free_rect(640, 480, covers, aspect, 0.0);
    EXPECT_FALSE(r.empty()) << aspect;
    EXPECT_TRUE(inside(r, {0, 0, 640, 480})) << aspect;
    for (const Rect& c : covers) EXPECT_FALSE(r.overlaps(c)) << aspect;
  }
}

TEST(FreeRect, AsAPartOfThePicture) {
  const PictureRect p = picture_rect({400, 100, 1200, 800}, 1600, 1000);
  EXPECT_DOUBLE_EQ(p.x, 0.25);
  EXPECT_DOUBLE_EQ(p.y, 0.1);
  EXPECT_DOUBLE_EQ(p.width, 0.5);
  EXPECT_DOUBLE_EQ(p.height, 0.7);
  EXPECT_TRUE(picture_rect({0, 0, 1600, 1000}, 1600, 1000).whole());
}

}  // namespace
}  // namespace draught::viewer
