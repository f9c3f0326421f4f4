#include "core/vessel/decal.hpp"

#include "core/io/files.hpp"
#include "core/vessel/decal_files.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

static_assert(int(DecalKind::Enamel) == int(contract::DecalKind::Enamel));
static_assert(int(DecalKind::Etched) == int(contract::DecalKind::Etched));
static_assert(int(DecalKind::Metallic) == int(contract::DecalKind::Metallic));

namespace {

// Knot k's fractional segment position for height y: segment k, fraction f (as
// Vessel::outer_radius interpolates).
void segment_of(const Vessel& v, double y, int& k, double& f) {
  const double s = std::clamp(y / v.dy, 0.0, double(Vessel::kSegments));
  k = std::min(int(s), Vessel::kSegments - 1);
  f = s - k;
}
}  // namespace

double WallArcLengths::at(const Vessel& v, bool inner_wall, double y) const {
  const std::vector<double>& s = inner_wall ? inner : outer;
  int k;
  double f;
  segment_of(v, y, k, f);
  return s[size_t(k)] * (1 - f) + s[size_t(k) + 1] * f;
}

WallArcLengths wall_arc_lengths(const Vessel& v) {
  WallArcLengths a;
  for (bool inner_wall : {false, true}) {
    const std::vector<double>& r = inner_wall ? v.r_inner : v.r_outer;
    std::vector<double>& s = inner_wall ? a.inner : a.outer;
    s.assign(r.size(), 0.0);
    for (size_t k = 1; k < r.size(); ++k) s[k] = s[k - 1] + std::hypot(v.dy, r[k] - r[k - 1]);
  }
  return a;
}

DecalPlacement place_decal(const Vessel& v, const WallArcLengths& arcs, const DecalParams& p, bool inner_wall,
                           int image_w, int image_h) {
  DecalPlacement d;
  if (p.file.empty() || image_w < 1 || image_h < 1) return d;
  d.present = true;
  d.inner = inner_wall;
  d.angle = glm::radians(double(p.angle));
  d.centre_s = arcs.at(v, inner_wall, p.height);
  d.repeat = std::max(1, p.repeat);
  d.width = std::max(0.0, double(p.width));
  // Its height along the profile keeps the image's aspect at the centre; a band's width
  // there is its share of the turn.
  const double r_centre = inner_wall ? v.inner_radius(p.height) : v.outer_radius(p.height);
  const double width_at_centre = d.width > 0 ? d.width : 2 * kPi * r_centre / d.repeat;
  d.extent = std::max(width_at_centre * double(image_h) / double(image_w), 1e-6);
  d.span = std::max({width_at_centre, d.extent, 1e-6});
  d.kind = DecalKind(std::clamp(p.kind, 0, 2));
  d.color = glm::dvec3(p.color);
  d.opacity = p.opacity;
  d.roughness = p.roughness;
  return d;
}

std::optional<glm::dvec2> decal_uv(const Vessel& v, const WallArcLengths& arcs, const DecalPlacement& d,
                                   const glm::dvec3& p) {
  if (!d.present) return std::nullopt;
  // Across: the angle from the nearest copy's centre, in (-period/2, period/2].
  const double period = 2 * kPi / d.repeat;
  double a = std::atan2(p.x, p.z) - d.angle;
  a -= period * std::floor(a / period + 0.5);
  const double r = d.inner ? v.inner_radius(p.y) : v.outer_radius(p.y);
  const double u = d.width > 0 ? 0.5 + r * a / d.width : 0.5 + a / period;
  // Down: the arc length along the profile from the centre.
  const double vv = 0.5 - (arcs.at(v, d.inner, p.y) - d.centre_s) / d.extent;
  if (u < 0 || u > 1 || vv < 0 || vv > 1) return std::nullopt;
  return glm::dvec2(u, vv);
}

namespace {
// Texel (x, y) premultiplied, in linear light.
glm::dvec4 premultiplied(const Image& img, int x, int y) {
  const std::uint8_t* p = img.px(x, y);
  const double a = p[3] / 255.0;
  return {srgb8_to_linear(p[0]) * a, srgb8_to_linear(p[1]) * a, srgb8_to_linear(p[2]) * a, a};
}
}  // namespace

glm::dvec4 sample_decal_image(const Image& img, glm::dvec2 uv) {
  // Texel centres at (i + 0.5) / size, as GL's; u wraps (a band joins), v is clamped.
  const double x = uv.x * img.width - 0.5, y = std::clamp(uv.y * img.height - 0.5, 0.0, img.height - 1.0);
  const double fx = std::floor(x), fy = std::floor(y);
  const int x0 = int(fx), y0 = int(fy), y1 = std::min(y0 + 1, img.height - 1);
  auto wrap = [&](int i) { return ((i % img.width) + img.width) % img.width; };
  const double tx = x - fx, ty = y - fy;
  const glm::dvec4 top = glm::mix(premultiplied(img, wrap(x0), y0), premultiplied(img, wrap(x0 + 1), y0), tx);
  const glm::dvec4 bottom = glm::mix(premultiplied(img, wrap(x0), y1), premultiplied(img, wrap(x0 + 1), y1), tx);
  return glm::mix(top, bottom, ty);
}

DecalSample VesselDecals::sample(const Vessel& v, bool inner_wall, const glm::dvec3& local) const {
  const int layer = inner_wall ? 1 : 0;
  const DecalPlacement& d = layers[size_t(layer)];
  if (!d.present || !images[size_t(layer)] || d.inner != inner_wall) return {};
  const std::optional<glm::dvec2> uv = decal_uv(v, arcs, d, local);
  if (!uv) return {};
  const glm::dvec4 texel = sample_decal_image(*images[size_t(layer)], *uv);
  DecalSample s;
  s.cover = texel.a * d.opacity;
  s.tint = texel.a > 1e-6 ? glm::dvec3(texel) / texel.a * d.color : glm::dvec3(0.0);
  s.kind = d.kind;
  s.roughness = d.roughness;
  return s;
}

bool has_decals(const VesselParams& p) { return !p.decal_outer.file.empty() || !p.decal_inner.file.empty(); }

std::shared_ptr<const VesselDecals> vessel_decals(const Vessel& v, const VesselParams& p) {
  if (!has_decals(p)) return nullptr;
  auto out = std::make_shared<VesselDecals>();
  out->arcs = wall_arc_lengths(v);
  for (int layer = 0; layer < kMaxDecalLayers; ++layer) {
    const DecalParams& dp = layer == 0 ? p.decal_outer : p.decal_inner;
    if (dp.file.empty()) continue;
    try {
      out->images[size_t(layer)] = load_decal(dp.file);
    } catch (const InputError&) {
      continue;  // checked when it was set; a file gone since is left out, as the renderer does
    }
    const Image& img = *out->images[size_t(layer)];
    out->layers[size_t(layer)] = place_decal(v, out->arcs, dp, layer == 1, img.width, img.height);
  }
  if (!out->any()) return nullptr;
  return out;
}

std::vector<std::uint8_t> decal_layer_texels(const Image& img, int size) {
  // Separable: rows to `size` columns, then columns to `size` rows, in linear light,
  // premultiplied. Shrinking, each output texel is the mean of the source over its
  // footprint (a box); enlarging, the source's bilinear value at its centre (a tent).
  auto weights = [](int from, int to, int i, int& first, std::vector<double>& w) {
    const double scale = double(from) / to;         // source texels per output texel
    const double centre = (i + 0.5) * scale - 0.5;  // in source texel-centre units
    w.clear();
    if (scale >= 1) {
      const double lo = centre - 0.5 * scale, hi = centre + 0.5 * scale;
      first = int(std::floor(lo + 0.5));
      for (int k = first; k - 0.5 < hi; ++k) w.push_back(std::max(0.0, std::min(hi, k + 0.5) - std::max(lo, k - 0.5)));
    } else {
      first = int(std::floor(centre));
      const double f = centre - first;
      w = {1 - f, f};
    }
    double sum = 0;
    for (double x : w) sum += x;
    for (double& x : w) x /= sum > 0 ? sum : 1;
  };
  const int w = img.width, h = img.height;
  std::vector<glm::dvec4> rows(size_t(size) * size_t(h));
  std::vector<double> wt;
  for (int x = 0; x < size; ++x) {
    int first;
    weights(w, size, x, first, wt);
    for (int y = 0; y < h; ++y) {
      glm::dvec4 sum(0.0);
      for (size_t k = 0; k < wt.size(); ++k) {
        const int sx = ((first + int(k)) % w + w) % w;  // u wraps
        sum += wt[k] * premultiplied(img, sx, y);
      }
      rows[size_t(y) * size_t(size) + size_t(x)] = sum;
    }
  }
  std::vector<std::uint8_t> out(size_t(size) * size_t(size) * 4);
  for (int y = 0; y < size; ++y) {
    int first;
    weights(h, size, y, first, wt);
    for (int x = 0; x < size; ++x) {
      glm::dvec4 sum(0.0);
      for (size_t k = 0; k < wt.size(); ++k) {
        const int sy = std::clamp(first + int(k), 0, h - 1);  // v is clamped
        sum += wt[k] * rows[size_t(sy) * size_t(size) + size_t(x)];
      }
      std::uint8_t* o = &out[(size_t(y) * size_t(size) + size_t(x)) * 4];
      for (int c = 0; c < 3; ++c) o[c] = linear_to_srgb8(sum[c]);
      o[3] = std::uint8_t(std::lround(std::clamp(sum.a, 0.0, 1.0) * 255.0));
    }
  }
  return out;
}

}  // namespace draught
