// The per-point fields the loaders fill (a PLY's vertex properties, a text file's
// columns): which names give which field, what each value must be, and the one place a
// point is checked and stored, so every format accepts exactly the same values.
// docs/POINT_CLOUDS.md.
#pragma once

#include "core/math/srgb.hpp"
#include "core/pointcloud/cloud.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace draught {

enum class PointField : int { X, Y, Z, Radius, Temperature, Red, Green, Blue, VelocityX, VelocityY, VelocityZ };
inline constexpr int kPointFieldCount = 11;

// Limits of the values: coordinates and speeds are bounded so that they stay far inside
// float's range and a BVH's arithmetic; the least radius keeps a radius positive as a float.
inline constexpr double kMinPointRadius = 1.0e-9;         // in the file's units
inline constexpr double kMaxPointRadius = 1.0e6;          // in the file's units (scaled to metres by the object)
inline constexpr double kMaxPointTemperature = 10000.0;   // K
inline constexpr double kMaxPointCoordinate = 1.0e6;      // m, |x|, |y|, |z|
inline constexpr double kMaxPointSpeed = 1.0e6;           // m/s, |vx|, |vy|, |vz|

// The field's canonical name, as a text file's header writes it: "x", "radius", "r", "vx".
const char* point_field_name(PointField);

// The names every loader accepts, canonical first, with their aliases (a line each of
// docs/POINT_CLOUDS.md): {"x"}, ..., {"r", "red", "diffuse_red"}, {"vx", "velocity_x"}.
const std::vector<std::vector<std::string>>& point_field_names();

// What a value of the field must be ("a radius in [1e-9, 1e6] (the file's units)"), or nullptr when `v` is one.
const char* point_value_expected(PointField, double v);

// Which field each of a file's names (PLY properties, text columns) gives: column[field]
// is the index of the name that gives it, or -1.
struct PointFieldColumns {
  std::array<int, kPointFieldCount> column;
  PointFieldColumns() { column.fill(-1); }
  bool has(PointField f) const { return column[std::size_t(f)] >= 0; }
};

// Maps names to fields (case-insensitive). Names that are no field are left out when
// `unknown_ok` (a PLY's other properties), else they are a problem. Returns the problem,
// "" when none: a name twice, two names for one field (both 'red' and 'r'), a colour or
// velocity not given whole, x, y or z missing. *unknown is the index of an unknown name.
std::string resolve_point_fields(const std::vector<std::string_view>& names, bool unknown_ok,
                                 PointFieldColumns& out, int* unknown = nullptr);

// Collects checked points into a PointCloud; the vectors of fields not given stay empty.
class PointCloudBuilder {
 public:
  explicit PointCloudBuilder(const PointFieldColumns&, std::size_t reserve = 0);
  // Checks every given field of one point (values by PointField) and stores it; returns
  // the first field whose value is not acceptable (nothing stored then), or -1.
  int add(const std::array<double, kPointFieldCount>& values);
  std::size_t size() const { return cloud_.position.size(); }
  PointCloud take() { return std::move(cloud_); }

 private:
  PointFieldColumns fields_;
  PointCloud cloud_;
};

// A whole token as a number: decimal, with an optional sign (a leading '+' too) and
// exponent; "nan" and "inf" read, for the value checks to refuse by name. Nothing else
// (no hex, no spaces, no trailing text). Through strtod in the "C" locale, as everywhere
// in core: Emscripten's libc++ has no floating-point from_chars.
bool parse_number(std::string_view, double&);

// A token of the file quoted for an error message: capped, escaped and valid UTF-8
// whatever the bytes were ("abc", "\u001b[2J").
std::string quote_token(std::string_view);

// A number for an error message: the shortest text that reads back as `v` ("0.25", "nan").
std::string number_text(double v);

}  // namespace draught
