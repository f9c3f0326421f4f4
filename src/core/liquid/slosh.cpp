#include "core/liquid/slosh.hpp"
#include "core/math/vectors.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {
constexpr double kRingRoot = 3.8317;   // first root of J1: the axisymmetric mode
constexpr double kCrossRoot = 3.0542;  // first root of J2': the m = 2 modes

}  // namespace

double slosh_frequency(double radius, double depth, double root) {
  radius = std::max(radius, 1e-3);
  depth = std::max(depth, 1e-4);
  return std::sqrt(kGravity * root / radius * std::tanh(root * depth / radius));
}

void step_slosh(SloshState& s, const LiquidParams& p, const SloshEnvironment& e, double dt) {
  // The parameters are in their table ranges (checked when they were set).
  const double stiffness = p.slosh_stiffness;
  const double zeta = p.slosh_damping;
  const double speed = p.wave_speed;
  const double w1 = slosh_frequency(e.radius, e.depth) * std::sqrt(stiffness);
  // The tilt mode: a damped spring towards the level of the effective gravity. Large
  // swings lose more (the surface breaks up), so resonance stays bounded as in a glass.
  const glm::dvec2 off = s.slope - e.level_slope;
  const double zeta_eff = std::min(zeta + 2.0 * glm::dot(off, off), 1.0);
  const glm::dvec2 acc = -w1 * w1 * off - 2.0 * zeta_eff * w1 * s.slope_rate;
  s.slope_rate += dt * acc;
  s.slope += dt * s.slope_rate;
  if (glm::length(s.slope) > e.max_slope) {  // held by the rim: lose the outward speed
    s.slope = clamp_length(s.slope, e.max_slope);
    const glm::dvec2 out = glm::normalize(s.slope);
    s.slope_rate -= std::max(glm::dot(s.slope_rate, out), 0.0) * out;
  }
  // Waves: forced by how fast the level moves; higher modes ring faster and die sooner.
  const double drive = double(p.wave_amplitude) * 0.02 * e.radius;
  const double rate = std::min(glm::length(e.level_rate), 50.0);
  auto mode = [&](double& x, double& v, double root, double force) {
    const double w = slosh_frequency(e.radius, e.depth, root) * speed;
    const double zw = std::min(1.0, zeta * 1.5);
    v += dt * (w * w * (force - x) - 2.0 * zw * w * v);
    x += dt * v;
    if (std::abs(x) > e.max_wave) {
      x = std::copysign(e.max_wave, x);
      v = 0;
    }
  };
  mode(s.ring, s.ring_rate, kRingRoot, drive * rate);
  glm::dvec2 dir = rate > 1e-12 ? e.level_rate / rate : glm::dvec2(0.0);
  const glm::dvec2 shape(dir.x * dir.x - dir.y * dir.y, 2.0 * dir.x * dir.y);  // cos 2a, sin 2a
  mode(s.cross.x, s.cross_rate.x, kCrossRoot, drive * rate * shape.x);
  mode(s.cross.y, s.cross_rate.y, kCrossRoot, drive * rate * shape.y);
  // Settle: below these the motion is invisible; stop it exactly instead of forever.
  if (rate == 0 && glm::length(s.slope - e.level_slope) < 1e-6 && glm::length(s.slope_rate) < 1e-5 &&
      std::abs(s.ring) < 1e-7 && std::abs(s.ring_rate) < 1e-5 && glm::length(s.cross) < 1e-7 &&
      glm::length(s.cross_rate) < 1e-5) {
    s = SloshState{};
    s.slope = e.level_slope;
  }
}

double slosh_energy(const SloshState& s, const LiquidParams& p, const SloshEnvironment& e) {
  const double w1 = slosh_frequency(e.radius, e.depth) * std::sqrt(double(p.slosh_stiffness));
  const glm::dvec2 d = s.slope - e.level_slope;
  // Waves in slope units (divided by the radius) so all terms weigh alike.
  const double r = std::max(e.radius, 1e-3);
  const double wr = slosh_frequency(e.radius, e.depth, kRingRoot), wc = slosh_frequency(e.radius, e.depth, kCrossRoot);
  return 0.5 * (glm::dot(s.slope_rate, s.slope_rate) + w1 * w1 * glm::dot(d, d)) +
         0.5 * (s.ring_rate * s.ring_rate + wr * wr * s.ring * s.ring) / (r * r) +
         0.5 * (glm::dot(s.cross_rate, s.cross_rate) + wc * wc * glm::dot(s.cross, s.cross)) / (r * r);
}

bool at_rest(const SloshState& s) {
  return s.slope_rate == glm::dvec2(0.0) && s.ring == 0 && s.ring_rate == 0 && s.cross == glm::dvec2(0.0) &&
         s.cross_rate == glm::dvec2(0.0);
}

// Beyond 1.25 radii (a flared glass's wider wall) the shapes are held at their value
// there, so they stay bounded.
namespace {
// The dimple's height at (x, z) and, if asked, its gradient (as dimple_shape in
// shaders/lib/liquid/surface.glsl).
double dimple_height(const SurfaceWaves& w, double x, double z, glm::dvec2* gradient) {
  if (!(w.dimple_depth > 0 && w.dimple_radius > 0)) return 0.0;
  const glm::dvec2 q = (glm::dvec2(x, z) - w.dimple_xz) / w.dimple_radius;
  const double s2 = glm::dot(q, q), e = std::exp(-s2);
  if (gradient) *gradient += 2.0 * w.dimple_depth * e * (2.0 - s2) * q / w.dimple_radius;
  return -w.dimple_depth * (1.0 - s2) * e;
}
}  // namespace

double SurfaceWaves::height(double x, double z) const {
  const double dimple = dimple_height(*this, x, z, nullptr);
  x /= radius, z /= radius;
  double u2 = x * x + z * z;
  if (u2 > 1.5625) {
    const double k = 1.25 / std::sqrt(u2);
    x *= k, z *= k, u2 = 1.5625;
  }
  return ring * (1.0 - 3.0 * u2 + 1.5 * u2 * u2) + cross.x * (x * x - z * z) + cross.y * (2.0 * x * z) + dimple;
}

glm::dvec2 SurfaceWaves::gradient(double x, double z) const {
  glm::dvec2 q(x / radius, z / radius);
  const double len = glm::length(q);
  // Beyond 1.25 radii the height is that of the point pulled in to 1.25 radii: chain rule
  // through that projection (only the angular part of the gradient survives).
  const bool held = len * len > 1.5625;
  const glm::dvec2 c = held ? q * (1.25 / len) : q;
  const double u2 = glm::dot(c, c);
  const double dr = ring * (-6.0 + 6.0 * u2);  // d(ring shape)/dx = dr * x
  glm::dvec2 g(dr * c.x + 2.0 * cross.x * c.x + 2.0 * cross.y * c.y, dr * c.y - 2.0 * cross.x * c.y + 2.0 * cross.y * c.x);
  if (held) {
    const glm::dvec2 dir = q / len;
    g = (1.25 / len) * (g - dir * glm::dot(dir, g));
  }
  g /= radius;
  dimple_height(*this, x, z, &g);
  return g;
}

}  // namespace draught
