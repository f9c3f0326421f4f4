#include "gpu/renderer.hpp"

#include "core/bubbles/bubble_view.hpp"
#include "core/scene/camera.hpp"
#include "gpu/program.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace draught::gpu {

FrameUniforms pack_uniforms(const FrameState& f, int width, int height, DebugView debug) {
  // Today's pass draws the first vessel of the scene (the multi-object pass replaces this).
  const SceneParams& p = f.params;
  const VesselFrame& vf = f.vessels.front();
  const VesselParams& vp = vf.params;
  const Vessel& v = vf.vessel;
  FrameUniforms u{};
  CameraBasis cam = camera_basis(f.camera, width, height);
  u.cam_eye = {cam.eye, cam.tan_half_vfov};
  u.cam_right = {cam.right, cam.aspect};
  u.cam_up = {cam.up, 0};
  u.cam_forward = {cam.forward, 0};
  u.viewport = {width, height, 1.0f / width, 1.0f / height};
  u.vessel = {v.height, v.base, v.dy, 1.0 / v.dy};
  u.rim = {v.rim_major, v.rim_minor, v.bound_radius, v.r_outer.front()};
  u.glass = {vp.glass.ior, vp.glass.roughness, v.inner_radius(v.base), vf.mean_outer_radius};
  u.glass_absorb = {vp.glass.absorption, 0};
  u.liquid_plane = {glm::vec3(vf.liquid.n), vf.liquid_fraction};
  u.liquid = {vp.liquid.ior, vp.liquid.roughness, vp.liquid.haze, vf.has_liquid ? 1.0f : 0.0f};
  u.liquid_absorb = {vf.liquid_absorption, 0};
  u.haze_color = {vp.liquid.haze_color, 0};
  glm::vec3 ld = glm::length(p.light.direction) > 1e-6f ? glm::normalize(p.light.direction) : glm::vec3(0, 1, 0);
  u.light_dir = {ld, p.light.intensity};
  u.light_color = {p.light.color, std::cos(glm::radians(p.light.size))};
  const bool floor = p.env.floor && !p.render.transparent;
  u.env = {float(p.env.mode), p.env.strip_intensity, p.env.backdrop_glow, floor ? 1.0f : 0.0f};
  u.env_color = {p.env.color, 0};
  u.sky_top = {p.env.sky_top, 0};
  u.sky_horizon = {p.env.sky_horizon, 0};
  u.ground = {p.env.ground, 0};
  u.floor_a = {p.env.floor_a, p.env.checker_size};
  u.floor_b = {p.env.floor_b, 0};
  u.output = {float(p.render.tonemap), p.render.exposure, p.render.transparent ? 1.0f : 0.0f, float(debug)};
  if (debug == DebugView::Material) u.output.w = float(DebugView::Depth);  // same channels
  u.limits = {p.render.max_events, 0, 0, 0};
  const glm::dmat3 rot = glm::mat3_cast(vf.pose.orientation);
  u.pose_x = {glm::vec3(rot[0]), 0};
  u.pose_y = {glm::vec3(rot[1]), 0};
  u.pose_z = {glm::vec3(rot[2]), 0};
  u.pose_pos = {glm::vec3(vf.pose.position), 0};
  const SurfaceWaves& w = vf.liquid.waves;
  u.waves = {w.ring, w.cross.x, w.cross.y, w.radius};
  const FoamFrame& fo = vf.foam;
  const FoamParams& fp = vp.foam;
  const bool head = vf.has_liquid && fo.thickness > 1e-4;
  u.foam = {fo.thickness, fo.dome, fp.density, head ? 1.0f : 0.0f};
  u.foam_color = {fp.color, fp.anisotropy};
  u.foam_detail = {fp.multiscatter, fp.bubble_size, fp.detail, float(head ? fo.bubbles.size() : 0)};
  const size_t rings = std::min<size_t>(fo.lacing.size(), 8);
  u.lacing_info = {float(rings), fp.lacing, 0, 0};
  for (size_t i = 0; i < rings; ++i) u.lacing[i / 4][int(i % 4)] = float(fo.lacing[i]);
  // Big bubbles sit in the head's top, their caps standing out by 70 % of their radius.
  const glm::dvec3 n = vf.liquid.n;
  for (size_t i = 0; i < std::min<size_t>(fo.bubbles.size(), 12); ++i) {
    const BigBubble& b = fo.bubbles[i];
    const double y = (vf.liquid.offset - n.x * b.xz.x - n.z * b.xz.y) / std::max(n.y, 1e-3);
    const glm::dvec3 c = glm::dvec3(b.xz.x, y, b.xz.y) +
                         n * (fo.thickness_at(b.xz.x, b.xz.y, vf.liquid.waves.radius) - 0.3 * b.radius);
    u.bubbles[i] = {glm::vec3(c), b.popped ? -b.radius : b.radius};
  }
  u.clip = glm::vec4(scene_geometry(f).vessels.front().clip);  // normalised there; (0, 0, 0, 1) when off
  for (int k = 0; k <= Vessel::kSegments; ++k) u.knots[k] = {v.r_outer[size_t(k)], v.r_inner[size_t(k)], 0, 0};
  return u;
}

RenderTarget::RenderTarget(int w, int h, bool float_target) {
  glGenTextures(1, &tex_);
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexStorage2D(GL_TEXTURE_2D, 1, float_target ? GL_RGBA32F : GL_RGBA8, w, h);
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

namespace {
// The source with `#define name 1` right after its #version line (line numbers kept).
ShaderSource with_define(ShaderSource src, const std::string& name) {
  const size_t eol = src.text.find('\n');
  src.text.insert(eol + 1, "#define " + name + " 1\n#line 2 0\n");
  return src;
}
}  // namespace

std::unique_ptr<Program> Renderer::build_program(int variant) const {
  ShaderSource vert = assemble_shader("fullscreen.vert.glsl", shader_dir_);
  ShaderSource frag = assemble_shader("vessel.frag.glsl", shader_dir_);
  if (variant & kWaves) frag = with_define(std::move(frag), "SURFACE_WAVES");
  if (variant & kFoam) frag = with_define(std::move(frag), "FOAM_HEAD");
  auto program = std::make_unique<Program>(vert, frag);
  GLuint block = glGetUniformBlockIndex(program->id(), "Frame");
  if (block == GL_INVALID_INDEX) throw ShaderError("vessel.frag.glsl: uniform block 'Frame' is missing");
  GLint size = 0;
  glGetActiveUniformBlockiv(program->id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
  if (size_t(size) != sizeof(FrameUniforms))
    throw ShaderError("common.glsl: uniform block 'Frame' is " + std::to_string(size) +
                      " bytes but gpu/uniforms.hpp FrameUniforms is " + std::to_string(sizeof(FrameUniforms)));
  glUniformBlockBinding(program->id(), block, 0);
  glUseProgram(program->id());
  glUniform1i(glGetUniformLocation(program->id(), "u_fill_table"), 0);
  return program;
}

Renderer::Renderer(const std::filesystem::path& shader_dir) : shader_dir_(shader_dir) {
  if (const char* env = std::getenv("DRAUGHT_SHADER_DIR"); shader_dir_.empty() && env && *env) shader_dir_ = env;
  programs_[0] = build_program(0);  // compiles now, so a broken shader is reported at once
  // The fill table: R32F, fetched texel by texel (float textures need not filter in ES 3.0).
  glGenTextures(1, &fill_tex_);
  glBindTexture(GL_TEXTURE_2D, fill_tex_);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32F, FillTable::kVolumes, FillTable::kTilts);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &ubo_);
  glBindBuffer(GL_UNIFORM_BUFFER, ubo_);
  glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameUniforms), nullptr, GL_DYNAMIC_DRAW);
}

Renderer::~Renderer() {
  glDeleteBuffers(1, &bubble_vbo_);
  glDeleteVertexArrays(1, &bubble_vao_);
  glDeleteTextures(1, &fill_tex_);
  glDeleteBuffers(1, &ubo_);
  glDeleteVertexArrays(1, &vao_);
}

void Renderer::draw(const FrameState& f, int width, int height, DebugView debug) {
  FrameUniforms u = pack_uniforms(f, width, height, debug);
  glBindBuffer(GL_UNIFORM_BUFFER, ubo_);
  glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof u, &u);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, fill_tex_);
  if (f.vessels.front().fill_table && f.vessels.front().fill_table != uploaded_table_) {  // only when the glass changed
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, FillTable::kVolumes, FillTable::kTilts, GL_RED, GL_FLOAT,
                    f.vessels.front().fill_table->offset.data());
    uploaded_table_ = f.vessels.front().fill_table;
  }
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  // Only the code a frame needs: waves and foam are compiled in when present (software
  // rasterizers pay for code even where a uniform branch skips it). Built when first used.
  const VesselFrame& vf = f.vessels.front();
  const SurfaceWaves& w = vf.liquid.waves;
  const bool waves = vf.has_liquid && !w.flat();
  const bool foam = vf.has_liquid && vf.foam.thickness > 1e-4;
  const int variant = (waves ? kWaves : 0) | (foam ? kFoam : 0);
  auto& program = programs_[variant];
  if (!program) program = build_program(variant);
  glUseProgram(program->id());
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (debug == DebugView::None) draw_bubbles(f, width, height);
}

void Renderer::draw_bubbles(const FrameState& f, int width, int height) {
  const std::vector<BubbleSprite> sprites = bubble_sprites(f, width, height);
  if (sprites.empty()) return;
  if (!bubble_program_) {
    bubble_program_ = std::make_unique<Program>(assemble_shader("bubbles.vert.glsl", shader_dir_),
                                                assemble_shader("bubbles.frag.glsl", shader_dir_));
    glGenVertexArrays(1, &bubble_vao_);
    glGenBuffers(1, &bubble_vbo_);
    glBindVertexArray(bubble_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, bubble_vbo_);
    for (GLuint a = 0; a < 2; ++a) {  // per instance: sprite, tint
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 4, GL_FLOAT, GL_FALSE, 8 * sizeof(float), reinterpret_cast<void*>(a * 4 * sizeof(float)));
      glVertexAttribDivisor(a, 1);
    }
  }
  std::vector<float> data;
  data.reserve(sprites.size() * 8);
  for (const BubbleSprite& s : sprites)
    data.insert(data.end(), {s.centre.x, s.centre.y, s.radius, 0.0f, s.tint.r, s.tint.g, s.tint.b, 0.0f});
  glBindVertexArray(bubble_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, bubble_vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STREAM_DRAW);
  const SceneParams& p = f.params;
  const GLuint id = bubble_program_->id();
  glUseProgram(id);
  // What a bubble mirrors: the studio around it (its lights are several times the sky).
  const glm::vec3 sky = p.env.mode == int(EnvMode::Constant) ? p.env.color : 0.5f * (p.env.sky_top + p.env.sky_horizon);
  const glm::vec3 env = sky * 2.0f + glm::vec3(0.15f * p.env.strip_intensity + 0.1f * p.env.backdrop_glow);
  const CameraBasis cam = camera_basis(f.camera, width, height);
  const glm::vec3 l = glm::length(p.light.direction) > 1e-6f ? glm::normalize(p.light.direction) : glm::vec3(0, 1, 0);
  glUniform2f(glGetUniformLocation(id, "u_viewport"), float(width), float(height));
  glUniform3fv(glGetUniformLocation(id, "u_env_light"), 1, &env.x);
  const glm::vec3 glint = p.light.color * p.light.intensity * 0.8f;
  glUniform3fv(glGetUniformLocation(id, "u_glint"), 1, &glint.x);
  glUniform2f(glGetUniformLocation(id, "u_glint_dir"), 0.45f * glm::dot(l, cam.right), -0.45f * glm::dot(l, cam.up));
  glUniform1f(glGetUniformLocation(id, "u_exposure"), p.render.exposure);
  glUniform1i(glGetUniformLocation(id, "u_tonemap"), p.render.tonemap);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(sprites.size()));
  glDisable(GL_BLEND);
  glBindVertexArray(vao_);
}

void Renderer::finish() { glFinish(); }

Image Renderer::render(const FrameState& f, int width, int height) {
  const int ss = std::clamp(f.params.render.supersample, 1, 4);
  const int w = width * ss, h = height * ss;
  RenderTarget target(w, h, false);
  draw(f, w, h);
  Image img{w, h, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4)};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  // GL rows are bottom-up; images are top-down.
  for (int y = 0; y < h / 2; ++y)
    std::swap_ranges(img.px(0, y), img.px(0, y) + size_t(w) * 4, img.px(0, h - 1 - y));
  return downsample(img, ss);
}

DebugImage Renderer::render_debug(const FrameState& f, int width, int height, DebugView view) {
  RenderTarget target(width, height, true);
  draw(f, width, height, view);
  DebugImage out{width, height, std::vector<float>(size_t(width) * size_t(height) * 4)};
  std::vector<float> rows(out.rgba.size());
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rows.data());
  for (int y = 0; y < height; ++y)
    std::copy_n(&rows[size_t(height - 1 - y) * size_t(width) * 4], size_t(width) * 4,
                &out.rgba[size_t(y) * size_t(width) * 4]);
  return out;
}

Image visualize_debug(const DebugImage& d, DebugView view) {
  Image img{d.width, d.height, std::vector<std::uint8_t>(size_t(d.width) * size_t(d.height) * 4, 255)};
  float tmin = 1e30f, tmax = 0;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x)
      if (d.px(x, y)[0] > 0 && view == DebugView::Depth) {
        tmin = std::min(tmin, d.px(x, y)[0]);
        tmax = std::max(tmax, d.px(x, y)[0]);
      }
  static const std::uint8_t palette[10][3] = {{0, 0, 0},      {90, 90, 90},   {80, 160, 255}, {255, 140, 40},
                                              {240, 240, 60}, {200, 60, 200}, {60, 200, 120}, {255, 60, 60},
                                              {150, 220, 255}, {255, 170, 170}};
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) {
      const float* s = d.px(x, y);
      std::uint8_t* o = img.px(x, y);
      if (view == DebugView::Depth) {
        float v = s[0] > 0 ? 1.0f - 0.85f * (s[0] - tmin) / std::max(tmax - tmin, 1e-6f) : 0.0f;
        o[0] = o[1] = o[2] = std::uint8_t(std::lround(v * 255));
      } else if (view == DebugView::Normal) {
        for (int c = 0; c < 3; ++c) o[c] = std::uint8_t(std::lround(std::clamp(s[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255));
        if (s[3] == 0) o[0] = o[1] = o[2] = 0;
      } else if (view == DebugView::Cost) {  // 0 tests black, 64 or more white
        o[0] = o[1] = o[2] = std::uint8_t(std::lround(std::clamp(s[0] / 64.0f, 0.0f, 1.0f) * 255));
      } else {
        int m = std::clamp(int(std::lround(s[1])), 0, 9);
        for (int c = 0; c < 3; ++c) o[c] = palette[m][c];
      }
    }
  return img;
}

}  // namespace draught::gpu
