#include "core/environment/lights.hpp"

#include "core/math/atan2.hpp"
#include "core/math/basis.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

// 1 - cos of the half-angle a sphere of radius r subtends from distance^2 d2 (> r^2),
// without the cancellation of 1 - sqrt(1 - r^2/d2) for small, far lights.
double one_minus_cos_cone(double r, double d2) {
  const double s2 = r * r / d2;
  return s2 / (1 + std::sqrt(std::max(0.0, 1 - s2)));
}

// Where ray o + t d (d unit) meets a sphere, the nearer t > tmin, from outside it.
bool hit_sphere(const glm::dvec3& c, double r, const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t) {
  const glm::dvec3 oc = o - c;
  const double b = glm::dot(oc, d), cc = glm::dot(oc, oc) - r * r;
  if (cc <= 0) return false;  // inside: a lamp is not seen from within
  const double disc = b * b - cc;
  if (disc < 0) return false;
  t = -b - std::sqrt(disc);
  return t > tmin;
}

}  // namespace

std::array<double, 17> AreaLight::numbers() const {
  return {double(int(shape)), radius,   center.x, center.y, center.z,   normal.x,   normal.y,   normal.z, half_u.x,
          half_u.y,           half_u.z, half_v.x, half_v.y, half_v.z, radiance.x, radiance.y, radiance.z};
}

double AreaLight::area() const {
  if (shape == LightShape::Sphere) return 4 * kPi * radius * radius;
  return 4 * glm::length(half_u) * glm::length(half_v);
}

bool AreaLight::emits() const { return area() > 0 && std::max(radiance.x, std::max(radiance.y, radiance.z)) > 0; }

bool AreaLight::intersect(const glm::dvec3& o, const glm::dvec3& d, double tmin, double& t) const {
  if (shape == LightShape::Sphere) return hit_sphere(center, radius, o, d, tmin, t);
  const double denom = glm::dot(d, normal);
  if (denom >= 0) return false;  // parallel, or its back
  t = glm::dot(center - o, normal) / denom;
  if (!(t > tmin)) return false;
  const glm::dvec3 q = o + t * d - center;
  return std::fabs(glm::dot(q, half_u)) <= glm::dot(half_u, half_u) &&
         std::fabs(glm::dot(q, half_v)) <= glm::dot(half_v, half_v);
}

double sphere_irradiance_factor(const glm::dvec3& center, double radius, const glm::dvec3& x, const glm::dvec3& n) {
  // Snyder, "Area light sources for real-time graphics" (1996): a sphere of angular
  // radius sigma at angle theta from the normal, clipped by the horizon.
  const glm::dvec3 w = center - x;
  const double d2 = glm::dot(w, w);
  if (d2 <= radius * radius) return kPi;
  const double sin2 = radius * radius / d2, cos_t = glm::dot(n, w) / std::sqrt(d2);
  if (cos_t * cos_t > sin2) return kPi * sin2 * std::max(cos_t, 0.0);
  const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
  const double xx = std::sqrt(1 / sin2 - 1);
  const double y = std::clamp(-xx * cos_t / std::max(sin_t, 1e-12), -1.0, 1.0);
  const double s = sin_t * std::sqrt(1 - y * y);
  return std::max(0.0, (cos_t * std::acos(y) - xx * s) * sin2 + std::atan(s / xx));
}

double AreaLight::irradiance_factor(const glm::dvec3& x, const glm::dvec3& n) const {
  if (shape == LightShape::Sphere) return sphere_irradiance_factor(center, radius, x, n);
  if (glm::dot(x - center, normal) <= 0) return 0;  // behind the softbox
  // The rect's corners seen from x, clipped to the surface's upper hemisphere
  // (Sutherland-Hodgman against the plane n . v = 0).
  const glm::dvec3 corner[4] = {center - half_u - half_v - x, center + half_u - half_v - x,
                                center + half_u + half_v - x, center - half_u + half_v - x};
  glm::dvec3 poly[8];
  int count = 0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 &a = corner[i], &b = corner[(i + 1) % 4];
    const double da = glm::dot(n, a), db = glm::dot(n, b);
    if (da >= 0) poly[count++] = a;
    if ((da >= 0) != (db >= 0)) poly[count++] = a + (b - a) * (da / (da - db));
  }
  if (count < 3) return 0;
  // Lambert: the sum over edges of the angle they subtend times the cosine of their
  // plane's normal with n. Both are ratios, so the corners need no normalizing: the angle
  // is atan2(|a x b|, a . b) and the cosine n . (a x b) / |a x b| at any lengths of a and b
  // (the backdrop's light map sums millions of these).
  double sum = 0;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 &a = poly[i], &b = poly[i + 1 < count ? i + 1 : 0];
    const glm::dvec3 c = glm::cross(a, b);
    const double len2 = glm::dot(c, c);
    if (len2 <= 1e-30 * glm::dot(a, a) * glm::dot(b, b)) continue;  // a and b (anti)parallel
    const double len = std::sqrt(len2);
    sum += atan2_fast(len, glm::dot(a, b)) * (glm::dot(n, c) / len);
  }
  return 0.5 * std::fabs(sum);
}

bool AreaLight::sample_from(const glm::dvec3& x, double u1, double u2, Sample& s) const {
  if (shape == LightShape::Sphere) {
    const glm::dvec3 w = center - x;
    const double d2 = glm::dot(w, w);
    if (d2 <= radius * radius) return false;
    const double omc = one_minus_cos_cone(radius, d2);
    const double cos_t = 1 - u1 * omc, sin_t = std::sqrt(std::max(0.0, u1 * omc * (2 - u1 * omc)));
    const double phi = 2 * kPi * u2;
    glm::dvec3 t, b;
    const glm::dvec3 axis = w / std::sqrt(d2);
    basis(axis, t, b);
    s.dir = glm::normalize(sin_t * std::cos(phi) * t + sin_t * std::sin(phi) * b + cos_t * axis);
    s.pdf = 1 / (2 * kPi * omc);
    if (!hit_sphere(center, radius, x, s.dir, 0, s.dist)) s.dist = glm::dot(w, s.dir);  // the grazing edge
    return true;
  }
  const glm::dvec3 p = center + (2 * u1 - 1) * half_u + (2 * u2 - 1) * half_v;
  const glm::dvec3 w = p - x;
  s.dist = glm::length(w);
  if (s.dist <= 0) return false;
  s.dir = w / s.dist;
  const double cos_l = -glm::dot(s.dir, normal);
  if (cos_l <= 1e-12) return false;
  s.pdf = s.dist * s.dist / (cos_l * area());
  return true;
}

double AreaLight::pdf_from(const glm::dvec3& x, const glm::dvec3& d) const {
  double t;
  if (!intersect(x, d, 0, t)) return 0;
  if (shape == LightShape::Sphere) {
    const glm::dvec3 w = center - x;
    return 1 / (2 * kPi * one_minus_cos_cone(radius, glm::dot(w, w)));
  }
  return t * t / (-glm::dot(d, normal) * area());
}

void AreaLight::sample_point(double u1, double u2, glm::dvec3& p, glm::dvec3& n) const {
  if (shape == LightShape::Sphere) {
    const double z = 1 - 2 * u1, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u2;
    n = {r * std::cos(phi), r * std::sin(phi), z};
    p = center + radius * n;
    return;
  }
  p = center + (2 * u1 - 1) * half_u + (2 * u2 - 1) * half_v;
  n = normal;
}

AreaLight place_light(const LightParams& lp, const glm::dvec3& aim, bool mirror_x) {
  AreaLight l;
  glm::dvec3 dir(lp.direction);
  if (mirror_x) dir.x = -dir.x;
  dir = glm::length(dir) > 1e-9 ? glm::normalize(dir) : glm::dvec3(0, 1, 0);
  l.center = aim + dir * double(lp.distance);
  l.normal = lp.facing == int(LightFacing::Away) ? dir : -dir;
  // The rect's height runs up the world as far as its tilt allows; a light straight
  // above or below has its height along z.
  glm::dvec3 up = glm::dvec3(0, 1, 0) - l.normal.y * l.normal;
  up = glm::length(up) > 1e-6 ? glm::normalize(up) : glm::dvec3(0, 0, -1);
  const glm::dvec3 across = glm::normalize(glm::cross(up, l.normal));
  const double w = lp.width, h = lp.height;
  const glm::dvec3 color(lp.color);
  l.camera_visible = lp.camera_visible;
  if (lp.shape == int(LightShape::Sphere)) {
    l.shape = LightShape::Sphere;
    l.radius = 0.5 * w;
    l.radiance = color * double(lp.power) / (4 * kPi * kPi * l.radius * l.radius);
  } else {
    l.shape = LightShape::Rect;
    l.half_u = across * (0.5 * w);
    l.half_v = up * (0.5 * h);
    l.radiance = color * double(lp.power) / (kPi * w * h);
  }
  return l;
}

LightRig light_rig(const SceneParams& p, const glm::dvec3& aim) { return light_rig(p, aim, aim); }

LightRig light_rig(const SceneParams& p, const glm::dvec3& aim, const glm::dvec3& backlight_aim) {
  LightRig rig;
  rig.aim = aim;
  if (p.env.mode == int(EnvMode::Image)) return rig;  // the image's light replaces the rig's
  for (const AreaLight& l : {place_light(p.light, aim), place_light(p.strips, aim), place_light(p.strips, aim, true),
                             place_light(p.backlight, backlight_aim)})
    if (l.emits()) rig.lights.push_back(l);
  return rig;
}

glm::dvec3 LightRig::irradiance(const glm::dvec3& x, const glm::dvec3& n) const {
  glm::dvec3 e(0.0);
  for (const AreaLight& l : lights) e += l.radiance * l.irradiance_factor(x, n);
  return e;
}

}  // namespace draught
