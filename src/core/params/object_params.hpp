// The parameters of an object kind that is not a vessel (a droplets trail, a point cloud):
// a table of names, ranges, units and docs, and the checks that read them from a scene
// preset's object with errors naming the file, the field and what was expected. One
// reading for every such kind (the vessels' own parameters are the table of params.hpp).
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace draught {

struct ObjectParamInfo {
  const char* name;
  double min, max;
  const char* unit;
  const char* doc;
};

// "[0, 0.2] (m)": the range a number must be in, for error messages.
std::string object_param_range(const ObjectParamInfo&);

// The entry of `key` in the table; InputError "FILE: field 'AT.KEY': unknown WHAT
// parameter (did you mean '...'?)" for none.
const ObjectParamInfo& find_object_param(const std::vector<ObjectParamInfo>& table, const std::string& key,
                                         const std::string& file, const std::string& at, const char* what);

// A number of `info`'s range; InputError "FILE: field 'FIELD': expected a number in
// [min, max] (unit), got ..." (FIELD names where it is, e.g. "objects[1].droplets.blend").
double object_param_number(const nlohmann::json&, const ObjectParamInfo& info, const std::string& file,
                           const std::string& field);

// A whole number of `info`'s range (a count); InputError "FILE: field 'FIELD': expected a
// whole number in [min, max], got ...".
int object_param_int(const nlohmann::json&, const ObjectParamInfo& info, const std::string& file,
                     const std::string& field);

// Three numbers [r, g, b], each of `info`'s range; InputError "FILE: field 'FIELD':
// expected [r, g, b], each in [min, max] (unit), got ..." for anything but three, and
// object_param_number's error for a component out of range.
glm::vec3 object_param_rgb(const nlohmann::json&, const ObjectParamInfo& info, const std::string& file,
                           const std::string& field);

}  // namespace draught
