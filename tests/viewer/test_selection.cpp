// The viewer's selection rules without a window: clicks against drags, Tab's cycling.
#include "selection.hpp"

#include <gtest/gtest.h>

namespace draught::viewer {
namespace {

TEST(ClickTracker, AStillPressIsAClick) {
  ClickTracker c;
  c.press(100, 50);
  c.move(102, 51);  // a hand is not still
  EXPECT_TRUE(c.release());
  EXPECT_FALSE(c.release());  // no press, no click
}

TEST(ClickTracker, ADragIsNoClickEvenWhenItComesBack) {
  ClickTracker c;
  c.press(100, 50);
  c.move(130, 50);
  c.move(100, 50);
  EXPECT_FALSE(c.release());
  c.press(10, 10);  // the next press starts afresh
  EXPECT_TRUE(c.release());
}

TEST(Cycle, WrapsBothWays) {
  EXPECT_EQ(cycle(0, 4, 1), 1);
  EXPECT_EQ(cycle(3, 4, 1), 0);
  EXPECT_EQ(cycle(0, 4, -1), 3);
  EXPECT_EQ(cycle(0, 1, 1), 0);
  EXPECT_EQ(cycle(0, 0, 1), 0);
}

}  // namespace
}  // namespace draught::viewer
