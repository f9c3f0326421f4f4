// Minor bubbles: small CO2 bubbles that nucleate on the inner wall and the cavity floor
// (and on an etched ring in the base), grow as they rise, rise faster as they grow,
// wobble a little and pop at the surface. Simulated in the glass frame, deterministic for
// a seed and a sequence of steps. The renderer draws them; pops can feed the foam.
#pragma once

#include "core/reference/intersect.hpp"
#include "core/vessel/vessel.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace draught {

// A plain struct so it does not depend on the parameter set (the caller maps onto it).
struct BubbleSettings {
  float carbonation = 0;    // 0 still .. 1 champagne (volumes of CO2, scaled); rate and size
  int sites = 0;            // nucleation sites on the wall and floor
  bool etched_base = false; // a ring of fast sites etched into the floor's centre (flute style)
  float size = 2e-4f;       // radius at birth, metres, at full carbonation
  int max_bubbles = 500;    // alive at once
  int seed = 0;
};

struct Bubble {
  glm::vec3 p{0.0f};  // centre, glass frame
  float radius = 0;   // metres
  float age = 0;      // seconds since birth
};

struct BubbleSite {
  glm::dvec3 p{0.0};           // glass frame, a hair off the glass
  double rate = 0;             // bubbles per second at this carbonation
  bool etched = false;
  std::uint64_t emitted = 0;   // emission index (counts skipped emissions too)
  double pending = 0;          // emission accumulator, in bubbles
};

class BubbleField {
 public:
  static constexpr int kEtchedSites = 12;
  static constexpr double kMaxStep = 0.1;  // seconds: a longer step is simulated as this

  BubbleField(const BubbleSettings&, const Vessel&);

  // Advance by dt. `surface` bounds the liquid (glass frame); `up_local` is world up in the
  // glass frame, the way bubbles rise (not normalised; garbage keeps the previous one).
  void step(double dt, const LiquidPlane& surface, const glm::dvec3& up_local);
  void clear();  // the liquid was poured fresh: no bubbles, accumulators reset

  const std::vector<Bubble>& bubbles() const { return bubbles_; }
  const std::vector<glm::vec3>& pops() const { return pops_; }  // on the surface; this step only
  const std::vector<BubbleSite>& sites() const { return sites_; }
  const BubbleSettings& settings() const { return settings_; }

 private:
  struct Track {
    glm::dvec3 path{0.0};  // centre without the wobble
    double r0 = 0, risen = 0, age = 0, phase = 0, freq = 0;
  };
  double radius(const Track&) const;
  // Moves a bubble by dt; false when it left the liquid (pop recorded when at the surface).
  bool advance(Track&, Bubble&, double dt, const LiquidPlane&);
  // Keeps a sphere inside the cavity: above the floor, clear of the wall; false if it cannot fit.
  bool confine(glm::dvec3& p, double r) const;

  BubbleSettings settings_;
  Vessel vessel_;  // a copy: the field outlives a rebuilt glass until it is replaced
  bool valid_ = false;
  glm::dvec3 e1_{1, 0, 0}, e2_{0, 0, 1};  // perpendicular to up: the wobble's plane
  double growth_ = 0;  // relative radius growth per metre risen
  glm::dvec3 up_{0, 1, 0};
  std::vector<BubbleSite> sites_;
  std::vector<Track> tracks_;
  std::vector<Bubble> bubbles_;
  std::vector<glm::vec3> pops_;
};

}  // namespace draught
