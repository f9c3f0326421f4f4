#include "gpu/scene_data.hpp"

#include "core/pointcloud/glow_light.hpp"

#include "core/foam/head_volume.hpp"
#include "core/liquid/haze.hpp"
#include "core/output/cutout.hpp"
#include "core/scene/camera.hpp"
#include "gpu/condensation_textures.hpp"
#include "gpu/decal_textures.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

namespace draught::gpu {

contract::FrameBlock pack_frame_block(const FrameState& f, int width, int height, DebugView debug, int debug_event) {
  const SceneParams& p = f.params;
  contract::FrameBlock b{};
  const CameraBasis cam = camera_basis(f, width, height);
  b.cam_eye = cam.eye;
  b.cam_tan_half_vfov = cam.tan_half_vfov;
  b.cam_right = cam.right;
  b.cam_aspect = cam.aspect;
  b.cam_up = cam.up;
  b.cam_forward = cam.forward;
  b.cam_shift = cam.shift;
  b.object_count = int(f.vessels.size());
  b.max_events = p.render.max_events;
  b.viewport_size = {width, height};
  b.viewport_inv = {1.0f / width, 1.0f / height};
  // The studio's rig (at most MAX_LIGHTS lights: key, strips, backlight) and backdrop.
  const int lights = std::min<int>(int(f.lights.lights.size()), contract::kMaxLights);
  b.light_count = lights;
  for (int i = 0; i < lights; ++i) {
    const AreaLight& l = f.lights.lights[size_t(i)];
    b.light_center[i] = {glm::vec3(l.center), float(l.radius)};
    b.light_normal[i] = {glm::vec3(l.normal), float(int(l.shape))};
    const double bound = l.shape == LightShape::Sphere ? l.radius : glm::length(l.half_u) + glm::length(l.half_v);
    b.light_half_u[i] = {glm::vec3(l.half_u), float(bound)};
    b.light_half_v[i] = {glm::vec3(l.half_v), l.camera_visible ? 1.0f : 0.0f};
    if (l.shape == LightShape::Rect) {
      const double lu = glm::length(l.half_u), lv = glm::length(l.half_v);
      b.light_extent[i] = {float(lu), float(lv), float(4.0 * lu * lv), 0.0f};
    }
    b.light_radiance[i] = {glm::vec3(l.radiance), 0.0f};
  }
  for (int i = 0; i < 9; ++i) b.sky_sh[i] = {glm::vec3(f.environment.sky.coef[size_t(i)]), 0.0f};
  b.backdrop_kind = f.backdrop.kind == Backdrop::Checker ? 1 : f.backdrop.plane ? 2 : 0;
  b.sweep_z_curve = float(f.backdrop.z_curve);
  b.sweep_radius = float(f.backdrop.radius);
  b.sweep_albedo = glm::vec3(f.backdrop.sweep_albedo);
  b.cutout_light = glm::vec3(cutout_light(f));
  for (int i = 0; i < 9; ++i) b.surround_sh[i] = {glm::vec3(f.environment.surround.coef[size_t(i)]), 0.0f};
  if (const PaperBounceMap* m = f.environment.paper_bounce.get(); m && !m->empty()) {
    b.paper_bounce_rect = glm::vec4(glm::vec2(m->origin), glm::vec2(m->size));
    for (size_t k = 0; k < m->bounce.size(); ++k) b.paper_bounce[k] = {glm::vec3(m->bounce[k]), 0.0f};
  } else {
    b.paper_bounce_rect = glm::vec4(0.0f);
  }
  // What heads and haze take: the rig, or an image's brightest patches (core media_light).
  const MediaLight& media = f.environment.media;
  b.media_light_count = std::min<int>(int(media.lights.size()), contract::kMaxLights);
  for (int i = 0; i < b.media_light_count; ++i) b.media_light_radiance[i] = {glm::vec3(media.lights[size_t(i)].radiance), 0.0f};
  for (int i = 0; i < 9; ++i) b.media_sh[i] = {glm::vec3(media.surround.coef[size_t(i)]), 0.0f};
  b.env_mode = p.env.mode;
  b.strip_intensity = p.env.strip_intensity;
  b.backdrop_glow = p.env.backdrop_glow;
  b.floor_on = p.env.floor;  // (a transparent picture's glass mirrors it too; no path of its own meets it)
  b.env_color = p.env.color;
  b.checker_size = p.env.checker_size;
  b.sky_top = p.env.sky_top;
  b.exposure = p.render.exposure;
  b.matcap_tint = p.matcap.tint;
  b.matcap_edge_range = p.matcap.edge_range;
  b.matcap_edge_intensity = p.matcap.edge_intensity;
  b.matcap_refraction = p.matcap.refraction;
  b.matcap_thickness = p.matcap.thickness;
  b.sky_horizon = p.env.sky_horizon;
  b.tonemap = p.render.tonemap;
  b.ground = p.env.ground;
  b.transparent = p.render.transparent;
  b.exclude_object = -1;  // (the PANORAMA variant's: gpu/reflection_panoramas)
  b.floor_a = p.env.floor_a;
  b.debug_view = int(debug);
  b.floor_b = p.env.floor_b;
  b.debug_event = debug_event;
  b.bubble_env = f.environment.reflected;
  b.glint_dir = f.environment.glint_dir;
  b.glint = f.environment.glint;
  if (const EnvironmentMap* m = f.environment.image.get()) {
    b.env_rotation = {f.environment.rotation_cos, f.environment.rotation_sin};
    b.env_intensity = f.environment.intensity;
    b.env_blur_lod = f.environment.blur_lod;
    b.env_max_lod = float(m->levels.size() - 1);
    b.env_texels_per_radian = float(m->width() / (2 * 3.14159265358979));
  }
  pack_droplets(f.droplets, b);
  return b;
}

void pack_droplets(const std::vector<DropletsFrame>& droplets, contract::FrameBlock& b) {
  // Every droplet member first (what the MatCap background's key clears, gpu/renderer).
  b.droplet_count = b.droplet_kernel = 0;
  b.droplet_blend = b.droplet_noise_amplitude = b.droplet_noise_frequency = b.droplet_lipschitz = 0.0f;
  b.droplet_margin = b.droplet_ior = b.droplet_roughness = 0.0f;
  b.droplet_absorption = b.droplet_bound_lo = b.droplet_bound_hi = glm::vec3(0.0f);
  for (glm::vec4& s : b.droplet_spheres) s = glm::vec4(0.0f);
  if (droplets.empty()) return;  // (at most one droplets object: core/params/preset.cpp)
  const DropletsFrame& d = droplets.front();
  const DropletField& field = d.field;
  const DropletBounds box = droplet_bounds(field);
  b.droplet_count = box.empty ? 0 : int(std::min(field.spheres.size(), size_t(kMaxDroplets)));
  b.droplet_kernel = int(field.kernel);
  b.droplet_blend = float(field.blend);
  b.droplet_noise_amplitude = float(field.noise_amplitude);
  b.droplet_noise_frequency = float(field.noise_frequency);
  b.droplet_lipschitz = float(droplet_lipschitz(field));
  b.droplet_margin = float(droplet_margin(field));
  b.droplet_ior = d.params.ior;
  b.droplet_roughness = d.params.roughness;
  b.droplet_absorption = d.params.absorption;
  b.droplet_bound_lo = glm::vec3(box.lo - 2.0 * kDropletSkim);
  b.droplet_bound_hi = glm::vec3(box.hi + 2.0 * kDropletSkim);
  for (int i = 0; i < b.droplet_count; ++i)
    b.droplet_spheres[i] = glm::vec4(glm::vec3(field.spheres[size_t(i)].centre), float(field.spheres[size_t(i)].radius));
}

void pack_clouds(const FrameState& f, const CloudScene& clouds, contract::FrameBlock& b) {
  // The glow's table: the same for every frame (the shader interpolates it in 1/T).
  const std::vector<glm::vec4>& table = picture_blackbody_table();
  for (int i = 0; i < contract::kBlackbodyEntries; ++i) b.blackbody[i] = table[size_t(i)];
  const std::vector<CloudRange>& ranges = clouds.ranges();
  b.cloud_count = int(std::min({f.clouds.size(), ranges.size(), size_t(contract::kMaxClouds)}));
  for (int i = 0; i < b.cloud_count; ++i) {
    const CloudFrame& c = f.clouds[size_t(i)];
    const CloudRange& r = ranges[size_t(i)];
    b.cloud_ref[i] = glm::vec4(float(r.root), c.threshold, r.min_support, float(c.material));
    b.cloud_lo[i] = glm::vec4(r.lo, c.ior);
    b.cloud_hi[i] = glm::vec4(r.hi, c.roughness);
    b.cloud_absorption[i] = glm::vec4(c.absorption, c.temperature);
    b.cloud_glow[i] = glm::vec4(float(c.glow * kGlowPerNit), c.glow_depth > 0 ? 1.0f / c.glow_depth : 0.0f, 0.0f, 0.0f);
    const GlowSphere glow = cloud_glow_sphere(c);
    b.cloud_glow_sphere[i] = glm::vec4(glm::vec3(glow.centre), float(glow.radius));
    b.cloud_glow_radiance[i] = glm::vec4(glm::vec3(glow.radiance), 0.0f);
  }
}

contract::ObjectRecord pack_object(const FrameState& f, int row) {
  const VesselFrame& vf = f.vessels[size_t(row)];
  const VesselParams& vp = vf.params;
  const Vessel& v = vf.vessel;
  contract::ObjectRecord r{};
  // bounds: the local bounding cylinder (walls and rim bead) in the world
  r.bound_base = glm::vec3(vf.pose.position);
  r.bound_axis = glm::vec3(vf.pose.orientation * glm::dvec3(0, 1, 0));
  r.bound_radius = float(v.bound_radius);
  r.bound_length = float(v.height + v.rim_minor);
  // body: what the floor needs (contact), the size and the drink
  r.height = float(v.height);
  r.foot_radius = float(v.r_outer.front());
  r.mean_outer_radius = float(vf.mean_outer_radius);
  r.absorption_fast = vf.liquid_absorption.fast;
  r.absorption_slow = vf.liquid_absorption.slow;
  r.absorption_share = vf.liquid_absorption.share;
  r.has_liquid = vf.has_liquid ? 1 : 0;
  // The cross-section as the reference intersector has it (normalised; off: 0, 0, 0, 1),
  // and in the world for the floor, which sees no rotation.
  const glm::dvec4 clip = scene_geometry(f).vessels[size_t(row)].clip;
  const glm::dvec3 clip_world = vf.pose.orientation * glm::dvec3(clip);
  r.clip_world_normal = glm::vec3(clip_world);
  r.clip_world_offset = float(clip.w + glm::dot(clip_world, vf.pose.position));
  // shape
  const glm::dmat3 rot = glm::mat3_cast(vf.pose.orientation);
  r.rot_x = glm::vec3(rot[0]);
  r.rot_y = glm::vec3(rot[1]);
  r.rot_z = glm::vec3(rot[2]);
  r.position = glm::vec3(vf.pose.position);
  r.base = float(v.base);
  r.dy = float(v.dy);
  r.inv_dy = float(1.0 / v.dy);
  r.rim_major = float(v.rim_major);
  r.rim_minor = float(v.rim_minor);
  r.cavity_floor_radius = float(v.inner_radius(v.base));
  r.clip_normal = glm::vec3(clip);
  r.clip_offset = float(clip.w);
  r.knot_row = row;
  const bool head = has_head(vf);
  r.has_head = head ? 1 : 0;
  // liquid: the plane core solved (volume-true, never above the lowest rim point)
  r.plane_normal = glm::vec3(vf.liquid.n);
  r.plane_offset = float(vf.liquid.offset);
  const SurfaceWaves& w = vf.liquid.waves;
  r.wave_ring = float(w.ring);
  r.wave_cos2a = float(w.cross.x);
  r.wave_sin2a = float(w.cross.y);
  r.wave_radius = float(w.radius);
  r.dimple = {float(w.dimple_xz.x), float(w.dimple_xz.y), float(w.dimple_radius), float(w.dimple_depth)};
  r.ior = vp.liquid.ior;
  r.haze = vp.liquid.haze;
  r.roughness = vp.liquid.roughness;
  // Each light the media take (the rig's, or an image's brightest patches: core
  // media_light) as a distant light from the glass's middle: what the head and the haze
  // receive (small lights far from small glasses: the irradiance barely varies over one).
  const glm::dvec3 middle = vessel_middle(vf);
  const MediaLight& media = f.environment.media;
  const int lights = std::min<int>(int(media.lights.size()), contract::kMaxLights);
  // The haze's light (isotropic scattering): the surroundings' mean radiance, held beyond
  // the wall, and each light's irradiance over 4 pi from its side, both falling off
  // inwards as diffusion's kappa (core/liquid/haze.hpp; a hefeweizen's liquid against the
  // reference 2.82 -> 1.31 where one tint at 0.7 of the mean radius served the whole
  // drink: the side the key lights and the edges came out dark and too saturated).
  const glm::dvec3 surround = mean_radiance(media.surround);
  glm::dvec3 haze_in = surround;
  for (int i = 0; i < lights; ++i) {
    const AreaLight& l = media.lights[size_t(i)];
    const glm::dvec3 to = glm::normalize(l.center - middle);
    r.lit_by[i] = {glm::vec3(to), float(l.irradiance_factor(middle, to))};
    haze_in += glm::dvec3(l.radiance) * double(r.lit_by[i].w) / (4.0 * std::numbers::pi);
  }
  const HazeDiffusion haze =
      haze_diffusion(vp.liquid.haze, glm::dvec3(vp.liquid.haze_color), glm::dvec3(vf.liquid_absorption.effective()),
                     vp.glass.ior);
  r.haze_albedo = vp.liquid.haze_color;
  r.haze_surround = glm::vec3(surround);
  r.haze_kappa = glm::vec3(haze.kappa);
  r.haze_reach = glm::vec3(haze.reach);
  // The MatCap tier takes all of it as even light, the field's mean over the drink's
  // cross-section (of the mean outer radius: the walls' thickness is small beside it).
  r.haze_light = glm::vec3(glm::dvec3(vp.liquid.haze_color) * haze_in *
                           haze_field_mean(haze, double(vf.mean_outer_radius)));
  // glass
  r.glass_absorption = vp.glass.absorption;
  r.glass_ior = vp.glass.ior;
  r.glass_roughness = vp.glass.roughness;
  // foam
  const FoamFrame& fo = vf.foam;
  const FoamParams& fp = vp.foam;
  r.thickness = float(fo.thickness);
  r.dome = float(fo.dome);
  r.crater = {float(fo.crater_xz.x), float(fo.crater_xz.y), float(fo.crater_radius), float(fo.crater_depth)};
  r.density = fp.density;
  r.anisotropy = fp.anisotropy;
  r.foam_color = glm::vec3(foam_single_scattering_albedo(glm::dvec3(fp.color), fp.anisotropy));
  r.under_chord = float(drink_mean_chord(vf));
  r.wall_diffuse = float(wall_diffuse_transmittance(vp.glass.ior));
  r.bubble_size = fp.bubble_size;
  r.detail = fp.detail;
  const int bubbles = head ? std::min<int>(int(vf.big_bubbles.size()), contract::kMaxBigBubbles) : 0;
  r.big_bubble_count = bubbles;
  for (int i = 0; i < bubbles; ++i) {
    const PlacedBubble& b = vf.big_bubbles[size_t(i)];
    r.big_bubbles[i] = {glm::vec3(b.centre), float(b.popped ? -b.radius : b.radius)};
  }
  // Lacing is drawn with the head (as the renderer always did).
  const int rings = head ? std::min<int>(int(fo.lacing.size()), contract::kMaxLacing) : 0;
  r.lacing_count = rings;
  r.lacing_strength = fp.lacing;
  for (int i = 0; i < rings; ++i) r.lacing[i] = float(fo.lacing[size_t(i)]);
  for (int i = 0; i < 9; ++i) r.head_sh[i] = {glm::vec3(vf.head_surround.coef[size_t(i)]), 0.0f};
  pack_decals(f, row, r);        // gpu/decal_textures
  pack_condensation(f, row, r);  // gpu/condensation_textures
  return r;
}

std::vector<glm::vec4> pack_knots(const Vessel& v) {
  std::vector<glm::vec4> row(static_cast<size_t>(contract::kSegments));
  for (size_t k = 0; k < row.size(); ++k)
    row[k] = glm::vec4(glm::dvec4(v.r_outer[k], v.r_inner[k], v.r_outer[k + 1], v.r_inner[k + 1]));
  return row;
}

namespace {
void make_texture(unsigned& tex, int width, int rows) {
  if (tex) glDeleteTextures(1, &tex);
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, rows);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}
}  // namespace

std::vector<glm::vec4> pack_floor_light(const FloorLightMap& m) {
  std::vector<glm::vec4> texels;
  texels.reserve(m.factor.size() + m.surround_factor.size());
  for (const glm::vec3& f : m.factor) texels.emplace_back(f, 1.0f);
  for (const glm::vec3& f : m.surround_factor) texels.emplace_back(f, 1.0f);
  return texels;
}

std::vector<glm::vec4> pack_backdrop_light(const BackdropLightMap& m) {
  std::vector<glm::vec4> texels(m.irradiance.size());
  for (size_t k = 0; k < texels.size(); ++k) texels[k] = glm::vec4(m.irradiance[k], m.trusted[k]);
  return texels;
}

namespace {
// Linear filtering of the bound texture (min_filter: within a level, or across mipmaps
// too), clamped to its edges except across when wrap_s is GL_REPEAT.
void set_sampling(GLint min_filter, GLint wrap_s) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_s);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

// A filtered RGBA16F texture of the floor's light factor or the backdrop's light (ES 3.0 and WebGL2 filter
// half floats; they take float data for them).
unsigned make_floor_texture(int width, int height, const float* rgba) {
  unsigned tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, height, 0, GL_RGBA, GL_FLOAT, rgba);
  set_sampling(GL_LINEAR, GL_CLAMP_TO_EDGE);
  return tex;
}

// The environment's chain as one mipmapped RGBA16F texture: level i is the chain's level i,
// and the texture stops there (GL_TEXTURE_MAX_LEVEL), so GL filters exactly as
// EnvironmentMap::radiance does: bilinear in a level, wrapping across, linear between levels.
unsigned make_environment_texture(const EnvironmentMap& m) {
  unsigned tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  std::vector<glm::vec4> rgba;
  for (size_t i = 0; i < m.levels.size(); ++i) {
    const HdrImage& level = m.levels[i];
    rgba.resize(level.rgb.size());
    for (size_t k = 0; k < rgba.size(); ++k) rgba[k] = glm::vec4(level.rgb[k], 1.0f);
    glTexImage2D(GL_TEXTURE_2D, GLint(i), GL_RGBA16F, level.width, level.height, 0, GL_RGBA, GL_FLOAT, rgba.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(m.levels.size() - 1));
  set_sampling(GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT);
  return tex;
}
}  // namespace

void SceneTextures::update_environment(const FrameState& f) {
  environment_uploaded_ = false;
  if (f.environment.image == environment_) return;  // the same map: nothing to do
  glDeleteTextures(1, &environment_tex_);
  environment_tex_ = 0;
  environment_ = f.environment.image;
  if (environment_) {
    environment_tex_ = make_environment_texture(*environment_);
    environment_uploaded_ = true;
  }
}

SceneTextures::SceneTextures() {
  allocate(4);
  const float one[4] = {1, 1, 1, 1};
  neutral_tex_ = make_floor_texture(1, 1, one);
}

SceneTextures::~SceneTextures() {
  clear_floor_light();
  glDeleteTextures(1, &environment_tex_);
  for (BackdropEntry& e : backdrop_cache_) glDeleteTextures(1, &e.tex);
  glDeleteTextures(1, &neutral_tex_);
  glDeleteTextures(1, &objects_tex_);
  glDeleteTextures(1, &knots_tex_);
}

void SceneTextures::allocate(int rows) {
  // Rows are bounded by memory (GL_MAX_TEXTURE_SIZE, >= 2048 in ES 3.0), not by the
  // uniform-block size; grown in powers of two, everything re-uploaded.
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (rows > max_size)
    throw std::runtime_error("a scene of " + std::to_string(rows) + " objects needs more texture rows than this GL driver has (" +
                             std::to_string(max_size) + ")");
  make_texture(objects_tex_, contract::kObjectTexels, rows);
  make_texture(knots_tex_, contract::kSegments, rows);
  capacity_ = rows;
  objects_.clear();
  knots_.clear();
}

void SceneTextures::update(const FrameState& f, int width, int height, bool light_maps) {
  const int n = int(f.vessels.size());
  if (n > contract::kMaxSceneObjects)
    throw std::runtime_error("the scene has " + std::to_string(n) + " objects; the renderer draws at most " +
                             std::to_string(contract::kMaxSceneObjects) + " (kMaxSceneObjects)");
  if (n > capacity_) {
    int rows = capacity_;
    while (rows < n) rows *= 2;
    allocate(rows);
  }
  object_uploads_ = knot_uploads_ = 0;
  objects_.resize(size_t(n));
  knots_.resize(size_t(n));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int i = 0; i < n; ++i) {
    const contract::ObjectRecord r = pack_object(f, i);
    // (Records are value-initialised, padding included, so bytes compare.)
    if (!objects_[size_t(i)] || std::memcmp(&r, &*objects_[size_t(i)], sizeof r) != 0) {
      glBindTexture(GL_TEXTURE_2D, objects_tex_);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, i, contract::kObjectTexels, 1, GL_RGBA, GL_FLOAT, &r);
      objects_[size_t(i)] = r;
      ++object_uploads_;
    }
    std::vector<glm::vec4> k = pack_knots(f.vessels[size_t(i)].vessel);
    if (k != knots_[size_t(i)]) {  // only when the glass changed
      glBindTexture(GL_TEXTURE_2D, knots_tex_);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, i, contract::kSegments, 1, GL_RGBA, GL_FLOAT, k.data());
      knots_[size_t(i)] = std::move(k);
      ++knot_uploads_;
    }
  }
  maps_read_ = light_maps;
  if (light_maps) {
    update_floor_light(f);
    update_backdrop_light(f, backdrop_light_texel(f, width, height));
  } else {
    floor_computed_ = floor_uploaded_ = backdrop_computed_ = false;
  }
  update_environment(f);
}

bool SceneTextures::use_cached_backdrop_light(const std::vector<double>& inputs) {
  for (size_t i = 0; i < backdrop_cache_.size(); ++i)
    if (backdrop_cache_[i].inputs == inputs) {  // unchanged lights and backdrop cost nothing
      std::rotate(backdrop_cache_.begin(), backdrop_cache_.begin() + long(i), backdrop_cache_.begin() + long(i) + 1);
      return true;
    }
  return false;
}

void SceneTextures::update_backdrop_light(const FrameState& f, double texel) {
  backdrop_computed_ = false;
  std::vector<double> inputs = backdrop_light_inputs(f, texel);
  const bool changing = backdrop_drafts_ && inputs != backdrop_last_inputs_;
  backdrop_last_inputs_ = inputs;
  if (use_cached_backdrop_light(inputs)) return;
  if (changing && texel < kBackdropLightCoarsestTexel) {  // a draft while the inputs change (set_backdrop_drafts)
    texel = std::min(4.0 * texel, kBackdropLightCoarsestTexel);
    inputs = backdrop_light_inputs(f, texel);
    if (use_cached_backdrop_light(inputs)) return;
  }
  BackdropEntry e;
  e.inputs = std::move(inputs);
  BackdropLightSettings settings;
  settings.texel = texel;
  e.map = compute_backdrop_light(f, settings);
  backdrop_computed_ = true;
  if (!e.map.empty()) {
    const std::vector<glm::vec4> texels = pack_backdrop_light(e.map);
    e.tex = make_floor_texture(e.map.width, e.map.height, &texels[0].x);
  }
  if (backdrop_cache_.size() == kFloorCache) {
    glDeleteTextures(1, &backdrop_cache_.back().tex);
    backdrop_cache_.pop_back();
  }
  backdrop_cache_.insert(backdrop_cache_.begin(), std::move(e));
}

const BackdropLightMap& SceneTextures::backdrop_light() const {
  static const BackdropLightMap none;
  return backdrop_cache_.empty() ? none : backdrop_cache_.front().map;
}

void SceneTextures::describe_backdrop_light(contract::FrameBlock& b) const {
  const BackdropLightMap& m = backdrop_light();
  const bool on = maps_read_ && !m.empty();
  b.backdrop_light_on = on ? 1 : 0;
  b.backdrop_light_origin = on ? glm::vec2(m.origin) : glm::vec2(0.0f);
  b.backdrop_light_size = on ? glm::vec2(m.size) : glm::vec2(0.0f);
}

void SceneTextures::set_floor_light(const FloorLightSettings& s, bool on, int draft_photons) {
  floor_settings_ = s;
  floor_on_ = on;
  draft_photons_ = draft_photons;
  clear_floor_light();  // computed again on the next update
}

void SceneTextures::set_floor_refinement(int batch_photons, double ms_per_frame) {
  refine_batch_photons_ = std::max(0, batch_photons);
  refine_ms_per_frame_ = std::isfinite(ms_per_frame) ? std::max(0.0, ms_per_frame) : 0.0;
}

void SceneTextures::clear_floor_light() {
  for (FloorEntry& e : floor_cache_) glDeleteTextures(1, &e.tex);
  floor_cache_.clear();
}

void SceneTextures::update_floor_light(const FrameState& f) {
  floor_computed_ = floor_uploaded_ = false;
  // The scene's own budget (render.floor_photons) where it gives one, else the app's.
  FloorLightSettings full = floor_settings_;
  if (f.params.render.floor_photons > 0) full.photons = f.params.render.floor_photons;
  std::vector<double> inputs = floor_light_inputs(f);
  inputs.push_back(full.photons);  // another budget, another map
  bool refine = false;
  for (size_t i = 0; i < floor_cache_.size(); ++i)
    if (floor_cache_[i].inputs == inputs) {  // a still or an unchanged frame costs nothing more
      std::rotate(floor_cache_.begin(), floor_cache_.begin() + long(i), floor_cache_.begin() + long(i) + 1);
      for (size_t k = 1; k < floor_cache_.size(); ++k) floor_cache_[k].settle();
      FloorEntry& front = floor_cache_.front();
      if (front.refining) {
        refine_floor_light(front, 1);
        return;
      }
      drafted_last_ = false;
      if (i > 0 || !front.draft) return;
      // A draft the frame holds still on: traced again in full.
      glDeleteTextures(1, &front.tex);
      floor_cache_.erase(floor_cache_.begin());
      refine = true;
      break;
    }
  // While things keep moving, a draft every other frame (the last one stays a frame
  // longer): half the cost of a moving scene's frames.
  if (draft_photons_ > 0 && !refine && drafted_last_ && floor_on_ && !floor_cache_.empty()) {
    drafted_last_ = false;
    return;
  }
  drafted_last_ = false;
  FloorEntry e;
  e.inputs = std::move(inputs);
  FloorLightSettings s = full;
  if (!floor_on_) {
    // no map: the floor takes the unoccluded light
  } else if (draft_photons_ > 0 && refine) {
    // In batches (a draft's photons unless set_floor_refinement says) on full texels, two
    // drafts' worth at once (one would be noisier than the draft it replaces, whose
    // texels are four times the area).
    const int batch = refine_batch_photons_ > 0 ? std::min(refine_batch_photons_, draft_photons_) : draft_photons_;
    s.photons = std::max(1, std::min(s.photons, batch));
    e.batches_left = std::max(1, (full.photons + s.photons - 1) / s.photons);
    // The surroundings' shadow gathered a share with every batch too (all at once it was
    // most of the first frame's cost).
    s.gather_rays_per_batch = (s.gather_rays + e.batches_left - 1) / e.batches_left;
    e.refining = std::make_unique<FloorLightTrace>(f, s);
    refine_floor_light(e, std::max(1, (2 * draft_photons_ + s.photons - 1) / s.photons));
  } else if (draft_photons_ > 0) {
    e.draft = true;
    drafted_last_ = true;
    e.map = compute_floor_light(f, floor_light_draft(s, draft_photons_));
  } else {
    e.map = compute_floor_light(f, s);
  }
  floor_computed_ = true;
  if (!e.map.empty() && !e.tex) {  // (a refined entry made its texture as it began)
    const std::vector<glm::vec4> texels = pack_floor_light(e.map);
    e.tex = make_floor_texture(e.map.width, 2 * e.map.height, &texels[0].x);
    floor_uploaded_ = true;
  }
  if (floor_cache_.size() == kFloorCache) {
    glDeleteTextures(1, &floor_cache_.back().tex);
    floor_cache_.pop_back();
  }
  for (FloorEntry& old : floor_cache_) old.settle();
  floor_cache_.insert(floor_cache_.begin(), std::move(e));
}

void SceneTextures::refine_floor_light(FloorEntry& e, int min_batches) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  for (int b = 0; e.batches_left > 0; ++b, --e.batches_left) {
    if (b >= min_batches &&
        (refine_ms_per_frame_ <= 0 ||
         std::chrono::duration<double, std::milli>(Clock::now() - start).count() >= refine_ms_per_frame_))
      break;
    e.refining->add_batch();
  }
  floor_computed_ = true;
  // The texture takes the map when the batches have grown by an eighth since it last did
  // (every batch at first, then every few: hundreds of small batches would otherwise
  // merge, pack and upload the whole map hundreds of times for changes too small to see),
  // and when the last batch is in.
  const int batches = e.refining->batches();
  if (e.batches_left > 0 && batches - e.uploaded_batches < std::max(1, e.uploaded_batches / 8)) return;
  e.uploaded_batches = batches;
  const FloorLightMap& m = e.refining->map();
  if (!m.empty()) {
    floor_uploaded_ = true;
    const std::vector<glm::vec4> texels = pack_floor_light(m);
    if (e.tex) {  // the same rect: the texels replaced
      glBindTexture(GL_TEXTURE_2D, e.tex);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m.width, 2 * m.height, GL_RGBA, GL_FLOAT, &texels[0].x);
    } else {
      e.tex = make_floor_texture(m.width, 2 * m.height, &texels[0].x);
    }
  }
  if (e.batches_left == 0) e.settle();  // the full budget: done
}

std::vector<contract::ObjectRecord> SceneTextures::records() const {
  std::vector<contract::ObjectRecord> out;
  for (const auto& r : objects_) out.push_back(*r);
  return out;
}

const FloorLightMap& SceneTextures::floor_light() const {
  static const FloorLightMap none;
  return floor_cache_.empty() ? none : floor_cache_.front().current();
}

const FloorLightMap& SceneTextures::floor_rect() const {
  static const FloorLightMap none;
  return floor_cache_.empty() ? none : floor_cache_.front().rect();
}

void SceneTextures::describe_floor_light(contract::FrameBlock& b) const {
  const FloorLightMap& m = floor_rect();
  const bool on = maps_read_ && !m.empty();
  b.floor_light_on = on ? 1 : 0;
  b.floor_light_origin = on ? glm::vec2(m.origin) : glm::vec2(0.0f);
  b.floor_light_size = on ? glm::vec2(m.size) : glm::vec2(0.0f);
}

void SceneTextures::bind() const {
  glActiveTexture(GL_TEXTURE0 + contract::kObjectSampler.unit);
  glBindTexture(GL_TEXTURE_2D, objects_tex_);
  glActiveTexture(GL_TEXTURE0 + contract::kKnotsSampler.unit);
  glBindTexture(GL_TEXTURE_2D, knots_tex_);
  glActiveTexture(GL_TEXTURE0 + contract::kFloorLightSampler.unit);
  glBindTexture(GL_TEXTURE_2D, floor_rect().empty() ? neutral_tex_ : floor_cache_.front().tex);
  glActiveTexture(GL_TEXTURE0 + contract::kBackdropLightSampler.unit);
  glBindTexture(GL_TEXTURE_2D, backdrop_light().empty() ? neutral_tex_ : backdrop_cache_.front().tex);
  glActiveTexture(GL_TEXTURE0 + contract::kEnvImageSampler.unit);
  glBindTexture(GL_TEXTURE_2D, environment_tex_ ? environment_tex_ : neutral_tex_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace draught::gpu
