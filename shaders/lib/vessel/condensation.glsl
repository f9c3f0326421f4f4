// Condensation on a glass's outer wall (core/condensation, docs/CONDENSATION.md): the bead
// a wall point lies on, found through the wall's (angle, height) grid (a few texel fetches,
// not a march over the beads), and the fog's cover there. A bead is a water lens: a
// spherical cap drawn by its normal. Compiled only into frames that show condensation
// (CONDENSATION). Twin of core/condensation/wall_grid (bead_at, fog_at); compared by
// tests/gpu/test_condensation.cpp.
#ifndef LIB_VESSEL_CONDENSATION_GLSL
#define LIB_VESSEL_CONDENSATION_GLSL
#include "generated/constants.glsl"
#include "generated/objects.glsl"
#include "lib/common/math.glsl"
#include "lib/scene/objects.glsl"
#include "lib/optics/fresnel.glsl"
#include "lib/environment/lights.glsl"
#include "lib/environment/studio.glsl"

// The mist's FOG_SCATTER and FOG_ALBEDO (generated/constants.glsl) as a veil, not a
// blur: its light is what the air side's lights and sky send it (cheap: no look-ups).

// A bead is listed in the grid's cells within this many of its radii (twin of kHalo).
const float BEAD_HALO = 1.35;

struct BeadSample {
  bool found;  // the point lies on a bead's base
  vec3 n;      // the bead's cap there (outward, local frame); the wall's elsewhere
  float clear; // what is left of the fog: 0 under a bead, 1 from BEAD_HALO radii on
};

// The bead at local point p of vessel v's outer wall (outward normal n, local).
BeadSample condensation_bead(Vessel v, vec3 p, vec3 n) {
  BeadSample s = BeadSample(false, n, 1.0);
  ObjectCondensation c = fetch_object_condensation(v.row);
  float fy = (p.y - c.condensation_y0) / (c.condensation_y1 - c.condensation_y0);
  if (c.condensation_band < 0 || !(fy >= 0.0 && fy < 1.0)) return s;
  float a = atan(p.x, p.z);
  int ia = clamp(int(floor((a + PI) / (2.0 * PI) * float(CONDENSATION_ANGLES))), 0, CONDENSATION_ANGLES - 1);
  int iy = clamp(int(fy * float(CONDENSATION_ROWS)), 0, CONDENSATION_ROWS - 1);
  float rw = length(p.xz);
  vec3 across = vec3(p.z, 0.0, -p.x) / rw;     // round the axis
  vec3 up = normalize(cross(n, across));       // up the profile
  float up_y = max(up.y, 0.2);
  float sin_contact = sin(c.contact_angle);
  ivec2 cell = ivec2(ia * CONDENSATION_SLOTS, c.condensation_band * CONDENSATION_ROWS + iy);
  for (int k = 0; k < CONDENSATION_SLOTS; ++k) {
    vec4 b = texelFetch(u_condensation_beads, cell + ivec2(k, 0), 0);
    float da = a - b.x;
    da -= 2.0 * PI * floor(da / (2.0 * PI) + 0.5);
    vec3 rho = (rw * da) * across + ((p.y - b.y) / up_y) * up;
    float q = b.z > 0.0 ? length(rho) / b.z : 2.0;
    s.clear = min(s.clear, smoothstep(1.0, BEAD_HALO, q));
    if (q < 1.0 && !s.found) {
      float R = b.z / sin_contact;
      s.found = true;
      s.n = normalize(rho + n * sqrt(max(R * R - dot(rho, rho), 0.0)));
    }
  }
  return s;
}

// The fog's cover at local point p of vessel v's outer wall (the map's linear filtering).
float condensation_fog(Vessel v, vec3 p) {
  ObjectCondensation c = fetch_object_condensation(v.row);
  float fy = (p.y - c.condensation_y0) / (c.condensation_y1 - c.condensation_y0);
  if (c.condensation_band < 0 || !(fy >= 0.0 && fy < 1.0)) return 0.0;
  float rows = float(textureSize(u_condensation_fog, 0).y);
  float t = (float(c.condensation_band * CONDENSATION_FOG_ROWS) +
             clamp(fy * float(CONDENSATION_FOG_ROWS), 0.5, float(CONDENSATION_FOG_ROWS) - 0.5)) / rows;
  return texture(u_condensation_fog, vec2((atan(p.x, p.z) + PI) / (2.0 * PI), t)).r;
}

// What the fog on vessel v's wall (outward normal n, world; cover f) does to a path crossing it:
// the light it adds per unit of the path's throughput, and (w) what it lets through.
// The lights are taken as distant lights from the glass's middle (objects.def lit_by, as
// the head takes them): a mist needs no more, and the exact area-light sum per wall point
// cost a fifth of a cold pint's frame on llvmpipe. Besides them the mist is lit by all
// that lies around, the lit paper of the backdrop included (surround_irradiance; with the
// sky's alone it came out too yellow and dark against the reference: the cold pint's
// liquid 3.08 / 5.32, close up 2.87 / 4.47; now 2.23 / 4.00 and 1.74 / 2.85).
vec4 fog_veil(Vessel v, vec3 n, float f) {
  float m = f * FOG_SCATTER;
  vec3 irradiance = surround_irradiance(n);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= g_light_count) break;
    vec4 lit = object_lit_by(v.row, i);
    irradiance += area_light(i).radiance * lit.w * max(dot(n, lit.xyz), 0.0);
  }
  // The half it scatters on through the wall is taken on straight with what passes
  // (the picture cannot blur it; behind a mist is mostly the drink's smooth colour): the
  // reference, which follows it, showed the mist between the beads as dark as if that
  // half were lost.
  return vec4(m * FOG_ALBEDO * 0.5 * irradiance / PI, 1.0 - m + 0.5 * m * FOG_ALBEDO);
}

// The outer wall crossed through a bead: air and water meet at the cap (normal nb,
// world), water and glass at the wall (nw, world, facing the path's side it comes from).
// From the air: the cap bends the path in, the wall a little more (no total reflection
// going into denser media). From the glass: the wall first (total reflection beyond
// water's wider critical angle), then the cap; light the cap turns back (total internal
// reflection in the bead) re-enters the glass. F: the part reflected where the path meets
// the surface (the cap from the air; the wall, plus the cap's share, from the glass);
// onward: the path's direction after all; leaves: whether it is then in the air.
struct BeadCrossing {
  vec3 n;    // the normal the reflection sees (facing the path)
  float F;
  vec3 onward;
  bool leaves;
};

BeadCrossing bead_crossing(vec3 d, vec3 nb, vec3 nw, float glass_ior, bool from_air) {
  BeadCrossing x;
  if (from_air) {
    x.n = dot(nb, d) < 0.0 ? nb : -nb;
    x.F = fresnel_dielectric(-dot(x.n, d), 1.0, WATER_IOR);
    vec3 in_water = refract(d, x.n, 1.0 / WATER_IOR);
    x.onward = refract(in_water, nw, WATER_IOR / glass_ior);
    x.leaves = false;
    return x;
  }
  x.n = nw;
  float Fw = fresnel_dielectric(-dot(nw, d), glass_ior, WATER_IOR);
  vec3 in_water = refract(d, nw, glass_ior / WATER_IOR);
  vec3 cap = dot(nb, in_water) < 0.0 ? nb : -nb;
  float Fc = fresnel_dielectric(-dot(cap, in_water), WATER_IOR, 1.0);
  x.leaves = Fw < 1.0 && Fc < 1.0;
  x.F = Fw >= 1.0 ? 1.0 : (x.leaves ? Fw + (1.0 - Fw) * Fc : Fw);
  // Turned back by the cap: through the wall into the glass again (going into glass: no
  // total reflection).
  vec3 back = refract(reflect(in_water, cap), -nw, WATER_IOR / glass_ior);
  x.onward = Fw >= 1.0 ? reflect(d, nw) : (x.leaves ? refract(in_water, cap, WATER_IOR) : back);
  return x;
}

#endif  // LIB_VESSEL_CONDENSATION_GLSL
