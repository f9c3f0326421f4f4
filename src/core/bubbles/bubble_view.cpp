#include "core/bubbles/bubble_view.hpp"

#include "core/scene/camera.hpp"
#include "core/reference/media.hpp"
#include "core/reference/optics.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {

enum class Medium { Air, Glass, Liquid };

// The leg of a camera path inside one glass's liquid (world frame), and what it crossed
// to get there: other glasses and their drinks, in any order. straight: the path is not
// bent at the interfaces (the MatCap tier's view), only dimmed by them.
struct LiquidLeg {
  bool ok = false;
  Ray ray;
  double before = 0;     // path length before the liquid
  glm::dvec3 thr{1.0};   // Fresnel, glass and other drinks' absorption on the way
};

LiquidLeg trace_to_liquid(const FrameState& f, const SceneGeometry& geo, int target, Ray r, bool straight = false) {
  LiquidLeg leg;
  Medium medium = Medium::Air;
  int inside = -1;  // the object whose glass or liquid the path is in
  for (int e = 0; e < 6 + 4 * int(f.vessels.size()); ++e) {
    const Hit h = first_hit(geo, r, 1e-6);
    if (!h.valid() || h.m == Material::Floor) return leg;
    if (inside >= 0 && h.object != inside) return leg;  // objects do not overlap: numerical trouble
    const VesselFrame& v = f.vessels[size_t(h.object)];
    const VesselParams& p = v.params;
    const double n_of[3] = {1.0, p.glass.ior, p.liquid.ior};
    const glm::dvec3 p_hit = r.at(h.t);
    leg.before += h.t;
    if (medium == Medium::Glass) leg.thr *= glm::exp(-glm::dvec3(p.glass.absorption) * h.t);
    if (medium == Medium::Liquid)  // another glass's drink on the way
      leg.thr *= glm::exp(-(glm::dvec3(v.liquid_absorption.effective()) + double(p.liquid.haze)) * h.t);
    const bool below = v.liquid.below(glm::inverse(v.pose.orientation) * (p_hit - v.pose.position));
    // From above, a head sits on the surface: what is under it is hidden.
    if (h.m == Material::LiquidSurface && medium == Medium::Air && v.foam.thickness > 5e-4) return leg;
    const Medium next = Medium(int(medium_across(h.m, MediumKind(int(medium)), below)));
    const glm::dvec3 n = glm::dot(h.n, r.d) < 0 ? h.n : -h.n;
    const double n1 = n_of[int(medium)], n2 = n_of[int(next)];
    const auto refracted = refract_dir(r.d, n, n1 / n2);
    if (!refracted) return leg;  // total internal reflection: not a straight view of the liquid
    leg.thr *= 1.0 - fresnel_dielectric(-glm::dot(n, r.d), n1, n2);
    r = Ray{p_hit, straight ? r.d : glm::normalize(*refracted)};
    medium = next;
    inside = medium == Medium::Air ? -1 : h.object;
    if (medium == Medium::Liquid && h.object == target) {
      leg.ok = true;
      leg.ray = r;
      return leg;
    }
  }
  return leg;
}

void add_sprites(const FrameState&, const SceneGeometry&, int target, const CameraBasis&, int width, int height,
                 std::vector<BubbleSprite>& out);
void add_straight_sprites(const FrameState&, const SceneGeometry&, int target, const CameraBasis&, int width, int height,
                          std::vector<BubbleSprite>& out);
}  // namespace

std::vector<BubbleSprite> bubble_sprites(const FrameState& f, int width, int height) {
  std::vector<BubbleSprite> out;
  const SceneGeometry geo = scene_geometry(f);
  const CameraBasis cam = camera_basis(f, width, height);
  for (size_t k = 0; k < f.vessels.size(); ++k) {
    const VesselFrame& vf = f.vessels[k];
    if (!vf.has_liquid || vf.bubbles.empty()) continue;
    if (f.params.render.tier == int(RenderTier::MatCap)) add_straight_sprites(f, geo, int(k), cam, width, height, out);
    else add_sprites(f, geo, int(k), cam, width, height, out);
  }
  std::sort(out.begin(), out.end(), [](const BubbleSprite& a, const BubbleSprite& b) { return a.distance > b.distance; });
  return out;
}

namespace {
void add_sprites(const FrameState& f, const SceneGeometry& geo, int target, const CameraBasis& cam, int width,
                 int height, std::vector<BubbleSprite>& out) {
  const VesselFrame& vf = f.vessels[size_t(target)];
  const glm::dvec3 right(cam.right), up(cam.up);
  const glm::dvec3 sigma = glm::dvec3(vf.liquid_absorption.effective()) + double(vf.params.liquid.haze);
  for (const Bubble& b : vf.bubbles) {
    if (geo.vessels[size_t(target)].clipped(glm::dvec3(b.p))) continue;  // cut away with the cross-section
    const glm::dvec3 c = vf.pose.orientation * glm::dvec3(b.p) + vf.pose.position;
    // Miss of the pixel's liquid leg past the bubble centre, in the picture's axes.
    auto miss = [&](double px, double py, glm::dvec2& e, double& t, LiquidLeg& leg) {
      leg = trace_to_liquid(f, geo, target, camera_ray(cam, px, py, width, height));
      if (!leg.ok) return false;
      t = glm::dot(c - leg.ray.o, leg.ray.d);
      const glm::dvec3 d = c - leg.ray.at(t);
      e = {glm::dot(d, right), glm::dot(d, up)};
      return t > 0;
    };
    // Start where the bubble would be without the glass; Newton with a numeric Jacobian.
    const glm::dvec3 v = c - glm::dvec3(cam.eye);
    const double z = glm::dot(v, glm::dvec3(cam.forward));
    if (z <= 0) continue;
    double px = (glm::dot(v, right) / (z * cam.tan_half_vfov * cam.aspect) + 1 + cam.shift.x) * 0.5 * width;
    double py = (1 - glm::dot(v, up) / (z * cam.tan_half_vfov) - cam.shift.y) * 0.5 * height;
    glm::dvec2 e;
    double t = 0, det = 0;
    LiquidLeg leg;
    bool ok = false;
    for (int it = 0; it < 6; ++it) {
      if (!miss(px, py, e, t, leg)) break;
      glm::dvec2 ex, ey;
      double tx, ty;
      LiquidLeg lx, ly;
      if (!miss(px + 0.5, py, ex, tx, lx) || !miss(px, py + 0.5, ey, ty, ly)) break;
      const glm::dmat2 J((ex - e) / 0.5, (ey - e) / 0.5);  // metres of miss per pixel
      det = glm::determinant(J);
      if (!(std::abs(det) > 1e-18)) break;
      const glm::dvec2 step = glm::inverse(J) * e;
      px -= step.x;
      py -= step.y;
      if (glm::length(e) < 0.05 * b.radius) {
        ok = miss(px, py, e, t, leg);
        break;
      }
    }
    if (!ok || px < -10 || py < -10 || px > width + 10 || py > height + 10) continue;
    // Nothing between the leg's start and the bubble: it is inside this stretch of liquid.
    if (first_hit(geo, leg.ray, 1e-6).t < t) continue;
    BubbleSprite s;
    s.centre = {float(px), float(py)};
    s.radius = float(b.radius / std::sqrt(std::abs(det)));  // metres over metres-per-pixel
    s.tint = glm::vec3(leg.thr * glm::exp(-sigma * t));
    s.distance = float(leg.before + t);
    s.object = target;
    if (s.radius > 0.05f) out.push_back(s);
  }
}

// The MatCap tier sees the drink straight through the glass (no refracted march): each
// bubble where the camera's straight line to it meets the picture, its size by the
// distance, dimmed by what that line crosses (Fresnel, the glass, the drink before it).
void add_straight_sprites(const FrameState& f, const SceneGeometry& geo, int target, const CameraBasis& cam,
                          int width, int height, std::vector<BubbleSprite>& out) {
  const VesselFrame& vf = f.vessels[size_t(target)];
  const glm::dvec3 eye(cam.eye), fwd(cam.forward), right(cam.right), up(cam.up);
  const glm::dvec3 sigma = glm::dvec3(vf.liquid_absorption.effective()) + double(vf.params.liquid.haze);
  for (const Bubble& b : vf.bubbles) {
    if (geo.vessels[size_t(target)].clipped(glm::dvec3(b.p))) continue;
    const glm::dvec3 c = vf.pose.orientation * glm::dvec3(b.p) + vf.pose.position, v = c - eye;
    const double z = glm::dot(v, fwd);
    if (z <= 0) continue;
    const double px = (glm::dot(v, right) / (z * cam.tan_half_vfov * cam.aspect) + 1 + cam.shift.x) * 0.5 * width;
    const double py = (1 - glm::dot(v, up) / (z * cam.tan_half_vfov) - cam.shift.y) * 0.5 * height;
    if (px < -10 || py < -10 || px > width + 10 || py > height + 10) continue;
    const LiquidLeg leg = trace_to_liquid(f, geo, target, Ray{eye, glm::normalize(v)}, true);
    if (!leg.ok) continue;
    const double t = glm::dot(c - leg.ray.o, leg.ray.d);
    if (t <= 0 || first_hit(geo, leg.ray, 1e-6).t < t) continue;  // not in this stretch of the drink
    BubbleSprite s;
    s.centre = {float(px), float(py)};
    s.radius = float(b.radius / (2.0 * z * cam.tan_half_vfov / height));  // metres over metres-per-pixel
    s.tint = glm::vec3(leg.thr * glm::exp(-sigma * t));
    s.distance = float(leg.before + t);
    s.object = target;
    if (s.radius > 0.05f) out.push_back(s);
  }
}
}  // namespace

}  // namespace draught
