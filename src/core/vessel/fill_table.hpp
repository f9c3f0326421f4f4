// The liquid's level under any tilt, keeping its volume, for any glass profile.
// The surface is a plane dot(n, p) = offset in the glass's local frame, its normal
// tilted by `tilt` from the axis. The volume under it is integrated over the
// profile's frustum segments (each horizontal slice is a disk cut by a line), and a
// table offset(tilt, volume) is built at load time and interpolated bilinearly, on the
// CPU here and on the GPU from a texture of the same numbers.
#pragma once

#include "core/vessel/vessel.hpp"
#include "generated/constants.hpp"

#include <vector>

namespace draught {

// Volume of the cavity (base..rim) below the plane whose normal is tilted by `tilt`
// radians (towards local +X; the cavity is round, so the direction does not matter).
// Splits every segment where the cutting line touches the slice and integrates each
// piece with Gauss-Legendre: accurate to ~1e-7 of the cavity volume.
double volume_below_plane(const Vessel&, double tilt, double offset);
// The offset whose plane holds `volume` m^3 (bisection on the above; reference solver).
double plane_offset_for_volume(const Vessel&, double tilt, double volume);
// The offset of the plane through the lowest point of the rim: liquid above it spills.
double rim_offset(const Vessel&, double tilt);
// The smallest and largest offsets that touch the cavity.
void offset_range(const Vessel&, double tilt, double& lo, double& hi);

struct FillTable {
  // Sizes from src/interface/constants.def.
  static constexpr int kTilts = contract::kFillTilts, kVolumes = contract::kFillVolumes;
  static constexpr double kMaxTilt = contract::kFillMaxTilt;  // tilts 0..135 deg, uniform; beyond, clamped (every glass has spilled)
  double cavity_volume = 0;
  // offset[i * kVolumes + j]: tilt i * kMaxTilt / (kTilts - 1), volume fraction
  // u^2 (3 - 2u) with u = j / (kVolumes - 1): columns crowd at the nearly empty and
  // nearly full ends, where a tipped surface is a thin wedge.
  std::vector<float> offset;
  Vessel vessel;  // the glass it was built for

  double offset_at(double tilt, double fraction) const;  // bilinear, clamped
  // The fraction that stays in below the lowest rim point: integrated exactly (a few
  // microseconds), since it falls steeply towards 90 degrees where rows are too coarse.
  double capacity_at(double tilt) const;
};

FillTable build_fill_table(const Vessel&);

}  // namespace draught
