#include "core/liquid/beverage.hpp"

#include "core/math/srgb.hpp"
#include "core/math/cie1931.hpp"

#include <algorithm>
#include <cstdio>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>
#include <numbers>

namespace draught {

namespace {

constexpr double kFirstNm = 380.0, kStepNm = 10.0;
// CIE illuminant D65, relative spectral power, 380-730 nm in 10 nm steps (CIE 15:2004).
constexpr std::array<double, 36> kD65 = {
    49.9755, 54.6482, 82.7549, 91.486,  93.4318, 86.6823, 104.865, 117.008, 117.812,
    114.861, 115.923, 108.811, 109.354, 107.802, 104.790, 107.689, 104.405, 104.046,
    100.000, 96.3342, 95.788,  88.6856, 90.0062, 89.5991, 87.6987, 83.2886, 83.6992,
    80.0268, 80.2146, 82.2778, 78.2842, 69.7213, 71.6091, 74.349,  61.604,  69.8856};

// XYZ -> linear sRGB (IEC 61966-2-1).
glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& c) {
  return {3.2406 * c.x - 1.5372 * c.y - 0.4986 * c.z, -0.9689 * c.x + 1.8758 * c.y + 0.0415 * c.z,
          0.0557 * c.x - 0.2040 * c.y + 1.0570 * c.z};
}

// The weight of each wavelength in each channel: D65 times the positive part of the sRGB
// colour matching functions (the negative lobes would let a filter drive a channel
// below zero; without them a channel's transmittance is a weighted mean of T(l)).
glm::dvec3 channel_weight(std::size_t i) {
  const double nm = kFirstNm + kStepNm * double(i);
  return kD65[i] * glm::max(xyz_to_linear_srgb(cie1931_cmf(nm)), glm::dvec3(0.0));
}

}  // namespace

glm::dvec3 channel_transmittance(const std::function<double(double)>& absorbance_per_cm, double metres) {
  glm::dvec3 through{0.0}, white{0.0};
  for (std::size_t i = 0; i < kD65.size(); ++i) {
    const double nm = kFirstNm + kStepNm * double(i);
    const glm::dvec3 w = channel_weight(i);
    through += w * std::pow(10.0, -absorbance_per_cm(nm) * metres * 100.0);
    white += w;
  }
  return glm::clamp(through / white, glm::dvec3(kMinChannelTransmittance), glm::dvec3(1.0));
}

double absorbance_per_cm_to_absorption(double a) { return a * std::numbers::ln10 * 100.0; }

glm::vec3 spectrum_to_absorption(const std::function<double(double)>& absorbance_per_cm, double metres) {
  return glm::vec3(-glm::log(channel_transmittance(absorbance_per_cm, metres)) / metres);
}

double ebc_to_srm(double ebc) { return ebc / kEbcPerSrm; }

double beer_absorbance(double srm, double nm) {
  const double x = nm - 430.0;
  return srm / kSrmPerA430 * (0.02465 * std::exp(-x / 17.591) + 0.97535 * std::exp(-x / 82.122));
}

glm::vec3 srm_to_absorption(float srm, double metres) {
  if (srm <= 0.0f) return glm::vec3(0.0f);
  return spectrum_to_absorption([srm](double nm) { return beer_absorbance(srm, nm); }, metres);
}

double wine_absorbance(const glm::vec3& a, double nm) {
  if (nm <= 420.0) return a[0];
  if (nm <= 520.0) return a[0] + (a[1] - a[0]) * (nm - 420.0) / 100.0;
  if (nm <= 620.0) return a[1] + (a[2] - a[1]) * (nm - 520.0) / 100.0;
  if (a[2] <= 0.0f || a[1] <= a[2]) return a[2];
  // The anthocyanin band's Gaussian fall from 520 nm, its width set by A620 / A520:
  // A(l) = A520 exp(-(l - 520)^2 / (2 s^2)), which meets A620 at 620 nm.
  const double two_s2 = 100.0 * 100.0 / std::log(double(a[1]) / a[2]), x = nm - 520.0;
  return a[1] * std::exp(-x * x / two_s2);
}

glm::vec3 wine_to_absorption(const glm::vec3& a420_520_620, double metres) {
  if (a420_520_620 == glm::vec3(0.0f)) return glm::vec3(0.0f);
  return spectrum_to_absorption([a420_520_620](double nm) { return wine_absorbance(a420_520_620, nm); }, metres);
}

glm::dvec3 DrinkAbsorption::transmittance(double metres) const {
  glm::dvec3 left(share);
  return onward(left, metres);
}

glm::dvec3 DrinkAbsorption::onward(glm::dvec3& left, double metres) const {
  const glm::dvec3 ef = glm::exp(-glm::dvec3(fast) * metres), es = glm::exp(-glm::dvec3(slow) * metres);
  const glm::dvec3 t = left * ef + (1.0 - left) * es;
  left = left * ef / glm::max(t, glm::dvec3(1e-300));  // what is left, shared anew (no underflow to 0 / 0)
  return t;
}

glm::vec3 DrinkAbsorption::effective(double metres) const {
  return glm::vec3(-glm::log(glm::max(transmittance(metres), glm::dvec3(kMinChannelTransmittance))) / metres);
}

namespace {

// The lengths the bands are fitted over: 1 mm to 16 cm in steps of sqrt(2) (a thin
// edge to a wide bowl's middle), each length one sample of the error.
constexpr int kFitLengths = 15;
double fit_length(int j) { return 0.001 * std::pow(2.0, 0.5 * j); }

struct Band {
  double share, rate;
};

// The minimum of f over [a, b] by golden sections, one evaluation a step (f unimodal there).
template <class F>
double golden_min(const F& f, double a, double b, int steps) {
  const double r = (std::sqrt(5.0) - 1) / 2;
  double x1 = b - r * (b - a), x2 = a + r * (b - a), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < steps; ++i) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - r * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + r * (b - a), f2 = f(x2);
    }
  }
  return 0.5 * (a + b);
}

// The one rate that best gives a group's transmittance (share x its mean of e^(-k L))
// over the fitted lengths: a golden-section search on log(rate) within the group's rates.
Band fit_group(const std::array<double, kFitLengths>& target, double share, double lo, double hi) {
  if (share <= 0) return {0.0, lo};
  const auto error = [&](double log_rate) {
    double e = 0;
    for (int j = 0; j < kFitLengths; ++j) {
      const double d = share * std::exp(-std::exp(log_rate) * fit_length(j)) - target[size_t(j)];
      e += d * d;
    }
    return e;
  };
  return {share, std::exp(golden_min(error, std::log(std::max(lo, 1e-6)), std::log(std::max(hi, 1e-6)), 32))};
}

}  // namespace

DrinkAbsorption spectrum_to_bands(const std::function<double(double)>& absorbance_per_cm) {
  DrinkAbsorption out;
  for (int c = 0; c < 3; ++c) {
    // The channel's wavelengths: weight (D65 x its colour matching function, summing to
    // one) and rate (natural absorption per metre), sorted fastest first.
    std::vector<std::pair<double, double>> lines;  // rate, weight
    double total = 0;
    for (std::size_t i = 0; i < kD65.size(); ++i) {
      const double w = channel_weight(i)[c];
      if (w <= 0) continue;
      lines.emplace_back(absorbance_per_cm_to_absorption(absorbance_per_cm(kFirstNm + kStepNm * double(i))), w);
      total += w;
    }
    std::sort(lines.begin(), lines.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    for (auto& l : lines) l.second /= total;
    const auto group = [&](std::size_t from, std::size_t to, std::array<double, kFitLengths>& t) {
      double share = 0;
      t.fill(0.0);
      for (std::size_t i = from; i < to; ++i) {
        share += lines[i].second;
        for (int j = 0; j < kFitLengths; ++j) t[size_t(j)] += lines[i].second * std::exp(-lines[i].first * fit_length(j));
      }
      return share;
    };
    std::array<double, kFitLengths> whole{};
    group(0, lines.size(), whole);
    double best = std::numeric_limits<double>::infinity();
    std::array<double, 3> fit{};  // log fast, log slow, fast's share
    // Split after i: the first i wavelengths (the fastest) one band, the rest the other;
    // i = 0 is a single band.
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::array<double, kFitLengths> tf{}, ts{};
      const double wf = group(0, i, tf), ws = group(i, lines.size(), ts);
      if (i > 0 && ws < 1e-3) break;  // the slow band keeps a share
      const Band f = i == 0 ? Band{0.0, 0.0} : fit_group(tf, wf, lines[i - 1].first, lines[0].first);
      const Band s = fit_group(ts, ws, lines.back().first, lines[i].first);
      double e = 0;
      for (int j = 0; j < kFitLengths; ++j) {
        const double L = fit_length(j);
        // (the error in sRGB codes: as the eye weighs it)
        const double two_bands = f.share * std::exp(-f.rate * L) + s.share * std::exp(-s.rate * L);
        const double d = linear_to_srgb(two_bands) - linear_to_srgb(whole[size_t(j)]);
        e += d * d;
      }
      if (e >= best) continue;
      best = e;
      fit = i == 0 ? std::array<double, 3>{std::log(std::max(s.rate, 1e-6)), std::log(std::max(s.rate, 1e-6)), 0.5}
                   : std::array<double, 3>{std::log(std::max(f.rate, 1e-6)), std::log(std::max(s.rate, 1e-6)),
                                           f.share / (f.share + s.share)};
    }
    // The best split's bands refined together in the same error: each of the two log
    // rates and the share in turn, by golden sections about where it is.
    const auto error = [&](const std::array<double, 3>& x) {
      double e = 0;
      for (int j = 0; j < kFitLengths; ++j) {
        const double L = fit_length(j);
        const double t = x[2] * std::exp(-std::exp(x[0]) * L) + (1 - x[2]) * std::exp(-std::exp(x[1]) * L);
        const double d = linear_to_srgb(t) - linear_to_srgb(whole[size_t(j)]);
        e += d * d;
      }
      return e;
    };
    for (int round = 0; round < 6; ++round)
      for (std::size_t k = 0; k < 3; ++k) {
        std::array<double, 3> x = fit;
        const auto at = [&](double v) {
          x[k] = v;
          return error(x);
        };
        x[k] = golden_min(at, k < 2 ? fit[k] - 1.0 : 0.0, k < 2 ? fit[k] + 1.0 : 0.999, 32);
        if (error(x) < error(fit)) fit = x;
      }
    double fast = std::exp(fit[0]), slow = std::exp(fit[1]), share = fit[2];
    if (fast < slow) {
      std::swap(fast, slow);
      share = 1 - share;
    }
    out.fast[c] = float(fast);
    out.slow[c] = float(slow);
    out.share[c] = float(std::clamp(share, 0.0, 0.999));
  }
  return out;
}

std::function<double(double)> drink_spectrum(const LiquidParams& l) {
  // (EBC through a float SRM, as srm_to_absorption takes it: the same colour either way.)
  if (l.ebc > 0) return [srm = double(float(ebc_to_srm(l.ebc)))](double nm) { return beer_absorbance(srm, nm); };
  if (l.srm > 0) return [srm = double(l.srm)](double nm) { return beer_absorbance(srm, nm); };
  if (l.wine.x > 0 || l.wine.y > 0 || l.wine.z > 0) return [w = l.wine](double nm) { return wine_absorbance(w, nm); };
  return {};
}

DrinkAbsorption drink_absorption(const LiquidParams& l) {
  const auto spectrum = drink_spectrum(l);
  return spectrum ? spectrum_to_bands(spectrum) : DrinkAbsorption::uniform(l.absorption);
}

glm::vec3 liquid_absorption(const LiquidParams& l, double metres) {
  const auto spectrum = drink_spectrum(l);
  return spectrum ? spectrum_to_absorption(spectrum, metres) : l.absorption;
}

std::string drink_colour_note(const LiquidParams& l, std::string_view field) {
  const bool wine = l.wine.x > 0 || l.wine.y > 0 || l.wine.z > 0;
  const std::string_view used = l.ebc > 0 ? "ebc" : l.srm > 0 ? "srm" : wine ? "wine" : "absorption";
  if (field == used || std::find(std::begin(kDrinkColourFields), std::end(kDrinkColourFields), field) ==
                           std::end(kDrinkColourFields))
    return "";
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return std::string(text);
  };
  if (field == "ebc" && used == "srm") return "in effect: " + number(kEbcPerSrm * l.srm) + " (from SRM)";
  if (field == "srm" && used == "ebc") return "in effect: " + number(ebc_to_srm(l.ebc)) + " (from EBC)";
  const char* name = used == "ebc" ? "EBC" : used == "srm" ? "SRM" : used == "wine" ? "the wine colour" : "the absorption";
  return std::string("unused: ") + name + " in effect";
}

}  // namespace draught
