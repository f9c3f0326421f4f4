// The backdrop in the picture (the sweep or the checker floor, lib/environment/backdrop.glsl):
// where a path meets it, and the light it receives: the rig's direct light from the
// backdrop's light map (backdrop_light.glsl), with every glass's shadow and caustics from
// the traced map near the glasses (floor_light.glsl), and the paper's own bounce with
// the glasses' gathered soft shadow round the feet (the map's second half); the MatCap
// tier, which traces no map, darkens round each foot with an estimate (floor_contact).
// A cross-section (clip.*) takes away the shadows of what it cuts away.
#ifndef LIB_ENVIRONMENT_FLOOR_GLSL
#define LIB_ENVIRONMENT_FLOOR_GLSL
#include "generated/frame.glsl"
#include "lib/scene/objects.glsl"
#include "lib/environment/studio.glsl"
#include "lib/environment/lights.glsl"
#include "lib/environment/backdrop.glsl"
#include "lib/environment/floor_light.glsl"

// Object `row` seen from floor point p (world), with only its bounds: the point's height
// on the glass's axis and its offset across it. A glass is round, so this is all the
// contact darkening needs.
struct FloorView {
  vec3 across;  // p's offset across the axis
  float along;  // p's height on the axis (local y)
};

FloorView floor_view(ObjectBounds b, vec3 p) {
  FloorView v;
  vec3 rel = p - b.bound_base;
  v.along = dot(rel, b.bound_axis);
  v.across = rel - v.along * b.bound_axis;
  return v;
}

// Where a path in the air meets the backdrop. Where a glass stands on the floor, its
// foot is the surface (as core/reference/intersect.cpp first_hit).
Hit hit_floor(vec3 o, vec3 d, float tmin) {
  float t;
  vec3 n;
  if (!intersect(backdrop_surface(), o, d, tmin, t, n)) return no_hit();
  vec3 p = o + t * d;
  if (n.y > 0.999) {
    for (int i = 0; i < OBJECT_COUNT; ++i) {
      ObjectBounds b = bounds_of(i);
      vec3 rel = p - b.bound_base;
      if (object_excluded(i) || dot(rel, rel) > b.bound_radius * b.bound_radius) continue;
      FloorView v = floor_view(b, p);
      if (abs(v.along) < 1e-5 && length(v.across) <= body_of(i).foot_radius) return no_hit();
    }
  }
  return Hit(t, n, M_FLOOR, -1);
}

// The MatCap tier's contact (it traces no floor map; the full tier's is gathered, core
// FloorLightMap::surround_factor): an ambient-occlusion estimate at backdrop point p
// (world) from every glass: darker near
// each foot (which lifts off the floor when the glass tips), where the cross-section
// leaves the foot: its point nearest p decides, blended over 2 mm. Beyond three bound
// radii (at least two foot radii from the foot) it darkens by less than 2e-4 of the
// sky's light, nothing an 8-bit pixel shows. (Direct light, shadows and caustics
// included, comes from the traced map: floor_light.glsl.)
float floor_contact(vec3 p) {
  float contact = 1.0;
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    ObjectBounds b = bounds_of(i);
    vec3 rel = p - b.bound_base;
    if (dot(rel, rel) < 9.0 * b.bound_radius * b.bound_radius) {  // (a block, not a continue: llvmpipe runs it faster)
      ObjectBody body = body_of(i);
      FloorView v = floor_view(b, p);
      float across = length(v.across);
      float foot_dist = length(vec2(max(across - body.foot_radius, 0.0), v.along));
      vec3 foot = b.bound_base + v.across * (min(across, body.foot_radius) / max(across, 1e-9));
      float foot_kept = 1.0 - smoothstep(-0.002, 0.002, dot(body.clip_world_normal, foot) - body.clip_world_offset);
      contact *= 1.0 - 0.55 * foot_kept * exp(-foot_dist / (0.25 * body.foot_radius));
    }
  }
  return contact;
}

// The backdrop's colour c at distance dist along d as the eye takes it: the checker to
// the horizon fades into the sky's ground, so it never aliases there; under an
// environment image the floor reaches its horizon and fades into what the image shows
// along the ray (Studio::floor_visibility), so it is a table, not a desert.
vec3 backdrop_faded(BackdropSurface bd, vec3 c, vec3 d, float dist) {
#ifdef ENV_IMAGE
  return mix(env_image(d, 0.0), c, exp(-dist / 2.0));
#else
  return bd.checker ? mix(g_ground, c, exp(-dist / 2.0)) : c;
#endif
}

// The light hot clouds cast on the backdrop at p (normal n): each glowing cloud a sphere
// of even radiance (frame.cloud_glow_*, core/pointcloud/glow_light), nothing in between.
vec3 clouds_glow_irradiance(vec3 p, vec3 n) {
  vec3 e = vec3(0.0);
  for (int k = 0; k < MAX_CLOUDS; ++k) {  // (in every pass that draws the backdrop: the MatCap tier's too)
    if (k >= frame.cloud_count) break;
    vec4 s = frame.cloud_glow_sphere[k];
    if (s.w > 0.0) e += frame.cloud_glow_radiance[k].rgb * sphere_irradiance_factor(s.xyz, s.w, p, n);
  }
  return e;
}

// The backdrop at p (world, normal n), seen along d from `dist` away: albedo / pi times the
// light it receives, the rig's direct light (one texel of the backdrop's light map; on the
// floor through the traced map's shadows and caustics), the paper's own bounce where it is
// (the sky and the lit paper round it: paper_bounce) darkened round the feet, and hot
// clouds' glow.
vec3 shade_backdrop(vec3 p, vec3 n, vec3 d, float dist) {
  BackdropSurface bd = backdrop_surface();
#ifdef ENV_IMAGE
  // An image's light is all sky: the map's shadows and caustics of its brightest patches
  // (core floor_emitters) and the gathered shadow of the rest change it on the floor.
  vec3 e = paper_bounce(p) + backdrop_light(p, n);
  if (n.y > 0.999) e *= floor_image_factor(p);
#else
  vec3 e = floor_light(p, n, backdrop_light(p, n), paper_bounce(p));
#endif
  e += clouds_glow_irradiance(p, n);
  return backdrop_faded(bd, albedo(bd, p) / PI * e, d, dist);
}

// The backdrop as a glass mirrors it (a few per cent of a pixel): each light taken as a
// point, cheap enough for every reflection; with `shadows`, on the floor through the
// traced map's shadows and caustics and darkened around the feet. (Without them a dark
// drink's glass mirrored the paper round it unshadowed, brighter than it is: the stout
// close up's body against the reference 2.20 -> 2.03, docs/REFERENCE.md. The MatCap tier
// traces no map and darkens what it sees round the feet its own way.)
vec3 shade_backdrop_mirrored(vec3 p, vec3 n, vec3 d, float dist, bool shadows) {
  BackdropSurface bd = backdrop_surface();
  vec3 direct = rig_irradiance_far(p, n, g_light_count), around = paper_bounce(p);
#ifdef ENV_IMAGE
  vec3 e = direct + around;
  if (shadows && n.y > 0.999) e *= floor_image_factor(p);
#else
  vec3 e = shadows ? floor_light(p, n, direct, around) : direct + around;
#endif
  vec3 c = albedo(bd, p) / PI * (e + clouds_glow_irradiance(p, n));
  return backdrop_faded(bd, c, d, dist);
}

#endif  // LIB_ENVIRONMENT_FLOOR_GLSL
