// The built-in molten-glass gob: a gather of glass on the end of a horizontal blowpipe,
// turning with the pipe and sagging under gravity, glowing as it cools. A creeping-flow
// particle model (glass at working heat flows with a Reynolds number near 1e-4, so
// inertia is dropped): in the pipe's turning frame each particle moves with the
// velocity u = g_pipe(t) phi, where the mobility phi solves the viscous balance
// nu laplace(u) + g = 0 on the particles (a neighbour-weighted Laplacian, Gauss-Seidel
// warm-started from the last step), zero on the particles that wet the pipe. Turning
// only turns gravity in that frame, so the sag's direction goes round and the centre of
// mass stays near the axis, as a glassblower keeps a gob centred. A position-based
// density projection keeps the particles' spacing (and so, roughly, the glass's volume).
// Temperatures fall by radiation and convection at the surface (particles with fewer
// neighbours) and spread by conduction inside.
// Frame: the pipe's end at the origin, the pipe along -x (the gob hangs around +x),
// y up, metres. The pipe is not in the cloud (the renderer may draw it as a cylinder of
// pipe_radius along -x). Fixed steps, deterministic: no global RNG, one thread.
#pragma once

#include "core/pointcloud/cloud.hpp"
#include "core/pointcloud/glass_heat.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace draught {

struct GobParams {
  int count = 8000;              // particles, about (a lattice fills the gob), [500, 100000]
  double radius = 0.04;          // m, the gob's radius at the start, [0.01, 0.2]
  double blob_radius = 0;        // m, a particle's blob radius; 0 = 0.8 x the spacing; else [1e-4, 0.05]
  double pipe_radius = 0.012;    // m, the blowpipe's outer radius, [0.003, 0.05], < radius
  double pipe_depth = 0.02;      // m, how far the pipe's end reaches into the gob, [0, radius]
  double turn_rate = 2.0;        // rad/s about +x (the pipe's axis), [-20, 20]
  double viscosity = 6000;       // Pa s, [100, 1e7] (soda-lime glass near 1000-1100 C: 1e3-1e4)
  double density = 2500;         // kg/m^3, [2000, 3000]
  double gravity = 9.81;         // m/s^2, [0, 30]
  double start_kelvin = 1373.15; // K, [293, 2000]: 1100 C, a gob fresh from the furnace
  double ambient_kelvin = 293.15;// K, [0, 400]: the surroundings it radiates to
  double diffusivity = 1e-6;     // m^2/s, [0, 1e-4]: heat spreading inside (conduction and
                                 // radiation within hot glass)
  GlassCooling surface{};        // emissivity, heat capacity, convection of the surface
                                 // (its thickness is unused: a surface particle's layer is
                                 // one spacing thick)
  std::uint32_t seed = 1;        // the lattice's jitter (core/math/hash.hpp)
};

class MoltenGob {
 public:
  // Throws std::invalid_argument naming the field and its range for a parameter out of it.
  explicit MoltenGob(const GobParams& = {});
  // Steps of kStep up to time() + seconds (a remainder is carried to the next call).
  void advance(double seconds);
  // The particles in the gob's frame (positions, temperatures, velocities; every blob
  // radius default_radius).
  PointCloud cloud() const;
  double time() const { return steps_ * kStep; }

  std::size_t size() const { return x_.size(); }
  double spacing() const { return spacing_; }
  double blob_radius() const { return blob_; }
  // The pipe's turn so far, radians about +x.
  double angle() const;
  // Particle i in the gob's frame, m.
  glm::dvec3 position(std::size_t i) const;
  bool pinned(std::size_t i) const { return pinned_[i] != 0; }
  double temperature(std::size_t i) const { return temp_[i]; }
  // How exposed particle i is: 0 inside, 1 on a flat surface (from its neighbours).
  double exposure(std::size_t i) const { return exposure_[i]; }
  glm::dvec3 centre_of_mass() const;

  static constexpr double kStep = 1.0 / 60.0;

 private:
  void build_neighbours();
  void relax_mobility(int sweeps);
  void measure_rest_density();
  void keep_density();
  void step();

  GobParams p_;
  double spacing_ = 0, blob_ = 0, reach_ = 0, interior_weight_ = 0;
  std::vector<glm::dvec3> x_;      // the turning (pipe's) frame
  std::vector<double> phi_, temp_, exposure_;
  std::vector<std::uint8_t> pinned_;
  // Neighbour lists (CSR) with weights and squared distances, rebuilt every few steps.
  std::vector<int> start_, nbr_;
  std::vector<float> w_;
  std::vector<double> mean_r2_, weight_sum_;
  double rest_density_ = 1, rest_eps_ = 0;
  std::vector<double> lambda_;
  std::vector<glm::dvec3> dx_;
  long steps_ = 0;
  double pending_ = 0;
};

}  // namespace draught
