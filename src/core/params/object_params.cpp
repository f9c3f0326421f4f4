#include "core/params/object_params.hpp"

#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/text/suggest.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <sstream>

namespace draught {

std::string object_param_range(const ObjectParamInfo& p) {
  std::ostringstream s;
  s << "[" << p.min << ", " << p.max << "]";
  if (*p.unit) s << " (" << p.unit << ")";
  return s.str();
}

const ObjectParamInfo& find_object_param(const std::vector<ObjectParamInfo>& table, const std::string& key,
                                         const std::string& file, const std::string& at, const char* what) {
  std::vector<std::string> names;
  for (const ObjectParamInfo& info : table) {
    if (key == info.name) return info;
    names.emplace_back(info.name);
  }
  const std::string near = nearest_choice(key, names);
  throw InputError(file + ": field '" + at + "." + key + "': unknown " + what + " parameter" +
                   (near.empty() ? "" : " (did you mean '" + near + "'?)"));
}

double object_param_number(const nlohmann::json& x, const ObjectParamInfo& info, const std::string& file,
                           const std::string& field) {
  if (!x.is_number() || !(x.get<double>() >= info.min && x.get<double>() <= info.max))
    throw InputError(file + ": field '" + field + "': expected a number in " + object_param_range(info) + ", got " +
                     short_dump(x));
  return x.get<double>();
}

int object_param_int(const nlohmann::json& x, const ObjectParamInfo& info, const std::string& file,
                     const std::string& field) {
  if (!x.is_number_integer() || x.get<std::int64_t>() < info.min || x.get<std::int64_t>() > info.max)
    throw InputError(file + ": field '" + field + "': expected a whole number in " + object_param_range(info) +
                     ", got " + short_dump(x));
  return int(x.get<std::int64_t>());
}

glm::vec3 object_param_rgb(const nlohmann::json& x, const ObjectParamInfo& info, const std::string& file,
                           const std::string& field) {
  if (!x.is_array() || x.size() != 3)
    throw InputError(file + ": field '" + field + "': expected [r, g, b], each in " + object_param_range(info) +
                     ", got " + short_dump(x));
  glm::vec3 rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = float(object_param_number(x[std::size_t(c)], info, file, field));
  return rgb;
}

}  // namespace draught
