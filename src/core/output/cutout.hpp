// Transparent pictures (render.transparent): cutouts of the objects for compositing over
// a background of the user's. Alpha carries what the objects let through unchanged (the
// achromatic part of a path's throughput when it leaves them: see_through in
// shaders/passes/path.frag); the coloured rest of that light (a lager's gold, which no
// alpha can carry) is baked in, lit by the light behind: what the studio shows behind
// the objects. So a cutout over the studio's own background looks as the opaque picture
// does (tests/gpu/test_cutout.cpp), and over white it glows as a drink held to a window.
#pragma once

#include "core/io/image.hpp"
#include "core/scene/frame.hpp"

#include <glm/glm.hpp>

namespace draught {

// The light behind a transparent picture's objects (radiance, linear RGB): the backdrop
// where the camera's line through the scene's centre (surroundings_centre) meets it, lit
// as the opaque picture lights it with nothing in between (the rig's exact irradiance and
// the sky's, times its albedo, over pi); where there is no backdrop (env.floor off) or
// the line misses it, the sky seen round that line (its irradiance facing along it,
// over pi: the mean of the sky a cosine lobe round the line sees).
glm::dvec3 cutout_light(const FrameState&);

// A transparent picture's display samples (premultiplied: sRGB codes of the light the
// objects send, and coverage) as a PNG holds them (straight alpha, which the format
// defines and every viewer, browser and editor assumes): each colour decoded to linear
// light, divided by alpha and encoded again. Where a pixel sends more light than its
// coverage carries (a highlight on clear glass: colour above alpha), alpha is raised to
// the brightest channel, so over black the pixel keeps its light and colour exactly and
// over a light background it hides a little more of it. Alpha 0 stays 0 0 0 0.
Image straight_alpha(const Image& premultiplied);

// A rendered picture as a PNG file holds it (the CLI's stills and frames, the viewer's and
// the page's saved pictures): straight_alpha where it is transparent, else as it is. (A
// WebM's frames take straight_alpha too; an MP4 or a GIF takes the premultiplied samples:
// it drops alpha, a GIF keeping one bit, which shows them over black.)
inline Image png_picture(const Image& picture, bool transparent) {
  return transparent ? straight_alpha(picture) : picture;
}

}  // namespace draught
