// Droplets on the GPU (lib/droplets/field.glsl) against the C++ reference marcher
// (core/droplets/field.cpp): the first surface's distance, normal and material, pixel
// by pixel, over the trail of the droplets timeline with a pint behind it; the
// silhouettes (grazing rays) must have no holes.
//
// Tolerances (float on the GPU vs double on the CPU): materials may differ only where
// the reference changes material within a pixel's neighbourhood; on droplet pixels the
// distance within 0.1 mm and the normal within 1 degree on 99 % of them (the noise's
// gradient in float), and no droplet pixel of the reference, edges included, is a miss
// on the GPU beyond 0.5 %.
#include "core/droplets/field.hpp"
#include "core/scene/camera.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

// The droplets timeline's frame at t, in its scene of objects (the fixture's
// timeline_frame takes the first object's document only).
FrameState trail_frame(double t, const std::vector<std::string>& camera = {}) {
  const Timeline tl = load_timeline("droplets-trail");
  SceneRequest req;
  req.camera = camera;
  req.preset = tl.preset;
  return draught::timeline_frame(tl, resolve_scene_objects(req), t);
}

struct RefHit {
  double t = INFINITY;
  glm::dvec3 n{0.0};
  int m = 0;
};

// The nearest of the vessels' and the floor's first hit and the droplets' march.
std::vector<RefHit> reference(const FrameState& f, int w, int h) {
  std::vector<RefHit> out;
  const CameraBasis cam = camera_basis(f, w, h);
  const SceneGeometry geo = scene_geometry(f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Ray ray = camera_ray(cam, x + 0.5, y + 0.5, w, h);
      const Hit vh = first_hit(geo, ray, 0.0);
      RefHit r{vh.t, vh.n, int(vh.m)};
      if (auto d = march_droplets(f.droplets.front().field, ray.o, ray.d, 0.0, vh.valid() ? vh.t : 1e30, false))
        r = {d->t, d->n, int(Material::Droplet)};
      out.push_back(r);
    }
  return out;
}

void compare(const FrameState& f, int w, int h, const char* name) {
  Gpu& g = gpu_instance();
  ASSERT_FALSE(f.droplets.empty());
  const gpu::DebugImage depth = g.renderer->render_debug(f, w, h, gpu::DebugView::Depth);
  const gpu::DebugImage normal = g.renderer->render_debug(f, w, h, gpu::DebugView::Normal);
  const std::vector<RefHit> ref = reference(f, w, h);
  auto at = [&](int x, int y) -> const RefHit& { return ref[size_t(y) * size_t(w) + size_t(x)]; };
  auto edge = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int xx = x + dx, yy = y + dy;
        if (xx >= 0 && yy >= 0 && xx < w && yy < h && at(xx, yy).m != at(x, y).m) return true;
      }
    return false;
  };
  int droplet = 0, holes = 0, mismatched = 0, far = 0, bent = 0, agreeing = 0;
  double worst_t = 0, worst_deg = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const RefHit& r = at(x, y);
      const float* d = depth.px(x, y);
      const float* n = normal.px(x, y);
      const int gm = int(std::lround(d[1]));
      if (r.m == int(Material::Droplet)) {
        ++droplet;
        // A hole: the GPU sees what lies behind the droplet (or nothing) where the
        // reference sees the droplet, edges included.
        if (gm != int(Material::Droplet) && at(x, y).t < double(d[0]) - 1e-4) ++holes;
        if (gm == int(Material::None)) ++holes;
      }
      if (gm != r.m) {
        if (!edge(x, y)) ++mismatched;
        continue;
      }
      if (r.m != int(Material::Droplet)) continue;
      ++agreeing;
      const double dt = std::abs(double(d[0]) - r.t);
      worst_t = std::max(worst_t, dt);
      if (dt > 1e-4) ++far;
      const glm::dvec3 gn = glm::normalize(glm::dvec3(n[0], n[1], n[2]));
      const double deg = glm::degrees(std::acos(std::clamp(glm::dot(gn, r.n), -1.0, 1.0)));
      worst_deg = std::max(worst_deg, deg);
      if (deg > 1.0) ++bent;
    }
  std::printf("[%s] droplet pixels %d (agreeing %d): holes %d, other mismatches %d, |dt| > 0.1 mm %d (worst %.3g m), "
              "normal > 1 deg %d (worst %.3g deg)\n",
              name, droplet, agreeing, holes, mismatched, far, worst_t, bent, worst_deg);
  EXPECT_GT(droplet, w * h / 50) << "the droplets are in the picture";
  EXPECT_LE(holes, droplet / 200);
  EXPECT_LE(mismatched, w * h / 1000);
  EXPECT_LE(far, agreeing / 100);
  EXPECT_LE(bent, agreeing / 100);
}

TEST(Droplets, ProbesMatchReferenceMarcher) {
  compare(trail_frame(1.0), 128, 96, "trail, stretched");
  compare(trail_frame(3.9), 128, 96, "trail, gathered");
}

TEST(Droplets, GrazingCloseUpHasNoHoles) {
  // Close to the droplets: their silhouettes span many pixels of rays that graze them.
  compare(trail_frame(1.0, {"eye=-0.02,0.12,0.3", "target=-0.02,0.12,0.1", "vfov=20"}), 128, 96,
          "close-up");
}

TEST(Droplets, ExponentialKernelToo) {
  FrameState f = trail_frame(1.0);
  f.droplets.front().field.kernel = BlendKernel::Exponential;
  compare(f, 96, 72, "exponential");
}

}  // namespace
}  // namespace draught::test
