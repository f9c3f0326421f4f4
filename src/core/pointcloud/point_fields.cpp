#include "core/pointcloud/point_fields.hpp"

#include "core/text/echo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace draught {

namespace {
// Names by field; several spellings of one field are aliases. Colour and velocity come in
// sets (index in the field's list): r g b, red green blue, diffuse_red ... must not mix.
const std::array<std::vector<std::string>, kPointFieldCount> kNames = {{
    {"x"},
    {"y"},
    {"z"},
    {"radius", "pscale"},  // pscale: Houdini's point radius
    {"temperature"},
    {"r", "red", "diffuse_red"},
    {"g", "green", "diffuse_green"},
    {"b", "blue", "diffuse_blue"},
    {"vx", "velocity_x"},
    {"vy", "velocity_y"},
    {"vz", "velocity_z"},
}};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

bool finite_within(double v, double limit) { return std::isfinite(v) && std::abs(v) <= limit; }
}  // namespace

const char* point_field_name(PointField f) { return kNames[std::size_t(f)][0].c_str(); }

const std::vector<std::vector<std::string>>& point_field_names() {
  static const std::vector<std::vector<std::string>> names(kNames.begin(), kNames.end());
  return names;
}

const char* point_value_expected(PointField f, double v) {
  switch (f) {
    case PointField::X:
    case PointField::Y:
    case PointField::Z:
      return finite_within(v, kMaxPointCoordinate) ? nullptr : "a finite coordinate in [-1e6, 1e6] m";
    case PointField::Radius:
      return std::isfinite(v) && v >= kMinPointRadius && v <= kMaxPointRadius ? nullptr : "a radius in [1e-9, 1e6] (the file's units)";
    case PointField::Temperature:
      return std::isfinite(v) && v >= 0 && v <= kMaxPointTemperature ? nullptr : "a temperature in [0, 10000] K";
    case PointField::Red:
    case PointField::Green:
    case PointField::Blue:
      return std::isfinite(v) && v >= 0 && v <= 1 ? nullptr : "a linear colour channel in [0, 1]";
    case PointField::VelocityX:
    case PointField::VelocityY:
    case PointField::VelocityZ:
      return finite_within(v, kMaxPointSpeed) ? nullptr : "a finite velocity in [-1e6, 1e6] m/s";
  }
  return "a known field";
}

std::string resolve_point_fields(const std::vector<std::string_view>& names, bool unknown_ok,
                                 PointFieldColumns& out, int* unknown) {
  out = PointFieldColumns{};
  std::array<int, kPointFieldCount> alias{};  // which spelling gave each field
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string name = lower(names[i]);
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) return "'" + name + "' is given twice";
    seen.push_back(name);
    bool known = false;
    for (int f = 0; f < kPointFieldCount && !known; ++f) {
      const auto& spellings = kNames[std::size_t(f)];
      for (std::size_t a = 0; a < spellings.size(); ++a) {
        if (spellings[a] != name) continue;
        known = true;
        if (out.column[std::size_t(f)] >= 0)
          return "both '" + spellings[std::size_t(alias[std::size_t(f)])] + "' and '" + name + "' give the " +
                 (f == int(PointField::Radius) ? std::string("radius") : "same field") + ": expected one of them";
        out.column[std::size_t(f)] = int(i);
        alias[std::size_t(f)] = int(a);
      }
    }
    if (!known && !unknown_ok) {
      if (unknown) *unknown = int(i);
      return "unknown";
    }
  }
  // Colour and velocity are whole or absent, in one spelling (not 'red' with 'g').
  for (int first : {int(PointField::Red), int(PointField::VelocityX)}) {
    int given = 0;
    for (int k = 0; k < 3; ++k) given += out.column[std::size_t(first + k)] >= 0;
    if (given != 0 && given != 3) {
      std::string missing;
      for (int k = 0; k < 3; ++k)
        if (out.column[std::size_t(first + k)] < 0)
          missing += (missing.empty() ? "'" : ", '") + kNames[std::size_t(first + k)][0] + "'";
      return std::string(first == int(PointField::Red) ? "a colour" : "a velocity") +
             " is given in part: expected also " + missing;
    }
    if (given == 3 && (alias[std::size_t(first)] != alias[std::size_t(first + 1)] ||
                       alias[std::size_t(first)] != alias[std::size_t(first + 2)]))
      return std::string(first == int(PointField::Red) ? "the colour" : "the velocity") +
             " mixes spellings: expected one of " +
             (first == int(PointField::Red) ? "r g b, red green blue or diffuse_red diffuse_green diffuse_blue"
                                            : "vx vy vz or velocity_x velocity_y velocity_z");
  }
  for (PointField f : {PointField::X, PointField::Y, PointField::Z})
    if (!out.has(f)) return std::string("no '") + point_field_name(f) + "': expected x, y and z";
  return "";
}

PointCloudBuilder::PointCloudBuilder(const PointFieldColumns& fields, std::size_t reserve) : fields_(fields) {
  cloud_.position.reserve(reserve);
  if (fields_.has(PointField::Radius)) cloud_.radius.reserve(reserve);
  if (fields_.has(PointField::Temperature)) cloud_.temperature.reserve(reserve);
  if (fields_.has(PointField::Red)) cloud_.color.reserve(reserve);
  if (fields_.has(PointField::VelocityX)) cloud_.velocity.reserve(reserve);
}

int PointCloudBuilder::add(const std::array<double, kPointFieldCount>& v) {
  for (int f = 0; f < kPointFieldCount; ++f)
    if (fields_.column[std::size_t(f)] >= 0 && point_value_expected(PointField(f), v[std::size_t(f)])) return f;
  auto at = [&](PointField f) { return float(v[std::size_t(f)]); };
  cloud_.position.emplace_back(at(PointField::X), at(PointField::Y), at(PointField::Z));
  if (fields_.has(PointField::Radius)) cloud_.radius.push_back(at(PointField::Radius));
  if (fields_.has(PointField::Temperature)) cloud_.temperature.push_back(at(PointField::Temperature));
  if (fields_.has(PointField::Red))
    cloud_.color.emplace_back(at(PointField::Red), at(PointField::Green), at(PointField::Blue));
  if (fields_.has(PointField::VelocityX))
    cloud_.velocity.emplace_back(at(PointField::VelocityX), at(PointField::VelocityY), at(PointField::VelocityZ));
  return -1;
}

std::string quote_token(std::string_view s) { return make_valid_utf8(quote_input(s)); }

bool parse_number(std::string_view t, double& v) {
  if (t.empty() || t.size() > 400) return false;  // (longer is no float a file would write)
  // Only the characters of a decimal number or of nan/inf reach strtod, so it cannot
  // take hex or a locale's own forms.
  for (char c : t) {
    const bool number = (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
    const char l = char(c | 0x20);
    if (!number && l != 'n' && l != 'a' && l != 'i' && l != 'f' && l != 't' && l != 'y') return false;
  }
  char small[64];
  std::string large;
  const char* z;
  if (t.size() < sizeof small) {
    std::memcpy(small, t.data(), t.size());
    small[t.size()] = 0;
    z = small;
  } else {
    large.assign(t);
    z = large.c_str();
  }
  char* end = nullptr;
  v = std::strtod(z, &end);
  return end == z + t.size();
}

std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  for (int digits = 6; digits <= 17; ++digits) {  // the shortest that reads back as v
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace draught
