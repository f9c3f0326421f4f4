// Decals on a vessel's walls (core/vessel/decal.hpp, docs/DECALS.md): where a wall point
// lies on its layer's image, what it shows there, and what each kind does to a path that
// meets it. Compiled only into frames that draw a decal (DECALS). The mapping is the twin
// of core's WallArcLengths::at and decal_uv; tests/gpu/test_decals.cpp compares them.
#ifndef LIB_VESSEL_DECAL_GLSL
#define LIB_VESSEL_DECAL_GLSL
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "generated/objects.glsl"
#include "lib/liquid/body.glsl"
#include "lib/common/math.glsl"
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/lights.glsl"
#include "lib/environment/floor.glsl"
#include "lib/vessel/media.glsl"

// Of the light a frosted decal scatters, the part sent back to the side it came from; the
// rest goes through. Twin of kFrostBackscatter (core/reference/path_tracer.cpp).
const float FROST_BACKSCATTER = 0.2;

// The wall's arc length along its profile from the foot at height y (local): linear inside
// a segment, one fetch. Twin of WallArcLengths::at.
float wall_arc_length(Vessel v, bool inner, float y) {
  float s = clamp(y * v.shape.inv_dy, 0.0, float(SEGMENTS));
  int k = min(int(s), SEGMENTS - 1);
  vec4 a = texelFetch(u_decal_arcs, ivec2(k, v.shape.knot_row), 0);
  return inner ? mix(a.y, a.w, s - float(k)) : mix(a.x, a.z, s - float(k));
}

// Where the wall point p (local, on the layer's wall: 0 outer, 1 inner) lies on the
// layer's decal: uv over its image ((0, 0) the top-left corner seen from outside); false
// outside it. Across: the arc around the wall at p's height from the nearest copy's
// centre; down: the arc length along the profile from the centre. Twin of decal_uv.
bool decal_uv(Vessel v, int layer, vec3 p, out vec2 uv) {
  uv = vec2(0.0);
  vec4 form = object_decal_form(v.row, layer);
  if (form.x < 0.0) return false;
  vec4 place = object_decal_place(v.row, layer);
  float period = 2.0 * PI / form.z;
  float a = atan(p.x, p.z) - place.x;
  a -= period * floor(a / period + 0.5);
  bool inner = layer == 1;
  float r = inner ? inner_radius(v, p.y) : outer_radius(v, p.y);
  uv.x = place.z > 0.0 ? 0.5 + r * a / place.z : 0.5 + a / period;
  uv.y = 0.5 - (wall_arc_length(v, inner, p.y) - place.y) / place.w;
  return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// What a wall point shows of its decal: the part of the surface it covers (the image's
// alpha times the opacity) and its colour there (the image's times the layer's colour).
struct DecalSample {
  float cover;
  vec3 tint;
  int kind;
  float rough;
};

// The decal at wall point p (local) of surface m, seen by a pixel `footprint` metres wide
// there (the image's mipmap level).
DecalSample decal_at(Vessel v, int m, vec3 p, float footprint) {
  DecalSample s = DecalSample(0.0, vec3(0.0), DECAL_ENAMEL, 0.0);
  if (m != M_GLASS_OUTER && m != M_GLASS_INNER) return s;
  int layer = m == M_GLASS_INNER ? 1 : 0;
  vec2 uv;
  if (!decal_uv(v, layer, p, uv)) return s;
  vec4 form = object_decal_form(v.row, layer), look = object_decal_look(v.row, layer);
  float texels = float(textureSize(u_decal_images, 0).x);
  vec4 texel = textureLod(u_decal_images, vec3(uv, form.x), log2(max(footprint * texels / form.w, 1.0)));
  s.cover = texel.a * look.a;
  s.tint = texel.a > 1e-4 ? texel.rgb / texel.a * look.rgb : vec3(0.0);
  s.kind = int(form.y + 0.5);
  s.rough = object_decal_finish(v.row, layer).x;
  return s;
}

// The light the backdrop's floor sends a face of normal n at p, beyond the sky's: the
// floor under p lit and unshadowed (shade_backdrop_mirrored) over the part of what
// the face sees that an endless floor fills, its view factor (1 - n.y) / 2. A decal facing
// the camera gets about a third of its light from the lit paper in front of it.
vec3 floor_bounce(vec3 p, vec3 n) {
  vec3 q = vec3(p.x, 0.0, p.z);
  vec3 up = shade_backdrop_mirrored(q, vec3(0.0, 1.0, 0.0), normalize(q - frame.cam_eye), length(q - frame.cam_eye), false) - frame.ground;
  return frame.floor_on != 0 ? PI * max(up, vec3(0.0)) * 0.5 * (1.0 - n.y) : vec3(0.0);
}

// What a decal does to a path that meets it: the light it sends along the path (enamel
// and frost), the part it passes on, and what it looks up in the surroundings on its own:
// `behind` (frost: what it scatters through from the other side) and `mirror` (metal:
// what it reflects) weigh the mean of the surroundings over `taps` directions about
// `look` (frost: the hemisphere behind, its axis and a ring at 50 degrees; metal: set by
// the pass to the reflection, the GGX lobe's mirror direction and two rings, `spread`).
struct DecalEffect {
  vec3 light;
  float pass;
  vec3 behind;
  bool metal;
  vec3 mirror;
  int taps;
  vec3 look;
  float rough;
  vec2 spread;  // the rings' angles from `look`, rad
};

// The decal at the surface h of vessel v (world point p, local pl) for a path in `medium`
// going along d; below: p lies under the drink's surface. Light on a face that looks into
// the drink has crossed it (the drink's mean chord, as the head's underside); so has what
// shows through a frosted face from the drink's side. The rig's light is exact and
// unshadowed (a decal is lit as the glass is: through clear glass). Frost scatters light from the
// other side only through the escape cone of the medium there, (1 / n)^2 of it: the rest
// is guided round the glass and leaves anywhere, so it sees the surroundings' mean over
// the sphere (what a rising bubble mirrors, core/environment/reflection).
DecalEffect decal_effect(Vessel v, Hit h, int medium, vec3 p, vec3 pl, vec3 d, bool below) {
  DecalEffect e = DecalEffect(vec3(0.0), 1.0, vec3(0.0), false, vec3(0.0), 0, d, 0.0, vec2(0.0));
  // (Counts, not branches, pick what runs: llvmpipe runs both sides of a branch for every
  // pixel, but leaves a loop as soon as all its pixels have.)
  // (Loops keep a constant bound and break, as lib/environment/lights.glsl's: with a bound
  // that varied per pixel, a loop over the Frame block's lights added nothing on llvmpipe.)
  bool wall = h.m == M_GLASS_OUTER || h.m == M_GLASS_INNER;
  for (int once = 0; once < 1; ++once) {
    if (!wall) break;
    float footprint = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y * length(p - frame.cam_eye);
    DecalSample s = decal_at(v, h.m, pl, footprint);
    bool frost = s.kind == DECAL_ETCHED, lit = s.cover > 0.0 && s.kind != DECAL_METALLIC;
    e.metal = s.cover > 0.0 && s.kind == DECAL_METALLIC;
    e.pass = 1.0 - s.cover;
    e.mirror = e.metal ? s.cover * s.tint : vec3(0.0);
    e.rough = s.rough;
    float a = s.rough * s.rough;  // GGX alpha: rings at tan(theta_h) = 0.67 and 1.83 alpha hold equal shares of its normals
    e.spread = e.metal ? 2.0 * atan(vec2(0.67, 1.83) * a) : vec2(radians(50.0), 0.0);
    e.taps = e.metal ? 13 : (lit && frost ? 7 : 0);
    vec3 n = dot(h.n, d) < 0.0 ? h.n : -h.n;  // the face the path sees
    e.look = -n;
    bool faces_drink = below && ((h.m == M_GLASS_INNER) != (medium == MEDIUM_GLASS));
    vec3 drink = below ? mean_chord_transmittance(v) : vec3(1.0);
    vec3 light = (rig_irradiance(p, n, lit ? frame.light_count : 0) + sky_irradiance(n) + floor_bounce(p, n)) / PI *
                 (faces_drink ? drink : vec3(1.0));
    float n_far = medium_ior(v, glass_of(v.row), medium_across(h.m, medium, below));
    float escape = 1.0 / (n_far * n_far);
    vec3 through = (below && !faces_drink ? drink : vec3(1.0)) * s.cover * s.tint * (1.0 - FROST_BACKSCATTER);
    e.behind = lit && frost ? escape * through : vec3(0.0);
    e.light = !lit ? vec3(0.0)
                   : frost ? s.cover * s.tint * FROST_BACKSCATTER * light + (1.0 - escape) * through * frame.bubble_env
                           : s.cover * s.tint * light;
  }
  return e;
}

// The mean of what the surroundings show from p over `taps` directions about unit m: m
// itself, then a ring of six at spread.x from it, then a ring of six at spread.y (turned
// by 30 degrees). Each direction sees a light's front, else the backdrop (lights as
// points, and, for up to 13 taps a pixel, without the glass's reflections' shadows), else
// the sky. One call site in the
// path pass (llvmpipe pays for every copy of inlined code, run or not).
vec3 decal_surroundings(vec3 p, vec3 m, vec2 spread, float rough, int taps) {
  vec3 t = normalize(abs(m.y) < 0.9 ? cross(m, vec3(0.0, 1.0, 0.0)) : cross(m, vec3(1.0, 0.0, 0.0)));
  vec3 b = cross(m, t);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < 13; ++i) {
    if (i >= taps) break;
    int k = i - 1;
    float off = i == 0 ? 0.0 : (k < 6 ? spread.x : spread.y), phi = float(k) * (PI / 3.0) + (k < 6 ? 0.0 : PI / 6.0);
    vec3 d = cos(off) * m + sin(off) * (cos(phi) * t + sin(phi) * b);
    float tb, tl;
    vec3 nb;
    bool on_backdrop = intersect(backdrop_surface(), p, d, 0.0, tb, nb);
    vec4 light = lights_seen(p, d, rough, tb, false, tl);
    vec3 beyond = on_backdrop ? shade_backdrop_mirrored(p + tb * d, nb, d, tb, false) : sky_seen(d, rough);
    sum += light.rgb * light.a + beyond * (1.0 - light.a);
  }
  return sum / max(float(taps), 1.0);
}

#endif  // LIB_VESSEL_DECAL_GLSL
