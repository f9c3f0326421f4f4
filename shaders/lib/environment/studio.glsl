// The surroundings: a procedural photo studio (gradient sky, key softbox, two vertical
// strip lights, a glow behind the scene) or a constant colour. Directions in the world.
#ifndef LIB_ENVIRONMENT_STUDIO_GLSL
#define LIB_ENVIRONMENT_STUDIO_GLSL
#include "generated/frame.glsl"

vec3 studio_sky(vec3 d) {
  if (frame.env_mode == 1) return frame.env_color;
  vec3 sky = d.y >= 0.0 ? mix(frame.sky_horizon, frame.sky_top, pow(d.y, 0.6))
                        : mix(frame.sky_horizon, frame.ground, smoothstep(0.0, 0.25, -d.y));
  // Strip lights, left and right and a little behind the scene, tall and narrow.
  for (int i = 0; i < 2; ++i) {
    float az = radians(i == 0 ? 105.0 : -105.0);
    vec2 sd = vec2(sin(az), cos(az));
    float horiz = length(d.xz);
    float c = horiz > 1e-4 ? dot(d.xz / horiz, sd) : 0.0;
    float across = smoothstep(0.985, 0.996, c);
    float along = smoothstep(-0.15, 0.0, d.y) * (1.0 - smoothstep(0.55, 0.75, d.y));
    sky += vec3(frame.strip_intensity) * across * along;
  }
  // The glow on the backdrop behind the scene.
  vec3 g = normalize(vec3(0.0, 0.12, -1.0));
  float cg = max(dot(d, g), 0.0);
  sky += frame.backdrop_glow * vec3(1.0, 0.97, 0.92) * pow(cg, 200.0);
  // The key softbox.
  float ck = dot(d, frame.light_dir);
  sky += frame.light_color * frame.light_intensity * 2.0 *
         smoothstep(frame.light_cos_radius - 0.004, frame.light_cos_radius + 0.004, ck);
  return sky;
}

// Mean light arriving from the upper hemisphere (for the floor and the haze).
vec3 ambient_light() {
  if (frame.env_mode == 1) return frame.env_color;
  return 0.5 * (frame.sky_top + frame.sky_horizon);
}

#endif  // LIB_ENVIRONMENT_STUDIO_GLSL
