// Decals on a vessel's walls: an image with alpha on the outer wall (layer 0) and one on
// the inner wall (layer 1), placed by the centre's angle around the axis and height, and
// mapped by distances on the surface: across, by the arc around the wall at each height
// (the radius there times the angle), and down, by the arc length along the wall's
// profile. A decal is therefore not stretched on a curved bowl: a tulip's belly or a wine
// glass keeps it at its printed size in both directions (a surface of revolution that is
// not a cylinder or a cone cannot keep its shape exactly; it shears where the radius
// changes along the decal's height). docs/DECALS.md says what each kind looks like.
//
// What the GPU's record holds is DecalPlacement (gpu/decal_textures.cpp packs it), and
// the arc lengths at the profile's knots go to a data texture: decal_uv here and in
// shaders/lib/vessel/decal.glsl are twins, compared by tests/gpu/test_decals.cpp.
#pragma once

#include "core/io/image.hpp"
#include "core/params/params.hpp"
#include "core/vessel/vessel.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace draught {

inline constexpr int kMaxDecalLayers = contract::kMaxDecalLayers;  // 0 the outer wall's, 1 the inner wall's

// The arc length along each wall's profile from the foot (y = 0) at every knot
// (Vessel::kSegments + 1 of them): a frustum segment is straight, so inside one the arc
// length is linear in y and the table is exact for the segmented walls.
struct WallArcLengths {
  std::vector<double> outer, inner;
  double at(const Vessel&, bool inner, double y) const;
};
WallArcLengths wall_arc_lengths(const Vessel&);

// One decal layer placed on its wall, in the units the mapping uses.
struct DecalPlacement {
  bool present = false;
  bool inner = false;     // on the inner wall
  double angle = 0;       // rad about the axis from +z towards +x: the centre (of copy 0)
  double centre_s = 0;    // m: the centre's arc length along the wall's profile
  double width = 0;       // m around the wall at every height; 0: a band (each copy spans 2 pi / repeat)
  double extent = 0;      // m along the profile: the image's height (width x its aspect, at the centre)
  int repeat = 1;         // copies spaced 2 pi / repeat apart
  DecalKind kind = DecalKind::Enamel;
  glm::dvec3 color{1.0};  // multiplies the image's colour
  double opacity = 1.0;   // multiplies its alpha
  double roughness = 0.3;  // a metallic decal's (GGX, as the glass's)
  double span = 0;        // m: the longer of its width at the centre and its extent (a texture's mipmap level)
};

// `p` placed on the wall (inner or outer) of `v`, for an image of image_w x image_h pixels.
// Not present when p names no file.
DecalPlacement place_decal(const Vessel& v, const WallArcLengths&, const DecalParams& p, bool inner, int image_w,
                           int image_h);

// Where the wall point `local` (the glass's frame, on the placement's wall) lies on the
// decal: (u, v) over its image, (0, 0) its top-left corner as seen from outside the glass,
// u to the right (counter-clockwise seen from above), v down the profile; nullopt outside
// it. GLSL twin: decal_uv in shaders/lib/vessel/decal.glsl.
std::optional<glm::dvec2> decal_uv(const Vessel&, const WallArcLengths&, const DecalPlacement&, const glm::dvec3& local);

// A decal's image at (u, v), as the GPU's texture gives it (bilinear, u wrapping, v
// clamped): colour premultiplied by alpha, in linear light (the PNG's sRGB decoded).
glm::dvec4 sample_decal_image(const Image&, glm::dvec2 uv);

// What a wall point shows of its decal: `cover`, the part of the surface the decal takes
// (the image's alpha times the opacity), and `tint`, its colour there (the image's colour
// times the layer's colour). cover 0: none.
struct DecalSample {
  double cover = 0;
  glm::dvec3 tint{0.0};
  DecalKind kind = DecalKind::Enamel;
  double roughness = 0;
};

// Every decal of one vessel, placed, with its images (read through core/vessel/decal_files).
struct VesselDecals {
  WallArcLengths arcs;
  std::array<DecalPlacement, kMaxDecalLayers> layers;
  std::array<std::shared_ptr<const Image>, kMaxDecalLayers> images;
  bool any() const { return layers[0].present || layers[1].present; }
  // The decal at the wall point `local` of the layer on that wall (none where there is none).
  DecalSample sample(const Vessel&, bool inner_wall, const glm::dvec3& local) const;
};

// Whether any layer of `p` names a file.
bool has_decals(const VesselParams& p);
// The decals of a vessel with these parameters; a layer whose image cannot be read (a file
// removed since it was set) is left out. Null when there is none.
std::shared_ptr<const VesselDecals> vessel_decals(const Vessel&, const VesselParams&);

// An image resampled to size x size texels for the GPU's texture array: each texel the
// mean over its footprint of the source (a box filter, bilinear when enlarging) in linear
// light with alpha premultiplied, encoded back to sRGB (the texture is SRGB8_ALPHA8, so
// filtering and mipmaps average light, and a transparent border does not darken an edge).
std::vector<std::uint8_t> decal_layer_texels(const Image&, int size);

}  // namespace draught
