// The sky around the studio: a dim gradient (with, for the checker test environment,
// two strip lights and a glow painted into it) or a constant colour, directions in the
// world; and its irradiance. The studio's real lights are lib/environment/lights.glsl.
#ifndef LIB_ENVIRONMENT_STUDIO_GLSL
#define LIB_ENVIRONMENT_STUDIO_GLSL
#include "generated/frame.glsl"
#include "lib/common/math.glsl"
#include "lib/environment/image.glsl"
#include "lib/environment/screen.glsl"

// The strips and the glow painted in the sky (the checker test environment) are compiled
// in only when they are not black (gpu/renderer.cpp).
#ifndef PAINTED_SKY
#define PAINTED_SKY 0
#endif

// The sky's numbers, read from the Frame block once per pixel (init_studio, first in
// main) and held: on llvmpipe each read of a uniform block's member is a load and a
// broadcast to every lane, and the sky is read by every look at the surroundings.
vec3 g_sky_sh[9];  // the irradiance's spherical-harmonic coefficients (frame.sky_sh)
vec3 g_surround_sh[9];  // and the surround's, the sky and the lit backdrop (frame.surround_sh)
vec3 g_sky_top, g_sky_horizon, g_ground, g_env_color;
int g_env_mode;

void init_studio() {
  for (int i = 0; i < 9; ++i) {
    g_sky_sh[i] = frame.sky_sh[i].rgb;
    g_surround_sh[i] = frame.surround_sh[i].rgb;
  }
  g_sky_top = frame.sky_top;
  g_sky_horizon = frame.sky_horizon;
  g_ground = frame.ground;
  g_env_color = frame.env_color;
  g_env_mode = frame.env_mode;
}

// The sky's radiance in direction d. Twin of Studio::sky
// (core/environment/studio.cpp). Under an environment image (the ENV_IMAGE variant) the
// image, blurred by env.blur.
vec3 studio_backdrop(vec3 d) {
#ifdef ENV_IMAGE
  return env_image(d, 0.0);
#endif
  if (g_env_mode == 1) return g_env_color;
  vec3 sky = d.y >= 0.0 ? mix(g_sky_horizon, g_sky_top, pow(d.y, 0.6))
                        : mix(g_sky_horizon, g_ground, smoothstep(0.0, 0.25, -d.y));
#if PAINTED_SKY
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
#endif
  return sky;
}

// The sky seen through a surface of GGX roughness `roughness`: an environment image at
// the level of detail of the reflected lobe (twin of Studio::sky(d, roughness)); the
// procedural studio is smooth enough to be read as it is.
vec3 sky_seen(vec3 d, float roughness) {
#if defined(SCREEN) && SCREEN == 2
  return screen_background(d, roughness);  // the screen is the background (the AR view)
#endif
#ifdef ENV_IMAGE
  return env_image(d, roughness);
#else
  return studio_backdrop(d);
#endif
}

// The irradiance nine spherical-harmonic coefficients c (Ramamoorthi and Hanrahan's
// convolution applied) give a surface of unit normal n. Twin of SkyIrradiance::at
// (core/environment/sky_irradiance.cpp).
vec3 sh_irradiance(vec3 c[9], vec3 n) {
  vec3 e = c[0] * 0.282095;
  e += 0.488603 * (c[1] * n.y + c[2] * n.z + c[3] * n.x);
  e += 1.092548 * (c[4] * n.x * n.y + c[5] * n.y * n.z + c[7] * n.x * n.z);
  e += c[6] * (0.315392 * (3.0 * n.z * n.z - 1.0)) + c[8] * (0.546274 * (n.x * n.x - n.y * n.y));
  return max(e, vec3(0.0));
}

// The sky's mean radiance over the sphere (its band-0 harmonic; the rig's lights left
// out): what light turned back inside a glass at an internal reflection's way out sees,
// wherever it leaves in the end (media.glsl reflected_light).
vec3 sky_mean() { return g_sky_sh[0] * (0.282095 / PI); }

// The sky's irradiance on a surface of unit normal n: the nine coefficients core
// projected Studio::sky onto.
vec3 sky_irradiance(vec3 n) { return sh_irradiance(g_sky_sh, n); }

// The irradiance of what lies around the scene's centre besides the lights (the sky and
// the lit backdrop: EnvironmentFrame::surround) on a surface of unit normal n: the light
// of the heads, the haze, condensation's mist and the backdrop itself (its bounce off
// its own paper).
vec3 surround_irradiance(vec3 n) { return sh_irradiance(g_surround_sh, n); }
// Its mean radiance over the sphere (as sky_mean).
vec3 surround_mean() { return g_surround_sh[0] * (0.282095 / PI); }

// The even light behind a transparent picture's objects (core/output/cutout): what lights
// the colour a path's throughput keeps beyond what alpha lets through.
vec3 cutout_light() { return frame.cutout_light; }

#endif  // LIB_ENVIRONMENT_STUDIO_GLSL
