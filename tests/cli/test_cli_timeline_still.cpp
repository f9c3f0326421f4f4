// End-to-end tests of `draught render --timeline T --at SECONDS`: a timeline's frame as a
// still PNG (the picture, a debug view or the reference), the same frame an animation
// writes at that time. Small images throughout: CI has two cores.
#include "cli_helpers.hpp"

#include "core/io/image.hpp"

namespace draught_cli_test {
namespace {

class TimelineStill : public CliTest {
 protected:
  // `render --timeline <timeline> --size 48x48 --supersample 1 <args...>`.
  RunResult render_timeline(const std::string& timeline, std::vector<std::string> args) {
    std::vector<std::string> a = {"render", "--timeline", timeline, "--size", "48x48", "--supersample", "1"};
    a.insert(a.end(), args.begin(), args.end());
    return draught(a);
  }
  std::string png(const std::string& name) const { return (out() / name).string(); }
};

TEST_F(TimelineStill, IsTheAnimationsFrameAtThatTime) {
  // The glass tipping until it spills: frame 3 at 4 fps is the timeline at 0.75 s.
  auto seq = render_timeline("tilt-until-spill", {"--fps", "4", "--duration", "1", "-o", (out() / "frames").string() + "/"});
  ASSERT_EQ(seq.exit_code, 0) << seq.describe();
  auto still = render_timeline("tilt-until-spill", {"--fps", "4", "--at", "0.75", "-o", png("still.png")});
  ASSERT_EQ(still.exit_code, 0) << still.describe();
  EXPECT_TRUE(contains(still.out, "wrote " + png("still.png"))) << still.describe();
  const draught::Image a = draught::read_png(out() / "frames" / "frame_00003.png"), b = draught::read_png(png("still.png"));
  ASSERT_EQ(b.width, 48);
  ASSERT_EQ(b.height, 48);
  EXPECT_EQ(a.rgba, b.rgba) << "the still differs from the animation's frame at the same time";
}

TEST_F(TimelineStill, MovesWithTheTime) {
  ASSERT_EQ(render_timeline("tilt-until-spill", {"--at", "0", "-o", png("a.png")}).exit_code, 0);
  ASSERT_EQ(render_timeline("tilt-until-spill", {"--at", "2.5", "-o", png("b.png")}).exit_code, 0);
  const draught::Image a = draught::read_png(png("a.png")), b = draught::read_png(png("b.png"));
  int differ = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) differ += std::abs(int(a.rgba[i]) - int(b.rgba[i])) > 8;
  EXPECT_GT(differ, 200) << "the glass tipped at 2.5 s looks like the upright one at 0 s";
}

TEST_F(TimelineStill, DebugViewsAndTheReferenceRenderIt) {
  auto d = render_timeline("fresh-pour", {"--at", "1.5", "--debug", "depth", "-o", png("depth.png")});
  ASSERT_EQ(d.exit_code, 0) << d.describe();
  EXPECT_EQ(draught::read_png(png("depth.png")).width, 48);
  auto r = draught({"render", "--timeline", "fresh-pour", "--at", "1.5", "--reference", "--spp", "1", "--size", "12x12",
                    "-o", png("reference.png")});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  const draught::Image img = draught::read_png(png("reference.png"));
  EXPECT_EQ(img.width, 12);
  EXPECT_EQ(img.height, 12);
}

TEST_F(TimelineStill, FlagsThatDoNotMixAreRefused) {
  const std::string x = png("x.png");
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> said;
  };
  const std::vector<Case> cases = {
      {{"render", "--at", "1", "-o", x}, {"--at", "--timeline"}},
      {{"render", "--timeline", "fresh-pour", "--at", "1", "--duration", "2", "-o", x}, {"--duration", "--at"}},
      {{"render", "--timeline", "fresh-pour", "--at", "1", "--overwrite", "-o", x}, {"--overwrite", "--at"}},
      {{"render", "--timeline", "fresh-pour", "--at", "-1", "-o", x}, {"--at -1", "0 to 600"}},
      {{"render", "--timeline", "fresh-pour", "--at", "soon", "-o", x}, {"--at soon", "0 to 600"}},
      {{"render", "--timeline", "fresh-pour", "--at", "1", "-o", png("x.mp4")}, {"x.mp4", ".png"}},
      {{"render", "--timeline", "fresh-pour", "--reference", "-o", x}, {"--reference", "--at"}},
  };
  for (const Case& c : cases) {
    auto r = draught(c.args);
    EXPECT_EQ(r.exit_code, 1) << r.describe();
    expect_failure(r, c.said);
  }
  EXPECT_FALSE(fs::exists(x)) << "a refused still wrote its file";
}

}  // namespace
}  // namespace draught_cli_test
