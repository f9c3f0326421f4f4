#include "core/scene/frame.hpp"

#include "core/scene/camera.hpp"
#include "core/environment/studio.hpp"
#include "core/droplets/trail.hpp"
#include "core/sim/scene_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>

namespace draught {

namespace {
// Where everything to be framed lies: a box around the glasses as they stand.
struct Bounds {
  glm::dvec3 lo{1e30}, hi{-1e30};
  void add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool empty() const { return lo.x > hi.x; }
};

CameraParams frame_bounds(const CameraParams& c, const Bounds& b, double aspect = 1.0) {
  if (!c.auto_frame || b.empty()) return c;
  glm::dvec3 back = glm::dvec3(c.eye - c.target);
  back = glm::length(back) > 1e-9 ? glm::normalize(back) : glm::dvec3(0, 0, 1);
  const double half_tan = std::tan(glm::radians(double(c.vfov)) * 0.5);
  const glm::dvec3 size = b.hi - b.lo;
  const double radius = 0.5 * std::max(size.x, size.z);
  const double height = b.hi.y;
  // Half the height with a margin for the floor and the rim, or the width.
  // The width fits the picture's width: a wide picture of a flight frames it tightly.
  const double half = std::max(0.5 * height + 0.012, radius * 1.1 / std::max(aspect, 1e-3)) * 1.12;
  const double dist = half / half_tan + radius;
  CameraParams out = c;
  const glm::dvec3 centre(0.5 * (b.lo.x + b.hi.x), 0.47 * height, 0.5 * (b.lo.z + b.hi.z));
  out.target = glm::vec3(centre);
  out.eye = glm::vec3(centre + back * dist);
  return out;
}
}  // namespace

CameraParams frame_camera(const CameraParams& c, const Vessel& v) {
  Bounds b;
  b.add({-v.bound_radius, 0, -v.bound_radius});
  b.add({v.bound_radius, v.height, v.bound_radius});
  return frame_bounds(c, b);
}

namespace {
Bounds standing_bounds(const std::vector<VesselFrame>& vessels) {
  Bounds b;
  // Each glass as it stands at its place (its upright bounds, so motion does not make the
  // camera swim).
  for (const VesselFrame& f : vessels) {
    const glm::dvec3 at(f.placement.position.x, 0, f.placement.position.z);
    const double r = f.vessel.bound_radius;
    b.add(at + glm::dvec3(-r, 0, -r));
    b.add(at + glm::dvec3(r, f.vessel.height, r));
  }
  return b;
}

// Points on each glass's outer outline (circles up the profile, the rim bead's outside),
// in the world: `posed` as the glass is in the frame (tilted, spun, shaken), else upright
// at its place. A glass tipped past lying (a timeline may tip it to 135 degrees on its
// foot) goes under the floor, which hides that part: only what is above it counts, and
// where the outline crosses the floor.
std::vector<glm::dvec3> outline(const std::vector<VesselFrame>& vessels, bool posed) {
  constexpr int kCircles = 12, kAround = 16;
  std::vector<glm::dvec3> points;
  for (const VesselFrame& f : vessels) {
    const Vessel& v = f.vessel;
    if (v.r_outer.empty()) continue;
    const glm::dvec3 at(f.placement.position.x, 0, f.placement.position.z);
    std::vector<glm::dvec3> grid;  // (kCircles + 2) circles of kAround points
    for (int k = 0; k <= kCircles + 1; ++k) {
      // kCircles + 1: the outside of the rim bead, over its top.
      const bool rim = k > kCircles;
      const double y = rim ? v.height + v.rim_minor : v.height * k / kCircles;
      const double r = rim ? v.rim_major + v.rim_minor : v.outer_radius(y);
      for (int j = 0; j < kAround; ++j) {
        const double a = 2 * std::numbers::pi * j / kAround;
        const glm::dvec3 local(r * std::cos(a), y, r * std::sin(a));
        grid.push_back(posed ? f.pose.orientation * local + f.pose.position : at + local);
      }
    }
    auto edge = [&](const glm::dvec3& a, const glm::dvec3& b) {
      if ((a.y < 0) != (b.y < 0)) points.push_back(glm::mix(a, b, a.y / (a.y - b.y)));
    };
    for (int k = 0; k <= kCircles + 1; ++k)
      for (int j = 0; j < kAround; ++j) {
        const glm::dvec3& p = grid[size_t(k * kAround + j)];
        if (p.y >= 0) points.push_back(p);
        edge(p, grid[size_t(k * kAround + (j + 1) % kAround)]);
        if (k <= kCircles) edge(p, grid[size_t((k + 1) * kAround + j)]);
      }
  }
  return points;
}

// How far out the furthest point lies in the picture: 1 is the picture's edge (left,
// right, top or bottom); a point behind the camera is infinitely far out.
double reach(const CameraParams& c, const std::vector<glm::dvec3>& points, double aspect) {
  const CameraBasis b = camera_basis(c, 1, 1);  // the directions do not depend on the size
  const double half_tan = std::tan(glm::radians(double(c.vfov)) * 0.5);
  double out = 0;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = p - glm::dvec3(b.eye);
    const double z = glm::dot(d, glm::dvec3(b.forward));
    if (z <= 1e-6) return std::numeric_limits<double>::infinity();
    const double x = glm::dot(d, glm::dvec3(b.right)) / (z * half_tan * aspect);
    const double y = glm::dot(d, glm::dvec3(b.up)) / (z * half_tan);
    out = std::max({out, std::abs(x), std::abs(y)});
  }
  return out;
}
}  // namespace

CameraParams frame_camera(const CameraParams& c, const std::vector<VesselFrame>& vessels, double aspect) {
  // The glasses as they stand set the framing, so a moving glass does not make the camera
  // swim. A glass tilted (or shaken) so far that it would reach out further than its
  // upright self, and out of the picture, makes the camera back away along its line of
  // sight just far enough to keep it in (continuously, so an animation does not jump).
  const CameraParams standing = frame_bounds(c, standing_bounds(vessels), aspect);
  if (!c.auto_frame) return standing;
  const std::vector<glm::dvec3> posed = outline(vessels, true);
  constexpr double kInside = 0.97;  // of the picture's half-size: a sliver of margin
  const double allowed = std::max(kInside, 1.02 * reach(standing, outline(vessels, false), aspect));
  if (reach(standing, posed, aspect) <= allowed) return standing;
  const glm::dvec3 target(standing.target), back = glm::dvec3(standing.eye) - target;
  auto at = [&](double scale) {
    CameraParams out = standing;
    out.eye = glm::vec3(target + back * scale);
    return out;
  };
  double lo = 1, hi = 2;
  for (int i = 0; i < 16 && reach(at(hi), posed, aspect) > allowed; ++i) lo = hi, hi *= 2;
  for (int i = 0; i < 32; ++i) {
    const double mid = 0.5 * (lo + hi);
    (reach(at(mid), posed, aspect) > allowed ? lo : hi) = mid;
  }
  return at(hi);
}

CameraParams FrameState::camera_for(int width, int height) const {
  if (width <= 0 || height <= 0 || width == height) return camera;
  return frame_camera(params.camera, vessels, double(width) / double(height));
}

CameraBasis camera_basis(const FrameState& f, int width, int height) {
  if (f.view.whole()) return camera_basis(f.camera_for(width, height), width, height);
  const int w = std::max(1, int(std::lround(width * f.view.width)));
  const int h = std::max(1, int(std::lround(height * f.view.height)));
  return camera_basis(f.camera_for(w, h), width, height, f.view);
}

namespace {
// Where the liquid's surface meets the glass's axis (local y), within the glass (a glass
// tipped over has its surface nearly along the axis).
double surface_on_axis(const VesselFrame& v) {
  return std::clamp(v.liquid.offset / std::max(v.liquid.n.y, 1e-3), v.vessel.base, v.vessel.height);
}
}  // namespace

std::vector<DrinkColumn> drink_column_list(const std::vector<VesselFrame>& vessels) {
  std::vector<DrinkColumn> columns;
  for (const VesselFrame& v : vessels) {
    if (!v.has_liquid) continue;
    // The surface in steps of 0.5 mm: a settling head moves it all the time by far less
    // than the shadow's edge can show, and each step would take the heads' views again.
    const double level = std::round(surface_on_axis(v) / kViewStep) * kViewStep;
    if (level <= v.vessel.base) continue;
    columns.push_back({glm::inverse(v.pose.orientation), v.pose.position, v.mean_outer_radius, v.vessel.base, level,
                       glm::dvec3(v.liquid_absorption.effective())});
  }
  return columns;
}

LightPasses light_passes(std::vector<DrinkColumn> columns) {
  if (columns.empty()) return {};
  return [columns = std::move(columns)](const glm::dvec3& from, const glm::dvec3& to) {
    glm::dvec3 pass(1.0);
    for (const DrinkColumn& c : columns) {
      const glm::dvec3 o = c.to_local * (from - c.origin), e = c.to_local * (to - c.origin);
      const glm::dvec3 d = e - o;  // the segment o + s d, s in [0, 1]
      double s0 = 0, s1 = 1;
      // Within the column's height.
      if (std::abs(d.y) < 1e-12) {
        if (o.y < c.y0 || o.y > c.y1) continue;
      } else {
        double a = (c.y0 - o.y) / d.y, b = (c.y1 - o.y) / d.y;
        if (a > b) std::swap(a, b);
        s0 = std::max(s0, a);
        s1 = std::min(s1, b);
      }
      // Within its radius.
      const double qa = d.x * d.x + d.z * d.z, qb = o.x * d.x + o.z * d.z, qc = o.x * o.x + o.z * o.z - c.radius * c.radius;
      if (qa < 1e-18) {
        if (qc > 0) continue;
      } else {
        const double disc = qb * qb - qa * qc;
        if (disc <= 0) continue;
        const double sq = std::sqrt(disc);
        s0 = std::max(s0, (-qb - sq) / qa);
        s1 = std::min(s1, (-qb + sq) / qa);
      }
      if (s1 > s0) pass *= glm::exp(-c.absorption * ((s1 - s0) * glm::length(d)));
    }
    return pass;
  };
}

LightPasses drink_columns(const std::vector<VesselFrame>& vessels) { return light_passes(drink_column_list(vessels)); }

namespace {

// Numbers as exact text, for the cache's keys.
void put_numbers(std::string& key, std::initializer_list<double> xs) {
  char buf[32];
  for (double x : xs) {
    std::snprintf(buf, sizeof buf, "%.17g,", x);
    key += buf;
  }
}

// The frame's surroundings and each head's view of them, from the cache where what they
// are made of is unchanged (EnvironmentCache), else computed (and kept when there is a cache).
EnvironmentFrame frame_environment(const FrameState& f, const glm::dvec3& aim, const glm::dvec3& backlit,
                                   const std::vector<glm::dvec3>& heads, EnvironmentCache* cache) {
  const SceneParams& p = f.params;
  const std::vector<DrinkColumn> columns = heads.empty() ? std::vector<DrinkColumn>{} : drink_column_list(f.vessels);
  if (!cache) return environment_frame(p, f.lights, f.backdrop, heads, light_passes(columns));
  // The scene's part is made of the studio's parameters, the environment image as read (a
  // file changed on disk is read again, a new map) and where the rig and the sweep stand
  // (aim, and the backlight's aim through the drinks, light_rig's and backdrop_surface's
  // other inputs). (Not whether the picture is transparent: the studio lights a cutout as
  // it lights the opaque picture.)
  const Studio studio(p);
  std::string key = studio_params_key(p);
  key += std::to_string(reinterpret_cast<std::uintptr_t>(studio.image.get())) + ";";
  put_numbers(key, {aim.x, aim.y, aim.z, backlit.x, backlit.y, backlit.z});
  if (key != cache->scene_key) {
    cache->scene = environment_frame(p, f.lights, f.backdrop);
    cache->scene_key = std::move(key);
    cache->views.clear();
  }
  // The heads' views are made of the scene's part, the drinks' columns and their own points.
  std::string columns_key;
  for (const DrinkColumn& c : columns)
    put_numbers(columns_key, {c.to_local.w, c.to_local.x, c.to_local.y, c.to_local.z, c.origin.x, c.origin.y,
                              c.origin.z, c.radius, c.y0, c.y1, c.absorption.x, c.absorption.y, c.absorption.z});
  if (columns_key != cache->columns_key) {
    cache->columns_key = std::move(columns_key);
    cache->views.clear();
  }
  EnvironmentFrame e = cache->scene;
  LightPasses passes;  // (made only when a view is taken again)
  std::vector<std::pair<glm::dvec3, SkyIrradiance>> views;
  for (const glm::dvec3& at : heads) {
    auto kept = std::find_if(cache->views.begin(), cache->views.end(), [&](const auto& v) { return v.first == at; });
    if (kept == cache->views.end() && !passes) passes = light_passes(columns);
    views.emplace_back(at, kept != cache->views.end() ? kept->second
                                                       : environment_seen_from(e, p, f.lights, f.backdrop, at, passes));
    e.media_seen_from.push_back(views.back().second);
  }
  cache->views = std::move(views);  // (the heads there are now: a head gone is not kept)
  return e;
}

}  // namespace

FrameState assemble_frame(const SceneParams& scene, std::vector<VesselFrame> vessels, int selected, double time,
                          EnvironmentCache* cache) {
  FrameState f;
  f.params = scene;
  if (scene.screen.mode == int(ScreenMode::Background)) f.params.env.floor = false;
  const SceneParams& p = f.params;
  f.time = time;
  f.vessels = std::move(vessels);
  f.selected = std::clamp(selected, 0, std::max(0, int(f.vessels.size()) - 1));
  f.camera = frame_camera(p.camera, f.vessels);
  const glm::dvec3 aim = scene_aim(f.vessels);
  const glm::dvec3 backlit = drink_aim(f.vessels);
  f.lights = light_rig(p, aim, backlit);
  f.backdrop = backdrop_surface(p.env, aim);
  std::vector<VesselFrame*> with_head;
  std::vector<glm::dvec3> heads;
  // Each head sees the surroundings from its middle, in steps of 0.5 mm (a settling head
  // moves all the time; a step changes its light by far less than a level of the picture).
  for (VesselFrame& v : f.vessels)
    if (has_head(v)) with_head.push_back(&v), heads.push_back(glm::round(head_middle(v) / kViewStep) * kViewStep);
  f.environment = frame_environment(f, aim, backlit, heads, cache);
  for (size_t k = 0; k < with_head.size(); ++k) with_head[k]->head_surround = f.environment.media_seen_from[k];
  f.screen = screen_frame(p, aim, time);
  return f;
}

glm::dvec3 head_middle(const VesselFrame& v) {
  const glm::dvec3 n(v.liquid.n);
  return v.pose.position + v.pose.orientation * (glm::dvec3(0, surface_on_axis(v), 0) + 0.5 * v.foam.thickness * n);
}

glm::dvec3 vessel_middle(const VesselFrame& v) {
  return v.pose.position + v.pose.orientation * glm::dvec3(0, 0.5 * v.vessel.height, 0);
}

glm::dvec3 scene_aim(const std::vector<VesselFrame>& vessels) {
  if (vessels.empty()) return glm::dvec3(0.0);
  glm::dvec2 lo(1e30), hi(-1e30);
  double top = 0;
  for (const VesselFrame& v : vessels) {
    const glm::dvec2 at(v.placement.position.x, v.placement.position.z);
    lo = glm::min(lo, at);
    hi = glm::max(hi, at);
    top = std::max(top, double(v.placement.position.y) + v.vessel.height);
  }
  const glm::dvec2 mid = 0.5 * (lo + hi);
  return {mid.x, 0.5 * top, mid.y};
}

glm::dvec3 surroundings_centre(const FrameState& f) {
  if (!f.vessels.empty()) return scene_aim(f.vessels);
  glm::dvec3 sum(0.0);
  int n = 0;
  for (const DropletsFrame& d : f.droplets) sum += glm::dvec3(d.position), ++n;
  for (const CloudFrame& c : f.clouds) sum += glm::dvec3(c.placement), ++n;
  return n ? sum / double(n) : glm::dvec3(0.0);
}

glm::dvec3 drink_aim(const std::vector<VesselFrame>& vessels) {
  glm::dvec3 aim = scene_aim(vessels);
  if (vessels.empty()) return aim;
  double lo = 1e30, hi = -1e30;
  for (const VesselFrame& v : vessels) {
    const double y0 = v.placement.position.y;
    const double fill = v.params.liquid.fill;
    if (fill > 0) {
      lo = std::min(lo, y0 + v.vessel.base);
      hi = std::max(hi, y0 + v.vessel.fill_height(fill));
    } else {
      lo = std::min(lo, y0);
      hi = std::max(hi, y0 + v.vessel.height);
    }
  }
  aim.y = 0.5 * (lo + hi);
  return aim;
}

FrameState make_frame(const Scene& s) {
  SceneSimulation sim(s);
  sim.settle_bubbles(4.0);
  return sim.frame();
}

FrameState make_frame(const Params& p) { return make_frame(single_glass_scene(p)); }

SceneGeometry scene_geometry(const FrameState& f, bool with_decals) {
  SceneGeometry g;
  g.backdrop = f.backdrop;
  g.backdrop.present = f.backdrop.present && !f.params.render.transparent;
  for (const VesselFrame& v : f.vessels) {
    VesselGeometry vg{&v.vessel, v.liquid, v.pose};
    const ClipParams& c = v.params.clip;
    const double len = glm::length(glm::dvec3(c.normal));
    if (c.enabled && len > 1e-4) vg.clip = glm::dvec4(glm::dvec3(c.normal) / len, c.offset);
    if (with_decals) vg.decals = vessel_decals(v.vessel, v.params);
    g.vessels.push_back(vg);
  }
  return g;
}

int pick_object(const FrameState& f, double px, double py, int width, int height) {
  const CameraBasis cam = camera_basis(f, width, height);
  return first_hit(scene_geometry(f), camera_ray(cam, px, py, width, height)).object;
}

std::optional<glm::dvec2> droplet_pointer_at(const FrameState& f, double px, double py, int width, int height) {
  if (f.droplets.empty() || width < 1 || height < 1 || !std::isfinite(px) || !std::isfinite(py)) return std::nullopt;
  const Ray ray = camera_ray(camera_basis(f, width, height), px, py, width, height);
  const DropletsFrame& d = f.droplets.front();  // at most one per scene
  glm::dvec2 q;
  if (!droplet_plane_hit(d.position, d.yaw, ray.o, ray.d, q)) return std::nullopt;
  return q;
}

DepthRange depth_range(const FrameState& f, int width, int height) {
  const glm::dvec3 eye(camera_basis(f, width, height).eye);
  DepthRange r{1e30, 0};
  for (const VesselFrame& v : f.vessels) {
    // The glass's bounding box in its own frame: the eye moved there, the nearest point of
    // the box is a clamp and the farthest one of its corners.
    const double b = v.vessel.bound_radius, top = v.vessel.height + v.vessel.rim_minor;
    const glm::dvec3 lo(-b, 0, -b), hi(b, top, b);
    const glm::dvec3 e = glm::inverse(v.pose.orientation) * (eye - v.pose.position);
    r.near = std::min(r.near, glm::length(glm::clamp(e, lo, hi) - e));
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 corner(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
      r.far = std::max(r.far, glm::length(corner - e));
    }
  }
  if (f.vessels.empty()) r = {};
  return r;
}

}  // namespace draught
