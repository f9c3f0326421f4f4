// Decals on the GPU (lib/vessel/decal.glsl, gpu/decal_textures):
// - probes: the Decal debug view's (u, v) and layer of the first surface, pixel by pixel,
//   against the reference intersector's (core/reference decal_hit) for the same camera
//   rays: the outer and the inner wall, a curved bowl, copies and bands, a cut glass, a
//   glass in motion and a flight of glasses. Tolerances: where both see the same surface
//   and a decal, (u, v) agree within 0.1 mm on the wall (u times the decal's width, v
//   times its extent) on 99.5 % of pixels and within 1 mm everywhere; whether a pixel
//   shows a decal agrees except next to a decal's edge in the reference (0.2 % of pixels).
// - a furnace: white decals of every kind are invisible in a uniform environment, and a
//   coloured one shows its colour under the glass's gloss as in the reference;
// - a decal of opacity 0 leaves the picture as it was; a still frame uploads nothing.
#include "color_difference.hpp"
#include "core/scene/camera.hpp"
#include "gpu/decal_textures.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace draught::test {
namespace {

DecalParams layer(const char* file, float angle, float height, float width, int repeat = 1) {
  DecalParams d;
  d.file = file;
  d.angle = angle;
  d.height = height;
  d.width = width;
  d.repeat = repeat;
  return d;
}

// Every vessel of the frame gets these layers (the frame's own copy: both the GPU and the
// reference read the decals from the frame's parameters).
FrameState with_decals(FrameState f, const DecalParams& outer, const DecalParams& inner = {}) {
  for (VesselFrame& v : f.vessels) {
    v.params.decal_outer = outer;
    v.params.decal_inner = inner;
  }
  return f;
}

struct DecalProbeCase {
  const char* name;
  FrameState (*frame)();
  int size;
};

FrameState decal_pint_front_frame() {
  return with_decals(scene_frame({"lager", "pint", {}, {}}), layer("wordmark", 0, 0.075f, 0.07f));
}
FrameState tulip_crest() {
  return with_decals(scene_frame({"amber-ale", "tulip", {}, {"eye=0,0.12,0.25", "target=0,0.1,0", "vfov=24"}}),
                     layer("crest", 20, 0.1f, 0.045f));
}
FrameState wine_band() {  // two copies joined into a band round the bowl, seen from above the rim
  return with_decals(scene_frame({"red-wine", "wine", {}, {"eye=0.05,0.3,0.25", "target=0,0.13,0"}}),
                     layer("gold-band", 0, 0.15f, 0.0f, 2));
}
FrameState empty_tulip_inner() {  // the inner wall is the first surface through the mouth
  return with_decals(scene_frame({"amber-ale", "tulip", {"liquid.fill=0"}, {"eye=0.03,0.4,0.12", "target=0,0.05,0"}}),
                     {}, layer("crest", 180, 0.12f, 0.05f));
}
FrameState pint_cut() {  // the front half of the empty glass cut away: the inner decal at the back seen directly
  return with_decals(scene_frame({"lager", "pint", {"clip.enabled=true", "clip.normal=0,0,1", "liquid.fill=0"}, {}}),
                     layer("wordmark", 0, 0.075f, 0.07f), layer("crest", 180, 0.09f, 0.05f));
}
FrameState pint_tilted() { return with_decals(timeline_frame("gentle-tilt", 1.9), layer("wordmark", 30, 0.08f, 0.06f, 3)); }
FrameState flight() {
  return with_decals(make_frame(flight_scene(FlightView::AtAnAngle)), layer("crest", 35, 0.09f, 0.04f, 2));
}

void PrintTo(const DecalProbeCase& c, std::ostream* os) { *os << c.name; }

class DecalProbe : public ::testing::TestWithParam<DecalProbeCase> {};

TEST_P(DecalProbe, UvMatchesTheReference) {
  const DecalProbeCase& c = GetParam();
  const FrameState f = on_checker_floor(c.frame());
  const int n = c.size;
  const CameraBasis cam = camera_basis(f, n, n);
  const SceneGeometry geo = scene_geometry(f, true);
  std::vector<Hit> hits;
  std::vector<DecalHit> ref;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Ray ray = camera_ray(cam, x + 0.5, y + 0.5, n, n);
      const Hit h = first_hit(geo, ray, 0.0);
      hits.push_back(h);
      ref.push_back(h.object >= 0 ? decal_hit(geo.vessels[size_t(h.object)], h, ray) : DecalHit{});
    }
  const gpu::DebugImage img = gpu_instance().renderer->render_debug(f, n, n, gpu::DebugView::Decal);
  auto at = [&](int x, int y) { return size_t(y) * size_t(n) + size_t(x); };
  // Next to a change of surface or of decal in the reference (within a pixel).
  auto on_edge = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int xx = std::clamp(x + dx, 0, n - 1), yy = std::clamp(y + dy, 0, n - 1);
        if (ref[at(xx, yy)].layer != ref[at(x, y)].layer || hits[at(xx, yy)].m != hits[at(x, y)].m ||
            hits[at(xx, yy)].object != hits[at(x, y)].object)
          return true;
      }
    return false;
  };
  int compared = 0, far = 0, presence = 0;
  double worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float* g = img.px(x, y);
      const Hit& h = hits[at(x, y)];
      const DecalHit& r = ref[at(x, y)];
      if (int(std::lround(g[3])) != int(h.m)) continue;  // another surface: the probes' business
      const int glayer = int(std::lround(g[2]));
      if (glayer != r.layer) {
        presence += !on_edge(x, y);
        continue;
      }
      if (r.layer < 0) continue;
      const DecalPlacement& d = geo.vessels[size_t(h.object)].decals->layers[size_t(r.layer)];
      const double width = d.width > 0 ? d.width : d.span;  // a band: about its width at the centre
      const double err = std::max(std::fabs(g[0] - r.uv.x) * width, std::fabs(g[1] - r.uv.y) * d.extent);
      // u wraps round a band: 0 and 1 are the same place.
      const double wrapped = d.width > 0 ? err : std::max(std::min(std::fabs(g[0] - r.uv.x), 1 - std::fabs(g[0] - r.uv.x)) * width,
                                                             std::fabs(g[1] - r.uv.y) * d.extent);
      worst = std::max(worst, wrapped);
      far += wrapped > 1e-4;
      ++compared;
    }
  std::printf("[%s] %dx%d: %d pixels on a decal compared, worst %.3f mm, %d over 0.1 mm, %d disagree on a decal\n",
              c.name, n, n, compared, worst * 1e3, far, presence);
  EXPECT_GT(compared, n * n / 50) << "the view should see the decal";
  EXPECT_LE(far, compared / 200) << "(u, v) off by more than 0.1 mm on the wall";
  EXPECT_LT(worst, 1e-3) << "(u, v) off by 1 mm or more";
  EXPECT_LE(presence, n * n / 500) << "the GPU and the reference disagree on where the decal is";
}

INSTANTIATE_TEST_SUITE_P(Scenes, DecalProbe,
                         ::testing::Values(DecalProbeCase{"pint_front", decal_pint_front_frame, 96},
                                           DecalProbeCase{"tulip_crest", tulip_crest, 96},
                                           DecalProbeCase{"wine_band", wine_band, 96},
                                           DecalProbeCase{"empty_tulip_inner", empty_tulip_inner, 96},
                                           DecalProbeCase{"pint_cut", pint_cut, 96},
                                           DecalProbeCase{"pint_tilted", pint_tilted, 96},
                                           DecalProbeCase{"flight", flight, 128}),
                         [](const auto& info) { return std::string(info.param.name); });

// ---- light ----

constexpr glm::vec3 kDecalEnv{0.5f, 0.4f, 0.3f};

// The empty pint in a uniform environment with no floor and no lights, nothing absorbing
// (tests/gpu/test_furnace.cpp), a band of the shipped gold-band decal (white, its middle
// opaque) round it at 7 cm.
FrameState decal_furnace(DecalKind kind, glm::vec3 colour, std::vector<std::string> camera) {
  SceneRequest req{"lager", "pint"};
  req.sets = {"env.mode=constant", "env.floor=false", "env.color=0.5,0.4,0.3", "light.power=0", "strips.power=0",
              "backlight.power=0", "render.tonemap=none", "render.exposure=1", "glass.absorption=0,0,0",
              "liquid.fill=0", "bubbles.carbonation=0", "render.max_events=24"};
  if (!camera.empty()) req.sets.push_back("camera.auto_frame=false");
  req.camera = std::move(camera);
  DecalParams d = layer("gold-band", 0, 0.07f, 0.0f);
  d.kind = int(kind);
  d.color = colour;
  return with_decals(scene_frame(req), d);
}

TEST(DecalLight, AWhiteDecalOfAnyKindIsInvisibleInAFurnace) {
  for (DecalKind kind : {DecalKind::Enamel, DecalKind::Etched, DecalKind::Metallic}) {
    const Image img = gpu_instance().renderer->render(decal_furnace(kind, glm::vec3(1), {}), 64, 64);
    double worst = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(srgb8_to_linear(img.px(x, y)[c]) / kDecalEnv[c] - 1.0));
    EXPECT_LT(worst, 0.02) << "kind " << int(kind);
  }
}

TEST(DecalLight, AColouredDecalShowsItsColourUnderTheGlassGloss) {
  // As the reference (tests/unit/reference/test_path_tracer.cpp): F of the environment,
  // and of the rest the paint's albedo or the metal's reflectance; the camera sees only
  // the band's opaque middle (4 mm of it), straight on.
  const double F = std::pow((1.52 - 1.0) / (1.52 + 1.0), 2);
  const glm::vec3 colour{0.8f, 0.5f, 0.2f};
  const std::vector<std::string> camera{"eye=0,0.07,0.08", "target=0,0.07,0", "vfov=5"};
  for (DecalKind kind : {DecalKind::Enamel, DecalKind::Metallic}) {
    FrameState f = decal_furnace(kind, colour, camera);
    f.params.render.supersample = 1;
    const Image img = gpu_instance().renderer->render(f, 8, 8);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(srgb8_to_linear(img.px(4, 4)[c]) / kDecalEnv[c], F + (1 - F) * colour[c], 0.02) << int(kind) << " channel " << c;
  }
}

TEST(DecalLight, ADecalOfOpacityZeroChangesNothing) {
  // The same scene without a decal and with one that is not there (the picture compiled
  // with decals, every lookup giving cover 0): the same picture.
  Gpu& g = gpu_instance();
  const FrameState plain = scene_frame({"lager", "pint", {}, {}});
  DecalParams none = layer("wordmark", 0, 0.075f, 0.07f);
  none.opacity = 0;
  const Image a = g.renderer->render(plain, 96, 96);
  const Image b = g.renderer->render(with_decals(plain, none, none), 96, 96);
  int worst = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  EXPECT_LE(worst, 1);
  // ...and one that is there changes it (this test can fail).
  const Image c = g.renderer->render(with_decals(plain, layer("wordmark", 0, 0.075f, 0.07f)), 96, 96);
  int changed = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) changed += std::abs(int(a.rgba[i + 2]) - int(c.rgba[i + 2])) > 8;  // blue: white paint on a yellow drink
  EXPECT_GT(changed, 100);
}

TEST(DecalTextures, AStillFrameUploadsNothing) {
  Gpu& g = gpu_instance();
  const FrameState f = pint_cut();
  g.renderer->render(f, 32, 32);
  g.renderer->render(f, 32, 32);
  EXPECT_EQ(g.renderer->decal_textures().images_uploaded(), 0);
  EXPECT_EQ(g.renderer->decal_textures().arc_rows_uploaded(), 0);
  // Another image: the array is built again, with both.
  FrameState other = f;
  other.vessels[0].params.decal_inner.file = "gold-band";
  g.renderer->render(other, 32, 32);
  EXPECT_EQ(g.renderer->decal_textures().images_uploaded(), 2);
  EXPECT_EQ(gpu::decal_image_names(other), (std::vector<std::string>{"wordmark", "gold-band"}));
}

TEST(DecalTextures, LayersShrinkForManyImages) {
  EXPECT_EQ(gpu::decal_layer_size(1, 1024), 1024);
  EXPECT_EQ(gpu::decal_layer_size(3, 300), 512);
  EXPECT_EQ(gpu::decal_layer_size(2, 4096), 1024);
  EXPECT_EQ(gpu::decal_layer_size(40, 4096), 512);
  EXPECT_EQ(gpu::decal_layer_size(100, 4096), 256);
  EXPECT_EQ(gpu::decal_layer_size(1, 10), 64);
}

}  // namespace
}  // namespace draught::test
