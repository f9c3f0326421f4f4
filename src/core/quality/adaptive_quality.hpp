// Adaptive quality for interactive pages and windows: from measured times between frames it
// picks the render scale (the backing store is the display size x scale; pixels cost
// scale^2), falls to the MatCap tier (docs/MATCAP.md: about 5x cheaper) when the budget
// cannot be held at 50 % resolution, and caps the surface interactions per pixel when even
// the smallest scale misses it in the full tier (the fall turned off). Pure logic, no clock:
// the caller feeds it frame times, so tests can drive it with a cost model.
#pragma once

namespace draught {

struct AdaptiveQuality {
  bool adaptive = true;
  double scale = 1.0;
  double budget_ms = 33.0;
  double ema_ms = 0;     // smoothed time between frames since the last change
  double shown_ms = 0;   // the same, never reset (for a readout)
  int samples = 0;       // frames in ema_ms
  int events_cap = 0;    // 0: render.max_events as set
  bool matcap_fallback = true;  // fall to the MatCap tier below kMatCapBelow
  bool matcap = false;          // drawing the MatCap tier because of the budget
  static constexpr double kMinScale = 0.3, kMaxScale = 1.0, kMatCapBelow = 0.5;
  // The MatCap tier costs about a fifth of the full one (docs/PERFORMANCE.md): the full tier
  // comes back when, by that, it would take under 60 % of the budget at kMatCapBelow.
  static constexpr double kMatCapCostRatio = 5.0;
  static constexpr int kCapEvents = 6;
  static constexpr double kStartPixels = 5e5;

  // Pins the scale (clamped to 0.1-2; nothing adapts, the interactions uncapped), or adapts
  // it again to budget_ms, measuring afresh.
  void pin(double fixed_scale);
  void adapt();
  // Whether it may fall to the MatCap tier below kMatCapBelow; turning it off leaves it.
  void allow_matcap(bool on);

  // Starts a display of `pixels` (at scale 1) at about half a megapixel, never below
  // lowest(): a frame's first scale follows the same rule as the later ones.
  void start(double pixels);

  // The smallest scale now: the full tier goes no lower than kMatCapBelow while it can fall
  // to the MatCap tier (below that the MatCap tier's cheaper pixels serve better).
  double lowest() const { return matcap_fallback && !matcap ? kMatCapBelow : kMinScale; }

  // What a full-tier frame at kMatCapBelow would take, from the MatCap tier's frames now.
  double full_estimate_ms() const;

  // dt: milliseconds since the previous frame. Waits for a dozen frames after each change
  // (three when far too slow), so one slow frame (a shader compiled) does not move it.
  void update(double dt);

  // Start measuring afresh (the budget, the tier or the scene changed).
  void restart() { samples = 0; }
};

}  // namespace draught
