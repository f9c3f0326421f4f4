// GPU probes: the shader's debug outputs (distance to the first surface, its normal,
// its material id) at small size, compared pixel by pixel with the C++ reference
// intersector (core/intersect) for the same camera rays.
//
// Tolerances (float on the GPU vs double on the CPU):
// - material: pixels may disagree only where the reference itself changes material
//   within one pixel (silhouettes); elsewhere at most 0.1 % of pixels.
// - distance: |t_gpu - t_ref| <= max(0.05 mm, 1e-4 t) on 99.5 % of agreeing pixels (a
//   float ray's direction error grows into distance on far, grazing floor hits), and
//   never more than 1 mm on the glass itself.
// - normal: <= 0.25 degrees on 99.5 % of agreeing pixels.
#include "core/scene/camera.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

struct ProbeCase {
  const char* name;
  SceneRequest request;
  int size;
  const char* timeline = nullptr;  // a glass in motion: this timeline's frame at `at` seconds
  double at = 0;
  FrameState (*scene)() = nullptr;  // a scene of several objects (request and timeline unused)
};

FrameState flight_along() { return make_frame(flight_scene(FlightView::AlongTheRow)); }
// The viewer's framing beside its panel: the lens shifted to the right part of the picture.
FrameState pint_beside_a_panel() {
  FrameState f = scene_frame({"lager", "pint", {}, {}});
  f.view = PictureRect{0.4, 0.25, 0.6, 0.75};
  return f;
}

struct Reference {
  int w, h;
  std::vector<Hit> hits;
  const Hit& at(int x, int y) const { return hits[size_t(y) * size_t(w) + size_t(x)]; }
};

Reference reference_hits(const FrameState& f, int w, int h) {
  Reference r{w, h, {}};
  CameraBasis cam = camera_basis(f, w, h);
  SceneGeometry geo = scene_geometry(f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) r.hits.push_back(first_hit(geo, camera_ray(cam, x + 0.5, y + 0.5, w, h), 0.0));
  return r;
}

// Where the reference changes material (or object) within a pixel's neighbourhood.
bool on_material_edge(const Reference& r, int x, int y) {
  const Hit& h = r.at(x, y);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int xx = x + dx, yy = y + dy;
      if (xx >= 0 && yy >= 0 && xx < r.w && yy < r.h && (r.at(xx, yy).m != h.m || r.at(xx, yy).object != h.object))
        return true;
    }
  return false;
}

void PrintTo(const ProbeCase& c, std::ostream* os) { *os << c.name; }

class Probe : public ::testing::TestWithParam<ProbeCase> {};

TEST_P(Probe, DebugChannelsMatchReferenceIntersector) {
  const ProbeCase& c = GetParam();
  Gpu& g = gpu_instance();
  FrameState f = on_checker_floor(c.scene ? c.scene() : case_frame(c.request, c.timeline, c.at));
  const int n = c.size;
  Reference ref = reference_hits(f, n, n);
  gpu::DebugImage depth = g.renderer->render_debug(f, n, n, gpu::DebugView::Depth);
  gpu::DebugImage normal = g.renderer->render_debug(f, n, n, gpu::DebugView::Normal);

  int interior_mismatch = 0, edge_mismatch = 0, agree_hits = 0, depth_bad = 0, normal_bad = 0, object_bad = 0;
  double worst_depth = 0, worst_angle = 0;
  glm::ivec2 worst_at{-1};
  std::vector<int> per_material(10, 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Hit& h = ref.at(x, y);
      const int gm = int(std::lround(depth.px(x, y)[1]));
      ASSERT_EQ(gm, int(std::lround(normal.px(x, y)[3]))) << "depth and normal passes disagree at " << x << "," << y;
      const int gobj = int(std::lround(depth.px(x, y)[2]));  // which glass (-1: the floor, none)
      if (gm != int(h.m) || gobj != h.object) {
        const bool edge = on_material_edge(ref, x, y);
        (edge ? edge_mismatch : interior_mismatch)++;
        object_bad += !edge && gm == int(h.m);
        continue;
      }
      if (!h.valid()) continue;
      ++agree_hits;
      per_material[size_t(gm)]++;
      double dt = std::fabs(double(depth.px(x, y)[0]) - h.t);
      if (h.m != Material::Floor && dt > worst_depth) {
        worst_depth = dt;
        worst_at = {x, y};
      }
      if (dt > std::max(5e-5, 1e-4 * h.t)) ++depth_bad;
      glm::dvec3 gn(normal.px(x, y)[0], normal.px(x, y)[1], normal.px(x, y)[2]);
      double angle = glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(gn), h.n), -1.0, 1.0)));
      worst_angle = std::max(worst_angle, angle);
      if (angle > 0.25) ++normal_bad;
    }
  std::printf("[%s] %dx%d: %d agreeing hits; materials:", c.name, n, n, agree_hits);
  for (int m = 1; m < 10; ++m)
    if (per_material[size_t(m)]) std::printf(" %s=%d", material_name(Material(m)), per_material[size_t(m)]);
  std::printf("; mismatches edge=%d interior=%d; worst glass |dt|=%.2e m (pixel %d,%d), worst normal %.3f deg\n",
              edge_mismatch, interior_mismatch, worst_depth, worst_at.x, worst_at.y, worst_angle);

  EXPECT_GT(agree_hits, n * n / 10) << "the probe should see the glass";
  EXPECT_LE(interior_mismatch, n * n / 1000) << "material ids disagree away from silhouettes";
  EXPECT_LE(edge_mismatch, n * n * 3 / 100) << "too many silhouette pixels disagree";
  EXPECT_LE(depth_bad, agree_hits / 200) << "hit distance off by more than 0.05 mm";
  EXPECT_LT(worst_depth, 1e-3) << "a glass hit distance is off by 1 mm or more";
  EXPECT_LE(normal_bad, agree_hits / 200) << "normals off by more than 0.25 degrees";
  EXPECT_EQ(object_bad, 0) << "the GPU names another object than the reference intersector";
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, Probe,
    ::testing::Values(
        ProbeCase{"pint-front", {"lager", "pint", {}, {}}, 96},
        ProbeCase{"pint-above", {"lager", "pint", {}, {"eye=0.06,0.34,0.16", "target=0,0.08,0"}}, 96},
        ProbeCase{"rim-closeup", {"lager", "pint", {}, {"eye=0.0,0.168,0.1", "target=0,0.145,0.03", "vfov=22"}}, 96},
        ProbeCase{"wine-glass", {"red-wine", "wine", {}, {}}, 96},
        ProbeCase{"empty-tulip-above", {"amber-ale", "tulip", {"liquid.fill=0"}, {"eye=0.03,0.4,0.12", "target=0,0.05,0"}}, 96},
        ProbeCase{"nonic-from-below", {"stout", "nonic", {"env.floor=false"}, {"eye=0.0,-0.12,0.3", "target=0,0.06,0"}}, 96},
        // Cross-sections: cut faces through glass and liquid, from the front and from above.
        ProbeCase{"pint-cross-section", {"lager", "pint", {"clip.enabled=true", "clip.normal=1,0,1"}, {}}, 96},
        ProbeCase{"wine-cross-section-above",
                  {"red-wine", "wine", {"clip.enabled=true", "clip.offset=0.01"}, {"eye=0.05,0.4,0.25", "target=0,0.14,0"}}, 96},
        // Tipped on its foot, sloshing with waves, spilling over the rim.
        ProbeCase{"pint-tilted", {}, 96, "gentle-tilt", 1.9},
        ProbeCase{"pint-sloshing", {}, 96, "shake-and-settle", 1.3},
        ProbeCase{"pint-sloshing-above", {"", "", {}, {"eye=0.06,0.34,0.16", "target=0,0.08,0"}}, 96, "shake-and-settle", 1.3},
        ProbeCase{"wine-spilling-above", {"", "", {}, {"eye=-0.1,0.4,0.2", "target=-0.05,0.1,0"}}, 96, "tilt-until-spill", 3.0},
        ProbeCase{"wine-spilling", {}, 96, "tilt-until-spill", 3.0},
        // Four glasses: the nearest hit over every object, and which object it is.
        ProbeCase{"flight-front", {}, 128, nullptr, 0, flight_front},
        ProbeCase{"flight-angle", {}, 128, nullptr, 0, flight_angle},
        ProbeCase{"flight-along-the-row", {}, 128, nullptr, 0, flight_along},
        ProbeCase{"pint-beside-a-panel", {}, 96, nullptr, 0, pint_beside_a_panel}),
    [](const auto& info) {
      std::string s = info.param.name;
      for (char& ch : s)
        if (ch == '-') ch = '_';
      return s;
    });

// The liquid surface sits exactly at the height that holds the requested volume.
TEST(Probe, LiquidSurfaceAtSolvedFillHeight) {
  Gpu& g = gpu_instance();
  FrameState f = scene_frame({"lager", "pint", {"liquid.fill=0.6"}, {"eye=0,0.4,0.001", "target=0,0,0"}});
  const int n = 64;
  CameraBasis cam = camera_basis(f, n, n);
  gpu::DebugImage depth = g.renderer->render_debug(f, n, n, gpu::DebugView::Depth);
  int checked = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      if (int(std::lround(depth.px(x, y)[1])) != int(Material::LiquidSurface)) continue;
      Ray r = camera_ray(cam, x + 0.5, y + 0.5, n, n);
      EXPECT_NEAR(r.at(depth.px(x, y)[0]).y, f.vessels[0].vessel.fill_height(0.6), 2e-5);
      ++checked;
    }
  EXPECT_GT(checked, 200);
}

}  // namespace
}  // namespace draught::test

namespace draught::test {
namespace {

// The work per pixel is bounded analytically: only segments a ray's height range
// crosses are tested, so the mean stays small, and no pixel exceeds the hard bound
// of max_events x (inner + outer segments + the torus).
TEST(Probe, IntersectionWorkPerPixelIsBounded) {
  Gpu& g = gpu_instance();
  FrameState f = scene_frame({"lager", "pint", {}, {}});
  const int n = 96;
  gpu::DebugImage cost = g.renderer->render_debug(f, n, n, gpu::DebugView::Cost);
  double sum = 0, worst = 0;
  for (size_t i = 0; i < cost.rgba.size(); i += 4) {
    sum += cost.rgba[i];
    worst = std::max(worst, double(cost.rgba[i]));
  }
  const double mean = sum / (n * n);
  std::printf("intersection tests per pixel: mean %.1f, max %.0f\n", mean, worst);
  EXPECT_GT(mean, 1.0);  // the view does see the glass
  EXPECT_LT(mean, 16.0);
  EXPECT_LE(worst, f.params.render.max_events * (2 * Vessel::kSegments + 1));
}

}  // namespace
}  // namespace draught::test
