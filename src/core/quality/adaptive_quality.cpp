#include "core/quality/adaptive_quality.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

void AdaptiveQuality::pin(double fixed_scale) {
  adaptive = false;
  scale = std::clamp(fixed_scale, 0.1, 2.0);
  events_cap = 0;
  restart();
}

void AdaptiveQuality::adapt() {
  adaptive = true;
  restart();
}

void AdaptiveQuality::allow_matcap(bool on) {
  matcap_fallback = on;
  if (!on) matcap = false;
  restart();
}

void AdaptiveQuality::start(double pixels) {
  if (!adaptive || !(pixels > kStartPixels)) return;
  scale = std::max(lowest(), std::round(std::sqrt(kStartPixels / pixels) * 20) / 20);
}

double AdaptiveQuality::full_estimate_ms() const {
  return ema_ms * kMatCapCostRatio * (kMatCapBelow / scale) * (kMatCapBelow / scale);
}

void AdaptiveQuality::update(double dt) {
  if (!(dt > 0) || dt > 10000) return;  // a hidden tab, a debugger
  shown_ms = shown_ms == 0 ? dt : 0.9 * shown_ms + 0.1 * dt;
  if (!adaptive) return;
  ema_ms = samples == 0 ? dt : 0.85 * ema_ms + 0.15 * dt;
  if (++samples < (ema_ms > 3 * budget_ms ? 3 : 12)) return;
  const double before = scale;
  const int cap_before = events_cap;
  const bool matcap_before = matcap;
  const double floor_scale = lowest();
  if (ema_ms > budget_ms * 1.15) {
    if (scale > floor_scale + 1e-9) {  // pixels cost scale^2
      scale *= std::clamp(std::sqrt(budget_ms / ema_ms) * 0.97, 0.5, 0.95);
      scale = std::max(floor_scale, std::round(scale * 20) / 20);
    } else if (matcap_fallback && !matcap) {
      if (samples < 12) return;  // a fall needs a dozen frames, not the three of "far too slow"
      matcap = true;
    } else if (!matcap) {
      events_cap = kCapEvents;
    }
  } else if (ema_ms < budget_ms * 0.6) {
    if (events_cap) events_cap = 0;
    else if (matcap && full_estimate_ms() < budget_ms * 0.6) {  // the full tier would hold 50 % after all
      matcap = false;
      scale = kMatCapBelow;
    } else {
      scale = std::min(kMaxScale, std::round(scale * 1.12 * 20) / 20);
    }
  }
  if (scale != before || events_cap != cap_before || matcap != matcap_before) samples = 0;
  else samples = 6;  // keep watching, a little less eagerly
}

}  // namespace draught
