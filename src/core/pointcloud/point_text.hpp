// Point clouds as text: XYZ and CSV. One point a line, columns separated by commas or by
// whitespace, '#' starts a comment, blank lines are skipped. An optional first line names
// the columns (x y z radius temperature r g b vx vy vz, any order, any subset with x y z);
// without it the count of columns says what they are:
//   3: x y z   4: x y z radius   5: x y z radius temperature   6: x y z r g b
//   7: x y z radius r g b
// Colours in text are linear, 0..1. docs/POINT_CLOUDS.md.
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <string>
#include <string_view>

namespace draught {

// A complete cloud or an InputError naming `name`, the line, column and field:
// "points.csv: line 7, column 3 (z): expected a number, got \"abc\"". A file of nothing but
// a header is an empty cloud; a file without a single point or header is an error.
PointCloud parse_point_text(std::string_view text, const std::string& name);

}  // namespace draught
