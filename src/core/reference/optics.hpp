// Optics shared by the reference code and tests; its GLSL twin is shaders/lib/optics/fresnel.glsl.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace draught {

// Unpolarised Fresnel reflectance for light going from index n1 into n2 with
// cos_i = cos(angle of incidence) in [0, 1]. Total internal reflection gives 1.
double fresnel_dielectric(double cos_i, double n1, double n2);

// Snell refraction of unit direction i at unit normal n (n facing against i),
// eta = n1 / n2. Empty under total internal reflection.
std::optional<glm::dvec3> refract_dir(const glm::dvec3& i, const glm::dvec3& n, double eta);
glm::dvec3 reflect_dir(const glm::dvec3& i, const glm::dvec3& n);

}  // namespace draught
