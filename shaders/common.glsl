// Frame uniforms (std140). Mirrors gpu/uniforms.hpp: FrameUniforms; static_asserts
// there pin every offset, so change both together.
precision highp float;
precision highp int;

#define SEGMENTS 96

layout(std140) uniform Frame {
  vec4 u_cam_eye;       // xyz, tan(vfov / 2)
  vec4 u_cam_right;     // xyz, aspect
  vec4 u_cam_up;
  vec4 u_cam_forward;
  vec4 u_viewport;      // width, height, 1/width, 1/height
  vec4 u_vessel;        // height, base, dy, 1/dy
  vec4 u_rim;           // major, minor, bound radius, bottom outer radius
  vec4 u_glass;         // ior, roughness, cavity floor radius, mean outer radius
  vec4 u_glass_absorb;  // rgb per metre
  vec4 u_liquid_plane;  // surface normal xyz (glass frame), volume fraction of the cavity
  vec4 u_liquid;        // ior, roughness, haze per metre, has liquid
  vec4 u_liquid_absorb; // rgb per metre
  vec4 u_haze_color;
  vec4 u_light_dir;     // xyz towards the light, intensity
  vec4 u_light_color;   // rgb, cos(angular radius)
  vec4 u_env;           // mode, strip intensity, backdrop glow, floor on
  vec4 u_env_color;
  vec4 u_sky_top;
  vec4 u_sky_horizon;
  vec4 u_ground;
  vec4 u_floor_a;       // rgb, checker size
  vec4 u_floor_b;
  vec4 u_output;        // tonemap, exposure, transparent, debug view
  ivec4 u_limits;       // max events
  vec4 u_pose_x;        // the glass's local axes in the world (rotation columns)
  vec4 u_pose_y;
  vec4 u_pose_z;
  vec4 u_pose_pos;      // where the glass's foot centre is in the world
  vec4 u_waves;         // ring, cross cos 2a, cross sin 2a, radius (core/slosh.hpp)
  vec4 u_foam;          // thickness, dome, density per metre, 1 when there is a head
  vec4 u_foam_color;    // albedo rgb, Henyey-Greenstein g
  vec4 u_foam_detail;   // multiscatter weight, micro-bubble size, detail, big bubble count
  vec4 u_lacing_info;   // ring count, strength
  vec4 u_lacing[2];     // ring heights (glass frame y), 8 at most
  vec4 u_bubbles[12];   // big bubbles: centre xyz (glass frame), radius (< 0: popped, a void)
  vec4 u_clip;          // cross-section: normal xyz (glass frame), offset; the side dot(n, p) > offset is cut away (n = 0, offset 1: off)
  vec4 u_knots[SEGMENTS + 1];  // outer radius, inner radius at y = k * dy
};

const float PI = 3.14159265358979;
const float INF = 1e30;

// Media a ray can be in.
const int AIR = 0;
const int GLASS = 1;
const int LIQUID = 2;

// Material ids: same numbers as core/intersect.hpp Material.
const int M_NONE = 0;
const int M_FLOOR = 1;
const int M_GLASS_OUTER = 2;
const int M_GLASS_INNER = 3;
const int M_RIM = 4;
const int M_GLASS_BOTTOM = 5;
const int M_CAVITY_FLOOR = 6;
const int M_LIQUID_SURFACE = 7;
const int M_CLIP_GLASS = 8;   // the cross-section's cut face through the glass
const int M_CLIP_LIQUID = 9;  // and through the liquid

// All intersections happen in the glass's frame; the surroundings are in the world.
mat3 pose_rotation() { return mat3(u_pose_x.xyz, u_pose_y.xyz, u_pose_z.xyz); }
vec3 to_world_dir(vec3 v) { return pose_rotation() * v; }
vec3 to_local_dir(vec3 v) { return v * pose_rotation(); }
vec3 to_world_point(vec3 p) { return pose_rotation() * p + u_pose_pos.xyz; }
vec3 to_local_point(vec3 p) { return (p - u_pose_pos.xyz) * pose_rotation(); }

// The cross-section: what lies beyond the clip plane is cut away.
bool clipped(vec3 p) { return dot(u_clip.xyz, p) > u_clip.w; }

// Intersection work done by this pixel (segments and tori solved), for the cost view.
int g_cost = 0;

struct Hit {
  float t;
  vec3 n;  // glass: out of the glass; liquid surface and floor: up
  int m;
};

Hit no_hit() { return Hit(INF, vec3(0.0), M_NONE); }

// Pixel centres from the top-left, as core/camera.cpp.
vec3 camera_dir(vec2 frag) {
  vec2 px = vec2(frag.x, u_viewport.y - frag.y);
  float x = (2.0 * px.x * u_viewport.z - 1.0) * u_cam_right.w * u_cam_eye.w;
  float y = (1.0 - 2.0 * px.y * u_viewport.w) * u_cam_eye.w;
  return normalize(u_cam_forward.xyz + x * u_cam_right.xyz + y * u_cam_up.xyz);
}
