#include "gpu/renderer.hpp"

#include "core/bubbles/bubble_view.hpp"
#include "core/output/resolve.hpp"
#include "gpu/decal_textures.hpp"
#include "gpu/matcap_texture.hpp"
#include "gpu/reflection_panoramas.hpp"
#include "gpu/cloud_textures.hpp"
#include "gpu/condensation_textures.hpp"
#include "gpu/program.hpp"
#include "gpu/scene_data.hpp"
#include "gpu/screen_texture.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>

namespace draught::gpu {

RenderTarget::RenderTarget(int w, int h, Format format) : width_(w), height_(h) {
  const bool float_target = format != Format::Rgba8;
  glGenTextures(1, &tex_);
  glBindTexture(GL_TEXTURE_2D, tex_);
  const GLenum internal = format == Format::Rgba32F ? GL_RGBA32F : format == Format::Rgba16F ? GL_RGBA16F : GL_RGBA8;
  glTexStorage2D(GL_TEXTURE_2D, 1, internal, w, h);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex_, 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    // Say which size failed and why: most often it is larger than the driver allows.
    const GLenum err = glGetError();
    GLint max_tex = 0, max_rb = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_tex);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
    release();
    const int limit = std::min(max_tex, max_rb);
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    if (std::max(w, h) > limit)
      throw std::runtime_error("cannot create an offscreen framebuffer of " + size + " pixels: larger than this GL "
                               "driver's limit of " + std::to_string(limit) + " pixels a side (GL_MAX_TEXTURE_SIZE " +
                               std::to_string(max_tex) + ", GL_MAX_RENDERBUFFER_SIZE " + std::to_string(max_rb) + ")");
    throw std::runtime_error(float_target ? "float render targets are not supported by this GL driver "
                                            "(EXT_color_buffer_float); debug views need them"
                                          : "cannot create an offscreen framebuffer of " + size + " pixels: " +
                                                (err == GL_OUT_OF_MEMORY ? "out of GPU memory" : "refused by the GL driver"));
  }
}

void RenderTarget::release() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (tex_) glDeleteTextures(1, &tex_);
  fbo_ = tex_ = 0;
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }

namespace {
// The source with `#define name value` right after its #version line (line numbers kept).
ShaderSource with_define(ShaderSource src, const std::string& name, const std::string& value = "1") {
  const size_t eol = src.text.find('\n');
  src.text.insert(eol + 1, "#define " + name + " " + value + "\n#line 2 0\n");
  return src;
}

// Uniform-block binding, block layout check and texture units for a program that reads
// the Frame block (and, for the path pass, the scene's data textures).
void bind_interface(const Program& program, const std::string& what) {
  check_uniform_block(program.id(), contract::kFrameBlockName, contract::kFrameBlockMembers,
                      contract::kFrameBlockUsedBytes, sizeof(contract::FrameBlock), contract::kFrameBlockBinding, what);
  glUseProgram(program.id());
  for (const contract::Sampler& s : {contract::kObjectSampler, contract::kKnotsSampler, contract::kFloorLightSampler,
                                       contract::kBackdropLightSampler, contract::kEnvImageSampler,
                                       contract::kDecalImagesSampler, contract::kDecalArcsSampler,
                                       contract::kScreenSampler, contract::kMatCapSampler,
                                       contract::kMatCapBackgroundSampler, contract::kCloudPointsSampler,
                                       contract::kCloudAttrsSampler, contract::kCloudNodesSampler,
                                       contract::kCondensationBeadsSampler, contract::kCondensationFogSampler,
                                       contract::kReflectionsSampler})
    if (GLint at = glGetUniformLocation(program.id(), s.name); at >= 0) glUniform1i(at, s.unit);
}
}  // namespace

std::unique_ptr<Program> Renderer::build_program(int variant) const {
  ShaderSource vert = assemble_shader("passes/fullscreen.vert.glsl", shader_dir_);
  const char* pass = variant & kMatCap ? "passes/matcap.frag.glsl" : "passes/path.frag.glsl";
  ShaderSource frag = assemble_shader(pass, shader_dir_);
  if (variant & kWaves) frag = with_define(std::move(frag), "SURFACE_WAVES");
  if (variant & kFoam) frag = with_define(std::move(frag), "FOAM_HEAD");
  if (variant & kDebug) frag = with_define(std::move(frag), "DEBUG_VIEWS");
  if (variant & kImage) frag = with_define(std::move(frag), "ENV_IMAGE");
  if (variant & kDecals) frag = with_define(std::move(frag), "DECALS");
  if (variant & kDroplets) frag = with_define(std::move(frag), "DROPLETS");
  if (variant & kClouds) frag = with_define(std::move(frag), "CLOUDS");
  if (variant & kCondensation) frag = with_define(std::move(frag), "CONDENSATION");
  if (variant & kHaze) frag = with_define(std::move(frag), "HAZE");
  if (variant & (kScreenCard | kScreenBackground))  // 1: a card in the scene, 2: the background
    frag = with_define(std::move(frag), "SCREEN", variant & kScreenCard ? "1" : "2");
  if (variant & kSphereLights) frag = with_define(std::move(frag), "SPHERE_LIGHTS");
  if (variant & kPaintedSky) frag = with_define(std::move(frag), "PAINTED_SKY");
  if (variant & kMatCapBackdrop) frag = with_define(std::move(frag), "MATCAP_BACKDROP");
  if (variant & kMatCapCached) frag = with_define(std::move(frag), "MATCAP_CACHED");
  if (variant & kMatCapSmall) frag = with_define(std::move(frag), "MATCAP_CACHED_SMALL");
  if (variant & kBackgroundOnly) frag = with_define(std::move(frag), "BACKGROUND_ONLY");
  if (variant & kPanorama) frag = with_define(std::move(frag), "PANORAMA");
  if (variant & kReflections) frag = with_define(std::move(frag), "REFLECTIONS");
  if (const int held = (variant >> kHeldShift) & kHeldMask)
    frag = with_define(std::move(frag), "HELD_OBJECTS", std::to_string(held));
  auto program = std::make_unique<Program>(vert, frag);
  bind_interface(*program, pass);
  return program;
}

Renderer::Renderer(const std::filesystem::path& shader_dir, Compile compile) : shader_dir_(shader_dir) {
  if (const char* env = std::getenv("DRAUGHT_SHADER_DIR"); shader_dir_.empty() && env && *env) shader_dir_ = env;
  if (compile == Compile::Now) programs_[0] = build_program(0);
  textures_ = std::make_unique<SceneTextures>();
  decals_ = std::make_unique<DecalTextures>();
  screen_ = std::make_unique<ScreenTexture>();
  matcap_ = std::make_unique<MatCapTexture>();
  matcap_background_ = std::make_unique<MatCapBackground>();
  reflections_ = std::make_unique<ReflectionPanoramas>();
  clouds_ = std::make_unique<CloudTextures>();
  condensation_ = std::make_unique<CondensationTextures>();
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &ubo_);
  glBindBuffer(GL_UNIFORM_BUFFER, ubo_);
  glBufferData(GL_UNIFORM_BUFFER, sizeof(contract::FrameBlock), nullptr, GL_DYNAMIC_DRAW);
}

Renderer::~Renderer() {
  glDeleteBuffers(1, &rect_vbo_);
  glDeleteVertexArrays(1, &rect_vao_);
  glDeleteBuffers(1, &bubble_vbo_);
  glDeleteVertexArrays(1, &bubble_vao_);
  glDeleteBuffers(1, &ubo_);
  glDeleteVertexArrays(1, &vao_);
}

void Renderer::set_moving_drafts(bool on) {
  moving_drafts_ = on;
  textures_->set_backdrop_drafts(on);
}

void Renderer::set_floor_light(const FloorLightSettings& s, bool on, int draft_photons) {
  textures_->set_floor_light(s, on, draft_photons);
}

void Renderer::set_floor_refinement(int batch_photons, double ms_per_frame) {
  textures_->set_floor_refinement(batch_photons, ms_per_frame);
}

void Renderer::draw(const FrameState& f, int width, int height, DebugView debug, int event) {
  draw_picture(f, width, height, debug, event, false);
}

void Renderer::draw_picture(const FrameState& f, int width, int height, DebugView debug, int event, bool linear,
                            const std::vector<PixelRect>* rects) {
  // The MatCap tier draws the picture with its own pass (and the thickness view is its);
  // the other debug views are the path pass's.
  const bool matcap = debug == DebugView::Thickness ||
                      (debug == DebugView::None && f.params.render.tier == int(RenderTier::MatCap));
  // More pixels of the frame just drawn (rects: adaptive supersampling's) take its
  // textures as they are, so that the frame's updates, uploads and panoramas happen once,
  // and the finer pixels see the same light maps as their neighbours.
  const bool same_frame = rects != nullptr;
  if (!same_frame) {
    if (matcap) matcap_->update(f);  // a bake or a read only when its inputs change
    // Only rows that changed; the floor's and the backdrop's light maps when their inputs
    // did, and never for the MatCap tier, which reads neither.
    textures_->update(f, width, height, !matcap);
    has_decals_ = decals_->update(f);     // the images when they change, arc rows when a glass does
    // Beads and fog: a band when its glass's condensation changed.
    has_condensation_ = condensation_->update(f);
    screen_->update(f.screen);  // only when another frame comes, into the texture not drawn from
  }
  const bool decals = has_decals_;
  const bool condensation = has_condensation_ && debug != DebugView::Thickness;  // (the bare glasses')
  screen_->bind();
  textures_->bind();  // (after the updates, which bind what they upload to the active unit)
  if (decals) decals_->bind();
  if (condensation) condensation_->bind();
  if (matcap) matcap_->bind();
  // The point clouds: trees kept, refit or rebuilt as their points change (core), the
  // textures uploaded only then.
  if (!same_frame && cloud_scene_.update(f.clouds)) clouds_->upload(cloud_scene_.texels(), cloud_scene_.changed());
  // (The thickness view is the glasses' alone.)
  const bool clouds = !f.clouds.empty() && debug != DebugView::Thickness;
  if (clouds) clouds_->bind();
  contract::FrameBlock block = pack_frame_block(f, width, height, debug, event);
  block.output_linear = linear ? 1 : 0;
  if (clouds) pack_clouds(f, cloud_scene_, block);
  block.matcap_max_lod = matcap_->max_lod();
  block.matcap_frost_lod = f.params.matcap.frost * std::max(matcap_->max_lod() - 3.0f, 0.0f);
  textures_->describe_floor_light(block);
  textures_->describe_backdrop_light(block);
  pack_screen(f, width, height, block);
  glBindBuffer(GL_UNIFORM_BUFFER, ubo_);
  glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof block, &block);
  glBindBufferBase(GL_UNIFORM_BUFFER, contract::kFrameBlockBinding, ubo_);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  // Only the code a frame needs: waves and foam when some object has them, the debug
  // views when one is asked for, sphere lights when the rig has one, the strips and glow
  // painted in the sky when they are not black, and for a few objects their records held
  // per pixel.
  bool waves = false, foam = false, spheres = false, haze = false;
  for (const VesselFrame& v : f.vessels) {
    waves = waves || (v.has_liquid && !v.liquid.waves.flat());
    foam = foam || has_head(v);
    haze = haze || (v.has_liquid && v.params.liquid.haze > 0.0f);
  }
  for (int i = 0; i < block.light_count; ++i) spheres = spheres || block.light_normal[i].w > 0.5f;
  const bool painted = block.env_mode == 0 && (block.strip_intensity != 0.0f || block.backdrop_glow != 0.0f);
  const int objects = int(f.vessels.size());
  const int held = held_objects_ && objects >= 1 && objects <= kMaxHeldObjects ? objects : 0;
  int variant = (waves ? kWaves : 0) | (foam ? kFoam : 0) | (debug != DebugView::None ? kDebug : 0) |
                      (f.environment.image ? kImage : 0) | (decals ? kDecals : 0) | (held << kHeldShift) |
                      (f.screen.mode == ScreenMode::Card ? kScreenCard : 0) |
                      (f.screen.mode == ScreenMode::Background ? kScreenBackground : 0) |
                      (spheres ? kSphereLights : 0) | (painted ? kPaintedSky : 0) |
                      (!f.droplets.empty() && !f.droplets.front().field.spheres.empty() && debug != DebugView::Thickness
                           ? kDroplets
                           : 0) |
                      (clouds ? kClouds : 0) | (condensation ? kCondensation : 0) | (haze ? kHaze : 0);
  // The MatCap pass marches no drink: waves (its surface is the plane) and heads (a layer)
  // need no variant of it, nor a hazy drink (one light for its whole haze). It marches
  // droplets and point clouds (seen as lenses).
  if (matcap) variant = (variant & ~(kWaves | kFoam | kHaze)) | kMatCap;
  // env.reflections: the glasses' surroundings first, from inside each (the full tier's).
  else if (debug == DebugView::None && draw_reflections(f, block, variant, same_frame)) variant |= kReflections;
  // Where the objects can show is found from their records as uploaded this frame.
  const bool parted = debug == DebugView::None && background_pass_;
  const std::vector<contract::ObjectRecord> records =
      matcap || parted ? textures_->records() : std::vector<contract::ObjectRecord>{};
  // (More pixels of a frame shade their background inline: the kept one is the picture's.)
  if (matcap && debug == DebugView::None && !same_frame)
    variant |= matcap_background(f, block, records, width, height, variant);
  // Only the runs of the screen where the objects' bounds lie run the pass with their
  // code; around them the same pass without it gives what a ray that meets no bound sees
  // (the background, a fraction of the cost: llvmpipe pays for all of a pass's code in
  // every pixel). Each run is drawn in a scissor (as instanced rectangles the MatCap
  // tier's droplets came out slower on llvmpipe). The MatCap tier's background is read
  // from the kept one, or shaded inline where the view is new (a moving camera: one
  // background per pixel, no pass of its own and no copy).
  if (rects) {  // a few pixels: the pass alone, which gives a line that meets nothing its background
    draw_rects(variant, *rects, width, height);
    if (debug == DebugView::None) draw_bubbles(f, width, height);
    return;
  }
  const ScreenParts parts =
      parted ? objects_on_screen(records, block, width, height) : ScreenParts{{PixelRect{0, 0, width, height}}, {}};
  glBindVertexArray(vao_);
  if (!parts.background.empty()) {
    // (Without the objects' code: one small program whatever the scene holds.)
    const int objects_code = kWaves | kFoam | kHaze | kDecals | kDroplets | kClouds | kCondensation | kReflections |
                             (kHeldMask << kHeldShift);
    draw_scissored((variant & ~objects_code) | kBackgroundOnly, parts.background);
  }
  draw_scissored(variant, parts.objects);
  // The rising bubbles over the picture (the MatCap tier's where its straight view sees them).
  if (debug == DebugView::None) draw_bubbles(f, width, height);
}

namespace {

// Where a world point lands in a width x height picture of the block's camera (pixels from
// the top-left, as camera_dir's inverse); nothing when it is not in front of the eye.
std::optional<glm::dvec2> on_screen(const contract::FrameBlock& b, const glm::vec3& p, int width, int height) {
  const glm::dvec3 q = glm::dvec3(p) - glm::dvec3(b.cam_eye);
  const double z = glm::dot(q, glm::dvec3(b.cam_forward));
  if (!(z > 1e-4)) return std::nullopt;
  const double x = glm::dot(q, glm::dvec3(b.cam_right)) / (z * b.cam_tan_half_vfov * b.cam_aspect);
  const double y = glm::dot(q, glm::dvec3(b.cam_up)) / (z * b.cam_tan_half_vfov);
  return glm::dvec2((x + 1.0 + b.cam_shift.x) * 0.5 * width, (1.0 - y - b.cam_shift.y) * 0.5 * height);
}

}  // namespace

ScreenParts objects_on_screen(const std::vector<contract::ObjectRecord>& vessels, const contract::FrameBlock& b,
                              int width, int height) {
  std::vector<PixelRect> boxes;  // each box's part of the picture
  bool behind = false;
  auto box = [&](const glm::vec3& a, const glm::vec3& c) {  // a box's corners
    glm::dvec2 lo(1e30), hi(-1e30);
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 p(k & 1 ? c.x : a.x, k & 2 ? c.y : a.y, k & 4 ? c.z : a.z);
      const auto s = on_screen(b, p, width, height);
      if (!s) behind = true;
      else lo = glm::min(lo, *s), hi = glm::max(hi, *s);
    }
    if (behind || hi.x < lo.x) return;
    // GL's rows count from the bottom; two pixels more each side for the rounding, then out
    // to whole blocks of kScreenBlock pixels (a software rasterizer shades blocks of
    // pixels: a run's edge through one shades it twice, once in each pass).
    auto down = [](double v) { return std::floor(v / kScreenBlock) * kScreenBlock; };
    auto up = [](double v) { return std::ceil(v / kScreenBlock) * kScreenBlock; };
    const double x0 = std::max(0.0, down(lo.x - 2)), x1 = std::min(double(width), up(hi.x + 2));
    const double y0 = std::max(0.0, down(height - hi.y - 2)), y1 = std::min(double(height), up(height - lo.y + 2));
    if (x1 > x0 && y1 > y0) boxes.push_back({int(x0), int(y0), int(x1 - x0), int(y1 - y0)});
  };
  for (const contract::ObjectRecord& r : vessels) {  // the bounding cylinder of the search (object_span)
    const glm::vec3 base(r.bound_base), axis(r.bound_axis), top = base + r.bound_length * axis;
    const glm::vec3 grow = r.bound_radius * glm::sqrt(glm::max(glm::vec3(1.0f) - axis * axis, glm::vec3(0.0f)));
    box(glm::min(base, top) - grow, glm::max(base, top) + grow);
  }
  // A droplet march is clipped to the droplets' box and to the spheres grown by the
  // field's reach (droplet_sphere_span): each sphere's cube within the box.
  for (int i = 0; i < b.droplet_count; ++i) {
    const glm::vec4 s = b.droplet_spheres[i];
    const float r = s.w + b.droplet_margin;
    if (!(r > 0.0f)) continue;
    const glm::vec3 lo = glm::max(glm::vec3(s) - r, b.droplet_bound_lo), hi = glm::min(glm::vec3(s) + r, b.droplet_bound_hi);
    if (glm::all(glm::lessThanEqual(lo, hi))) box(lo, hi);
  }
  for (int c = 0; c < b.cloud_count; ++c) box(glm::vec3(b.cloud_lo[c]), glm::vec3(b.cloud_hi[c]));
  if (behind) return {{PixelRect{0, 0, width, height}}, {}};
  // The union of the boxes' parts in bands between their top and bottom edges: in each, the
  // boxes that span it give runs along the row, the gaps between them the background's; a
  // band whose runs are the last band's extends them.
  std::vector<int> ys = {0, height};
  for (const PixelRect& r : boxes) ys.insert(ys.end(), {r.y, r.y + r.h});
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  ScreenParts parts;
  std::vector<std::pair<int, int>> last;  // the last band's runs
  size_t last_objects = 0, last_background = 0;  // where its rects start in the lists
  for (size_t k = 0; k + 1 < ys.size(); ++k) {
    const int y = ys[k], h = ys[k + 1] - y;
    std::vector<std::pair<int, int>> runs;
    for (const PixelRect& r : boxes)
      if (r.y <= y && r.y + r.h >= y + h) runs.push_back({r.x, r.x + r.w});
    std::sort(runs.begin(), runs.end());
    std::vector<std::pair<int, int>> merged;
    for (const auto& run : runs)
      if (!merged.empty() && run.first <= merged.back().second) merged.back().second = std::max(merged.back().second, run.second);
      else merged.push_back(run);
    if (k > 0 && merged == last) {
      for (size_t i = last_objects; i < parts.objects.size(); ++i) parts.objects[i].h += h;
      for (size_t i = last_background; i < parts.background.size(); ++i) parts.background[i].h += h;
      continue;
    }
    last_objects = parts.objects.size();
    last_background = parts.background.size();
    int x = 0;
    for (const auto& [x0, x1] : merged) {
      if (x0 > x) parts.background.push_back({x, y, x0 - x, h});
      parts.objects.push_back({x0, y, x1 - x0, h});
      x = x1;
    }
    if (x < width) parts.background.push_back({x, y, width - x, h});
    last = std::move(merged);
  }
  return parts;
}

bool Renderer::draw_reflections(const FrameState& f, contract::FrameBlock& block, int variant, bool same_frame) {
  const int layers = reflections_->layers_for(f);
  if (layers == 0) return false;
  if (same_frame && reflections_->layers() != layers) return false;
  if (!same_frame && reflections_->due(f, layers)) {
    GLint target = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
    const bool ready = reflections_->prepare(std::clamp(f.params.env.reflections_size, 32, 1024), layers);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    if (!ready) return false;
    // The picture's block, its camera at each glass's middle, that glass left out; a
    // panorama sees no panoramas (one bounce) and no bubbles (sprites of the picture).
    contract::FrameBlock pano = block;
    pano.viewport_size = {reflections_->width(), reflections_->height()};
    pano.viewport_inv = {1.0f / reflections_->width(), 1.0f / reflections_->height()};
    pano.reflections_count = 0;
    // A cutout's glasses mirror the studio and each other as the opaque picture's do: its
    // panoramas are the opaque world's (what escapes there is the studio, not the page).
    pano.transparent = 0;
    const int v = (variant & ~kDebug) | kPanorama;
    auto& program = programs_[v];
    if (!program) program = build_program(v);
    glUseProgram(program->id());
    glBindVertexArray(vao_);
    for (int k = 0; k < layers; ++k) {
      pano.cam_eye = glm::vec3(vessel_middle(f.vessels[size_t(k)]));
      pano.exclude_object = k;
      glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof pano, &pano);
      reflections_->begin_layer(k);
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    reflections_->finish(f);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
  }
  block.reflections_count = reflections_->layers();
  block.reflections_max_lod = reflections_->max_lod();
  block.reflections_texels_per_radian = float(reflections_->width() / (2.0 * 3.14159265358979));
  block.exclude_object = -1;
  glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof block, &block);
  glViewport(0, 0, block.viewport_size.x, block.viewport_size.y);
  reflections_->bind();
  return true;
}

int Renderer::matcap_background(const FrameState& f, const contract::FrameBlock& block,
                                const std::vector<contract::ObjectRecord>& records, int width, int height, int variant) {
  // A transparent picture has no background; a screen's frames change without the block.
  if (f.params.render.transparent || f.screen.mode != ScreenMode::Off || !matcap_background_->usable()) return 0;
  // What the background depends on: the block (camera, size, surroundings), the
  // environment image, and where the glasses stand (their contact on the floor). Not the
  // droplets (the tier's backdrop has no traced shadows: seen_straight; nor has the block
  // a floor light map in this tier): droplets following a pointer keep the background whole.
  contract::FrameBlock seen;
  std::memcpy(&seen, &block, sizeof block);  // (the padding too: the key is the bytes)
  pack_droplets({}, seen);  // (the block of the same frame without droplets)
  std::vector<unsigned char> key(sizeof seen + sizeof(void*));
  std::memcpy(key.data(), &seen, sizeof seen);
  const void* image = f.environment.image.get();
  std::memcpy(key.data() + sizeof seen, &image, sizeof image);
  for (const contract::ObjectRecord& r : records) {
    const float part[] = {r.bound_base.x, r.bound_base.y, r.bound_base.z, r.bound_axis.x, r.bound_axis.y, r.bound_axis.z,
                          r.bound_radius, r.bound_length, r.foot_radius, r.clip_world_normal.x, r.clip_world_normal.y,
                          r.clip_world_normal.z, r.clip_world_offset};
    const auto* b = reinterpret_cast<const unsigned char*>(part);
    key.insert(key.end(), b, b + sizeof part);
  }
  const bool held = matcap_background_->held(key.data(), key.size(), width, height);
  if (matcap_background_->ready(key.data(), key.size(), width, height)) {
    matcap_background_->bind();
    return kMatCapCached;
  }
  // A view seen once: its background inline (a still's first frame, as sharp as kept); a
  // second new view in a row (things move): on a picture a quarter as wide and high
  // (MatCapBackground::kMovingScale), a sixteenth of the work.
  const bool moving = moving_drafts_ && !held && matcap_background_->moving();
  if (!held && !moving) return 0;
  GLint target = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
  constexpr int s = MatCapBackground::kMovingScale;
  const int hw = (width + s - 1) / s, hh = (height + s - 1) / s;
  const bool drawn = moving ? matcap_background_->begin_drawing_small(hw, hh) : matcap_background_->begin_drawing(width, height);
  if (drawn) {
    const int v = (variant & ~(kDecals | kMatCapCached | kMatCapSmall | kDroplets | kClouds | kCondensation)) | kMatCapBackdrop;
    auto& program = programs_[v];
    if (!program) program = build_program(v);
    glUseProgram(program->id());
    glBindVertexArray(vao_);
    if (moving) {  // the same view on the smaller picture
      contract::FrameBlock small = block;
      small.viewport_size = {hw, hh};
      small.viewport_inv = {1.0f / float(hw), 1.0f / float(hh)};
      glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof small, &small);
      glViewport(0, 0, hw, hh);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof block, &block);
    } else {
      glViewport(0, 0, width, height);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      matcap_background_->done(key.data(), key.size());
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
  glViewport(0, 0, width, height);
  if (!drawn) return 0;
  if (moving) {
    matcap_background_->bind_small();
    return kMatCapCached | kMatCapSmall;
  }
  matcap_background_->bind();
  return kMatCapCached;
}

void Renderer::draw_rects(int variant, const std::vector<PixelRect>& rects, int width, int height) {
  // (The picture's own program: its vertex stage draws rectangles from a buffer.)
  auto& program = programs_[variant];
  if (!program) program = build_program(variant);
  glUseProgram(program->id());
  glUniform2f(glGetUniformLocation(program->id(), "u_target_inv"), 1.0f / float(width), 1.0f / float(height));
  if (!rect_vao_) {
    glGenVertexArrays(1, &rect_vao_);
    glGenBuffers(1, &rect_vbo_);
    glBindVertexArray(rect_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, rect_vbo_);
    glEnableVertexAttribArray(0);  // a_rect
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
    glVertexAttribDivisor(0, 1);
  }
  std::vector<float> data;
  data.reserve(rects.size() * 4);
  for (const PixelRect& r : rects) data.insert(data.end(), {float(r.x), float(r.y), float(r.w), float(r.h)});
  glBindVertexArray(rect_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, rect_vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STREAM_DRAW);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(rects.size()));
  glBindVertexArray(vao_);
}

// The pass of `variant` over each rectangle in turn, its one triangle in a scissor.
void Renderer::draw_scissored(int variant, const std::vector<PixelRect>& rects) {
  if (rects.empty()) return;
  auto& program = programs_[variant];
  if (!program) program = build_program(variant);
  glUseProgram(program->id());
  glEnable(GL_SCISSOR_TEST);
  for (const PixelRect& r : rects) {
    glScissor(r.x, r.y, r.w, r.h);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glDisable(GL_SCISSOR_TEST);
}

void Renderer::draw_bubbles(const FrameState& f, int width, int height) {
  const std::vector<BubbleSprite> sprites = bubble_sprites(f, width, height);
  if (sprites.empty()) return;
  // Per instance: centre (2), radius, tint (3), the drink's index of refraction.
  constexpr int kFloats = 7;
  if (!bubble_program_) {
    bubble_program_ = std::make_unique<Program>(assemble_shader("passes/bubbles.vert.glsl", shader_dir_),
                                                assemble_shader("passes/bubbles.frag.glsl", shader_dir_));
    bind_interface(*bubble_program_, "passes/bubbles.vert.glsl");
    glGenVertexArrays(1, &bubble_vao_);
    glGenBuffers(1, &bubble_vbo_);
    glBindVertexArray(bubble_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, bubble_vbo_);
    const struct {
      GLuint location;
      GLint size, offset;
    } attributes[] = {{0, 2, 0}, {1, 1, 2}, {2, 3, 3}, {3, 1, 6}};  // a_centre, a_radius, a_tint, a_liquid_ior
    for (const auto& a : attributes) {
      glEnableVertexAttribArray(a.location);
      glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, kFloats * sizeof(float),
                            reinterpret_cast<void*>(size_t(a.offset) * sizeof(float)));
      glVertexAttribDivisor(a.location, 1);
    }
  }
  std::vector<float> data;
  data.reserve(sprites.size() * kFloats);
  for (const BubbleSprite& s : sprites) {
    const float ior = s.object >= 0 ? f.vessels[size_t(s.object)].params.liquid.ior : 1.34f;
    data.insert(data.end(), {s.centre.x, s.centre.y, s.radius, s.tint.r, s.tint.g, s.tint.b, ior});
  }
  glBindVertexArray(bubble_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, bubble_vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STREAM_DRAW);
  glUseProgram(bubble_program_->id());
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(sprites.size()));
  glDisable(GL_BLEND);
  glBindVertexArray(vao_);
}

void Renderer::finish() { glFinish(); }

namespace {

// The bound float target's RGBA, rows top-down (GL's are bottom-up).
std::vector<float> read_float_rows(int w, int h) {
  std::vector<float> rows(size_t(w) * size_t(h) * 4), out(rows.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, rows.data());
  for (int y = 0; y < h; ++y)
    std::copy_n(&rows[size_t(h - 1 - y) * size_t(w) * 4], size_t(w) * 4, &out[size_t(y) * size_t(w) * 4]);
  return out;
}

}  // namespace

Image Renderer::render(const FrameState& f, int width, int height) {
  last_refined_ = {};
  const int ss = std::clamp(f.params.render.supersample, 1, 4);
  const int w = width * ss, h = height * ss;
  // Supersamples averaged in scene-linear light, then the output transform (a camera's
  // pixel integrates light before its response; the reference resolves its paths so):
  // averaged after the tone map, a thin highlight or a band of bright stripes came out
  // darker than its light (the concave tone map of each sample; docs/REFERENCE.md). A
  // transparent picture keeps the per-sample transform and averages its premultiplied
  // display values (downsample), so that its edges keep their colour for compositing; so
  // does a driver that cannot draw into half floats (no EXT_color_buffer_float).
  std::optional<RenderTarget> linear;
  if (ss > 1 && !f.params.render.transparent) {
    try {
      linear.emplace(w, h, RenderTarget::Format::Rgba16F);
    } catch (const std::runtime_error&) {
    }
  }
  const RenderParams& r = f.params.render;
  // Adaptive supersampling: the pixels whose samples disagree drawn again at more, and
  // the picture resolved with their finer samples (output: the output transform after the
  // mean, or none for display samples).
  const int fine = std::clamp(r.adaptive_supersample, 1, 4);
  const bool in_linear = linear.has_value();
  auto refine = [&](const std::vector<float>& samples, int output) -> std::optional<Image> {
    if (fine <= ss) return std::nullopt;
    RefinedSamples refined{fine, pixels_to_refine(samples, width, height, ss, output, r.adaptive_threshold), {}};
    if (refined.runs.empty()) return std::nullopt;
    const auto t0 = std::chrono::steady_clock::now();
    refined.rgba = draw_refined(f, width, height, refined.runs, fine, in_linear);
    last_refined_ = {pixels_in(refined.runs), fine,
                     std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()};
    return resolve_refined(samples, width, height, ss, refined, output);
  };
  if (linear) {
    draw_picture(f, w, h, DebugView::None, 0, true);
    const std::vector<float> samples = read_float_rows(w, h);
    linear.reset();
    if (std::optional<Image> img = refine(samples, r.tonemap)) return std::move(*img);
    return resolve_linear(samples, width, height, ss, r.tonemap);
  }
  Image img;
  {
    RenderTarget target(w, h, RenderTarget::Format::Rgba8);
    draw(f, w, h);
    img = Image{w, h, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4)};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    // GL rows are bottom-up; images are top-down.
    for (int y = 0; y < h / 2; ++y)
      std::swap_ranges(img.px(0, y), img.px(0, y) + size_t(w) * 4, img.px(0, h - 1 - y));
  }
  // (A transparent picture's samples are display values, averaged as they are.)
  if (ss > 1)
    if (std::optional<Image> refined = refine(samples_from_display(img), int(Tonemap::None))) return std::move(*refined);
  return downsample(img, ss);
}

std::vector<float> Renderer::draw_refined(const FrameState& f, int width, int height, const std::vector<PixelRun>& runs,
                                          int fine, bool linear) {
  // The fine picture in tiles (bounded memory whatever the picture's size), each a part of
  // it through the camera's lens shift (FrameState::view): the same rays as the whole fine
  // picture's.
  constexpr int kTile = 1536;  // fine samples a side (a multiple of 2, 3 and 4): 18 MB of half floats
  const int fw = width * fine, fh = height * fine;
  std::vector<size_t> at(runs.size() + 1, 0);  // each run's first value in the result
  for (size_t k = 0; k < runs.size(); ++k) at[k + 1] = at[k] + size_t(runs[k].length) * size_t(fine * fine) * 4;
  std::vector<float> out(at.back()), band;
  for (int ty = 0; ty < fh; ty += kTile)
    for (int tx = 0; tx < fw; tx += kTile) {
      const int tw = std::min(kTile, fw - tx), th = std::min(kTile, fh - ty);
      // A run's fine block in this tile, rows top-down (empty where it is not in it).
      auto block = [&](const PixelRun& r) {
        return PixelRect{std::max(r.x * fine, tx), std::max(r.y * fine, ty),
                         std::min((r.x + r.length) * fine, tx + tw) - std::max(r.x * fine, tx),
                         std::min((r.y + 1) * fine, ty + th) - std::max(r.y * fine, ty)};
      };
      std::vector<PixelRect> rects;  // in GL's rows from the bottom of the tile
      std::vector<std::pair<size_t, PixelRect>> blocks;  // the runs in this tile and their blocks
      for (size_t k = 0; k < runs.size(); ++k)
        if (const PixelRect b = block(runs[k]); b.w > 0 && b.h > 0) {
          rects.push_back({b.x - tx, th - (b.y + b.h - ty), b.w, b.h});
          blocks.emplace_back(k, b);
        }
      if (rects.empty()) continue;
      FrameState tile = f;  // the fine picture's part f.view, in fractions of this tile
      tile.view = {(f.view.x * fw - tx) / tw, (f.view.y * fh - ty) / th, f.view.width * fw / tw,
                   f.view.height * fh / th};
      RenderTarget target(tw, th, linear ? RenderTarget::Format::Rgba16F : RenderTarget::Format::Rgba8);
      draw_picture(tile, tw, th, DebugView::None, 0, linear, &rects);
      glPixelStorei(GL_PACK_ALIGNMENT, 4);
      for (size_t i = 0; i < blocks.size(); ++i) {
        const auto& [k, b] = blocks[i];
        const PixelRun& r = runs[k];
        const PixelRect& g = rects[i];
        band.resize(size_t(g.w) * size_t(g.h) * 4);
        if (linear) {
          glReadPixels(g.x, g.y, g.w, g.h, GL_RGBA, GL_FLOAT, band.data());
        } else {  // display values, decoded as samples_from_display decodes the picture's
          Image bytes{g.w, g.h, std::vector<std::uint8_t>(band.size())};
          glReadPixels(g.x, g.y, g.w, g.h, GL_RGBA, GL_UNSIGNED_BYTE, bytes.rgba.data());
          band = samples_from_display(bytes);
        }
        for (int j = 0; j < g.h; ++j) {  // band row j is fine row b.y + b.h - 1 - j (top-down)
          const int row = b.y + b.h - 1 - j - r.y * fine;
          float* dst = &out[at[k] + (size_t(row) * size_t(r.length * fine) + size_t(b.x - r.x * fine)) * 4];
          std::copy_n(&band[size_t(j) * size_t(g.w) * 4], size_t(g.w) * 4, dst);
        }
      }
    }
  return out;
}

DebugImage Renderer::render_debug(const FrameState& f, int width, int height, DebugView view, int event) {
  RenderTarget target(width, height, RenderTarget::Format::Rgba32F);
  draw(f, width, height, view, event);
  return DebugImage{width, height, read_float_rows(width, height)};
}

Image visualize_debug(const DebugImage& d, DebugView view, DepthRange depth) {
  Image img{d.width, d.height, std::vector<std::uint8_t>(size_t(d.width) * size_t(d.height) * 4, 255)};
  float tmin = float(depth.near), tmax = float(depth.far);
  if (!(depth.far > depth.near)) {
    tmin = 1e30f, tmax = 0;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x)
        if (d.px(x, y)[0] > 0 && view == DebugView::Depth) {
          tmin = std::min(tmin, d.px(x, y)[0]);
          tmax = std::max(tmax, d.px(x, y)[0]);
        }
  }
  static const std::uint8_t palette[10][3] = {{0, 0, 0},      {90, 90, 90},   {80, 160, 255}, {255, 140, 40},
                                              {240, 240, 60}, {200, 60, 200}, {60, 200, 120}, {255, 60, 60},
                                              {150, 220, 255}, {255, 170, 170}};
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) {
      const float* s = d.px(x, y);
      std::uint8_t* o = img.px(x, y);
      if (view == DebugView::Depth) {
        const float u = std::clamp((s[0] - tmin) / std::max(tmax - tmin, 1e-6f), 0.0f, 1.0f);
        const float v = s[0] > 0 ? 1.0f - 0.85f * u : 0.0f;
        o[0] = o[1] = o[2] = std::uint8_t(std::lround(v * 255));
      } else if (view == DebugView::Normal) {
        for (int c = 0; c < 3; ++c) o[c] = std::uint8_t(std::lround(std::clamp(s[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255));
        if (s[3] == 0) o[0] = o[1] = o[2] = 0;
      } else if (view == DebugView::Cost) {  // 0 tests black, 64 or more white
        o[0] = o[1] = o[2] = std::uint8_t(std::lround(std::clamp(s[0] / 64.0f, 0.0f, 1.0f) * 255));
      } else {
        // Material, PathEvent: the material id; MediumRule: the medium.
        const float id = view == DebugView::MediumRule ? s[0] : s[1];
        int m = std::clamp(int(std::lround(id)), 0, 9);
        for (int c = 0; c < 3; ++c) o[c] = palette[m][c];
      }
    }
  return img;
}

}  // namespace draught::gpu
