// The nearest surface along a world ray over every object of the scene and the floor.
// A path's medium is (medium, object): inside a glass or a drink only that object's
// surfaces bound it; in the air every object whose bounds the ray enters is tested
// (bounds first, so a pixel pays only for the objects its path meets). Twin of
// core/reference/intersect.cpp first_hit (air) and hit_vessel (inside an object).
#ifndef LIB_SCENE_TRACE_GLSL
#define LIB_SCENE_TRACE_GLSL
#include "lib/scene/objects.glsl"
#include "lib/vessel/vessel.glsl"
#include "lib/environment/floor.glsl"

// The loaded object's nearest surface for a world ray, as a world hit.
Hit object_hit(vec3 o, vec3 d, int medium, float tmin) {
  Hit h = vessel_hit(to_local_point(o), to_local_dir(d), medium, tmin);
  h.n = to_world_dir(h.n);
  return h;
}

// On return the hit object is the loaded one (use_object), so shading can read it.
Hit scene_hit(vec3 o, vec3 d, int medium, int obj, float tmin) {
  if (medium != MEDIUM_AIR) {
    use_object(obj);
    return object_hit(o, d, medium, tmin);
  }
  Hit best = no_hit();
  for (int i = 0; i < frame.object_count; ++i) {
    if (!object_in_reach(i, o, d, tmin, best.t)) continue;
    ++g_bounds_entered;
    use_object(i);
    keep_nearest(best, object_hit(o, d, MEDIUM_AIR, tmin));
  }
  keep_nearest(best, hit_floor(o, d, tmin));
  if (best.obj >= 0) use_object(best.obj);
  return best;
}

#endif  // LIB_SCENE_TRACE_GLSL
