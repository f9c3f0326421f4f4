// Big bubbles placed on the head (core/foam place_big_bubbles, what the renderer draws):
// each sits on the head's top over the liquid surface, its cap standing out by 70 % of
// its radius, also on a tilted surface; popped ones stay popped.
#include "core/foam/foam.hpp"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>

namespace draught {
namespace {

TEST(BigBubbles, CapsStandOnTheHeadsTop) {
  FoamFrame fo;
  fo.thickness = 0.012;
  fo.dome = 0.2;
  fo.bubbles = {{{0.01, -0.005}, 0.002, false}, {{-0.02, 0.0}, 0.0015, true}};
  const double radius = 0.035;
  for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0.2, 1, -0.1))}) {
    const double offset = 0.1;
    const std::vector<PlacedBubble> placed = place_big_bubbles(fo, n, offset, radius);
    ASSERT_EQ(placed.size(), fo.bubbles.size());
    for (size_t i = 0; i < placed.size(); ++i) {
      const BigBubble& b = fo.bubbles[i];
      const PlacedBubble& p = placed[i];
      // Above the surface by the head's thickness there, less 30 % of the radius.
      const double above = glm::dot(n, p.centre) - offset;
      EXPECT_NEAR(above, fo.thickness_at(b.xz.x, b.xz.y, radius) - 0.3 * b.radius, 1e-12);
      // Over the bubble's place on the head, along the surface normal.
      const glm::dvec3 foot = p.centre - n * above;
      EXPECT_NEAR(glm::dot(n, foot), offset, 1e-12);
      EXPECT_NEAR(foot.x, b.xz.x, 1e-12);
      EXPECT_NEAR(foot.z, b.xz.y, 1e-12);
      EXPECT_EQ(p.radius, b.radius);
      EXPECT_EQ(p.popped, b.popped);
    }
  }
}

TEST(BigBubbles, NoneWithoutBubbles) { EXPECT_TRUE(place_big_bubbles(FoamFrame{}, {0, 1, 0}, 0.1, 0.03).empty()); }

}  // namespace
}  // namespace draught
