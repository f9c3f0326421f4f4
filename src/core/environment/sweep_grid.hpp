// What the maps over the unrolled sweep share (backdrop_light: the rig's light;
// paper_bounce: the paper's own bounce): a grid of texels over (x, s), their centres,
// bilinear filtering between them as GL's linear filter (clamped to the outermost
// centres), and filling the texels on the machine's cores.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <thread>
#include <vector>

namespace draught {

struct SweepGrid {
  glm::dvec2 origin{0.0};  // (x, s) of the grid's corner
  glm::dvec2 size{0.0};    // extent along x and s
  int width = 0, height = 0;

  bool empty() const { return width == 0 || height == 0; }
  glm::dvec2 texel_centre(int i, int j) const {
    return origin + glm::dvec2((i + 0.5) * size.x / width, (j + 0.5) * size.y / height);
  }
  // The texels' values at (x, s): at(i, j) the value of texel (i, j), row-major.
  template <class At>
  auto bilinear(const glm::dvec2& xs, At&& at) const {
    const double u = std::clamp((xs.x - origin.x) / size.x * width - 0.5, 0.0, width - 1.0);
    const double v = std::clamp((xs.y - origin.y) / size.y * height - 0.5, 0.0, height - 1.0);
    const int i = std::min(int(u), width - 1), j = std::min(int(v), height - 1);
    const int i1 = std::min(i + 1, width - 1), j1 = std::min(j + 1, height - 1);
    const double fu = u - i, fv = v - j;
    return glm::mix(glm::mix(at(i, j), at(i1, j), fu), glm::mix(at(i, j1), at(i1, j1), fu), fv);
  }
};

// Calls f(lane) for lane in [0, lanes) on as many threads (the caller's the first), lanes
// the machine's cores, at most 8: each lane takes every lanes-th row or texel.
inline int sweep_grid_lanes() { return int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u)); }
template <class F>
void in_lanes(int lanes, F&& f) {
  std::vector<std::thread> pool;
  for (int t = 1; t < lanes; ++t) pool.emplace_back(f, t);
  f(0);
  for (std::thread& t : pool) t.join();
}

}  // namespace draught
