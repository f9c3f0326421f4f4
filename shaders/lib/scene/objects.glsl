// The scene's objects on the GPU: one record per object in u_objects (layout generated
// from src/interface/objects.def, filled by gpu/scene_data.cpp), and "the loaded
// object": the one whose records the intersection and shading code reads through the
// globals below, in its own local frame (glass axis = +y, foot at the origin). Paths
// run in the world; each object test moves the ray into the object's frame.
#ifndef LIB_SCENE_OBJECTS_GLSL
#define LIB_SCENE_OBJECTS_GLSL
#include "generated/frame.glsl"
#include "generated/objects.glsl"
#include "lib/common/math.glsl"

// A surface along a ray. n: glass surfaces point out of the glass, the liquid surface
// and the floor up; in the loaded object's frame inside lib/vessel, in the world after
// scene_hit. obj: the object (row), -1 for the floor and for no hit.
struct Hit {
  float t;
  vec3 n;
  int m;
  int obj;
};

Hit no_hit() { return Hit(INF, vec3(0.0), M_NONE, -1); }

void keep_nearest(inout Hit best, Hit h) {
  if (h.t < best.t) best = h;
}

// Work done by this pixel, for the cost debug view.
int g_cost = 0;            // segment and torus intersections solved
int g_bounds_entered = 0;  // object bounds the path entered

// The loaded object. use_object() fetches only when the row changes: a pixel that sees
// one glass fetches its records once.
int g_row = -1;
ObjectBounds g_bounds;
ObjectShape g_shape;
ObjectLiquid g_liquid;
ObjectGlass g_glass;

void use_object(int row) {
  if (row == g_row) return;
  g_row = row;
  g_bounds = fetch_object_bounds(row);
  g_shape = fetch_object_shape(row);
  g_liquid = fetch_object_liquid(row);
  g_glass = fetch_object_glass(row);
}

// Between the loaded object's frame and the world. The rotation's inverse is its transpose.
mat3 object_rotation() { return mat3(g_shape.rot_x, g_shape.rot_y, g_shape.rot_z); }
vec3 to_world_dir(vec3 v) { return object_rotation() * v; }
vec3 to_local_dir(vec3 v) { return v * object_rotation(); }
vec3 to_world_point(vec3 p) { return object_rotation() * p + g_shape.position; }
vec3 to_local_point(vec3 p) { return (p - g_shape.position) * object_rotation(); }

// The loaded object's cross-section: what lies beyond the clip plane is cut away.
bool clipped(vec3 p) { return dot(g_shape.clip_normal, p) > g_shape.clip_offset; }

// The part [t0, t1] of o + t d (world) inside the cylinder of radius R around the axis
// segment from b along unit a for length L. False when the ray misses it.
bool cylinder_span(vec3 o, vec3 d, vec3 b, vec3 a, float R, float L, out vec2 tr) {
  vec3 ob = o - b;
  float oa = dot(ob, a), da = dot(d, a);
  tr = vec2(-INF, INF);
  if (abs(da) < 1e-9) {
    if (oa < 0.0 || oa > L) return false;
  } else {
    float s0 = -oa / da, s1 = (L - oa) / da;
    tr = vec2(min(s0, s1), max(s0, s1));
  }
  vec3 op = ob - oa * a, dp = d - da * a;  // across the axis
  float A = dot(dp, dp), B = dot(op, dp), C = dot(op, op) - R * R;
  if (A < 1e-12) {
    if (C > 0.0) return false;
  } else {
    float disc = B * B - A * C;
    if (disc < 0.0) return false;
    float s = sqrt(disc);
    tr.x = max(tr.x, (-B - s) / A);
    tr.y = min(tr.y, (-B + s) / A);
  }
  return tr.x <= tr.y;
}

// Whether the world ray can meet object `row` between tmin and tmax: its bounding
// cylinder (slightly enlarged against float round-off; it only culls).
bool object_in_reach(int row, vec3 o, vec3 d, float tmin, float tmax) {
  ObjectBounds b = fetch_object_bounds(row);
  vec2 tr;
  float pad = 1e-3 * b.bound_radius + 1e-5;
  return cylinder_span(o, d, b.bound_base - pad * b.bound_axis, b.bound_axis, b.bound_radius + pad,
                       b.bound_length + 2.0 * pad, tr) &&
         tr.y >= tmin && tr.x <= tmax;
}

#endif  // LIB_SCENE_OBJECTS_GLSL
