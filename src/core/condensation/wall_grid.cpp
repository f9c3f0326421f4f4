#include "core/condensation/wall_grid.hpp"

#include "generated/constants.hpp"
#include "core/math/smoothstep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {

constexpr int kAngles = contract::kCondensationAngles, kRows = contract::kCondensationRows,
              kSlots = contract::kCondensationSlots;
constexpr int kFogAngles = contract::kCondensationFogAngles, kFogRows = contract::kCondensationFogRows;
static_assert(kFogAngles == Condensation::kFogAngles && kFogRows == Condensation::kFogRows);
constexpr float kPiF = std::numbers::pi_v<float>;
// A bead is listed in the cells within this many of its radii: the mist it drank around
// itself (BeadSample::clear) reaches that far.
constexpr float kHalo = 1.35f;

}  // namespace

std::vector<glm::vec4> bead_grid(const CondensationState& s, const Vessel& vessel) {
  std::vector<glm::vec4> grid(size_t(kRows) * kAngles * kSlots, glm::vec4(0.0f));
  const CondensationBand& band = s.band;
  if (band.empty()) return grid;
  const double cell_height = (band.y1 - band.y0) / kRows, cell_angle = 2 * std::numbers::pi / kAngles;
  for (const Bead& b : s.beads) {
    const double reach = kHalo * b.radius;
    const int r0 = std::max(0, int(std::floor((b.y - reach - band.y0) / cell_height))),
              r1 = std::min(kRows - 1, int(std::floor((b.y + reach - band.y0) / cell_height)));
    // Around the wall the bead spans the most angle where the wall is narrowest.
    const double narrowest = std::max(1e-4, std::min({vessel.outer_radius(b.y - reach), vessel.outer_radius(b.y),
                                                     vessel.outer_radius(b.y + reach)}));
    const double half_angle = std::min(std::numbers::pi, 1.05 * reach / narrowest);
    const int c0 = int(std::floor((b.angle - half_angle + std::numbers::pi) / cell_angle)),
              c1 = int(std::floor((b.angle + half_angle + std::numbers::pi) / cell_angle));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= std::min(c1, c0 + kAngles - 1); ++c) {
        // Whether the bead's base (not only its halo) touches the cell: those entries are
        // kept first when a cell is full (texel w = 1), then the larger beads.
        const double ya = band.y0 + r * cell_height, aa = -std::numbers::pi + c * cell_angle;
        const double up = std::max({ya - b.y, b.y - (ya + cell_height), 0.0});
        const double across = narrowest * std::max({aa - b.angle, b.angle - (aa + cell_angle), 0.0});
        const glm::vec4 texel(float(b.angle), float(b.y), float(b.radius), up * up + across * across < b.radius * b.radius ? 1.0f : 0.0f);
        glm::vec4* cell = &grid[(size_t(r) * kAngles + size_t((c % kAngles + kAngles) % kAngles)) * kSlots];
        auto rank = [](const glm::vec4& x) { return x.z > 0.0f ? x.w + x.z : -1.0f; };
        glm::vec4* slot = std::min_element(cell, cell + kSlots, [&](const glm::vec4& x, const glm::vec4& y) { return rank(x) < rank(y); });
        if (rank(*slot) < rank(texel)) *slot = texel;  // a free slot, else the least needed entry gives way
      }
  }
  return grid;
}

std::vector<std::uint8_t> fog_texels(const CondensationState& s) {
  std::vector<std::uint8_t> out(s.fog.size());
  for (size_t i = 0; i < s.fog.size(); ++i) out[i] = std::uint8_t(std::lround(std::clamp(s.fog[i], 0.0f, 1.0f) * 255.0f));
  return out;
}

BeadSample bead_at(const std::vector<glm::vec4>& grid, const CondensationBand& band, float contact_angle, glm::vec3 p,
                   glm::vec3 n) {
  BeadSample s;
  s.normal = n;
  const float fy = float((p.y - band.y0) / (band.y1 - band.y0));
  if (band.empty() || !(fy >= 0.0f && fy < 1.0f)) return s;
  const float a = std::atan2(p.x, p.z);
  const int ia = std::clamp(int(std::floor((a + kPiF) / (2.0f * kPiF) * float(kAngles))), 0, kAngles - 1);
  const int iy = std::clamp(int(fy * float(kRows)), 0, kRows - 1);
  const float rw = std::sqrt(p.x * p.x + p.z * p.z);
  const glm::vec3 across = glm::vec3(p.z, 0.0f, -p.x) / rw;  // round the axis
  const glm::vec3 up = glm::normalize(glm::cross(n, across));  // up the profile
  const float up_y = std::max(up.y, 0.2f);                    // metres along the profile per metre of height
  const float sin_contact = std::sin(contact_angle);
  for (int k = 0; k < kSlots; ++k) {
    const glm::vec4 b = grid[(size_t(iy) * kAngles + size_t(ia)) * kSlots + size_t(k)];
    if (b.z <= 0.0f) continue;
    float da = a - b.x;
    da -= 2.0f * kPiF * std::floor(da / (2.0f * kPiF) + 0.5f);
    const glm::vec3 rho = (rw * da) * across + ((p.y - b.y) / up_y) * up;
    const float q = glm::length(rho) / b.z;
    s.clear = std::min(s.clear, smoothstep(1.0f, kHalo, q));
    if (q < 1.0f && !s.found) {
      const float R = b.z / sin_contact;
      s.found = true;
      s.normal = glm::normalize(rho + n * std::sqrt(std::max(R * R - glm::dot(rho, rho), 0.0f)));
    }
  }
  return s;
}

float fog_at(const std::vector<std::uint8_t>& fog, const CondensationBand& band, glm::vec3 p) {
  const float fy = float((p.y - band.y0) / (band.y1 - band.y0));
  if (band.empty() || !(fy >= 0.0f && fy < 1.0f)) return 0.0f;
  const float u = (std::atan2(p.x, p.z) + kPiF) / (2.0f * kPiF) * float(kFogAngles) - 0.5f;
  const float v = std::clamp(fy * float(kFogRows), 0.5f, float(kFogRows) - 0.5f) - 0.5f;
  const float cu = std::floor(u), cv = std::floor(v), fu = u - cu, fv = v - cv;
  const int c0 = (int(cu) % kFogAngles + kFogAngles) % kFogAngles, c1 = (c0 + 1) % kFogAngles;
  const int r0 = int(cv), r1 = std::min(r0 + 1, kFogRows - 1);
  auto at = [&](int r, int c) { return float(fog[size_t(r) * kFogAngles + size_t(c)]) / 255.0f; };
  return (1.0f - fv) * ((1.0f - fu) * at(r0, c0) + fu * at(r0, c1)) + fv * ((1.0f - fu) * at(r1, c0) + fu * at(r1, c1));
}

}  // namespace draught
