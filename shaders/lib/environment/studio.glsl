// The surroundings: a procedural photo studio (gradient sky, key softbox, two vertical
// strip lights, a glow behind the scene) or a constant colour. Directions in the world.
#ifndef LIB_ENVIRONMENT_STUDIO_GLSL
#define LIB_ENVIRONMENT_STUDIO_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"

// Everything the studio shows but the key softbox. Twin of Studio::sky
// (core/environment/studio.cpp).
vec3 studio_backdrop(vec3 d) {
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
  return sky;
}

// The key softbox: the only place the key light exists (no highlight is added on top,
// so it is counted once). A disc of angular radius light.size whose radiance is
// intensity / (pi sin^2 radius): intensity is the irradiance it gives a surface facing
// it, as the reference's KeyLight (core/environment/studio.hpp). Its edge is spread
// symmetrically in cosine, which keeps its solid angle and so its light: a hair against
// aliasing, more where a rough surface (GGX roughness) blurs its reflection.
vec3 key_softbox(vec3 d, float roughness) {
  float c = frame.light_cos_radius, sin2 = 1.0 - c * c;
  if (frame.light_intensity <= 0.0 || sin2 <= 0.0) return vec3(0.0);
  float a = roughness * roughness;  // GGX alpha: the reflected lobe is about 2 alpha wide
  float w = min(max(0.004, 2.0 * a * sqrt(sin2)), 1.0 - c);
  return frame.light_color * (frame.light_intensity / (PI * sin2)) * smoothstep(c - w, c + w, dot(d, frame.light_dir));
}

// What the studio shows in direction d, seen in a surface of the given roughness
// (0: directly).
vec3 studio_seen(vec3 d, float roughness) { return studio_backdrop(d) + key_softbox(d, roughness); }
vec3 studio_sky(vec3 d) { return studio_seen(d, 0.0); }

// Mean light arriving from the upper hemisphere (for the floor and the haze).
vec3 ambient_light() {
  if (frame.env_mode == 1) return frame.env_color;
  return 0.5 * (frame.sky_top + frame.sky_horizon);
}

#endif  // LIB_ENVIRONMENT_STUDIO_GLSL
