// What the scene stands on (env.backdrop): the packshot studio's seamless sweep (the floor
// y = 0 in front of z_curve, a quarter cylinder of radius R up into the wall
// z = z_curve - R) or the checker floor to the horizon. Twins of
// core/environment/backdrop.cpp (BackdropSurface::intersect, BackdropSurface::albedo).
#ifndef LIB_ENVIRONMENT_BACKDROP_GLSL
#define LIB_ENVIRONMENT_BACKDROP_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"

struct BackdropSurface {
  bool present, checker, plane;  // plane: the floor alone to the horizon (BackdropSurface::plane)
  float z_curve, radius;
};

// Read from the Frame block once per pixel (init_backdrop, first in main) and held: every
// look at the surroundings reads them (a uniform block's member costs llvmpipe a load and
// a broadcast at each read).
BackdropSurface g_backdrop;
vec3 g_sweep_albedo;

void init_backdrop() {
  g_backdrop = BackdropSurface(frame.floor_on != 0, frame.backdrop_kind == 1, frame.backdrop_kind != 0, frame.sweep_z_curve,
                               frame.sweep_radius);
  g_sweep_albedo = frame.sweep_albedo;
}

BackdropSurface backdrop_surface() { return g_backdrop; }

// The nearest t > tmin where the ray o + t d meets the backdrop from the scene's side,
// and the normal there (unit, towards the scene). Twin of BackdropSurface::intersect.
bool intersect(BackdropSurface b, vec3 o, vec3 d, float tmin, out float t, out vec3 n) {
  t = INF;
  n = vec3(0.0, 1.0, 0.0);
  if (!b.present) return false;
  // The floor: the whole plane when `plane`, in front of the curve for the sweep.
  if (d.y < 0.0) {
    float tf = -o.y / d.y;
    if (tf > tmin && (b.plane || o.z + tf * d.z >= b.z_curve)) t = tf;
  }
  if (b.plane) return t < INF;
  // The wall above the curve.
  float z_wall = b.z_curve - b.radius;
  if (d.z < 0.0) {
    float tw = (z_wall - o.z) / d.z;
    if (tw > tmin && tw < t && o.y + tw * d.y >= b.radius) {
      t = tw;
      n = vec3(0.0, 0.0, 1.0);
    }
  }
  // The curve: the far crossing of the cylinder (the scene lies inside it there).
  float oy = o.y - b.radius, oz = o.z - b.z_curve;
  float qa = d.y * d.y + d.z * d.z, qb = oy * d.y + oz * d.z, qc = oy * oy + oz * oz - b.radius * b.radius;
  float disc = qb * qb - qa * qc;
  if (qa > 1e-12 && disc >= 0.0) {
    float tc = (-qb + sqrt(disc)) / qa;
    float y = oy + tc * d.y, z = oz + tc * d.z;  // relative to the cylinder's axis
    if (tc > tmin && tc < t && y <= 0.0 && z <= 0.0) {
      t = tc;
      n = normalize(vec3(0.0, -y, -z));
    }
  }
  return t < INF;
}

// The backdrop's diffuse albedo at point p on it. Twin of BackdropSurface::albedo.
vec3 albedo(BackdropSurface b, vec3 p) {
  if (!b.checker) return g_sweep_albedo;
  vec2 cell = floor(p.xz / frame.checker_size);
  return mod(cell.x + cell.y, 2.0) < 0.5 ? frame.floor_a : frame.floor_b;
}

#endif  // LIB_ENVIRONMENT_BACKDROP_GLSL
