// Environments the project makes itself, as equirectangular HDR images: its own studio
// (the procedural sky, the rig's lights and the lit sweep, as a glass's middle sees them)
// and a warm bar interior built from a few simple emitters. `draught environment bake` writes them; the shipped
// presets/environments/*.hdr are made so (docs/ENVIRONMENTS.md).
#pragma once

#include "core/io/hdr_image.hpp"
#include "core/params/params.hpp"

#include <string>
#include <vector>

namespace draught {

// The names `draught environment bake` takes, in order.
const std::vector<std::string>& baked_environment_names();

// Environment `name` as a width x width/2 equirectangular image (width even, 8-8192);
// each texel the mean of a 4 x 4 grid of directions across it, so a light smaller than a
// texel keeps its total. `scene` supplies the studio's sky and lights. Throws
// InputError for an unknown name or width.
HdrImage bake_environment(const std::string& name, const SceneParams& scene, int width);

}  // namespace draught
