// Condensation on the GPU (lib/vessel/condensation.glsl, gpu/condensation_textures):
// - probes: the Condensation debug view (the bead's cap normal and the fog's cover at the
//   first surface) pixel by pixel against core's twin (core/condensation/wall_grid
//   bead_at, fog_at) at the reference intersector's hit for the same camera ray: a cold
//   pint straight on, the same closer (beads several pixels wide, grazing rays at its
//   sides), a tilted glass and a flight. Tolerances: whether a pixel is on a bead agrees
//   but next to a bead's edge; normals within 0.5 degrees on 99 % of bead pixels and 1
//   everywhere; fog within 3 / 255.
// - the picture: a cold pint differs from the dry one only on its glass, and a still
//   frame uploads nothing.
#include "core/condensation/wall_grid.hpp"
#include "core/scene/camera.hpp"
#include "core/sim/scene_simulation.hpp"
#include "gpu/condensation_textures.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

struct CondensationProbeCase {
  const char* name;
  FrameState (*frame)();
  int size;
};

const std::vector<std::string> kCold = {"condensation.enabled=true", "condensation.hand=true", "condensation.hand_angle=150"};

FrameState cold_pint() { return scene_frame({"lager", "pint", kCold, {}}); }
FrameState cold_pint_close() {
  return scene_frame({"lager", "pint", kCold, {"eye=0.02,0.07,0.13", "target=0,0.06,0", "vfov=24"}});
}
FrameState cold_pint_tilted() {
  return draught::timeline_frame(load_timeline("gentle-tilt"), resolve_scene({"lager", "pint", kCold, {}}), 1.9);
}
FrameState cold_flight() {
  Scene s = flight_scene(FlightView::AtAnAngle);
  for (SceneObject& o : s.objects)
    if (VesselObject* v = as_vessel(o)) v->params.condensation.enabled = true;
  return make_frame(s);
}

void PrintTo(const CondensationProbeCase& c, std::ostream* os) { *os << c.name; }

class CondensationProbe : public ::testing::TestWithParam<CondensationProbeCase> {};

TEST_P(CondensationProbe, MatchesTheReference) {
  const CondensationProbeCase& c = GetParam();
  const FrameState f = on_checker_floor(c.frame());
  const int n = c.size;
  const CameraBasis cam = camera_basis(f, n, n);
  const SceneGeometry geo = scene_geometry(f, false);
  // Core's grids of every vessel, as the textures hold them.
  std::vector<std::vector<glm::vec4>> grids(f.vessels.size());
  std::vector<std::vector<std::uint8_t>> fogs(f.vessels.size());
  for (size_t i = 0; i < f.vessels.size(); ++i)
    if (gpu::condensation_band(f, int(i)) >= 0) {
      grids[i] = bead_grid(*f.vessels[i].condensation, f.vessels[i].vessel);
      fogs[i] = fog_texels(*f.vessels[i].condensation);
    }
  struct Ref {
    bool on_wall = false;
    BeadSample bead;
    float fog = 0;
  };
  std::vector<Ref> ref(size_t(n) * size_t(n));
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Ray ray = camera_ray(cam, x + 0.5, y + 0.5, n, n);
      const Hit h = first_hit(geo, ray, 0.0);
      if (h.m != Material::GlassOuter || h.object < 0 || grids[size_t(h.object)].empty()) continue;
      const VesselFrame& v = f.vessels[size_t(h.object)];
      const glm::dmat3 to_local = glm::inverse(glm::dmat3(v.pose.orientation));
      const glm::vec3 p(to_local * (ray.at(h.t) - v.pose.position));
      glm::vec3 nl(to_local * h.n);
      if (nl.x * p.x + nl.z * p.z < 0) nl = -nl;
      Ref& r = ref[size_t(y) * size_t(n) + size_t(x)];
      r.on_wall = true;
      r.bead = bead_at(grids[size_t(h.object)], v.condensation->band, v.condensation->contact_angle, p, nl);
      r.fog = fog_at(fogs[size_t(h.object)], v.condensation->band, p) * r.bead.clear;
    }
  const gpu::DebugImage img = gpu_instance().renderer->render_debug(f, n, n, gpu::DebugView::Condensation);
  auto at = [&](int x, int y) { return size_t(y) * size_t(n) + size_t(x); };
  auto on_edge = [&](int x, int y) {  // next to a change of bead or surface in the reference
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Ref& o = ref[at(std::clamp(x + dx, 0, n - 1), std::clamp(y + dy, 0, n - 1))];
        const Ref& r = ref[at(x, y)];
        if (o.on_wall != r.on_wall || o.bead.found != r.bead.found) return true;
      }
    return false;
  };
  int walls = 0, beads = 0, bent = 0, presence = 0, fog_far = 0, fogged = 0;
  double worst_angle = 0, worst_fog = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float* g = img.px(x, y);
      const Ref& r = ref[at(x, y)];
      if ((g[3] >= 0) != r.on_wall) continue;  // another surface first: the hit probes' business
      if (!r.on_wall) continue;
      ++walls;
      const bool gpu_bead = g[0] * g[0] + g[1] * g[1] + g[2] * g[2] > 0.25f;
      if (gpu_bead != r.bead.found) {
        presence += !on_edge(x, y);
        continue;
      }
      if (r.bead.found) {
        ++beads;
        const double cosine = std::clamp(double(glm::dot(glm::normalize(glm::vec3(g[0], g[1], g[2])), r.bead.normal)), -1.0, 1.0);
        const double angle = std::acos(cosine) * 180 / 3.14159265358979;
        worst_angle = std::max(worst_angle, angle);
        bent += angle > 0.5;
      } else {
        fogged += r.fog > 0.05f;
        const double e = std::fabs(double(g[3]) - r.fog);
        if (!on_edge(x, y)) worst_fog = std::max(worst_fog, e);
        fog_far += e > 3.0 / 255 && !on_edge(x, y);
        if (std::getenv("DRAUGHT_PROBE_DUMP") && e > 0.1 && (x + y) % 17 == 0) std::printf("  (%d,%d) gpu %g %g %g %g ref fog %g\n", x, y, g[0], g[1], g[2], g[3], r.fog);
      }
    }
  std::printf("[%s] %dx%d: %d wall pixels, %d on beads (worst normal %.3f deg, %d over 0.5), %d fogged (worst fog %.4f, %d over 3/255), %d disagree on a bead\n",
              c.name, n, n, walls, beads, worst_angle, bent, fogged, worst_fog, fog_far, presence);
  EXPECT_GT(walls, n * n / 20) << "the view should see the outer wall";
  EXPECT_GT(beads, walls / 50) << "the view should see beads";
  EXPECT_GT(fogged, walls / 30) << "the view should see fog";
  // Near a cap's edge its normal turns fast (the cap meets the wall at the contact angle),
  // so float rounding of the hit point shows there.
  EXPECT_LE(bent, beads / 100) << "normals over 0.5 degrees apart";
  EXPECT_LT(worst_angle, 1.0);
  EXPECT_LE(fog_far, walls / 200);
  EXPECT_LE(presence, walls / 200) << "the GPU and core disagree on where the beads are";
}

INSTANTIATE_TEST_SUITE_P(Scenes, CondensationProbe,
                         ::testing::Values(CondensationProbeCase{"pint", cold_pint, 128},
                                           CondensationProbeCase{"pint_close", cold_pint_close, 128},
                                           CondensationProbeCase{"pint_tilted", cold_pint_tilted, 128},
                                           CondensationProbeCase{"flight", cold_flight, 160}),
                         [](const auto& info) { return std::string(info.param.name); });


// The cold pint differs from the dry one where the glass is (beads, fog), not around it;
// and with no beads and no fog (count 0, coverage 0) it is the dry pint.
TEST(CondensationPicture, ChangesTheGlassOnly) {
  Gpu& g = gpu_instance();
  const int n = 96;
  const FrameState dry = scene_frame({"lager", "pint", {}, {}});
  const FrameState cold = scene_frame({"lager", "pint", {"condensation.enabled=true"}, {}});
  const FrameState bare = scene_frame({"lager", "pint", {"condensation.enabled=true", "condensation.count=0",
                                                          "condensation.coverage=0"}, {}});
  const Image a = g.renderer->render(dry, n, n), b = g.renderer->render(cold, n, n), c = g.renderer->render(bare, n, n);
  const gpu::DebugImage m = g.renderer->render_debug(dry, n, n, gpu::DebugView::Material);
  auto glass_near = [&](int x, int y) {  // a glass surface within two pixels
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int mat = int(std::lround(m.px(std::clamp(x + dx, 0, n - 1), std::clamp(y + dy, 0, n - 1))[1]));
        if (mat != int(Material::None) && mat != int(Material::Floor)) return true;
      }
    return false;
  };
  int on_glass = 0, elsewhere = 0, bare_worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      int d = 0;
      for (int k = 0; k < 3; ++k) {
        const size_t i = (size_t(y) * size_t(n) + size_t(x)) * 4 + size_t(k);
        d = std::max(d, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
        bare_worst = std::max(bare_worst, std::abs(int(a.rgba[i]) - int(c.rgba[i])));
      }
      if (d > 2) ++(glass_near(x, y) ? on_glass : elsewhere);
    }
  std::printf("cold vs dry: %d pixels changed on the glass, %d elsewhere; bare vs dry worst %d\n", on_glass, elsewhere, bare_worst);
  EXPECT_GT(on_glass, n * n / 20);
  EXPECT_EQ(elsewhere, 0);
  EXPECT_LE(bare_worst, 1);
}

TEST(CondensationTextures, AStillFrameUploadsNothing) {
  Gpu& g = gpu_instance();
  const FrameState f = cold_pint();
  g.renderer->render(f, 32, 32);
  g.renderer->render(f, 32, 32);
  EXPECT_EQ(g.renderer->condensation_textures().bands_uploaded(), 0);
  // The beads moving on: the band again.
  SceneSimulation sim(resolve_scene_objects({"lager", "pint", kCold, {}}));
  sim.step(MotionSample{});
  sim.step(MotionSample{});
  g.renderer->render(sim.frame(), 32, 32);
  EXPECT_EQ(g.renderer->condensation_textures().bands_uploaded(), 1);
  g.renderer->render(sim.frame(), 32, 32);  // (the same state: the frame's snapshot is shared)
  EXPECT_EQ(g.renderer->condensation_textures().bands_uploaded(), 0);
}

}  // namespace
}  // namespace draught::test
