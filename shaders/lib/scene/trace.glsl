// The nearest surface along a world ray over every object of the scene and the floor.
// A path's medium is (medium, object): inside a glass or a drink only that object's
// surfaces bound it; in the air every object whose bounds the ray enters is a candidate,
// tested in the order the ray enters their bounds until none can be nearer than the
// nearest hit, so a pixel pays only for the objects its path meets. Twin of
// core/reference/intersect.cpp first_hit (air) and hit_vessel (inside an object).
//
// The search advances one object test per call (search_step), and the caller's path
// loop calls it once per iteration: the heavy intersection code then sits in one loop
// rather than in a loop nested in the path's loop, which llvmpipe runs about twice as
// slowly (measured: docs/PERFORMANCE.md).
#ifndef LIB_SCENE_TRACE_GLSL
#define LIB_SCENE_TRACE_GLSL
#include "lib/scene/objects.glsl"
#include "lib/vessel/vessel.glsl"
#include "lib/environment/floor.glsl"
#ifndef DROPLETS
#define DROPLETS 0
#endif
#if DROPLETS
#include "lib/droplets/field.glsl"
#endif
#ifndef CLOUDS
#define CLOUDS 0
#endif
#if CLOUDS
#include "lib/pointcloud/scene.glsl"
#endif

// The vessel's nearest surface for a world ray, as a world hit.
Hit object_hit(Vessel v, vec3 o, vec3 d, int medium, float tmin) {
  Hit h = vessel_hit(v, to_local_point(v, o), to_local_dir(v, d), medium, tmin);
  h.n = to_world_dir(v, h.n);
  return h;
}

// The search for one segment's nearest surface.
struct Search {
  Hit best;         // nearest surface so far
  float after_t0;   // objects tested: those entering their bounds before (after_t0, after_row)
  int after_row;
  float tmin;
};

Search start_search(float tmin) { return Search(no_hit(), -INF, -1, tmin); }

// The object to test next: the smallest bound entry after the ones tested, while it can
// still be nearer than the best hit (ties: the lower row first); -1 when none is left.
// then: the bound entry of the candidate after it (INF for none), so that the search
// knows without another pass whether it is done once this one is tested.
int next_candidate(Search s, vec3 o, vec3 d, int medium, int obj, out float entry, out float then) {
  entry = 0.0;
  then = INF;
  if (medium != MEDIUM_AIR) return s.after_row < 0 ? obj : -1;
  int row = -1;
  float first = INF;
  for (int i = 0; i < OBJECT_COUNT; ++i) {
    vec2 tr;
    if (object_excluded(i) || !object_span(i, o, d, tr) || tr.y < s.tmin) continue;
    float e = max(tr.x, s.tmin);
    bool untested = e > s.after_t0 || (e == s.after_t0 && i > s.after_row);
    if (!untested || e > s.best.t) continue;
    if (e < first) {  // (rows rise: an equal entry keeps the lower row first)
      then = first;
      first = e;
      row = i;
    } else {
      then = min(then, e);
    }
  }
  entry = first;
  return row;
}

// Tests the next candidate object (its records in v). True when the search is done:
// s.best is the nearest surface (with `floor`, the backdrop too), and v holds its
// object's records when it is an object.
bool search_step(inout Search s, vec3 o, vec3 d, int medium, int obj, bool floor, out Vessel v) {
#if DROPLETS
  // The scene's droplets (lib/droplets), in the air: marched once, on the search's first
  // step, so that its hit bounds which vessels can still be nearer. Inside a droplet
  // only its surface bounds the path.
  if (s.after_t0 == -INF && (medium == MEDIUM_AIR || medium == MEDIUM_DROPLET)) {
    float t;
    vec3 n;
    if (march_droplets(o, d, s.tmin, s.best.t, medium == MEDIUM_DROPLET, t, n)) s.best = Hit(t, n, M_DROPLET, -1);
  }
#endif
#if CLOUDS
  // The scene's point clouds (lib/pointcloud), likewise: in the air every cloud is
  // marched on the search's first step; inside a blob (object -2 - cloud) only its own
  // surface bounds the path.
  if (s.after_t0 == -INF && (medium == MEDIUM_AIR || medium == MEDIUM_CLOUD)) {
    int own = medium == MEDIUM_CLOUD ? -2 - obj : -1;
    for (int c = 0; c < MAX_CLOUDS; ++c) {
      if (c >= frame.cloud_count) break;
      if (own >= 0 && c != own) continue;
      float t;
      vec3 n;
      vec4 a;
      if (march_cloud(cloud_ref_of(c), o, d, s.tmin, s.best.t, c == own, t, n, a)) {
        s.best = Hit(t, n, M_CLOUD, -2 - c);
        g_cloud_attrs = a;
      }
    }
  }
#endif
  float entry, then;
  int cand = next_candidate(s, o, d, medium, obj, entry, then);
  v = load_vessel(max(cand, 0));
  if (cand >= 0) {
    ++g_bounds_entered;
    keep_nearest(s.best, object_hit(v, o, d, medium, s.tmin));
    s.after_t0 = entry;
    s.after_row = cand;
    if (then <= s.best.t) return false;  // another object may still be nearer
  }
  if (floor && medium == MEDIUM_AIR) keep_nearest(s.best, hit_floor(o, d, s.tmin));
  if (s.best.obj >= 0 && s.best.obj != cand) v = load_vessel(s.best.obj);
  return true;
}

#endif  // LIB_SCENE_TRACE_GLSL
