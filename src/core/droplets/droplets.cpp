#include "core/droplets/droplets.hpp"

#include "core/params/json_input.hpp"
#include "core/text/echo.hpp"
#include "core/io/files.hpp"
#include "core/params/params.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace draught {

const std::vector<ObjectParamInfo>& droplet_param_table() {
  static const std::vector<ObjectParamInfo> table = {
      {"count", 1, kMaxDroplets, "", "spheres in the trail"},
      {"radius", 0.001, 0.2, "m", "radius of the head sphere"},
      {"taper", 0, 0.95, "", "the tail's radius is radius x (1 - taper), linearly along the trail"},
      {"blend", 0, 0.2, "m", "blend width of the smooth minimum (0: a plain union)"},
      {"kernel", 0, 1, "", "\"polynomial\" (local, the default) or \"exponential\""},
      {"noise_amplitude", 0, 0.02, "m", "displacement of the surface by value noise"},
      {"noise_frequency", 0, 1000, "1/m", "frequency of the noise"},
      {"ior", 1, 2.5, "", "index of refraction (water 1.33)"},
      {"roughness", 0, 1, "", "GGX roughness of the surface"},
      {"absorption", 0, 1000, "1/m", "Beer-Lambert absorption per metre, [r, g, b]"},
      {"stiffness", 10, 5000, "1/s^2", "each sphere's spring to the one before it (the head's to the pointer)"},
      {"damping", 0, 200, "1/s", "damping of the springs"},
  };
  return table;
}


DropletParams parse_droplet_params(const nlohmann::json& j, const std::string& file, const std::string& at) {
  if (!j.is_object())
    throw InputError(file + ": field '" + at + "': expected an object of droplet parameters, got " + short_dump(j));
  DropletParams p;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = it.key(), name = at + "." + key, field = file + ": field '" + name + "': ";
    const ObjectParamInfo* info = &find_object_param(droplet_param_table(), key, file, at, "droplet");
    const nlohmann::json& v = it.value();
    if (key == "kernel") {
      if (!v.is_string() || (v.get<std::string>() != "polynomial" && v.get<std::string>() != "exponential"))
        throw InputError(field + "expected \"polynomial\" or \"exponential\", got " + short_dump(v));
      p.kernel = v.get<std::string>() == "exponential" ? 1 : 0;
    } else if (key == "count") {
      p.count = object_param_int(v, *info, file, name);
    } else if (key == "absorption") {
      p.absorption = object_param_rgb(v, *info, file, name);
    } else {
      const float x = float(object_param_number(v, *info, file, name));
      if (key == "radius") p.radius = x;
      else if (key == "taper") p.taper = x;
      else if (key == "blend") p.blend = x;
      else if (key == "noise_amplitude") p.noise_amplitude = x;
      else if (key == "noise_frequency") p.noise_frequency = x;
      else if (key == "ior") p.ior = x;
      else if (key == "roughness") p.roughness = x;
      else if (key == "stiffness") p.stiffness = x;
      else if (key == "damping") p.damping = x;
    }
  }
  return p;
}

nlohmann::json droplet_params_json(const DropletParams& p) {
  return {{"count", p.count},
          {"radius", p.radius},
          {"taper", p.taper},
          {"blend", p.blend},
          {"kernel", p.kernel == 1 ? "exponential" : "polynomial"},
          {"noise_amplitude", p.noise_amplitude},
          {"noise_frequency", p.noise_frequency},
          {"ior", p.ior},
          {"roughness", p.roughness},
          {"absorption", {p.absorption.x, p.absorption.y, p.absorption.z}},
          {"stiffness", p.stiffness},
          {"damping", p.damping}};
}

DropletField droplet_field_of(const DropletParams& p, std::vector<DropletSphere> spheres) {
  DropletField f;
  if (spheres.size() > size_t(kMaxDroplets)) spheres.resize(size_t(kMaxDroplets));
  f.spheres = std::move(spheres);
  f.kernel = p.kernel == 1 ? BlendKernel::Exponential : BlendKernel::Polynomial;
  f.blend = p.blend;
  f.noise_amplitude = p.noise_amplitude;
  f.noise_frequency = p.noise_frequency;
  return f;
}

}  // namespace draught
