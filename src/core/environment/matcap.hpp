// The MatCap tier's lit sphere (docs/MATCAP.md): what a mirror sphere at the scene's centre
// shows, seen straight on from the default camera's direction, as an RGB image of linear
// radiance. Texel (x, y) of an N x N MatCap is the sphere's point with view-space normal
// matcap_normal((x + 0.5) / N, (y + 0.5) / N); the pass (shaders/passes/matcap.frag.glsl)
// looks it up by a surface's view-space normal (matcap_uv, twin in lib/shading/matcap.glsl).
// Baked from the current environment (sky, lights, backdrop; core/environment/studio,
// lights, backdrop) when it changes, or read from a PNG (matcap.file).
#pragma once

#include "core/environment/backdrop.hpp"
#include "core/environment/lights.hpp"
#include "core/io/image.hpp"
#include "core/params/params.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace draught {

inline constexpr int kMatCapSize = 256;

struct MatCap {
  int size = 0;
  std::vector<glm::vec3> rgb;  // size x size, rows top-down (row 0: the sphere's top), linear radiance
  const glm::vec3& at(int x, int y) const { return rgb[size_t(y) * size_t(size) + size_t(x)]; }
};

// The view the bake looks from: the default camera's (CameraParams{}) right, up, and the
// direction back towards the eye (world, unit). The pass maps normals into the picture's
// camera instead: a MatCap's light turns with the view, as a MatCap's does.
struct MatCapView {
  glm::dvec3 right, up, back;
};
MatCapView matcap_view();

// The view-space normal at MatCap coordinates (u, v) in [0, 1]^2, v down from the top;
// outside the disk the normal at its rim (so look-ups pushed past the edge stay sensible).
glm::dvec3 matcap_normal(double u, double v);
// Its inverse on the disk: the coordinates of view-space normal n. Twin of matcap_uv in
// shaders/lib/shading/matcap.glsl (which has v up, as GL's t).
glm::dvec2 matcap_uv(const glm::dvec3& n);

// The MatCap of these surroundings: for each texel, the radiance along the normal's
// mirror direction of the view from the scene's centre (surroundings_centre: rig.aim
// where there are glasses): the nearest of a light's front and the backdrop (lit by the
// rig and the sky), else the sky.
MatCap bake_matcap(const SceneParams&, const LightRig&, const BackdropSurface&, const glm::dvec3& centre,
                   int size = kMatCapSize);
// A MatCap from an image (8-bit sRGB, any size; resampled to a square of kMatCapSize).
MatCap matcap_from_image(const Image&);

// The image matcap.file names (a PNG's path), read through the strict PNG decoder;
// throws InputError naming the file and what was expected. check_matcap_image is the
// parameter table's check ("" is fine: the bake).
std::shared_ptr<const MatCap> load_matcap_file(const std::string& name);
void check_matcap_image(const std::string& name);

// The frame's MatCap: the file's, else the bake of these surroundings from `centre`; kept
// while what it depends on (env.*, the lights, the backdrop's place, the centre,
// matcap.file) stays the same.
std::shared_ptr<const MatCap> matcap_for(const SceneParams&, const LightRig&, const BackdropSurface&,
                                         const glm::dvec3& centre);

}  // namespace draught
