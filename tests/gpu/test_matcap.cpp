// The MatCap tier (render.tier matcap, shaders/passes/matcap.frag.glsl, docs/MATCAP.md):
// - probes: the Thickness debug view (lib/vessel/thickness.glsl view_thickness at the
//   GPU's first surface) against core's view_thickness at the reference intersector's first
//   hit, pixel by pixel: a pint (its wall and thick base), a wine glass (bowl, solid stem,
//   foot), a pint from above (rim, inner wall, the liquid), a flight from an angle.
//   Tolerance: where both see the same surface of the same object away from a change of
//   surface (within a pixel), 99 % of pixels within 0.1 mm + 1 % and none beyond 2 mm +
//   10 % (lines along a wall near the silhouette are ill-conditioned in float);
// - the picture: finite, the glass seen, the drink's colour in it; a still frame bakes and
//   uploads its MatCap once; the MatCap follows the surroundings.
#include "core/scene/camera.hpp"
#include "core/vessel/view_thickness.hpp"
#include "gpu/matcap_texture.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

struct ThicknessCase {
  const char* name;
  FrameState (*frame)();
  int size;
};

FrameState pint_front() { return scene_frame({"lager", "pint", {}, {}}); }
FrameState wine() { return scene_frame({"red-wine", "wine", {}, {}}); }
FrameState pint_above() { return scene_frame({"lager", "pint", {}, {"eye=0.08,0.32,0.2", "target=0,0.07,0"}}); }
FrameState flight_angle() { return make_frame(flight_scene(FlightView::AtAnAngle)); }

void PrintTo(const ThicknessCase& c, std::ostream* os) { *os << c.name; }

class MatCapThickness : public ::testing::TestWithParam<ThicknessCase> {};

TEST_P(MatCapThickness, MatchesCoreTwin) {
  const ThicknessCase& c = GetParam();
  const FrameState f = c.frame();
  const int n = c.size;
  const CameraBasis cam = camera_basis(f, n, n);
  const SceneGeometry geo = scene_geometry(f);
  std::vector<Hit> hits(size_t(n) * size_t(n));
  std::vector<double> ref(hits.size(), 0.0);
  auto at = [&](int x, int y) { return size_t(y) * size_t(n) + size_t(x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Ray ray = camera_ray(cam, x + 0.5, y + 0.5, n, n);
      const Hit h = first_hit(geo, ray, 0.0);
      hits[at(x, y)] = h;
      if (h.object < 0) continue;
      const VesselGeometry& g = geo.vessels[size_t(h.object)];
      const glm::dquat to_local = glm::inverse(g.pose.orientation);
      ref[at(x, y)] = view_thickness(*g.vessel, to_local * (ray.at(h.t) - g.pose.position), to_local * ray.d, h.m);
    }
  const gpu::DebugImage img = gpu_instance().renderer->render_debug(f, n, n, gpu::DebugView::Thickness);
  auto on_edge = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Hit& o = hits[at(std::clamp(x + dx, 0, n - 1), std::clamp(y + dy, 0, n - 1))];
        if (o.m != hits[at(x, y)].m || o.object != hits[at(x, y)].object) return true;
      }
    return false;
  };
  int compared = 0, loose = 0, far = 0, glass = 0;
  double worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float* g = img.px(x, y);
      const Hit& h = hits[at(x, y)];
      if (int(std::lround(g[1])) != int(h.m) || int(std::lround(g[2])) != h.object || on_edge(x, y)) continue;
      ++compared;
      const double r = ref[at(x, y)], d = std::abs(double(g[0]) - r);
      glass += r > 0;
      worst = std::max(worst, d);
      loose += d > 1e-4 + 0.01 * r;
      far += d > 2e-3 + 0.1 * r;
    }
  std::printf("[%s] %d pixels compared (%d through glass), %d beyond 0.1 mm + 1 %%, %d beyond 2 mm + 10 %%, worst %.3g mm\n",
              c.name, compared, glass, loose, far, worst * 1e3);
  EXPECT_GT(glass, n * n / 20);  // the glass is in the picture
  EXPECT_LE(loose, compared / 100);
  EXPECT_EQ(far, 0);
}

INSTANTIATE_TEST_SUITE_P(Views, MatCapThickness,
                         ::testing::Values(ThicknessCase{"pint_front", pint_front, 96},
                                           ThicknessCase{"wine", wine, 96},
                                           ThicknessCase{"pint_above", pint_above, 96},
                                           ThicknessCase{"flight_angle", flight_angle, 128}),
                         [](const auto& info) { return std::string(info.param.name); });

FrameState matcap_tier(FrameState f) {
  f.params.render.tier = int(RenderTier::MatCap);
  return f;
}

TEST(MatCapTier, DrawsTheGlassAndItsDrink) {
  Gpu& g = gpu_instance();
  const FrameState f = matcap_tier(pint_front());
  const Image img = g.renderer->render(f, 96, 96);
  // The middle of the glass is the lager's gold (red over blue), the corner the backdrop's grey.
  const std::uint8_t* mid = img.px(48, 50);
  const std::uint8_t* corner = img.px(4, 4);
  EXPECT_GT(int(mid[0]) - int(mid[2]), 40);
  EXPECT_LT(std::abs(int(corner[0]) - int(corner[2])), 12);
  // And it is another picture than the full tier's.
  const Image full = g.renderer->render(pint_front(), 96, 96);
  long differ = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) differ += std::abs(int(img.rgba[i]) - int(full.rgba[i])) > 8;
  EXPECT_GT(differ, 96 * 96 / 50);
}

TEST(MatCapTier, AStillFrameBakesAndUploadsOnce) {
  Gpu& g = gpu_instance();
  FrameState f = matcap_tier(pint_front());
  f.params.env.sky_top = {0.031f, 0.02f, 0.02f};  // surroundings no other test bakes
  g.renderer->render(f, 32, 32);
  const int uploads = g.renderer->matcap_texture().uploads();
  g.renderer->render(f, 32, 32);
  EXPECT_EQ(g.renderer->matcap_texture().uploads(), uploads);
  f.params.light.power *= 2;  // the surroundings change: a new bake
  g.renderer->render(f, 32, 32);
  EXPECT_EQ(g.renderer->matcap_texture().uploads(), uploads + 1);
}

TEST(MatCapTier, TheBackgroundIsDrawnOncePerView) {
  Gpu& g = gpu_instance();
  const FrameState f = matcap_tier(pint_front());
  gpu::RenderTarget target(48, 48, false);
  g.renderer->draw(f, 48, 48);
  const int draws = g.renderer->matcap_background().draws();
  g.renderer->draw(f, 48, 48);
  g.renderer->draw(f, 48, 48);
  EXPECT_EQ(g.renderer->matcap_background().draws(), draws);
  FrameState moved = f;
  moved.camera.eye.x += 0.01f;  // another view: drawn again
  g.renderer->draw(moved, 48, 48);
  EXPECT_EQ(g.renderer->matcap_background().draws(), draws + 1);
}

// Every matcap.* number at its minimum and its maximum: a picture with no black hole (a NaN
// shows as black). (matcap.tint black is a black glass body, rightly.)
TEST(MatCapTier, ExtremeParametersDrawAPicture) {
  Gpu& g = gpu_instance();
  for (const ParamDesc& d : param_table()) {
    if (!d.path.starts_with("matcap.") || d.type != ParamType::Float) continue;
    for (float v : {d.min, d.max}) {
      FrameState f = matcap_tier(pint_front());
      set_param(f.params, d, ParamValue(v));
      const Image img = g.renderer->render(f, 48, 48);
      long black = 0;
      for (size_t i = 0; i < img.rgba.size(); i += 4) black += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2] == 0;
      EXPECT_EQ(black, 0) << d.path << " = " << v;
    }
  }
}

}  // namespace
}  // namespace draught::test
