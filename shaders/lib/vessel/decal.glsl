// Decals on a vessel's walls (core/vessel/decal.hpp, docs/DECALS.md): where a wall point
// lies on its layer's image, what it shows there, and what each kind does to a path that
// meets it. Compiled only into frames that draw a decal (DECALS). The mapping is the twin
// of core's WallArcLengths::at and decal_uv; tests/gpu/test_decals.cpp compares them.
#ifndef LIB_VESSEL_DECAL_GLSL
#define LIB_VESSEL_DECAL_GLSL
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "generated/objects.glsl"
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

// The mean radiance of the surroundings over the hemisphere around unit m, cosine
// weighted: what a frosted face scatters through from that side. Seven directions, each
// standing for a seventh of the cosine-weighted hemisphere (m itself and a ring at 50
// degrees): the dark sky above and beside a glass counts as the reference's frost sees it,
// not only the lit backdrop straight behind.
vec3 frost_behind(vec3 p, vec3 m) {
  vec3 t = normalize(abs(m.y) < 0.9 ? cross(m, vec3(0.0, 1.0, 0.0)) : cross(m, vec3(1.0, 0.0, 0.0)));
  vec3 b = cross(m, t);
  vec3 sum = background(p, m, 1.0);
  for (int i = 0; i < 6; ++i) {
    float a = float(i) * (PI / 3.0);
    sum += background(p, normalize(0.643 * m + 0.766 * (cos(a) * t + sin(a) * b)), 1.0);
  }
  return sum / 7.0;
}

// What a decal does to a path that meets it: the light it sends along the path (enamel
// and frost), the part it mirrors (metal: added to the surface's reflection) and the part
// of the path that goes on past it.
struct DecalEffect {
  vec3 light;
  vec3 mirror;
  float pass;
  float metal;  // the part of the surface that is metal, and its roughness
  float rough;
};

// The decal at the surface h of vessel v (world point p, local pl) for a path in `medium`
// going along d; below: p lies under the drink's surface. Light on a face that looks into
// the drink has crossed it (the drink's mean chord, as the head's underside); so has what
// shows through a frosted face from the drink's side. The rig's light is taken unshadowed
// (a decal is lit as the glass is: through clear glass), and what lies behind frost is
// the surroundings along the path (the blur of a frosted face leaves only its mean).
DecalEffect decal_effect(Vessel v, Hit h, int medium, vec3 p, vec3 pl, vec3 d, bool below) {
  DecalEffect e = DecalEffect(vec3(0.0), vec3(0.0), 1.0, 0.0, 0.0);
  float footprint = 2.0 * frame.cam_tan_half_vfov * frame.viewport_inv.y * length(p - frame.cam_eye);
  DecalSample s = decal_at(v, h.m, pl, footprint);
  if (s.cover <= 0.0) return e;
  e.pass = 1.0 - s.cover;
  if (s.kind == DECAL_METALLIC) {
    e.mirror = s.cover * s.tint;
    e.metal = s.cover;
    e.rough = s.rough;
    return e;
  }
  vec3 n = dot(h.n, d) < 0.0 ? h.n : -h.n;  // the face the path sees
  bool faces_drink = below && ((h.m == M_GLASS_INNER) != (medium == MEDIUM_GLASS));
  vec3 drink = below ? exp(-v.body.absorption * fetch_object_foam(v.row).under_chord) : vec3(1.0);
  vec3 lit = (rig_irradiance(p, n, frame.light_count) + sky_irradiance(n)) / PI * (faces_drink ? drink : vec3(1.0));
  if (s.kind == DECAL_ENAMEL) {
    e.light = s.cover * s.tint * lit;
    return e;
  }
  // Into glass or a drink the frost scatters light from behind only through the escape
  // cone of that medium's surfaces, (1 / n)^2 of it; the rest is guided round the glass
  // and leaves anywhere: it sees the surroundings' mean over the sphere (what a rising
  // bubble mirrors, core/environment/reflection).
  float n_far = medium_ior(v, glass_of(v.row), medium_across(h.m, medium, below));
  float escape = 1.0 / (n_far * n_far);
  vec3 behind = (escape * frost_behind(p, -n) + (1.0 - escape) * frame.bubble_env) * (below && !faces_drink ? drink : vec3(1.0));
  e.light = s.cover * s.tint * (FROST_BACKSCATTER * lit + (1.0 - FROST_BACKSCATTER) * behind);
  return e;
}

#endif  // LIB_VESSEL_DECAL_GLSL
