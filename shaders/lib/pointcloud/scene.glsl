// The scene's point clouds as the path pass sees them (frames compiled with CLOUDS): each
// cloud's reference into the shared textures from the Frame block, and the glow of hot
// glass from the blackbody table. docs/POINT_CLOUDS.md.
#ifndef LIB_POINTCLOUD_SCENE_GLSL
#define LIB_POINTCLOUD_SCENE_GLSL
#include "generated/constants.glsl"
#include "generated/frame.glsl"
#include "lib/pointcloud/march.glsl"

// Cloud c's reference (c < frame.cloud_count).
CloudRef cloud_ref_of(int c) {
  vec4 r = frame.cloud_ref[c];
  return CloudRef(int(r.x), r.y, r.z, frame.cloud_lo[c].xyz, frame.cloud_hi[c].xyz);
}

// The surface the last cloud hit of a search was at: its k-weighted temperature (K;
// 0 where the points give none) and colour (0 where they give none).
vec4 g_cloud_attrs = vec4(0.0);

// A blackbody's radiance at `kelvin` in the table's units (cd/m^2 of luminance): twin of
// core/pointcloud/blackbody.cpp blackbody_table_lookup, spaced evenly in 1/T; ln Y is
// interpolated (nearly linear in 1/T by Wien's law) and extrapolated below the table.
vec3 blackbody_luminance(float kelvin) {
  if (kelvin <= 0.0) return vec3(0.0);
  const float n = float(BLACKBODY_ENTRIES);
  float u = (1.0 / BLACKBODY_MIN_K - 1.0 / kelvin) / (1.0 / BLACKBODY_MIN_K - 1.0 / BLACKBODY_MAX_K) * (n - 1.0);
  int i = int(clamp(floor(u), 0.0, n - 2.0));
  float f = u - float(i);
  vec4 a = frame.blackbody[i], b = frame.blackbody[i + 1];
  vec3 colour = mix(a.rgb, b.rgb, clamp(f, 0.0, 1.0));
  float lnY = mix(a.w, b.w, min(f, 1.0));
  return colour * exp(min(lnY, 80.0));
}
#endif  // LIB_POINTCLOUD_SCENE_GLSL
