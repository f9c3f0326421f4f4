#include "core/params/json_input.hpp"

#include "core/io/files.hpp"

#include <cstdint>

namespace draught {

using nlohmann::json;

std::string short_dump(const json& j) {
  std::string s = j.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

ParamValue param_value_from_json(const ParamDesc& d, const json& j, const std::string& file, const std::string& field) {
  auto fail = [&]() -> ParamValue {
    throw InputError(file + ": field '" + field + "': expected " + expected_text(d) + ", got " + short_dump(j));
  };
  auto num3 = [&](const json& a, glm::vec3& out) {
    if (!a.is_array() || a.size() != 3) return false;
    for (int i = 0; i < 3; ++i) {
      if (!a[size_t(i)].is_number()) return false;
      out[i] = a[size_t(i)].get<float>();
    }
    return true;
  };
  ParamValue v;
  switch (d.type) {
    case ParamType::Float:
      if (!j.is_number()) return fail();
      v = j.get<float>();
      break;
    case ParamType::Int: {
      if (!j.is_number_integer()) return fail();
      const auto wide = j.get<std::int64_t>();  // range-checked before narrowing
      if (wide < std::int64_t(d.min) || wide > std::int64_t(d.max)) return fail();
      v = int(wide);
      break;
    }
    case ParamType::Bool:
      if (!j.is_boolean()) return fail();
      v = j.get<bool>();
      break;
    case ParamType::Vec3:
    case ParamType::Color: {
      glm::vec3 c;
      if (!num3(j, c)) return fail();
      v = c;
      break;
    }
    case ParamType::Enum:
      if (!j.is_string()) return fail();
      v = j.get<std::string>();
      break;
    case ParamType::Curve: {
      if (!j.is_array()) return fail();
      Curve c;
      for (auto& pt : j) {
        if (!pt.is_array() || pt.size() != 2 || !pt[0].is_number() || !pt[1].is_number()) return fail();
        c.push_back({pt[0].get<float>(), pt[1].get<float>()});
      }
      v = c;
      break;
    }
  }
  try {
    validate_value(d, v);
  } catch (const ParamError& e) {
    throw InputError(file + ": field '" + field + "': expected " + e.expected + ", got " + short_dump(j));
  }
  return v;
}

json parse_json_file_text(const std::string& text, const std::string& file) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    size_t line = 1, col = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') ++line, col = 1;
      else ++col;
    }
    std::string what = e.what();
    auto p = what.find(": ", what.find("parse error"));
    throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(col) +
                     ": malformed JSON: " + (p == std::string::npos ? what : what.substr(p + 2)));
  } catch (const json::exception& e) {  // e.g. a number too large for a double
    std::string what = e.what();
    auto p = what.find("] ");
    throw InputError(file + ": malformed JSON: " + (p == std::string::npos ? what : what.substr(p + 2)));
  }
  return j;
}

}  // namespace draught
