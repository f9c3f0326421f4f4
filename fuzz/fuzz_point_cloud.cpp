// libFuzzer target: the point cloud loaders (core/pointcloud): the same bytes as a PLY
// (ascii or binary) and as XYZ/CSV text. Each must return a cloud that keeps the
// promises of PointCloud (attribute arrays empty or one value a point, every value in
// its range) or throw InputError naming the file.
#include "fuzz_common.hpp"

#include "core/pointcloud/ply.hpp"
#include "core/pointcloud/point_fields.hpp"
#include "core/pointcloud/point_text.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace {

void check_cloud(const draught::PointCloud& c) {
  using namespace draught;
  const std::size_t n = c.size();
  if (n > kMaxCloudPoints) fuzz::finding("a cloud over kMaxCloudPoints", "");
  auto sized = [n](std::size_t k) { return k == 0 || k == n; };
  if (!sized(c.radius.size()) || !sized(c.temperature.size()) || !sized(c.color.size()) || !sized(c.velocity.size()))
    fuzz::finding("an attribute array that is neither empty nor one value a point", "");
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!(std::abs(c.position[i][k]) <= kMaxPointCoordinate)) fuzz::finding("a coordinate out of range", "");
      if (!c.color.empty() && !(c.color[i][k] >= 0 && c.color[i][k] <= 1)) fuzz::finding("a colour out of range", "");
      if (!c.velocity.empty() && !(std::abs(c.velocity[i][k]) <= kMaxPointSpeed)) fuzz::finding("a velocity out of range", "");
    }
    if (!(c.radius_of(i) > 0 && c.radius_of(i) <= kMaxPointRadius)) fuzz::finding("a radius out of range", "");
    if (!c.temperature.empty() && !(c.temperature[i] >= 0 && c.temperature[i] <= kMaxPointTemperature))
      fuzz::finding("a temperature out of range", "");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace draught;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    check_cloud(parse_ply(bytes, fuzz::kFile));
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  try {
    check_cloud(parse_point_text(bytes, fuzz::kFile));
  } catch (const InputError& e) {
    fuzz::check_error(e);
  }
  return 0;  // any other exception escapes: libFuzzer reports it as a crash
}
