// PLY point clouds: ascii, binary_little_endian and binary_big_endian, every scalar type
// and list properties; the "vertex" element's x y z (and radius, temperature, colour,
// velocity when given) become a PointCloud, every other element and property is skipped.
// docs/POINT_CLOUDS.md.
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <string>
#include <string_view>

namespace draught {

// At most this many elements in a header, and properties in an element (real files have
// a handful): bounds the work a hostile header can ask for.
inline constexpr std::size_t kMaxPlyElements = 256;
inline constexpr std::size_t kMaxPlyProperties = 256;

// A complete cloud or an InputError naming `name`, the header line, ascii body line or
// binary byte offset, the element and its index, the property and what was expected:
// "gob.ply: byte 1732 (vertex 101, property z): the file ends; expected 4 more bytes".
PointCloud parse_ply(std::string_view bytes, const std::string& name);

}  // namespace draught
