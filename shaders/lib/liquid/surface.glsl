// The drink's surface in a vessel: a plane dot(n, p) = offset (volume-true and
// rim-clamped, computed by core: VesselFrame::liquid) plus the slosh waves. Twin of
// core/liquid/slosh.cpp (SurfaceWaves) and core/reference/intersect.cpp
// (hit_liquid_surface, LiquidPlane::level).
#ifndef LIB_LIQUID_SURFACE_GLSL
#define LIB_LIQUID_SURFACE_GLSL
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"

// The renderer compiles the path pass twice: with SURFACE_WAVES 1 when some surface of
// the frame moves and 0 otherwise, which then carries no wave code at all (software
// rasterizers pay for code even where a branch skips it; still drinks are the common case).
#ifndef SURFACE_WAVES
#define SURFACE_WAVES 0
#endif

// Where a pour's stream plunges in: -depth (1 - s^2) exp(-s^2), s in the dimple's radii
// (a hollow and a low ring that move no volume; core SurfaceWaves, dimple_height), and its
// gradient: (height, d/dx, d/dz), one exp for both.
vec3 dimple_shape(ObjectLiquid lq, vec2 xz) {
  if (lq.dimple.w <= 0.0) return vec3(0.0);
  vec2 q = (xz - lq.dimple.xy) / lq.dimple.z;
  float s2 = dot(q, q), e = lq.dimple.w * exp(-s2);
  return vec3(-e * (1.0 - s2), 2.0 * e * (2.0 - s2) * q / lq.dimple.z);
}

// The waves' height over the plane and its gradient: (height, d/dx, d/dz). Beyond 1.25
// radii the shapes hold their value there (as core/liquid/slosh.cpp), the gradient by the
// chain rule through the pull-in.
vec3 wave_shape(ObjectLiquid lq, vec2 xz) {
  vec2 q = xz / lq.wave_radius;
  float len = length(q);
  bool held = len > 1.25;
  vec2 c = held ? q * (1.25 / len) : q;
  float u2 = dot(c, c);
  float height = lq.wave_ring * (1.0 - 3.0 * u2 + 1.5 * u2 * u2) + lq.wave_cos2a * (c.x * c.x - c.y * c.y) +
                 lq.wave_sin2a * 2.0 * c.x * c.y;
  float dr = lq.wave_ring * (-6.0 + 6.0 * u2);
  vec2 g = vec2(dr * c.x + 2.0 * lq.wave_cos2a * c.x + 2.0 * lq.wave_sin2a * c.y,
                dr * c.y - 2.0 * lq.wave_cos2a * c.y + 2.0 * lq.wave_sin2a * c.x);
  if (held) {
    vec2 dir = q / len;
    g = (1.25 / len) * (g - dir * dot(dir, g));
  }
  return vec3(height, g / lq.wave_radius) + dimple_shape(lq, xz);
}

// Signed height of p (local) over the surface of `lq`: negative in the liquid.
float level_over(ObjectLiquid lq, vec3 p) {
  float level = dot(lq.plane_normal, p) - lq.plane_offset;
#if SURFACE_WAVES
  level -= wave_shape(lq, p.xz).x;
#endif
  return level;
}

bool below_liquid(Vessel v, vec3 p) { return v.body.has_liquid != 0 && level_over(v.liquid, p) < 0.0; }

Hit hit_liquid_surface(Vessel v, vec3 o, vec3 d, float tmin) {
  if (v.body.has_liquid == 0) return no_hit();
  vec3 n = v.liquid.plane_normal;
  float dn = dot(n, d);
  if (abs(dn) < 1e-12) return no_hit();
  float t = (v.liquid.plane_offset - dot(n, o)) / dn;
#if SURFACE_WAVES
  for (int it = 0; it < 4; ++it) {  // Newton steps from the plane onto the waves
    vec3 p = o + t * d;
    vec3 w = wave_shape(v.liquid, p.xz);
    float slope = dn - dot(w.yz, d.xz);
    if (abs(slope) < 1e-12) break;
    t -= (dot(n, p) - v.liquid.plane_offset - w.x) / slope;
  }
#endif
  vec3 p = o + t * d;
  if (t <= tmin || p.y <= v.shape.base || p.y >= v.body.height || length(p.xz) >= inner_radius(v, p.y) || clipped(v, p))
    return no_hit();
#if SURFACE_WAVES
  vec2 g = wave_shape(v.liquid, p.xz).yz;
  return Hit(t, normalize(n - vec3(g.x, 0.0, g.y)), M_LIQUID_SURFACE, v.row);
#else
  return Hit(t, n, M_LIQUID_SURFACE, v.row);
#endif
}

#endif  // LIB_LIQUID_SURFACE_GLSL
