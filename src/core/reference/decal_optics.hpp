// What a decal on a glass's wall does to light that meets it, for every tracer of light
// on the CPU: the reference's paths (core/reference/path_tracer) and the floor's photons
// (core/environment/floor_light), so a logo's shadow on the floor is the decal the
// reference draws. Its GLSL counterpart, the picture's look of a decal, is
// shaders/lib/vessel/decal.glsl (which uses the same backscatter share).
#pragma once

#include "core/math/random.hpp"
#include "core/reference/media.hpp"
#include "core/vessel/decal.hpp"

#include <glm/glm.hpp>

#include <optional>

namespace draught {

// Of the light an etched (frosted) decal scatters, the part it sends back to the side it
// came from; the rest goes through, scattered.
inline constexpr double kFrostBackscatter = 0.2;

// Whether light meeting a wall whose decal covers `cover` of it meets the decal, by the
// uniform u: from the air the surface's gloss comes first (reflectance F) and the decal
// takes its cover of the rest; from inside the glass or the drink the ink, frost or metal
// meets it first (no total internal reflection off a painted face). When it does not, u
// is what Fresnel's choice takes next (from inside, taken back to [0, 1); from the air,
// u >= F already refracts).
bool meets_decal(double& u, double F, double cover, bool from_air);

// Light along ray.d meets `decal` at ray.o (n: the wall's normal facing it; next: the
// medium beyond the wall; object: the glass). Its power `thr` takes the decal's colour. A
// metallic decal mirrors it about a microfacet normal drawn from GGX (alpha = roughness
// squared, masking left out): ray.d is turned and nullopt returned. Enamel sends it back
// and etched glass scatters it, kFrostBackscatter back and the rest on into `next`
// (medium and obj updated): the side it leaves to is returned, about which the caller
// draws a cosine-distributed direction (decal_diffuse_direction), after sampling the
// lights there if it does.
std::optional<glm::dvec3> decal_turn(const DecalSample& decal, const glm::dvec3& n, MediumKind next, int object,
                                     Ray& ray, MediumKind& medium, int& obj, glm::dvec3& thr, Rng& rng);

// A cosine-distributed direction about `side`; its cosine with `side` in `cos_t`.
glm::dvec3 decal_diffuse_direction(const glm::dvec3& side, Rng& rng, double& cos_t);

}  // namespace draught
