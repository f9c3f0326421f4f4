// The scene's objects on the GPU: one record per object in u_objects (layout generated
// from src/interface/objects.def, filled by gpu/scene_data.cpp). A vessel's records are
// loaded into a Vessel value where they are needed and passed down explicitly: no
// global "current object" (loops that carry such state cost llvmpipe twice the frame
// time; re-fetching a few texels per test is cheap). Paths run in the world; each
// object test moves the ray into the object's frame (glass axis = +y, foot at origin).
#ifndef LIB_SCENE_OBJECTS_GLSL
#define LIB_SCENE_OBJECTS_GLSL
#include "generated/frame.glsl"
#include "generated/objects.glsl"
#include "lib/common/math.glsl"

// The number of objects. The renderer compiles scenes of a few objects (up to
// Renderer::kMaxHeldObjects) with HELD_OBJECTS = their number: every object loop then
// has a trip count known at compile time (it unrolls), and every object's records are
// fetched once when the pixel starts and held (init_objects): the loops see constants,
// not state they carry, and no fetch at a row that varies per pixel. Larger scenes
// (HELD_OBJECTS 0) fetch records where they are used. Same source, same results
// (tests/gpu checks); on llvmpipe the held path is much faster (docs/PERFORMANCE.md).
#ifndef HELD_OBJECTS
#define HELD_OBJECTS 0
#endif
#if HELD_OBJECTS > 0
#define OBJECT_COUNT HELD_OBJECTS
#else
#define OBJECT_COUNT frame.object_count
#endif

// The PANORAMA variant renders one glass's surroundings from inside it (env.reflections):
// every object loop leaves that glass out (its surfaces, its head, its foot on the floor).
#ifndef PANORAMA
#define PANORAMA 0
#endif
bool object_excluded(int i) {
#if PANORAMA
  return i == frame.exclude_object;
#else
  return false;
#endif
}

// A surface along a ray. n: glass surfaces point out of the glass, the liquid surface
// and the floor up; in the vessel's frame inside lib/vessel, in the world after
// object_hit. obj: the object (row), -1 for the floor and for no hit.
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

// A vessel's records as the intersection and shading code reads them.
struct Vessel {
  int row;
  ObjectBounds bounds;
  ObjectBody body;
  ObjectShape shape;
  ObjectLiquid liquid;
};

Vessel fetch_vessel(int row) {
  return Vessel(row, fetch_object_bounds(row), fetch_object_body(row), fetch_object_shape(row), fetch_object_liquid(row));
}

#if HELD_OBJECTS > 0
// Every object's records, fetched when the pixel starts and never changed after.
Vessel g_held[HELD_OBJECTS];
ObjectGlass g_held_glass[HELD_OBJECTS];
#endif

// Call first in main().
void init_objects() {
#if HELD_OBJECTS > 0
  for (int i = 0; i < HELD_OBJECTS; ++i) {
    g_held[i] = fetch_vessel(i);
    g_held_glass[i] = fetch_object_glass(i);
  }
#endif
}

// Object `row`'s records (held: selected by comparisons, which unroll, rather than by an
// index that varies per pixel).
Vessel load_vessel(int row) {
#if HELD_OBJECTS > 0
  Vessel v = g_held[0];
  for (int i = 1; i < HELD_OBJECTS; ++i)
    if (row == i) v = g_held[i];
  return v;
#else
  return fetch_vessel(row);
#endif
}
ObjectBounds bounds_of(int row) {
#if HELD_OBJECTS > 0
  return load_vessel(row).bounds;
#else
  return fetch_object_bounds(row);
#endif
}
ObjectBody body_of(int row) {
#if HELD_OBJECTS > 0
  return load_vessel(row).body;
#else
  return fetch_object_body(row);
#endif
}
ObjectGlass glass_of(int row) {
#if HELD_OBJECTS > 0
  ObjectGlass g = g_held_glass[0];
  for (int i = 1; i < HELD_OBJECTS; ++i)
    if (row == i) g = g_held_glass[i];
  return g;
#else
  return fetch_object_glass(row);
#endif
}

// Between the vessel's frame and the world. The rotation's inverse is its transpose.
mat3 rotation(Vessel v) { return mat3(v.shape.rot_x, v.shape.rot_y, v.shape.rot_z); }
vec3 to_world_dir(Vessel v, vec3 d) { return rotation(v) * d; }
vec3 to_local_dir(Vessel v, vec3 d) { return d * rotation(v); }
vec3 to_local_point(Vessel v, vec3 p) { return (p - v.shape.position) * rotation(v); }
vec3 to_world_point(Vessel v, vec3 p) { return v.shape.position + rotation(v) * p; }

// The vessel's cross-section: what lies beyond the clip plane is cut away.
bool clipped(Vessel v, vec3 p) { return dot(v.shape.clip_normal, p) > v.shape.clip_offset; }

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

// Where the world ray o + t d is inside object `row`'s bounding cylinder (slightly
// enlarged against float round-off; it only culls): [t0, t1], false when it misses.
bool object_span(int row, vec3 o, vec3 d, out vec2 tr) {
  ObjectBounds b = bounds_of(row);
  float pad = 1e-3 * b.bound_radius + 1e-5;
  return cylinder_span(o, d, b.bound_base - pad * b.bound_axis, b.bound_axis, b.bound_radius + pad,
                       b.bound_length + 2.0 * pad, tr);
}

// Whether the world ray can meet object `row` between tmin and tmax.
bool object_in_reach(int row, vec3 o, vec3 d, float tmin, float tmax) {
  vec2 tr;
  return object_span(row, o, d, tr) && tr.y >= tmin && tr.x <= tmax;
}

#endif  // LIB_SCENE_OBJECTS_GLSL
