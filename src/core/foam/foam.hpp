// The foam head over time: it builds during a pour, settles, then collapses with the
// drink's half-life; it rides on the (sloshing) liquid surface; as the level drops it
// turns concave and leaves lacing rings on the glass; big bubbles on top grow, pop and
// leave voids that heal. Deterministic for a seed. The renderer marches the head as a
// volume (shaders/lib/foam/head.glsl); this module only says where it is.
#pragma once

#include "core/params/params.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace draught {

struct BigBubble {
  glm::dvec2 xz{0.0};  // on the head's top, glass frame, relative to the axis
  double radius = 0;   // metres; 0: this slot is empty
  bool popped = false; // popped: a void in the foam that heals (shrinks) instead of a shiny cap
};

struct FoamFrame {
  double thickness = 0;  // metres, along the surface normal, at the mean
  double dome = 0;       // thickness scales by 1 + dome (1 - 2 u^2), u = distance from axis / radius
  std::vector<double> lacing;  // heights (glass frame y) of the rings left on the inner wall
  std::vector<BigBubble> bubbles;
  // Where a pour's stream plunges into the head it pushes the foam aside: a dimple of
  // `crater_radius` (m) at crater_xz (glass frame) whose middle is `crater_depth` of the
  // thickness deep (0: none; at most kMaxCraterDepth), the foam heaped in a collar around
  // it (kCraterCollar of that depth, at kCraterCollarAt radii).
  glm::dvec2 crater_xz{0.0};
  double crater_radius = 0, crater_depth = 0;
  static constexpr double kMaxCraterDepth = contract::kCraterMaxDepth, kCraterCollar = contract::kCraterCollar,
                          kCraterCollarAt = contract::kCraterCollarAt;
  // The thickness at (x, z) in the glass frame, for a surface of this radius (as
  // shaders/lib/foam/head.glsl foam_thickness_at).
  double thickness_at(double x, double z, double radius) const;
  // The most thickness_at gives over the mean thickness's (1 + |dome|): the collar's.
  double crater_headroom() const { return 1 + kCraterCollar * crater_depth; }
};

// A big bubble where it sits in the picture: on the head's top over the liquid surface
// (glass frame), its cap standing out by 70 % of its radius. What the renderer draws.
struct PlacedBubble {
  glm::dvec3 centre{0.0};
  double radius = 0;
  bool popped = false;  // a void in the foam instead of a shiny cap
};

// Places the head's big bubbles on the surface dot(n, p) = offset (glass frame), whose
// radius at the axis is `surface_radius` (the head's dome is measured against it).
std::vector<PlacedBubble> place_big_bubbles(const FoamFrame&, const glm::dvec3& n, double offset,
                                            double surface_radius);

class FoamState {
 public:
  static constexpr int kMaxLacing = contract::kMaxLacing;  // src/interface/constants.def
  static constexpr int kMaxBubbles = contract::kMaxBigBubbles;

  explicit FoamState(const FoamParams&);
  void set_params(const FoamParams& p) { params_ = p; }
  void pour();  // a fresh head builds from nothing
  // Advance by dt (at most 1 s: a stalled caller does not age the head at once); `level` is the liquid's height on the axis (glass frame), `radius` the
  // inner radius there; the foam's top when the level drops is where lacing is left.
  void step(double dt, double level, double radius);
  FoamFrame frame(double radius) const;
  double age() const { return age_; }
  double thickness() const;

 private:
  BigBubble bubble(int slot, double radius) const;

  FoamParams params_;
  double age_ = 0;
  double drop_ = 0;           // how far the level has fallen since the pour (metres)
  double last_level_ = -1;    // level at the previous step
  double lace_level_ = -1;    // level where the last lacing ring was left
  std::vector<double> lacing_;
};

}  // namespace draught
