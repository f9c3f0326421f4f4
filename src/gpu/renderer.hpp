// gpu::Renderer draws a FrameState: it packs the generated Frame uniform block and the
// scene's data textures (gpu/scene_data), runs the path pass (one path per pixel
// through every object) into an offscreen framebuffer, draws the rising bubbles over it
// and reads back images. It does no physics.
#pragma once

#include "core/environment/floor_light.hpp"
#include "core/scene/frame.hpp"
#include "core/io/image.hpp"
#include "core/output/refine.hpp"
#include "core/pointcloud/cloud_scene.hpp"
#include "generated/constants.hpp"
#include "generated/frame.hpp"
#include "generated/objects.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

namespace draught::gpu {

class DecalTextures;
class CloudTextures;
class CondensationTextures;
class MatCapTexture;
class MatCapBackground;
class Program;
class SceneTextures;
class ScreenTexture;
class ReflectionPanoramas;

// A part of a picture in GL's window coordinates (x, y from the bottom-left).
struct PixelRect {
  int x = 0, y = 0, w = 0, h = 0;
};
// Where the frame's objects can show in a width x height picture of block b's camera:
// `objects`, the union of the parts of the picture that the boxes around their search
// bounds reach (a glass's cylinder, each droplet's sphere grown by the field's reach
// within the droplets' box, a cloud's root box), projected, grown by two pixels and out to
// whole blocks of kScreenBlock pixels, as runs along rows in bands between the boxes'
// edges; `background`, the runs between them.
// Together they cover the picture once. A box that reaches behind the eye makes it all
// objects. Outside the objects' runs every line misses every object (either tier draws
// only the background there: Renderer's kBackgroundOnly).
constexpr int kScreenBlock = 4;
struct ScreenParts {
  std::vector<PixelRect> objects, background;
};
// `vessels`: the glasses' records as u_objects holds them (SceneTextures::records).
ScreenParts objects_on_screen(const std::vector<contract::ObjectRecord>& vessels, const contract::FrameBlock& b,
                              int width, int height);

// Debug views, declared in src/interface/constants.def (shared with the shaders).
using contract::DebugView;

// Raw debug channels per pixel, rows top-down: Depth/Material: (t, material, object, 1);
// Normal: (nx, ny, nz, material); Cost: (segment and torus intersections solved for
// the whole path, foam march steps, object bounds entered, 1); PathEvent: (distance from
// the previous event, material, object, medium before it); MediumRule: (medium, 0, 0, 1).
// t is the distance to the first surface, 0 for none.
struct DebugImage {
  int width = 0, height = 0;
  std::vector<float> rgba;
  const float* px(int x, int y) const { return &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

// An offscreen colour target, bound on creation: RGBA8 for pictures, RGBA16F for a
// supersampled picture in scene-linear light (blendable, for the bubbles' sprites),
// RGBA32F for debug channels. Unbinds and frees itself when it goes out of scope; one kept
// across frames (the viewer's low quality tiers) is bound again with bind().
class RenderTarget {
 public:
  enum class Format { Rgba8, Rgba16F, Rgba32F };
  RenderTarget(int width, int height, Format);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;
  void bind() const;
  int width() const { return width_; }
  int height() const { return height_; }
  unsigned texture() const { return tex_; }  // its colour (GL's rows: bottom-up)

 private:
  void release();
  unsigned fbo_ = 0, tex_ = 0;
  int width_ = 0, height_ = 0;
};

class Renderer {
 public:
  // When the path pass's base program is compiled: at construction (a broken shader
  // is reported at once), or not until a frame draws it (the web page: its shaders are
  // embedded, and on a software WebGL the base program, which the default scene never
  // draws, held the page's start by about a second).
  enum class Compile { Now, WithFirstFrame };

  // Needs a current GLES 3.0 context. Shaders are embedded, or read from shader_dir when
  // given; each program variant is compiled when a frame first needs it (the base one at
  // once with Compile::Now), and its uniform-block members' offsets are checked against
  // the driver; a failure throws ShaderError naming file and line, or the member.
  explicit Renderer(const std::filesystem::path& shader_dir = {}, Compile compile = Compile::Now);
  ~Renderer();

  // The final picture at width x height (supersampled by params.render.supersample).
  Image render(const FrameState&, int width, int height);
  // How many pixels the last render() drew again at render.adaptive_supersample samples,
  // and the milliseconds that took (drawing, reading back).
  struct Refined {
    long pixels = 0;
    int samples = 0;
    double ms = 0;
  };
  Refined last_refined() const { return last_refined_; }
  // Debug channels; `event` is the event the PathEvent view reports (0 = first surface).
  DebugImage render_debug(const FrameState&, int width, int height, DebugView, int event = 0);
  // Draws into the currently bound framebuffer (windows, the web page, benchmarks).
  void draw(const FrameState&, int width, int height, DebugView = DebugView::None, int event = 0);
  void finish();
  // The scene's data textures (tests check what a frame uploads).
  const SceneTextures& scene_textures() const { return *textures_; }
  const DecalTextures& decal_textures() const { return *decals_; }
  const CondensationTextures& condensation_textures() const { return *condensation_; }
  // The screen's picture (gpu/screen_texture): uploaded from the frame's screen, or
  // streamed into by the app (the web page's video and camera).
  ScreenTexture& screen_texture() { return *screen_; }
  // The MatCap tier's lit sphere and its background (render.tier matcap; gpu/matcap_texture).
  const MatCapTexture& matcap_texture() const { return *matcap_; }
  const MatCapBackground& matcap_background() const { return *matcap_background_; }
  // env.reflections' panoramas of the glasses' surroundings (gpu/reflection_panoramas).
  const ReflectionPanoramas& reflection_panoramas() const { return *reflections_; }
  // Scenes of up to kMaxHeldObjects objects are drawn with a shader variant that holds
  // every object's records per pixel (object loops resolved at compile time; the same
  // pictures, much faster on llvmpipe). Four: a tasting flight; every held object costs
  // each pixel its records' fetches up front. Off: every scene takes the general path
  // (tests and benchmarks compare the two).
  static constexpr int kMaxHeldObjects = 4;
  void set_held_objects(bool on) { held_objects_ = on; }
  // The picture's pass runs with the objects' code only where they can show
  // (objects_on_screen), the background pass around it. Off: the objects' pass over the
  // whole picture (tests compare the two; the bench shows what it saves).
  void set_background_pass(bool on) { background_pass_ = on; }
  // The floor's shadows and caustics: the photon budget of its light map, or off (the floor
  // takes the unoccluded light); draft_photons > 0: drafts while the scene moves, the full
  // budget once it holds still (SceneTextures::set_floor_light).
  void set_floor_light(const FloorLightSettings&, bool on = true, int draft_photons = 0);
  // Its refinement once still: batch size and milliseconds a frame
  // (SceneTextures::set_floor_refinement).
  void set_floor_refinement(int batch_photons, double ms_per_frame);
  // Interactive apps (the viewer, the web page): while things move, the MatCap tier's
  // background is drawn smaller and read between its texels (MatCapBackground::moving),
  // and while the lights, the backdrop or the scene's aim change the backdrop's light map
  // is a draft (SceneTextures::set_backdrop_drafts). Off (the CLI, tests): every frame's
  // background and light map are a still's.
  void set_moving_drafts(bool on);

 private:
  // draw(), the passes leaving scene-linear light instead of display values with `linear`
  // (render's supersampled pictures: Frame::output_linear).
  // `rects`: the picture's pass drawn over these rectangles only (the rest of the target
  // is left as it was).
  void draw_picture(const FrameState&, int width, int height, DebugView, int event, bool linear,
                    const std::vector<PixelRect>* rects = nullptr);
  void draw_bubbles(const FrameState&, int width, int height);
  void draw_rects(int variant, const std::vector<PixelRect>&, int width, int height);
  void draw_scissored(int variant, const std::vector<PixelRect>&);
  // Adaptive supersampling: the fine x fine samples of the runs' pixels of a width x height
  // picture (core/output/refine's layout), drawn as tiles of the picture `fine` times as
  // wide and high, the pass over those pixels only: scene-linear light (`linear`), or
  // display values decoded by samples_from_display.
  std::vector<float> draw_refined(const FrameState&, int width, int height, const std::vector<PixelRun>& runs,
                                  int fine, bool linear);

  // What the path pass is compiled with (software rasterizers pay for code even where a
  // uniform branch skips it, so frames get only the code they use): these bits, and the
  // number of held objects (0: the general path) from bit kHeldShift on.
  // kMatCap: the MatCap tier's pass (passes/matcap.frag.glsl) instead of the path pass.
  // kMatCapBackdrop: its background pass (what lies behind, into MatCapBackground);
  // kMatCapCached: its picture pass reading that background. kBackgroundOnly: either
  // pass's picture where no object can show (outside objects_on_screen's part): what a
  // ray that meets no object's bounds sees, without the objects' code.
  enum Variant {
    kWaves = 1, kFoam = 2, kDebug = 4, kImage = 8, kDecals = 16, kScreenCard = 32, kScreenBackground = 64,
    kSphereLights = 128, kPaintedSky = 256, kDroplets = 512, kMatCap = 1024, kMatCapBackdrop = 2048,
    kMatCapCached = 4096, kHeldShift = 13, kHeldMask = 7, kClouds = 1 << 16,  // (held objects: bits 13-15)
    kCondensation = 1 << 17, kBackgroundOnly = 1 << 18,
    // kPanorama: a glass's surroundings for env.reflections (gpu/reflection_panoramas);
    // kReflections: the picture looking its glasses' reflections up there.
    kPanorama = 1 << 19, kReflections = 1 << 20,
    // kMatCapSmall: with kMatCapCached, the background read from its smaller picture
    // (drawn while things move: MatCapBackground::moving).
    kMatCapSmall = 1 << 21,
    // kHaze: some drink is hazy (its light by diffusion along each stretch in it).
    kHaze = 1 << 22
  };
  // env.reflections: draws the panoramas this frame needs into reflections_ (the block
  // as the picture's, its camera moved into each glass); true when the picture has them.
  // same_frame: more pixels of the frame just drawn, which take its panoramas as they are.
  bool draw_reflections(const FrameState&, contract::FrameBlock&, int variant, bool same_frame);
  // The MatCap tier's background: the variant bits that read it (kMatCapCached, with
  // kMatCapSmall while things move), drawing it when it is not the one of this frame; 0
  // when the pass shades it inline (a view seen once, no float targets, a screen whose
  // frames it does not follow, a transparent picture).
  int matcap_background(const FrameState&, const contract::FrameBlock&, const std::vector<contract::ObjectRecord>&,
                         int width, int height, int variant);
  std::unique_ptr<Program> build_program(int variant) const;

  std::filesystem::path shader_dir_;
  std::map<int, std::unique_ptr<Program>> programs_;  // by variant, built when first needed
  std::unique_ptr<Program> bubble_program_;  // pass 2: rising bubbles, built when first needed
  std::unique_ptr<SceneTextures> textures_;  // u_objects, u_knots, u_floor_light
  std::unique_ptr<DecalTextures> decals_;    // u_decal_images, u_decal_arcs
  std::unique_ptr<ScreenTexture> screen_;    // u_screen
  std::unique_ptr<MatCapTexture> matcap_;    // u_matcap
  std::unique_ptr<MatCapBackground> matcap_background_;  // u_matcap_background
  std::unique_ptr<ReflectionPanoramas> reflections_;     // u_reflections
  CloudScene cloud_scene_;                   // the point clouds' trees and texel arrays
  std::unique_ptr<CloudTextures> clouds_;    // u_cloud_points, u_cloud_attrs, u_cloud_nodes
  std::unique_ptr<CondensationTextures> condensation_;  // u_condensation_beads, u_condensation_fog
  unsigned bubble_vao_ = 0, bubble_vbo_ = 0;
  unsigned rect_vao_ = 0, rect_vbo_ = 0;
  unsigned vao_ = 0, ubo_ = 0;
  bool held_objects_ = true;
  bool background_pass_ = true;
  bool moving_drafts_ = false;
  bool has_decals_ = false, has_condensation_ = false;  // the last frame's update found them
  Refined last_refined_;
};

// Turns a debug image into a picture a person can read (grey depth, RGB normals,
// a colour per material). Depth runs from white at depth.near to dark grey at depth.far
// (the scene's range, core/scene/frame.hpp depth_range; nearer and farther surfaces are
// clamped), black where nothing was hit; without a range, over the picture's own depths.
Image visualize_debug(const DebugImage&, DebugView, DepthRange depth = {});

}  // namespace draught::gpu
