// The backdrop's direct light from the rig without the glasses: one filtered texel of the
// map core computes when the lights, the backdrop or the scene's aim change
// (core/environment/backdrop_light), over the sweep unrolled to (x, s); the exact sum of
// the lights (lights.glsl rig_irradiance) outside the map and where the map distrusts its
// filtering (a = 0: a light through the paper, a light's plane crossing it). And the
// paper's own bounce, from a coarse map over the same coordinates (paper_bounce).
#ifndef LIB_ENVIRONMENT_BACKDROP_LIGHT_GLSL
#define LIB_ENVIRONMENT_BACKDROP_LIGHT_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/environment/backdrop.glsl"
#include "lib/environment/lights.glsl"

// Where point p on the backdrop lies in the unrolled sweep: x across, s the arc length along
// floor -> curve -> wall (0 where the floor starts to curve, negative in front). Twin of
// core backdrop_coords.
vec2 backdrop_coords(BackdropSurface b, vec3 p) {
  if (b.plane || p.z >= b.z_curve) return vec2(p.x, b.z_curve - p.z);             // the floor
  if (p.y >= b.radius) return vec2(p.x, b.radius * (0.5 * PI) + (p.y - b.radius));  // the wall
  return vec2(p.x, b.radius * atan(b.z_curve - p.z, b.radius - p.y));               // the curve
}

// The rig's irradiance at backdrop point p (normal n) with nothing in between.
vec3 backdrop_light(vec3 p, vec3 n) {
  vec4 m = vec4(0.0);
  if (frame.backdrop_light_on != 0) {
    vec2 uv = (backdrop_coords(backdrop_surface(), p) - frame.backdrop_light_origin) / frame.backdrop_light_size;
    vec2 size = vec2(textureSize(u_backdrop_light, 0));
    vec2 texels = uv * size;
    // Between the outermost texel centres, where filtering interpolates.
    if (all(greaterThanEqual(texels, vec2(0.5))) && all(lessThanEqual(texels, size - 0.5))) m = texture(u_backdrop_light, uv);
  }
  // Elsewhere the exact sum, its lights counted only there (rig_irradiance: a pixel the
  // map serves runs none of them).
  bool served = m.a > 0.999;
  return (served ? m.rgb : vec3(0.0)) + rig_irradiance(p, n, served ? 0 : g_light_count);
}

// The light the paper receives at backdrop point p besides the rig's direct light: its own
// bounce, the sky's and the lit paper's round it (core/environment/paper_bounce), bilinear
// between the map's texel centres, the edge's beyond them. Twin of PaperBounceMap::at.
vec3 paper_bounce(vec3 p) {
  vec4 rect = frame.paper_bounce_rect;
  if (rect.z <= 0.0) return vec3(0.0);
  const int N = PAPER_BOUNCE_TEXELS;
  vec2 uv = clamp((backdrop_coords(backdrop_surface(), p) - rect.xy) / rect.zw * float(N) - 0.5, vec2(0.0), vec2(float(N - 1)));
  ivec2 i = min(ivec2(uv), ivec2(N - 2));
  vec2 f = uv - vec2(i);
  int k = i.y * N + i.x;
  vec3 lo = mix(frame.paper_bounce[k].rgb, frame.paper_bounce[k + 1].rgb, f.x);
  vec3 hi = mix(frame.paper_bounce[k + N].rgb, frame.paper_bounce[k + N + 1].rgb, f.x);
  return mix(lo, hi, f.y);
}

#endif  // LIB_ENVIRONMENT_BACKDROP_LIGHT_GLSL
