// Scenes of several objects on the GPU: the C++/GLSL contract (the medium rule's twins,
// the uniform block checked member by member), refracted paths through two glasses
// against a double-precision CPU trace, a scene at the object limit, data textures that
// upload only what changed, and the variants: records held per pixel, the background pass
// around the runs where the objects can show (and those runs, for both tiers).
#include "core/scene/camera.hpp"
#include "gpu/program.hpp"
#include "gpu/scene_data.hpp"
#include "gpu_fixture.hpp"
#include "reference_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>

namespace draught::test {
namespace {

// The medium rule exists once per language: core/reference/media.hpp medium_across and
// its GLSL twin in shaders/lib/vessel/media.glsl. The MediumRule view evaluates the
// GLSL one for every (material, medium, below) at pixel (material, medium + 3 below).
TEST(Contract, MediumRuleTwinsAgreeOnEveryInput) {
  Gpu& g = gpu_instance();
  const FrameState f = scene_frame({"lager", "pint", {}, {}});
  const int materials = int(Material::ClipLiquid) + 1;
  const gpu::DebugImage img = g.renderer->render_debug(f, materials, 6, gpu::DebugView::MediumRule);
  int checked = 0;
  for (int m = 0; m < materials; ++m)
    for (int from = 0; from < 3; ++from)
      for (int below = 0; below < 2; ++below) {
        const int gl_row = from + 3 * below;  // gl_FragCoord.y counts from the bottom
        const float* px = img.px(m, img.height - 1 - gl_row);
        const MediumKind cpu = medium_across(Material(m), MediumKind(from), below != 0);
        EXPECT_EQ(int(std::lround(px[0])), int(cpu)) << material_name(Material(m)) << " from medium " << from
                                                     << (below ? " below" : " above") << " the liquid";
        ++checked;
      }
  EXPECT_EQ(checked, materials * 6);
}

// The renderer checks every member of the Frame block against the driver's offsets. A
// block whose members are in another order than the C++ struct's is refused, naming
// the first member that moved.
TEST(Contract, UniformBlockMismatchNamesTheMember) {
  Gpu& g = gpu_instance();
  (void)g;
  gpu::ShaderSource frag = gpu::assemble_shader("generated/frame.glsl");
  const std::string a = "  vec3 cam_eye;", b = "  float cam_tan_half_vfov;";
  const size_t pa = frag.text.find(a), pb = frag.text.find(b);
  ASSERT_NE(pa, std::string::npos);
  ASSERT_NE(pb, std::string::npos);
  // Swap the first two members: float then vec3 moves cam_eye from byte 0 to byte 16.
  const std::string line_a = frag.text.substr(pa, frag.text.find('\n', pa) - pa);
  const std::string line_b = frag.text.substr(pb, frag.text.find('\n', pb) - pb);
  std::string swapped = frag.text;
  swapped.replace(pb, line_b.size(), line_a);
  swapped.replace(pa, line_a.size(), line_b);
  frag.text = "#version 300 es\n" + swapped +
              "out vec4 c;\nvoid main() { c = vec4(frame.cam_eye, frame.cam_tan_half_vfov); }\n";
  gpu::ShaderSource vert{"#version 300 es\nvoid main() { gl_Position = vec4(0.0); }\n", {"test.vert"}};
  gpu::Program program(vert, frag);
  try {
    gpu::check_uniform_block(program.id(), contract::kFrameBlockName, contract::kFrameBlockMembers,
                             contract::kFrameBlockUsedBytes, sizeof(contract::FrameBlock), contract::kFrameBlockBinding,
                             "test.frag");
    ADD_FAILURE() << "a block with moved members was accepted";
  } catch (const gpu::ShaderError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Frame.cam_eye"), std::string::npos) << what;
    EXPECT_NE(what.find("byte 16"), std::string::npos) << what;
    std::printf("refused as expected: %s\n", what.c_str());
  }
}

// Events of refracted paths through the flight seen along its row: the GPU's PathEvent
// view against the CPU trace. Float on the GPU, double on the CPU: a path may fork where
// an event grazes an edge, so an event is compared only where every earlier event
// agrees, and materials may differ on a small share of those pixels (1 %, the pixels
// whose path grazes an edge somewhere). Distances agree to max(0.1 mm, 1e-3 t).
TEST(Contract, ClearedDropletMembersAreTheBlockOfTheFrameWithout) {
  // The MatCap background's key (gpu/renderer) is the block with pack_droplets({}): it
  // must be, byte for byte, the block of the same frame with no droplets.
  SceneRequest req;
  req.preset = "droplets";
  const FrameState with = make_frame(resolve_scene_objects(req));
  ASSERT_FALSE(with.droplets.empty());
  FrameState without = with;
  without.droplets.clear();
  contract::FrameBlock cleared = gpu::pack_frame_block(with, 64, 48, gpu::DebugView::None);
  const contract::FrameBlock none = gpu::pack_frame_block(without, 64, 48, gpu::DebugView::None);
  EXPECT_GT(cleared.droplet_count, 0);
  EXPECT_NE(std::memcmp(&cleared, &none, sizeof cleared), 0);
  gpu::pack_droplets({}, cleared);
  EXPECT_EQ(std::memcmp(&cleared, &none, sizeof cleared), 0);
}

TEST(Flight, RefractedPathsThroughTwoGlassesMatchTheCpuTrace) {
  Gpu& g = gpu_instance();
  const FrameState f = on_checker_floor(make_frame(flight_scene(FlightView::AlongTheRow)));
  const int w = 96, h = 72, events = 6;
  const SceneGeometry geo = scene_geometry(f);
  const std::vector<std::vector<PathEvent>> cpu = reference_paths(f, geo, w, h);
  std::vector<bool> alive(size_t(w * h), true);  // all earlier events agree
  int through_two = 0;  // pixels whose agreeing path met two glasses
  std::vector<std::set<int>> met(size_t(w * h));
  for (int e = 0; e < events; ++e) {
    const gpu::DebugImage gpu = g.renderer->render_debug(f, w, h, gpu::DebugView::PathEvent, e);
    int compared = 0, material_bad = 0, distance_bad = 0;
    double worst = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y * w + x);
        if (!alive[i] || int(cpu[i].size()) <= e) continue;
        const PathEvent& c = cpu[i][size_t(e)];
        const float* px = gpu.px(x, y);
        ++compared;
        if (!same_event(px, c)) {
          ++material_bad;
          alive[i] = false;
          continue;
        }
        if (c.m == Material::None) continue;
        const double dt = std::fabs(double(px[0]) - c.t);
        worst = std::max(worst, dt);
        if (dt > std::max(1e-4, 1e-3 * c.t)) ++distance_bad;
        if (c.object >= 0) met[i].insert(c.object);
      }
    std::printf("[flight-along-the-row event %d] %d paths compared, %d differ in material/object/medium, %d in distance; worst "
                "|dt| %.2e m\n",
                e, compared, material_bad, distance_bad, worst);
    EXPECT_LE(material_bad, std::max(2, compared / 100)) << "event " << e;
    EXPECT_LE(distance_bad, std::max(1, compared / 200)) << "event " << e;
  }
  for (const auto& s : met) through_two += s.size() >= 2;
  std::printf("[flight-along-the-row] %d pixels' paths meet two glasses or more, every event agreeing\n", through_two);
  EXPECT_GT(through_two, w * h / 50) << "the view should see glasses through each other";
}

// A scene at the object limit: kMaxSceneObjects glasses in a grid. It renders, every
// pixel finite, and every glass is seen (it is the first surface of some pixel).
TEST(Limits, SceneAtTheObjectLimitRendersEveryGlass) {
  Gpu& g = gpu_instance();
  const int side = 8;
  static_assert(kMaxSceneObjects == 64, "the grid below holds 8 x 8 glasses");
  Params p = resolve_scene({"lager", "pint", {"bubbles.max_bubbles=0", "render.supersample=1"}, {"eye=0.9,1.1,1.4"}});
  Scene s;
  s.params = p;
  for (int i = 0; i < kMaxSceneObjects; ++i)
    s.objects.push_back(SceneObject{"glass" + std::to_string(i),
                                    Placement{{0.12f * float(i % side - 3.5f), 0.0f, 0.12f * float(i / side - 3.5f)}, 0.0f},
                                    VesselObject{p}});
  const FrameState f = make_frame(s);
  ASSERT_EQ(int(f.vessels.size()), kMaxSceneObjects);
  const int w = 192, h = 144;
  const gpu::DebugImage depth = g.renderer->render_debug(f, w, h, gpu::DebugView::Depth);
  std::set<int> seen;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(depth.px(x, y)[c])) << x << "," << y;
      if (depth.px(x, y)[2] >= 0) seen.insert(int(std::lround(depth.px(x, y)[2])));
    }
  EXPECT_EQ(int(seen.size()), kMaxSceneObjects) << "some glass is not the first surface of any pixel";
  const Image img = g.renderer->render(f, w, h);
  long black = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) black += img.rgba[i] == 0 && img.rgba[i + 1] == 0 && img.rgba[i + 2] == 0;
  EXPECT_EQ(black, 0) << "black (NaN) pixels";
  std::filesystem::create_directories(DRAUGHT_DIFF_DIR);  // a fresh build has none yet
  write_png(std::filesystem::path(DRAUGHT_DIFF_DIR) / "limit_64_glasses.png", img);
  std::printf("%d of %d glasses seen; picture in %s\n", int(seen.size()), kMaxSceneObjects, DRAUGHT_DIFF_DIR);
}

TEST(Limits, MoreObjectsThanTheLimitAreAClearError) {
  Gpu& g = gpu_instance();
  FrameState f = scene_frame({"lager", "pint", {}, {}});
  f.vessels.resize(size_t(kMaxSceneObjects + 1), f.vessels.front());
  try {
    g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(kMaxSceneObjects)), std::string::npos) << e.what();
  }
}

// The data textures: a frame like the last uploads nothing; a drink that changes
// uploads its object's row; knots only when a glass changes.
TEST(SceneData, UploadsOnlyWhatChanged) {
  Gpu& g = gpu_instance();
  Scene s = flight_scene();
  FrameState f = make_frame(s);
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  EXPECT_EQ(g.renderer->scene_textures().object_rows_uploaded(), 0);
  EXPECT_EQ(g.renderer->scene_textures().knot_rows_uploaded(), 0);
  EXPECT_FALSE(g.renderer->scene_textures().floor_light_computed()) << "an unchanged frame traced the floor's light again";
  f.vessels[2].liquid.offset -= 0.01;  // the stout drunk a little
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  EXPECT_EQ(g.renderer->scene_textures().object_rows_uploaded(), 1);
  EXPECT_EQ(g.renderer->scene_textures().knot_rows_uploaded(), 0);
  EXPECT_TRUE(g.renderer->scene_textures().floor_light_computed()) << "the drink's surface moved: its caustic moves";
  f.vessels[1].vessel = f.vessels[0].vessel;  // another glass for the amber ale
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  EXPECT_EQ(g.renderer->scene_textures().knot_rows_uploaded(), 1);
}

// An interactive app's floor light for one test: drafts of `draft` photons while the scene
// moves, a still's map refined in batches of `batch` photons within `ms` a frame (0, 0:
// the draft's, one a frame). The GPU tests' own (test_floor_light, no drafts) comes back
// when the test ends, however it ends. Setting it empties the cache: the next frame drafts.
struct AppFloorLight {
  gpu::Renderer& renderer;
  AppFloorLight(gpu::Renderer& r, const FloorLightSettings& s, int draft, int batch = 0, double ms = 0) : renderer(r) {
    set(s, draft, batch, ms);
  }
  void set(const FloorLightSettings& s, int draft, int batch = 0, double ms = 0) {
    renderer.set_floor_light(s, true, draft);
    renderer.set_floor_refinement(batch, ms);
  }
  ~AppFloorLight() {
    renderer.set_floor_refinement(0, 0);
    renderer.set_floor_light(test_floor_light());
  }
};

// An interactive app's floor light: a draft (few photons, texels twice as wide) every other
// frame while the scene moves; once it holds still, the full map in batches of the draft's
// photons, one a frame (two the first), ending at the full budget with the map one trace
// in as many batches gives; then nothing more.
TEST(SceneData, TheFloorLightIsRefinedInBatchesOnceStill) {
  Gpu& g = gpu_instance();
  FloorLightSettings s = test_floor_light();
  s.photons = 20000;
  const AppFloorLight app(*g.renderer, s, 5000);
  FrameState f = scene_frame({"lager", "pint", {}, {}});
  const gpu::SceneTextures& t = g.renderer->scene_textures();
  std::vector<bool> moving;
  for (int frame = 0; frame < 4; ++frame) {
    f.vessels[0].pose.position.x = 0.002 * frame;
    g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
    moving.push_back(t.floor_light_computed());
  }
  EXPECT_EQ(moving, (std::vector<bool>{true, false, true, false}));
  std::vector<int> photons, widths;
  for (int frame = 0; frame < 6; ++frame) {
    g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
    photons.push_back(t.floor_light_computed() ? t.floor_light().stats.photons : 0);
    widths.push_back(t.floor_light().width);
  }
  EXPECT_EQ(photons, (std::vector<int>{photons[0], 10000, 15000, 20000, 0, 0}));
  EXPECT_NEAR(photons[0], 5000, 100);  // the draft
  EXPECT_LT(widths[0], widths[1]);     // on wider texels
  FloorLightSettings batch = s;
  batch.photons = 5000;
  FloorLightTrace trace(f, batch);
  for (int b = 0; b < 4; ++b) trace.add_batch();
  EXPECT_EQ(widths[5], trace.map().width);
  EXPECT_EQ(t.floor_light().change, trace.map().change);
  EXPECT_EQ(t.floor_light().surround_factor, trace.map().surround_factor);  // (its rays spread over the batches)
}

// Batches smaller than the draft's (the web page's): two drafts' worth the first frame it
// holds still, then one a frame without a time budget, ending at the full budget with the
// map one trace in as many batches gives; with a budget no frame uses up, all of it the
// first frame still.
TEST(SceneData, TheFloorLightRefinesInSmallerBatchesWithinATimeBudget) {
  Gpu& g = gpu_instance();
  FloorLightSettings s = test_floor_light();
  s.photons = 20000;
  FrameState f = scene_frame({"lager", "pint", {}, {}});
  const gpu::SceneTextures& t = g.renderer->scene_textures();
  AppFloorLight app(*g.renderer, s, 5000);
  auto still_frames = [&](double ms_per_frame) {
    app.set(s, 5000, 2500, ms_per_frame);  // (an empty cache: the first frame drafts)
    g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
    EXPECT_NEAR(t.floor_light().stats.photons, 5000, 100);  // the draft
    std::vector<int> photons;
    for (int frame = 0; frame < 6; ++frame) {
      g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
      photons.push_back(t.floor_light_computed() ? t.floor_light().stats.photons : 0);
    }
    return photons;
  };
  EXPECT_EQ(still_frames(0), (std::vector<int>{10000, 12500, 15000, 17500, 20000, 0}));
  FloorLightSettings batch = s;
  batch.photons = 2500;
  FloorLightTrace trace(f, batch);
  for (int b = 0; b < 8; ++b) trace.add_batch();
  EXPECT_EQ(t.floor_light().change, trace.map().change);
  EXPECT_EQ(t.floor_light().surround_factor, trace.map().surround_factor);
  EXPECT_EQ(still_frames(1e9), (std::vector<int>{20000, 0, 0, 0, 0, 0}));
  EXPECT_EQ(t.floor_light().change, trace.map().change);
}

// Hundreds of small batches: every frame's map (on the CPU) holds every batch so far, but
// the texture takes it only when the batches have grown by an eighth since it last did
// (every batch at first), and when the last is in.
TEST(SceneData, ARefiningFloorLightIsUploadedWhenItHasGrownByAnEighth) {
  Gpu& g = gpu_instance();
  FloorLightSettings s = test_floor_light();
  s.photons = 40000;
  FrameState f = scene_frame({"lager", "pint", {}, {}});
  const gpu::SceneTextures& t = g.renderer->scene_textures();
  const AppFloorLight app(*g.renderer, s, 5000, 1000, 0);  // one batch a frame after the first's ten
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  EXPECT_TRUE(t.floor_light_uploaded());  // the draft
  std::vector<int> uploaded_at;
  for (int frame = 0; frame < 32; ++frame) {
    g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
    const int batches = t.floor_light_computed() ? t.floor_light().stats.photons / 1000 : 0;  // (about 1000 each)
    EXPECT_EQ(batches, frame < 31 ? 10 + frame : 0) << "frame " << frame;
    if (t.floor_light_uploaded()) uploaded_at.push_back(batches);
  }
  EXPECT_EQ(uploaded_at, (std::vector<int>{10, 11, 12, 13, 14, 15, 16, 18, 20, 22, 24, 27, 30, 33, 37, 40}));
}

// render.floor_photons: a scene may give its floor light's budget (an animation rendered
// faster); 0 leaves the app's (here the GPU tests' 50,000); another budget, another map.
TEST(SceneData, TheSceneMayGiveTheFloorLightsBudget) {
  Gpu& g = gpu_instance();
  const gpu::SceneTextures& t = g.renderer->scene_textures();
  FrameState f = scene_frame({"lager", "pint", {"render.floor_photons=3000"}, {}});
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  EXPECT_NEAR(t.floor_light().stats.photons, 3000, 100);
  f.params.render.floor_photons = 0;
  g.renderer->render_debug(f, 8, 8, gpu::DebugView::Depth);
  EXPECT_TRUE(t.floor_light_computed());
  EXPECT_NEAR(t.floor_light().stats.photons, test_floor_light().photons, 500);
}

// The record packed for a glass holds core's numbers: the liquid plane as the
// simulation solved it (the fill table never reaches the GPU) and the big bubbles as
// core/foam placed them.
TEST(SceneData, RecordsCarryCoresPhysics) {
  const FrameState f = make_frame(flight_scene());
  for (int i = 0; i < int(f.vessels.size()); ++i) {
    const VesselFrame& v = f.vessels[size_t(i)];
    const contract::ObjectRecord r = gpu::pack_object(f, i);
    EXPECT_FLOAT_EQ(r.plane_offset, float(v.liquid.offset));
    EXPECT_EQ(int(r.big_bubble_count.value), v.has_liquid && v.foam.thickness > 1e-4 ? int(v.big_bubbles.size()) : 0);
    for (int b = 0; b < int(r.big_bubble_count.value); ++b)
      EXPECT_FLOAT_EQ(r.big_bubbles[b].x, float(v.big_bubbles[size_t(b)].centre.x));
    EXPECT_EQ(int(r.knot_row.value), i);
  }
}

}  // namespace
}  // namespace draught::test

namespace draught::test {
namespace {

// The largest difference of any channel between two pictures of one size, in 8-bit levels.
int worst_level_difference(const Image& a, const Image& b) {
  int worst = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) worst = std::max(worst, std::abs(int(a.rgba[i]) - int(b.rgba[i])));
  return worst;
}

// Each frame drawn at 96 x 96 with one of the renderer's switches on and then off: the
// same picture within one 8-bit level (`what` names the difference when it is not).
void expect_the_same_either_way(const std::vector<FrameState>& frames, void (gpu::Renderer::*set)(bool),
                                const char* what) {
  Gpu& g = gpu_instance();
  for (const FrameState& f : frames) {
    const Image on = g.renderer->render(f, 96, 96);
    (g.renderer.get()->*set)(false);
    const Image off = g.renderer->render(f, 96, 96);
    (g.renderer.get()->*set)(true);
    EXPECT_LE(worst_level_difference(on, off), 1) << what;
  }
}

// Scenes of a few objects are drawn with their records held per pixel; the general path
// (records fetched where used) must give the same picture: one glass with waves, a head
// and a cross-section, and the flight of four.
TEST(Variants, HeldObjectsDrawWhatTheGeneralPathDraws) {
  expect_the_same_either_way({
      scene_frame({"lager", "pint", {"render.supersample=1"}, {}}),
      scene_frame({"stout", "nonic", {"render.supersample=1", "clip.enabled=true"}, {"eye=0,0.2,0.3", "target=0,0.14,0"}}),
      timeline_frame("shake-and-settle", 1.3),
      make_frame(flight_scene(FlightView::AtAnAngle, {"render.supersample=1"})),
  }, &gpu::Renderer::set_held_objects, "the held-objects variant differs from the general path");
}

// Only the runs of the screen where the objects can show run the pass with their code;
// the background pass around them must give what that pass gives a ray that meets
// nothing: a pint (its head within the glass's bounds), the stout cut open close up, a
// glass tipped and spilling, the flight, under an environment image, transparent (the
// alpha too), the droplets' stretched trail (each sphere's own runs), the molten gob and
// the MatCap tier.
TEST(Variants, TheBackgroundPassDrawsWhatTheObjectsPassDraws) {
  expect_the_same_either_way({
      scene_frame({"lager", "pint", {"render.supersample=1"}, {}}),
      scene_frame({"stout", "nonic", {"render.supersample=1", "clip.enabled=true"}, {"eye=0,0.2,0.3", "target=0,0.14,0"}}),
      timeline_frame("tilt-until-spill", 3.0),
      make_frame(flight_scene(FlightView::AtAnAngle, {"render.supersample=1"})),
      scene_frame({"lager", "pint", {"render.supersample=1", "env.mode=image", "env.image=bar"}, {}}),
      scene_frame({"hefeweizen", "weizen", {"render.supersample=1", "render.transparent=true"}, {}}),
      scene_frame({"lager", "pint", {"render.supersample=1", "render.tier=matcap"}, {}}),
      draught::timeline_frame(load_timeline("droplets-trail"), resolve_scene_objects({"droplets", "", {}, {}}), 1.0),
      make_frame(resolve_scene_objects({"molten-gob", "", {"render.supersample=1"}, {}})),
  }, &gpu::Renderer::set_background_pass, "the background pass differs from the objects' pass");
}

// objects_on_screen of the frame's glasses, their records packed as u_objects holds them.
gpu::ScreenParts screen_parts(const FrameState& f, const contract::FrameBlock& block, int width, int height) {
  std::vector<contract::ObjectRecord> records;
  for (int i = 0; i < int(f.vessels.size()); ++i) records.push_back(gpu::pack_object(f, i));
  return gpu::objects_on_screen(records, block, width, height);
}

// The runs of the screen either tier runs its pass in (objects_on_screen; the rest is
// the background alone) hold every pixel whose camera ray meets a glass by the reference
// intersector; with the background's they cover the picture once; for a single pint they
// are well short of the whole picture, and for the flight straight on the gaps between
// the glasses are background.
TEST(ScreenParts, ThePassRunsWhereTheObjectsAre) {
  struct View {
    const char* name;
    FrameState f;
    int w, h;
  };
  auto pixels = [](const std::vector<gpu::PixelRect>& rects) {
    long n = 0;
    for (const gpu::PixelRect& r : rects) n += long(r.w) * r.h;
    return n;
  };
  const FrameState pint = scene_frame({"lager", "pint", {}, {}});
  for (const View& view : {View{"pint", pint, 96, 96},
                           View{"pint from above", scene_frame({"lager", "pint", {}, {"eye=0.08,0.32,0.2", "target=0,0.07,0"}}), 80, 64},
                           View{"flight at an angle", make_frame(flight_scene(FlightView::AtAnAngle)), 120, 90},
                           View{"flight straight on", make_frame(flight_scene()), 160, 60}}) {
    const contract::FrameBlock block = gpu::pack_frame_block(view.f, view.w, view.h, gpu::DebugView::None);
    const gpu::ScreenParts parts = screen_parts(view.f, block, view.w, view.h);
    std::vector<int> in_objects(size_t(view.w) * view.h, 0), in_any(size_t(view.w) * view.h, 0);
    for (const auto* list : {&parts.objects, &parts.background})
      for (const gpu::PixelRect& r : *list)
        for (int y = r.y; y < r.y + r.h; ++y)
          for (int x = r.x; x < r.x + r.w; ++x) {
            ASSERT_TRUE(x >= 0 && x < view.w && y >= 0 && y < view.h) << view.name;
            ++in_any[size_t(y) * view.w + x];
            in_objects[size_t(y) * view.w + x] += list == &parts.objects;
          }
    long twice = 0, never = 0;
    for (int k : in_any) twice += k > 1, never += k == 0;
    EXPECT_EQ(twice, 0) << view.name;
    EXPECT_EQ(never, 0) << view.name;
    const SceneGeometry geo = scene_geometry(view.f);
    const CameraBasis cam = camera_basis(view.f, view.w, view.h);
    long hits = 0, outside = 0;
    for (int y = 0; y < view.h; ++y)
      for (int x = 0; x < view.w; ++x) {
        const Hit h = first_hit(geo, camera_ray(cam, x + 0.5, y + 0.5, view.w, view.h));
        if (h.object < 0) continue;
        ++hits;
        const int gy = view.h - 1 - y;  // GL's rows from the bottom
        outside += in_objects[size_t(gy) * view.w + x] == 0;
      }
    std::printf("[%s] %ld pixels on glasses, %ld outside the pass's runs (%ld of %d pixels in %zu rects; background %zu "
                "rects)\n",
                view.name, hits, outside, pixels(parts.objects), view.w * view.h, parts.objects.size(),
                parts.background.size());
    EXPECT_GT(hits, 0) << view.name;
    EXPECT_EQ(outside, 0) << view.name;
  }
  const gpu::ScreenParts part = screen_parts(pint, gpu::pack_frame_block(pint, 96, 96, gpu::DebugView::None), 96, 96);
  EXPECT_LT(pixels(part.objects), 96 * 96 * 2 / 3);
  const FrameState flight = make_frame(flight_scene());
  const gpu::ScreenParts gaps =
      screen_parts(flight, gpu::pack_frame_block(flight, 160, 60, gpu::DebugView::None), 160, 60);
  EXPECT_GE(gaps.objects.size(), 4u) << "the flight's glasses in one run";
}

}  // namespace
}  // namespace draught::test
