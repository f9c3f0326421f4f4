#include "core/pointcloud/gob.hpp"
#include "core/math/hash.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

// Neighbours reach this many spacings; the lists are rebuilt every kRebuild steps (the
// glass moves well under a tenth of a spacing in that time).
constexpr double kNeighbourReach = 1.6;
constexpr int kRebuild = 4;
// Gauss-Seidel sweeps of the mobility: many at the start (from zero), few per step
// (warm-started, the shape changes slowly).
constexpr int kFirstSweeps = 400;
constexpr int kSweepsPerStep = 2;
// The density projection's relaxation (of a full step towards the rest density) and
// its regulariser (of a typical denominator).
constexpr double kDensityRelax = 1.0;
constexpr double kDensityEps = 0.05;

void check_gob_field(double v, double lo, double hi, const char* field) {
  if (!(v >= lo && v <= hi))
    throw std::invalid_argument(std::string("gob: ") + field + " is " + std::to_string(v) +
                                ", expected " + std::to_string(lo) + " to " + std::to_string(hi));
}

glm::dvec3 rotate_x(glm::dvec3 v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
}

}  // namespace

MoltenGob::MoltenGob(const GobParams& p) : p_(p) {
  check_gob_field(p.count, 500, 100000, "count");
  check_gob_field(p.radius, 0.01, 0.2, "radius");
  if (p.blob_radius != 0) check_gob_field(p.blob_radius, 1e-4, 0.05, "blob_radius");
  check_gob_field(p.pipe_radius, 0.003, std::min(0.05, 0.9 * p.radius), "pipe_radius");
  check_gob_field(p.pipe_depth, 0, p.radius, "pipe_depth");
  check_gob_field(p.turn_rate, -20, 20, "turn_rate");
  check_gob_field(p.viscosity, 100, 1e7, "viscosity");
  check_gob_field(p.density, 2000, 3000, "density");
  check_gob_field(p.gravity, 0, 30, "gravity");
  check_gob_field(p.start_kelvin, 293, 2000, "start_kelvin");
  check_gob_field(p.ambient_kelvin, 0, 400, "ambient_kelvin");
  check_gob_field(p.diffusivity, 0, 1e-4, "diffusivity");
  check_gob_field(p.surface.emissivity, 0, 1, "surface.emissivity");
  check_gob_field(p.surface.heat_capacity, 700, 1600, "surface.heat_capacity");
  check_gob_field(p.surface.convection, 0, 100, "surface.convection");

  // A jittered cubic lattice filling the ball, less the pipe's end inside it, at the
  // spacing that gives about `count` particles.
  const glm::dvec3 centre(p.radius - p.pipe_depth, 0, 0);
  const double r = p.radius, pr = p.pipe_radius;
  const double pipe_in = M_PI * pr * pr * p.pipe_depth;
  spacing_ = std::cbrt((4.0 / 3.0 * M_PI * r * r * r - pipe_in) / p.count);
  blob_ = p.blob_radius != 0 ? p.blob_radius : 0.8 * spacing_;
  reach_ = kNeighbourReach * spacing_;
  const int n = static_cast<int>(std::ceil(r / spacing_)) + 1;
  const auto u = [](int v) { return static_cast<std::uint64_t>(v + 1024); };  // 11 bits each
  for (int k = -n; k <= n; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        // The lattice's jitter: up to 0.15 spacing per axis, from the project's hash.
        const std::uint64_t cell = u(i) | u(j) << 11 | u(k) << 22;
        auto jitter = [&](int axis) { return 0.15 * (2 * hash01(p.seed, cell, axis, 0) - 1); };
        const glm::dvec3 q = centre + spacing_ * glm::dvec3(i + jitter(0), j + jitter(1), k + jitter(2));
        if (glm::length(q - centre) > r) continue;
        const double axis = std::hypot(q.y, q.z);
        if (q.x < 0 && axis < pr) continue;  // inside the pipe
        x_.push_back(q);
        // Glass wetting the pipe's end and its outside turns with it.
        pinned_.push_back(q.x <= 0.5 * spacing_ && axis <= pr + 1.2 * spacing_);
      }
  phi_.assign(x_.size(), 0.0);
  temp_.assign(x_.size(), p.start_kelvin);
  exposure_.assign(x_.size(), 0.0);
  build_neighbours();
  measure_rest_density();
  relax_mobility(kFirstSweeps);
}

void MoltenGob::build_neighbours() {
  const std::size_t n = x_.size();
  glm::dvec3 lo(1e30), hi(-1e30);
  for (auto& q : x_) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::ivec3 dim = glm::ivec3((hi - lo) / reach_) + 1;
  auto cell_of = [&](const glm::dvec3& q) {
    const glm::ivec3 c = glm::clamp(glm::ivec3((q - lo) / reach_), glm::ivec3(0), dim - 1);
    return (c.z * dim.y + c.y) * dim.x + c.x;
  };
  // Counting sort of the particles into cells.
  std::vector<int> cell_start(static_cast<std::size_t>(dim.x) * dim.y * dim.z + 1, 0), order(n);
  for (auto& q : x_) ++cell_start[cell_of(q) + 1];
  for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
  std::vector<int> fill(cell_start.begin(), cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order[fill[cell_of(x_[i])]++] = static_cast<int>(i);

  start_.assign(n + 1, 0);
  nbr_.clear();
  w_.clear();
  mean_r2_.assign(n, 0.0);
  weight_sum_.assign(n, 0.0);
  const double reach2 = reach_ * reach_;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::ivec3 c = glm::clamp(glm::ivec3((x_[i] - lo) / reach_), glm::ivec3(0), dim - 1);
    double ws = 0, wr2 = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const glm::ivec3 d = c + glm::ivec3(dx, dy, dz);
          if (glm::any(glm::lessThan(d, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(d, dim))) continue;
          const int cell = (d.z * dim.y + d.y) * dim.x + d.x;
          for (int k = cell_start[cell]; k < cell_start[cell + 1]; ++k) {
            const int j = order[k];
            if (j == static_cast<int>(i)) continue;
            const glm::dvec3 e = x_[j] - x_[i];
            const double r2 = glm::dot(e, e);
            if (r2 >= reach2) continue;
            const double w = 1.0 - std::sqrt(r2) / reach_;
            nbr_.push_back(j);
            w_.push_back(static_cast<float>(w));
            ws += w;
            wr2 += w * r2;
          }
        }
    start_[i + 1] = static_cast<int>(nbr_.size());
    weight_sum_[i] = ws;
    mean_r2_[i] = ws > 0 ? wr2 / ws : spacing_ * spacing_;
  }
  // The weight of a full neighbourhood: the 75th percentile over all particles (more
  // than half of them are inside), taken afresh as the packing drifts.
  std::vector<double> sorted = weight_sum_;
  std::nth_element(sorted.begin(), sorted.begin() + 3 * n / 4, sorted.end());
  interior_weight_ = sorted[3 * n / 4];
  // 0.85 of a full neighbourhood or more: inside; half of one: a flat face.
  for (std::size_t i = 0; i < n; ++i)
    exposure_[i] = std::clamp((0.85 - weight_sum_[i] / interior_weight_) / 0.35, 0.0, 1.0);
}

void MoltenGob::relax_mobility(int sweeps) {
  // Discretely nu laplace(phi) = -1 with laplace(phi)_i ~ 6 (mean_j phi_j - phi_i) / <r^2>_i
  // (the weighted mean over neighbours), so phi_i = mean_j phi_j + <r^2>_i / (6 nu).
  const double nu = p_.viscosity / p_.density;  // kinematic, m^2/s
  for (int s = 0; s < sweeps; ++s)
    for (std::size_t i = 0; i < x_.size(); ++i) {
      if (pinned_[i]) continue;
      double sum = 0;
      for (int k = start_[i]; k < start_[i + 1]; ++k) sum += w_[k] * phi_[nbr_[k]];
      const double mean = weight_sum_[i] > 0 ? sum / weight_sum_[i] : 0.0;
      phi_[i] = mean + mean_r2_[i] / (6.0 * nu);
    }
}

void MoltenGob::measure_rest_density() {
  // The rest density and a typical denominator: 75th percentiles over all particles
  // (more than half of them are inside) of the starting lattice.
  const std::size_t n = x_.size();
  const double h2 = reach_ * reach_;
  std::vector<double> rho(n), denom(n);
  for (std::size_t i = 0; i < n; ++i) {
    double r = 1.0, sum2 = 0;
    glm::dvec3 gi(0.0);
    for (int k = start_[i]; k < start_[i + 1]; ++k) {
      const glm::dvec3 e = x_[i] - x_[nbr_[k]];
      const double q = 1.0 - glm::dot(e, e) / h2;
      if (q <= 0) continue;
      r += q * q * q;
      const glm::dvec3 gj = (6.0 * q * q / h2) * e;
      gi -= gj;
      sum2 += glm::dot(gj, gj);
    }
    rho[i] = r;
    denom[i] = sum2 + glm::dot(gi, gi);
  }
  std::nth_element(rho.begin(), rho.begin() + 3 * n / 4, rho.end());
  std::nth_element(denom.begin(), denom.begin() + 3 * n / 4, denom.end());
  rest_density_ = rho[3 * n / 4];
  rest_eps_ = kDensityEps * denom[3 * n / 4] / (rest_density_ * rest_density_);
}

double MoltenGob::angle() const { return p_.turn_rate * time(); }

glm::dvec3 MoltenGob::position(std::size_t i) const { return rotate_x(x_[i], angle()); }

glm::dvec3 MoltenGob::centre_of_mass() const {
  glm::dvec3 s(0.0);
  for (std::size_t i = 0; i < x_.size(); ++i) s += position(i);
  return s / static_cast<double>(x_.size());
}

void MoltenGob::keep_density() {
  // One position-based projection (Macklin and Mueller, "Position Based Fluids", 2013)
  // towards the rest density: it stands in for the pressure the creeping flow lacks
  // (that flow is not divergence-free: without it the glass would pack or thin).
  // Exposed particles only push (their missing neighbours are not a deficit), so the
  // surface is not drawn in.
  const std::size_t n = x_.size();
  const double h2 = reach_ * reach_;
  lambda_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double rho = 1.0, sum2 = 0;
    glm::dvec3 gi(0.0);
    for (int k = start_[i]; k < start_[i + 1]; ++k) {
      const glm::dvec3 e = x_[i] - x_[nbr_[k]];
      const double q = 1.0 - glm::dot(e, e) / h2;
      if (q <= 0) continue;
      rho += q * q * q;
      const glm::dvec3 gj = (6.0 * q * q / (h2 * rest_density_)) * e;  // d C_i / d x_j
      gi -= gj;
      sum2 += glm::dot(gj, gj);
    }
    double c = rho / rest_density_ - 1.0;
    if (exposure_[i] > 0) c = std::max(c, 0.0);
    const double denom = sum2 + glm::dot(gi, gi);
    lambda_[i] = -c / (denom + rest_eps_);
  }
  dx_.assign(n, glm::dvec3(0.0));
  for (std::size_t i = 0; i < n; ++i) {
    if (pinned_[i]) continue;
    glm::dvec3 d(0.0);
    for (int k = start_[i]; k < start_[i + 1]; ++k) {
      const int j = nbr_[k];
      const glm::dvec3 e = x_[i] - x_[j];
      const double q = 1.0 - glm::dot(e, e) / h2;
      if (q <= 0) continue;
      d -= (lambda_[i] + lambda_[j]) * (6.0 * q * q / h2) * e;
    }
    dx_[i] = d * (kDensityRelax / rest_density_);
  }
  for (std::size_t i = 0; i < n; ++i) x_[i] += dx_[i];
}

void MoltenGob::step() {
  if (steps_ % kRebuild == 0 && steps_ > 0) build_neighbours();
  relax_mobility(kSweepsPerStep);
  // Gravity in the pipe's frame: the world's (0, -g, 0) turned back by the pipe's angle.
  const double a = angle() + 0.5 * p_.turn_rate * kStep;  // mid-step
  const glm::dvec3 g = rotate_x(glm::dvec3(0, -p_.gravity, 0), -a);
  for (std::size_t i = 0; i < x_.size(); ++i) x_[i] += kStep * phi_[i] * g;
  keep_density();
  // Heat: lost at the surface by radiation and convection (a surface particle holds a
  // layer one spacing thick), spread by conduction.
  GlassCooling layer = p_.surface;
  layer.thickness = spacing_;
  layer.density = p_.density;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    double t = temp_[i];
    if (weight_sum_[i] > 0 && p_.diffusivity > 0) {
      double sum = 0;
      for (int k = start_[i]; k < start_[i + 1]; ++k) sum += w_[k] * temp_[nbr_[k]];
      const double c = std::min(1.0, kStep * p_.diffusivity * 6.0 / mean_r2_[i]);
      t += c * (sum / weight_sum_[i] - t);
    }
    if (exposure_[i] > 0) t += kStep * exposure_[i] * glass_cooling_rate(layer, t, p_.ambient_kelvin);
    temp_[i] = t;
  }
  ++steps_;
}

void MoltenGob::advance(double seconds) {
  if (!(seconds > 0)) return;
  pending_ += seconds;
  while (pending_ >= kStep * (1 - 1e-9)) {
    step();
    pending_ -= kStep;
  }
}

PointCloud MoltenGob::cloud() const {
  PointCloud c;
  c.default_radius = static_cast<float>(blob_);
  c.position.reserve(x_.size());
  c.temperature.reserve(x_.size());
  c.velocity.reserve(x_.size());
  const double a = angle();
  const glm::dvec3 g = rotate_x(glm::dvec3(0, -p_.gravity, 0), -a);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const glm::dvec3 q = rotate_x(x_[i], a);
    c.position.emplace_back(q);
    c.temperature.push_back(static_cast<float>(temp_[i]));
    // The turn (omega x q about +x) and the creeping flow turned into the gob's frame.
    const glm::dvec3 v = glm::dvec3(0, -p_.turn_rate * q.z, p_.turn_rate * q.y) + rotate_x(phi_[i] * g, a);
    c.velocity.emplace_back(v);
  }
  return c;
}

}  // namespace draught
