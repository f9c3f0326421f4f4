// Colour difference as a viewer sees it: 8-bit sRGB -> CIELAB (D65) -> CIEDE2000
// (Sharma, Wu and Dalal 2005). Used to compare the picture with the reference path tracer.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace draught::test {

inline double srgb8_to_linear(std::uint8_t v) {
  const double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

inline glm::dvec3 srgb8_to_lab(std::uint8_t r8, std::uint8_t g8, std::uint8_t b8) {
  const double r = srgb8_to_linear(r8), g = srgb8_to_linear(g8), b = srgb8_to_linear(b8);
  // XYZ relative to the D65 white.
  const double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
  const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
  auto f = [](double t) { return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16) / 116; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

inline double ciede2000(const glm::dvec3& lab1, const glm::dvec3& lab2) {
  constexpr double kPi = std::numbers::pi;
  auto deg = [&](double r) { return r * 180 / kPi; };
  auto rad = [&](double d) { return d * kPi / 180; };
  const double c1 = std::hypot(lab1.y, lab1.z), c2 = std::hypot(lab2.y, lab2.z);
  const double cm7 = std::pow((c1 + c2) / 2, 7);
  const double g = 0.5 * (1 - std::sqrt(cm7 / (cm7 + std::pow(25.0, 7))));
  const double a1 = (1 + g) * lab1.y, a2 = (1 + g) * lab2.y;
  const double cp1 = std::hypot(a1, lab1.z), cp2 = std::hypot(a2, lab2.z);
  auto hue = [&](double b, double a) {
    if (a == 0 && b == 0) return 0.0;
    const double h = deg(std::atan2(b, a));
    return h < 0 ? h + 360 : h;
  };
  const double h1 = hue(lab1.z, a1), h2 = hue(lab2.z, a2);
  const double dl = lab2.x - lab1.x, dc = cp2 - cp1;
  double dh = 0;
  if (cp1 * cp2 != 0) {
    dh = h2 - h1;
    if (dh > 180) dh -= 360;
    else if (dh < -180) dh += 360;
  }
  const double dH = 2 * std::sqrt(cp1 * cp2) * std::sin(rad(dh / 2));
  const double lm = (lab1.x + lab2.x) / 2, cm = (cp1 + cp2) / 2;
  double hm = h1 + h2;
  if (cp1 * cp2 != 0) {
    if (std::fabs(h1 - h2) <= 180) hm = (h1 + h2) / 2;
    else hm = h1 + h2 < 360 ? (h1 + h2 + 360) / 2 : (h1 + h2 - 360) / 2;
  }
  const double t = 1 - 0.17 * std::cos(rad(hm - 30)) + 0.24 * std::cos(rad(2 * hm)) +
                   0.32 * std::cos(rad(3 * hm + 6)) - 0.20 * std::cos(rad(4 * hm - 63));
  const double d_theta = 30 * std::exp(-std::pow((hm - 275) / 25, 2));
  const double cm7p = std::pow(cm, 7);
  const double rc = 2 * std::sqrt(cm7p / (cm7p + std::pow(25.0, 7)));
  const double sl = 1 + 0.015 * (lm - 50) * (lm - 50) / std::sqrt(20 + (lm - 50) * (lm - 50));
  const double sc = 1 + 0.045 * cm, sh = 1 + 0.015 * cm * t;
  const double rt = -std::sin(rad(2 * d_theta)) * rc;
  return std::sqrt(std::pow(dl / sl, 2) + std::pow(dc / sc, 2) + std::pow(dH / sh, 2) + rt * (dc / sc) * (dH / sh));
}

}  // namespace draught::test
