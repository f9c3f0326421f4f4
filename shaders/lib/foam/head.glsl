// The foam head of a vessel: a volume on the liquid surface up to the head's top (where
// core/foam puts it), marched only along the stretch of a ray inside it. Beer's-law
// opacity per step, light derived from single scattering of the studio's lights, or of an
// environment image's brightest patches (each a distant light from the glass's middle:
// objects.def lit_by, frame.media_light_*; core/environment/media_light) and the diffusion
// approximation between the head's faces (head_source; no shadow rays), micro-bubble
// detail from value noise, big
// bubbles (placed by core: VesselFrame::big_bubbles) as voids with a denser ring around
// them, and lacing rings left on the glass. All in the vessel's frame.
#ifndef LIB_FOAM_HEAD_GLSL
#define LIB_FOAM_HEAD_GLSL
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "lib/common/noise.glsl"
#include "lib/optics/fresnel.glsl"
#include "lib/scene/objects.glsl"
#include "lib/vessel/intersect.glsl"
#include "lib/vessel/media.glsl"
#include "lib/liquid/surface.glsl"
#include "lib/liquid/body.glsl"
#include "lib/environment/lights.glsl"

// Compiled in only for frames with a head (gpu/renderer.cpp builds the variants).
#ifndef FOAM_HEAD
#define FOAM_HEAD 0
#endif

int g_foam_steps = 0;  // march steps this pixel took (cost view)

// Big bubble i of vessel v (placed by core): centre (local frame) and radius; a popped
// one (its record's radius < 0) is a void that heals.
struct BigBubble {
  vec3 centre;
  float radius;
  bool popped;
};

BigBubble big_bubble(Vessel v, int i) {
  vec4 b = object_big_bubbles(v.row, i);  // the record's layout: centre xyz, signed radius
  return BigBubble(b.xyz, abs(b.w), b.w < 0.0);
}

// The head's thickness above the liquid at (x, z): domed or concave (as core/foam
// FoamFrame::thickness_at).
// A pour's stream pushes the foam aside where it plunges in: a dimple, the foam heaped
// in a collar around it (CRATER_COLLAR high at CRATER_COLLAR_AT radii).
float foam_thickness_at(Vessel v, ObjectFoam f, vec2 xz) {
  float u2 = min(dot(xz, xz) / (v.liquid.wave_radius * v.liquid.wave_radius), 1.5);
  float t = f.thickness * max(1.0 + f.dome * (1.0 - 2.0 * u2), 0.1);
  if (f.crater.w > 0.0 && f.crater.z > 0.0) {
    float s = length(xz - f.crater.xy) / f.crater.z, c = (s - CRATER_COLLAR_AT) / 0.5;
    t *= 1.0 - f.crater.w * (exp(-s * s) - CRATER_COLLAR * exp(-c * c));
  }
  return t;
}

// The normal of the head's top above (x, z): the dome's slope (foam_thickness_at without
// a pour's crater), about the liquid's plane.
vec3 foam_top_normal(Vessel v, ObjectFoam f, vec2 xz) {
  float inv_r2 = 1.0 / (v.liquid.wave_radius * v.liquid.wave_radius);
  float u2 = dot(xz, xz) * inv_r2;
  bool sloped = u2 < 1.5 && 1.0 + f.dome * (1.0 - 2.0 * u2) > 0.1;
  vec2 slope = sloped ? -4.0 * f.thickness * f.dome * inv_r2 * xz : vec2(0.0);
  return normalize(v.liquid.plane_normal - vec3(slope.x, 0.0, slope.y));
}

// Bubbles are bigger low in the head (they coarsen as liquid drains out of it): at the
// liquid 1 + FOAM_GROWTH times their size at the top. A foam's extinction goes as its
// bubbles' surface per volume, 1 / size, so the wet foam low in the head is the more
// translucent: the head fades into the drink. Its top is soft over FOAM_SOFT_TOP of its
// thickness. (As core/foam/head_volume.cpp.)
const float FOAM_GROWTH = 1.5;
const float FOAM_SOFT_TOP = 0.12;
float foam_growth(float height, float top) { return 1.0 + FOAM_GROWTH * (1.0 - height / top); }

// The extinction the head has on average at `height` above the liquid, under its top:
// foam_density without the bubbles' detail and the big bubbles.
float foam_smooth_density(ObjectFoam f, float height, float top) {
  if (height < 0.0 || height > top) return 0.0;
  return f.density / foam_growth(height, top) * clamp((top - height) / (FOAM_SOFT_TOP * top), 0.0, 1.0);
}

// Extinction at p; `height` is p's height above the liquid, `top` the head's thickness
// there. The twin of core/foam/head_volume.cpp HeadVolume::density.
float foam_density(Vessel v, ObjectFoam f, vec3 p, float height, float top) {
  if (height < 0.0 || height > top || p.y > v.body.height || length(p.xz) > inner_radius(v, p.y) || clipped(v, p))
    return 0.0;
  float grow = foam_growth(height, top);
  float d = foam_smooth_density(f, height, top) * max(1.0 + 1.6 * f.detail * (value_noise(p / (f.bubble_size * grow)) - 0.5), 0.0);
  for (int i = 0; i < f.big_bubble_count; ++i) {
    BigBubble b = big_bubble(v, i);
    float r = b.radius, dist = length(p - b.centre);
    if (dist < r) return 0.0;  // inside a big bubble, or the void a popped one left
    float ring = (dist - r) / (0.45 * r);
    d *= 1.0 + (b.popped ? 0.6 : 1.8) * exp(-ring * ring);
  }
  return d;
}

float hg_phase(float c, float g) {
  float g2 = g * g;
  return (1.0 - g2) / (4.0 * PI * pow(max(1.0 + g2 - 2.0 * g * c, 1e-4), 1.5));
}

// The light a head receives, per march. Its lighting is derived, not tuned
// (docs/REFERENCE.md, "The head in the picture"): the key's unscattered light scattered
// once (Henyey-Greenstein), plus the diffusion approximation's field between the head's
// three faces: the top (the sky and the key), the side against the glass (the studio and
// the key through the wall) and the underside (light from below through the drink, which
// tints it). The diffuse light is the surroundings' (the sky and the lit backdrop around
// the scene's centre, core surround_irradiance), facing up, sideways and on average. A
// white head in even light is then exactly as bright as that light.
struct HeadLight {
  vec3 albedo;  // single-scattering albedo (core derives it from foam.color)
  vec3 kappa;   // diffusion's decay per optical depth: sqrt(3 (1 - a)(1 - a g))
  float zb;     // the extrapolated boundary beyond each face, in optical depths: 2 / (3 (1 - g))
  vec3 top_sky;   // diffuse light arriving on the top
  // and on the side facing local (x, 0, z): side_xx x^2 + side_zz z^2 + side_xz x z +
  // side_x x + side_z z (irradiance of second-order harmonics is a quadratic form in the
  // normal, exactly), over pi
  vec3 side_xx, side_zz, side_xz, side_x, side_z;
  vec3 below;   // and on the underside, through the drink
  float ior;          // the glass's
  float wall_diffuse; // the part of even light the glass wall lets through (two faces)
  int count;    // the rig's lights, each a distant light from the glass's middle:
  vec3 key[MAX_LIGHTS];  // its irradiance (facing it)
  vec3 l[MAX_LIGHTS];    // the direction towards it (local)
  // What stays the same along one ray (head_along): each light's irradiance times the
  // phase function towards -d, the cosine of its direction with the surface's normal,
  // and the light all of them give the top face.
  vec3 key_phase[MAX_LIGHTS];
  float cos_top[MAX_LIGHTS];
  vec3 top_key;
};

// The part of a light's irradiance on a face (falling at cosine mu0) that the single
// scattering term (head_source's `single`) sends back out through that face, in a
// half-space of white foam: its exitance 2 pi a E integral of p(theta) mu / (mu0 + mu) dmu
// over the outgoing hemisphere, over E. For isotropic scattering exactly
// (1 - mu0 ln(1 + 1/mu0)) / 2 (0.153 at normal incidence, 1/2 at grazing); for g != 0 that
// times Henyey-Greenstein's backward share over isotropic's 1/2 (an approximation; every
// preset has g = 0). The diffusion's face takes the light less this part: a white head
// under a light then sends back what it receives, not that and its single scattering too.
float single_exitance(float mu0, float g) {
  if (mu0 <= 0.0) return 0.0;
  float back = abs(g) < 1e-3 ? 0.5 : (1.0 - g) / (2.0 * g) * ((1.0 + g) / sqrt(1.0 + g * g) - 1.0);
  return (1.0 - mu0 * log(1.0 + 1.0 / mu0)) * back;
}

// The light along a ray of direction d (local) through the head, which it enters above
// xz: the top's slope there (foam_top_normal) stands for the whole ray's.
void head_along(inout HeadLight h, Vessel v, ObjectFoam f, vec3 d, vec2 xz) {
  h.top_key = vec3(0.0);
  vec3 n_top = foam_top_normal(v, f, xz);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    h.key_phase[i] = h.key[i] * hg_phase(dot(h.l[i], d), f.anisotropy);
    h.cos_top[i] = dot(n_top, h.l[i]);
    h.top_key += h.key[i] * max(h.cos_top[i], 0.0) * (1.0 - single_exitance(h.cos_top[i], f.anisotropy));
  }
}

HeadLight head_light(Vessel v, ObjectFoam f) {
  HeadLight h;
  h.albedo = f.foam_color;
  h.kappa = sqrt(3.0 * max(1.0 - h.albedo, 0.0) * (1.0 - h.albedo * f.anisotropy));
  h.zb = 2.0 / (3.0 * (1.0 - f.anisotropy));
  // The surroundings besides the lights (frame.media_sh: the surround, less an image's
  // patches taken as lights) as the head sees them from its middle (the record's head_sh),
  // read once per head.
  vec3 sh[9];
  for (int i = 0; i < 9; ++i) sh[i] = object_head_sh(v.row, i).rgb;
  h.top_sky = sh_irradiance(sh, to_world_dir(v, vec3(0.0, 1.0, 0.0))) / PI;
  // The side's light at the four sides and between two of them fixes its quadratic form.
  vec3 u = to_world_dir(v, vec3(1.0, 0.0, 0.0)), w = to_world_dir(v, vec3(0.0, 0.0, 1.0));
  vec3 eu = sh_irradiance(sh, u) / PI, enu = sh_irradiance(sh, -u) / PI;
  vec3 ew = sh_irradiance(sh, w) / PI, enw = sh_irradiance(sh, -w) / PI;
  vec3 euw = sh_irradiance(sh, normalize(u + w)) / PI;
  h.side_xx = 0.5 * (eu + enu);
  h.side_zz = 0.5 * (ew + enw);
  h.side_x = 0.5 * (eu - enu);
  h.side_z = 0.5 * (ew - enw);
  h.side_xz = 2.0 * (euw - 0.5 * (h.side_xx + h.side_zz) - 0.70710678 * (h.side_x + h.side_z));
  // Under the head, light from all around through the drink: the surroundings' mean
  // radiance (their band-0 harmonic), along the drink's mean chord.
  h.below = sh[0] * (0.282095 / PI) * drink_transmittance(v.body, f.under_chord);
  // The lights: the rig's, or an image's brightest patches (core media_light).
  h.count = frame.media_light_count;
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    vec4 lit = i < h.count ? object_lit_by(v.row, i) : vec4(0.0, 1.0, 0.0, 0.0);
    h.key[i] = frame.media_light_radiance[i].rgb * lit.w;
    h.l[i] = to_local_dir(v, lit.xyz);
  }
  h.ior = fetch_object_glass(v.row).glass_ior;
  h.wall_diffuse = f.wall_diffuse;  // (of even light: core wall_diffuse_transmittance, once per frame)
  return h;
}

// The diffusion approximation's field (decay kappa per optical depth) in a head with
// faces at extrapolated distances u (optical depths; e = exp(kappa u)), each face held at
// its incoming radiance. Between two parallel faces the share of face i is exactly
//   sinh(kappa u_j) / sinh(kappa (u_i + u_j)) = 1 / (cosh(kappa u_i) + sinh(kappa u_i) coth(kappa u_j)),
// generalised to more faces by summing their pulls kappa (coth(kappa u_j) - 1): a lone
// face gives exp(-kappa u) (the semi-infinite medium, whose Marshak boundary is the
// exp(-kappa zb) at the face), and with kappa = 0 the shares are inverse-distance
// weights that sum to 1 (a white head in even light returns that light).
vec3 face_pull(vec3 kappa, float u, vec3 e) {
  return mix(2.0 * kappa / max(e * e - 1.0, 1e-30), vec3(1.0 / u) - kappa, lessThan(kappa * u, vec3(5e-4)));
}
vec3 face_share(vec3 kappa, float u, vec3 e, vec3 others) {
  vec3 sinh_k = mix(0.5 * (e - 1.0 / e) / max(kappa, 1e-30), vec3(u), lessThan(kappa * u, vec3(5e-4)));  // sinh(kappa u) / kappa
  return 1.0 / (0.5 * (e + 1.0 / e) + sinh_k * (kappa + others));
}

// Light scattered towards -d at p per unit extinction (albedo included): `height` is p's
// height above the liquid, `top` the head's thickness there; d, l local. Optical depths
// to the faces are those of the mean density.
vec3 head_source(Vessel v, ObjectFoam f, HeadLight h, vec3 d, vec3 p, float height, float top) {
  // The top is the head's (its soft ramp integrated) or the rim's where a dome stands
  // above the glass; the side the wall's or a cross-section's cut, whichever is nearer.
  // (The integrals of foam_density's 1 / growth over height; the soft top taken as if
  // the bubbles did not grow within it.)
  float ramp = FOAM_SOFT_TOP * top, depth = max(top - height, 0.0), grow = foam_growth(height, top);
  float to_top = depth > ramp ? top / FOAM_GROWTH * log(grow / (1.0 + FOAM_GROWTH * FOAM_SOFT_TOP)) + 0.5 * ramp
                              : depth * depth / (2.0 * ramp);
  float tau_t = f.density * min(to_top, max(v.body.height - p.y, 0.0));
  float tau_b = f.density * top / FOAM_GROWTH * log((1.0 + FOAM_GROWTH) / grow);
  float r = length(p.xz);
  float tau_s = f.density / grow * max(min(inner_radius(v, p.y) - r, v.shape.clip_offset - dot(v.shape.clip_normal, p)), 0.0);
  // Each light's unscattered light, through the top or through the wall beside p, and
  // what it gives the top and the side faces.
  // (d's share is in h, head_along.)
  vec3 single = vec3(0.0), side_key = vec3(0.0);
  vec2 across = r > 1e-6 ? p.xz / r : vec2(0.0);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= h.count) break;
    float cos_t = h.cos_top[i], cos_s = dot(across, h.l[i].xz);
    float wall = cos_s > 0.0 ? wall_transmittance(cos_s, h.ior) : 0.0;
    float direct = max(cos_t > 0.0 ? exp(-tau_t / cos_t) : 0.0, cos_s > 0.0 ? wall * exp(-tau_s / cos_s) : 0.0);
    single += h.key_phase[i] * direct;
    side_key += h.key[i] * wall * max(cos_s, 0.0) * (1.0 - single_exitance(cos_s, f.anisotropy));
  }
  // Diffusion between the faces: each face's incoming radiance (a light's irradiance
  // counted as a diffuse pi L) held at its extrapolated boundary, the field the sum of
  // each face's share (face_share).
  vec3 top_in = h.top_sky + h.top_key / PI;
  vec3 side_sky = max(h.side_xx * across.x * across.x + h.side_zz * across.y * across.y + h.side_xz * across.x * across.y +
                      h.side_x * across.x + h.side_z * across.y, vec3(0.0));
  vec3 side_in = side_sky + side_key / (PI * h.wall_diffuse);
  float ut = tau_t + h.zb, ub = tau_b + h.zb, us = tau_s + h.zb * (2.0 - h.wall_diffuse) / h.wall_diffuse;
  vec3 et = exp(min(h.kappa * ut, 60.0)), eb = exp(min(h.kappa * ub, 60.0)), es = exp(min(h.kappa * us, 60.0));
  vec3 pt = face_pull(h.kappa, ut, et), pb = face_pull(h.kappa, ub, eb), ps = face_pull(h.kappa, us, es);
  vec3 diffuse = face_share(h.kappa, ut, et, pb + ps) * top_in + face_share(h.kappa, ub, eb, pt + ps) * h.below +
                 face_share(h.kappa, us, es, pt + pb) * side_in;
  return h.albedo * (single + diffuse);
}

// The light a thin film of foam on the wall (lacing) scatters towards -d: a head's side
// face, lit straight.
vec3 lacing_light(Vessel v, ObjectFoam f, vec3 d) {
  HeadLight h = head_light(v, f);
  vec3 lit = 0.5 * (h.side_xx + h.side_zz);  // (the side's light, around the glass)
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    if (i >= h.count) break;
    lit += h.key[i] * hg_phase(dot(h.l[i], d), f.anisotropy);
  }
  return h.albedo * lit;
}

// The part of [t0, t1] along o + t d (local) where the head (or a big bubble's cap) can
// be: the slab from the lowest wave to the highest top, inside the cavity's bounding
// cylinder.
bool foam_interval(Vessel v, ObjectFoam f, vec3 o, vec3 d, inout float t0, inout float t1) {
  vec3 n = v.liquid.plane_normal;
  float waves = abs(v.liquid.wave_ring) + abs(v.liquid.wave_cos2a) + abs(v.liquid.wave_sin2a) + v.liquid.dimple.w;
  float top_max = f.thickness * (1.0 + abs(f.dome)) * (1.0 + CRATER_COLLAR * f.crater.w) + waves + 0.006;
  float h0 = dot(n, o) - v.liquid.plane_offset, dh = dot(n, d);
  float lo = -waves;
  if (abs(dh) > 1e-9) {
    float ta = (lo - h0) / dh, tb = (top_max - h0) / dh;
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
  } else if (h0 < lo || h0 > top_max) {
    return false;
  }
  vec2 tr;
  if (!clip_to_bounds(o, d, v.shape.base, v.body.height, v.bounds.bound_radius, t0, tr)) return false;
  t0 = tr.x;
  t1 = min(t1, tr.y);
  return t1 > t0;
}

// Marches the head along o + t d for t in [t0, t1] (a stretch through air, already cut to
// foam_interval). Adds the light it scatters to `radiance` and attenuates `thr`.
void march_foam(Vessel v, ObjectFoam f, vec3 o, vec3 d, float t0, float t1, inout vec3 radiance,
                inout vec3 thr) {
  // Steps of at most one optical depth of the top's density (a thick head stops the
  // march within about ten), at least 6 and at most 40 over the stretch. A step may still
  // be several optical depths thick (a ray into the head's side crosses a hundred), so its
  // one sample is not placed evenly along it: its depth into the step is drawn (the pixel's
  // jitter u) from the attenuation exp(-sigma s) of the foam's smooth density where the last
  // sample was, as the light scattered there reaches the eye. Placed evenly, a side's first
  // sample lay half a step deep on average, twice as deep as the light it sends comes from:
  // too little of a light's single scattering and too much of the diffusion's tinted light
  // (a stout's head side yellow against the reference). Weighed by its own opacity, a
  // step's share still telescopes: a white head in even light is exactly that light.
  float len = t1 - t0;
  int steps = int(clamp(ceil(len * f.density), 6.0, 40.0));
  float dt = len / float(steps);
  float u = march_jitter(), t = t0;
  HeadLight h = head_light(v, f);
  head_along(h, v, f, d, (o + t0 * d).xz);
  vec3 p = o + t0 * d;
  float sigma_n = foam_smooth_density(f, level_over(v.liquid, p), foam_thickness_at(v, f, p.xz));
  for (int i = 0; i < 40; ++i) {
    if (i >= steps) break;
    ++g_foam_steps;
    float dn = sigma_n * dt, s = dn > 1e-3 ? -log(1.0 - u * (1.0 - exp(-dn))) / sigma_n : u * dt;  // (u dt: even)
    p = o + (t + s) * d;
    float height = level_over(v.liquid, p), top = foam_thickness_at(v, f, p.xz);
    float sigma = foam_density(v, f, p, height, top);
    sigma_n = foam_smooth_density(f, height, top);
    if (sigma > 0.0) {
      float trans = exp(-sigma * dt);
      radiance += thr * head_source(v, f, h, d, p, height, top) * (1.0 - trans);
      thr *= trans;
      if (max(thr.r, max(thr.g, thr.b)) < 1e-3) {
        thr = vec3(0.0);
        return;
      }
    }
    t += dt;
  }
}

// A big bubble's cap is a thin film of the drink: it mirrors the surroundings at grazing
// angles (Fresnel from air into the liquid's index, both faces). The caps are taken in
// the bubbles' order, each pass finding the next one the ray meets: a cap's look at the
// surroundings is the heavy part, and llvmpipe would run it for every bubble, met or not.
void bubble_caps(Vessel v, ObjectFoam f, vec3 o, vec3 d, float t0, float t1, inout vec3 radiance,
                 inout vec3 thr) {
  int done = -1;  // the caps up to this bubble are done
  for (int pass = 0; pass < MAX_BIG_BUBBLES; ++pass) {
    int next = -1;
    vec3 p = vec3(0.0), nn = vec3(0.0, 1.0, 0.0);
    for (int i = 0; i < f.big_bubble_count; ++i) {
      BigBubble b = big_bubble(v, i);
      vec3 oc = o - b.centre;
      float bb = dot(oc, d), disc = bb * bb - (dot(oc, oc) - b.radius * b.radius);
      float t = -bb - sqrt(max(disc, 0.0));
      vec3 q = o + t * d;
      // only the cap above the foam
      bool cap = !b.popped && disc > 0.0 && t > t0 && t < t1 && level_over(v.liquid, q) >= foam_thickness_at(v, f, q.xz) &&
                 !clipped(v, q);
      if (cap && i > done && next < 0) {
        next = i;
        p = q;
        nn = normalize(q - b.centre);
      }
    }
    if (next < 0) break;
    done = next;
    float F = fresnel_dielectric(abs(dot(nn, d)), 1.0, v.liquid.ior);
    float film = 2.0 * F / (1.0 + F);  // two faces of the film
    vec3 refl = reflect(d, nn);
    radiance += thr * film * lights_and_sky(to_world_point(v, p), to_world_dir(v, refl), 0.0);
    thr *= 1.0 - film;
  }
}

// The network fades out where its cells are under a few pixels (`px` cells a pixel).
float cell_border_fade(float px) { return 1.0 - smoothstep(0.25, 0.5, px); }

// The borders of a Voronoi network of unit cells at q (1 on a border, fading out over a
// fifth of a cell and `px` cells more; 0 inside a cell).
float cell_border(vec2 q, float px) {
  vec2 i = floor(q), fq = q - i;
  float d1 = 8.0, d2 = 8.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      vec2 o = vec2(float(x), float(y));
      vec2 r = o + hash22_cell(ivec2(i + o)) - fq;
      float d = dot(r, r);
      d2 = d < d1 ? d1 : min(d2, d);
      d1 = min(d1, d);
    }
  return (1.0 - smoothstep(0.0, 0.2 + px, sqrt(d2) - sqrt(d1))) * cell_border_fade(px);
}

// The mean of cell_border over the plane at `px`: the share of a cell its border covers.
// Fitted to the network's own sites (hash22_cell; Monte Carlo over 60,000 points, within
// 1 % for px in [0, 0.5]): with w = 0.2 + px, 1.243 w - 0.4575 w^2 (0.23 at px = 0).
float cell_border_mean(float px) {
  float w = 0.2 + px;
  return (1.243 - 0.4575 * w) * w * cell_border_fade(px);
}

// The bubbles the head presses against the glass: Voronoi cells on the inner wall at the
// head's bubble size, the fine cells of its top giving way to the coarse ones at the
// liquid (1 + FOAM_GROWTH times larger; two networks blended by height, as one network
// whose cells grew would shear), whose borders are Plateau channels of the drink. The
// channels run down through the head into the drink and guide light along them: a
// border shows light that has crossed the drink in its channel from the liquid up to
// this height, so it takes the drink's tint over that length (a golden network in a
// lager's head, a brown one in a stout's), and the cells between them are as much
// brighter, so the head's side keeps its mean at any size; a head on a clear drink in the
// furnace is unchanged. The factor returned multiplies the path's throughput (1 above the
// head and wherever the cells are too small to see). An appearance term of the contact with the glass,
// not part of the medium: the reference does not simulate it (as lacing). p local, on
// the inner wall; `footprint` the pixel's width there (m): cells under a few pixels fade
// out rather than alias.
vec3 head_wall_cells(Vessel v, ObjectFoam f, vec3 p, float footprint) {
  float height = level_over(v.liquid, p), top = foam_thickness_at(v, f, p.xz);
  if (height < 0.0 || height > top || p.y > v.body.height) return vec3(1.0);
  vec2 wall = vec2(atan(p.z, p.x) * length(p.xz), p.y);  // arc length and height (m)
  float fine = f.bubble_size, coarse = f.bubble_size * (1.0 + FOAM_GROWTH), low = 1.0 - height / top;
  float border = mix(cell_border(wall / fine, footprint / fine), cell_border(wall / coarse + 17.0, footprint / coarse), low);
  float mean = mix(cell_border_mean(footprint / fine), cell_border_mean(footprint / coarse), low);
  float soft = clamp((top - height) / (FOAM_SOFT_TOP * top), 0.0, 1.0);  // the head's soft top
  // Divided by its mean over the network: the head's colour (foam.color, the medium's
  // albedo) is already the foam's average with its channels, so the network moves light
  // from the borders into the cells and the head's side is as bright at any size (it
  // darkened by up to a quarter of the drink's absorption where the cells were seen).
  vec3 tint = drink_transmittance(v.body, height);
  return mix(vec3(1.0), tint, border * soft) / mix(vec3(1.0), tint, mean * soft);
}

// Lacing: thin foam left on the inner wall where the head's top used to be (p local).
float lacing_cover(Vessel v, ObjectFoam f, vec3 p) {
  float cover = 0.0;
  for (int i = 0; i < f.lacing_count; ++i) {
    float y = object_lacing(v.row, i);
    float band = (p.y - y) / 0.0012;
    float lace = value_noise(vec3(atan(p.z, p.x) * 9.0, p.y * 900.0, float(i) * 3.7));
    cover = max(cover, exp(-band * band) * smoothstep(0.35, 0.75, lace));
  }
  return cover * f.lacing_strength;
}

// Whether a stretch [0, t_end] of a world path in the air can meet a head (or a big
// bubble's cap): foam_along has work there.
bool meets_head(vec3 o, vec3 d, float t_end) {
  bool meets = false;
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    Vessel v = load_vessel(i);
    float t0 = 0.0, t1 = t_end;  // (foam_interval keeps to the glass's bounds)
    meets = meets || (v.shape.has_head != 0 && !object_excluded(i) && foam_interval(v, fetch_object_foam(i), to_local_point(v, o), to_local_dir(v, d), t0, t1));
  }
  return meets;
}

// The heads of every glass along a stretch [0, t_end] of a world path in the air, front
// to back (heads do not overlap: each is inside its own glass). Adds their light to
// `radiance` and attenuates `thr`.
void foam_along(vec3 o, vec3 d, float t_end, inout vec3 radiance, inout vec3 thr) {
  float done = 0.0;  // heads before this distance are marched
  for (int pass = 0; pass < OBJECT_COUNT; ++pass) {
    // The nearest head that starts after the ones done, and whether another follows.
    int next = -1;
    float next_t0 = INF, next_t1 = INF;
    bool more = false;
    for (int i = 0; i < OBJECT_COUNT; ++i) {
      if (object_excluded(i) || !object_in_reach(i, o, d, done, t_end) || load_vessel(i).shape.has_head == 0) continue;
      Vessel v = load_vessel(i);
      float t0 = done, t1 = t_end;
      if (!foam_interval(v, fetch_object_foam(i), to_local_point(v, o), to_local_dir(v, d), t0, t1)) continue;
      more = more || next >= 0;
      if (t0 < next_t0) {
        next = i;
        next_t0 = t0;
        next_t1 = t1;
      }
    }
    if (next < 0) return;
    Vessel v = load_vessel(next);
    ObjectFoam f = fetch_object_foam(v.row);
    vec3 lo = to_local_point(v, o), ld = to_local_dir(v, d);
    bubble_caps(v, f, lo, ld, next_t0, next_t1, radiance, thr);
    march_foam(v, f, lo, ld, next_t0, next_t1, radiance, thr);
    if (max(thr.r, max(thr.g, thr.b)) < 1e-3 || !more) return;  // (no second pass for one head)
    done = next_t1;
  }
}

#endif  // LIB_FOAM_HEAD_GLSL
