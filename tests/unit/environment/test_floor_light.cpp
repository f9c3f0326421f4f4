// The floor's light map (shadows and caustics traced from the lights): a glass of index 1
// that absorbs nothing changes nothing; an opaque glass's shadow is the irradiance that
// backward shadow rays to light samples find; the change integrates to minus the power
// absorbed and sent away; a full lager focuses a caustic brighter than the open floor; a
// tipped glass's shadow moves; a glass cut away entirely casts none; a seed gives one map
// whatever the thread count; droplets and clouds cast shadows too (opaque droplets: what
// shadow rays through the droplets' march find), keeping the energy, keyed by their state;
// so do decals on the walls.
#include "core/droplets/field.hpp"
#include "core/environment/floor_light.hpp"
#include "core/math/random.hpp"
#include "core/params/preset.hpp"
#include "core/scene/motion.hpp"
#include "core/input/driver.hpp"
#include "core/sim/scene_simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace draught {
namespace {

double mean(const glm::dvec3& v) { return (v.x + v.y + v.z) / 3.0; }

// A pint lit by the key light only, bubbles off.
FrameState pint(std::vector<std::string> sets = {}, const std::string& drink = "lager") {
  sets.insert(sets.end(), {"strips.power=0", "backlight.power=0", "bubbles.max_bubbles=0"});
  return make_frame(resolve_scene({drink, "pint", sets, {}}));
}

FloorLightSettings budget(int photons, std::uint64_t seed = 1) {
  FloorLightSettings s;
  s.photons = photons;
  s.seed = seed;
  return s;
}

glm::dvec3 open_light(const FrameState& f, const FloorLightMap& m, int i, int j) {
  const glm::dvec2 c = m.texel_centre(i, j);
  return unoccluded_floor_irradiance(f.lights, {c.x, 0, c.y});
}

// The largest |map - unoccluded| over the map, relative to the largest unoccluded light.
double largest_change(const FrameState& f, const FloorLightMap& m) {
  double worst = 0, top = 0;
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) {
      const glm::dvec3 e = open_light(f, m, i, j);
      worst = std::max(worst, glm::length(m.at(i, j) - e));
      top = std::max(top, glm::length(e));
    }
  return worst / top;
}

TEST(FloorLight, AGlassOfIndexOneThatAbsorbsNothingChangesNothing) {
  FrameState f = pint({"glass.ior=1", "liquid.ior=1", "glass.absorption=0,0,0", "liquid.haze=0"});
  f.vessels[0].liquid_absorption = DrinkAbsorption::uniform(glm::vec3(0.0f));
  f.vessels[0].foam.thickness = 0;
  const FloorLightMap m = compute_floor_light(f, budget(50000));
  ASSERT_FALSE(m.empty());
  ASSERT_GT(mean(m.stats.hit), 0.0) << "no photon met the glass: the test tests nothing";
  const double change = largest_change(f, m);
  std::printf("index-1 glass: largest change %.2e of the open light\n", change);
  EXPECT_LT(change, 1e-4);
}

// Irradiance at floor point p by backward shadow rays: samples of every light, each counted
// when blocked(p, dir, dist) says nothing lies between.
template <class Blocked>
glm::dvec3 backward_irradiance(const FrameState& f, glm::dvec3 p, int samples, Rng& rng, const Blocked& blocked) {
  glm::dvec3 e(0.0);
  for (const AreaLight& l : f.lights.lights)
    for (int k = 0; k < samples; ++k) {
      AreaLight::Sample s;
      const double v = rng.uniform(), u = rng.uniform();  // (drawn in this order)
      if (!l.sample_from(p, u, v, s) || s.dir.y <= 0) continue;
      if (blocked(p + glm::dvec3(0, 1e-7, 0), s.dir, s.dist)) continue;
      e += l.radiance * s.dir.y / s.pdf / double(samples);
    }
  return e;
}

// An opaque object's shadow in the map against backward shadow rays, over a grid of texels
// (every `step`-th) where the map takes more than `least` of the open light, those `skip`
// names left out: the points, those the rays find darker than `shaded` of the open light,
// the largest pointwise difference over the mean open light, and the mean light blocked
// by the map and by the rays.
struct ShadowComparison {
  int points = 0, shaded = 0;
  double worst = 0, blocked_map = 0, blocked_back = 0;
  void print(const char* what) const {
    std::printf("%s: %d points (%d shaded), largest |map - shadow rays| %.3f of the open light; blocked %.4f vs %.4f\n",
                what, points, shaded, worst, blocked_map, blocked_back);
  }
};
template <class Blocked, class Skip>
ShadowComparison compare_with_shadow_rays(const FrameState& f, const FloorLightMap& m, int step, double least,
                                          double shaded, Rng& rng, const Blocked& blocked, const Skip& skip) {
  ShadowComparison r;
  double open_mean = 0;
  for (int j = step / 2; j < m.height; j += step)
    for (int i = step / 2; i < m.width; i += step) {
      const glm::dvec2 c = m.texel_centre(i, j);
      if (skip(c)) continue;
      const glm::dvec3 p(c.x, 0, c.y);
      const glm::dvec3 open = unoccluded_floor_irradiance(f.lights, p);
      if (mean(open - m.at(i, j)) < least * mean(open)) continue;
      const glm::dvec3 back = backward_irradiance(f, p, 2000, rng, blocked);
      const glm::dvec3 map(m.sample(c.x, c.y));
      r.worst = std::max(r.worst, std::fabs(mean(map) - mean(back)));
      open_mean += mean(open);
      r.blocked_map += mean(open - map);
      r.blocked_back += mean(open - back);
      r.shaded += mean(back) < shaded * mean(open);
      ++r.points;
    }
  if (r.points > 0) {
    r.worst /= open_mean / r.points;
    r.blocked_map /= r.points;
    r.blocked_back /= r.points;
  }
  return r;
}

TEST(FloorLight, AnOpaqueGlassShadowIsWhatShadowRaysFind) {
  // Index 1 everywhere (no reflection), glass and drink black: all that meets it is absorbed.
  // A stated key (not the tuned default): its penumbra decides how much the kernel blurs.
  FrameState f = pint({"glass.ior=1", "liquid.ior=1", "liquid.haze=0", "light.direction=-0.55,0.75,0.45",
                       "light.distance=1", "light.width=0.6", "light.height=0.6"});
  f.vessels[0].params.glass.absorption = glm::vec3(1e5f);
  f.vessels[0].liquid_absorption = DrinkAbsorption::uniform(glm::vec3(1e5f));
  f.vessels[0].foam.thickness = 0;
  const FloorLightMap m = compute_floor_light(f, budget(800000));
  const SceneGeometry geo = scene_geometry(f);
  Rng rng(3, 1, 0);
  const double foot = f.vessels[0].vessel.r_outer.front();
  // A grid over where the map changes the light, the floor under the foot left out.
  const ShadowComparison r = compare_with_shadow_rays(
      f, m, 8, 0.02, 0.5, rng,
      [&](const glm::dvec3& o, const glm::dvec3& d, double dist) {
        const Hit h = first_hit(geo, {o, d});
        return h.valid() && h.t < dist;
      },
      [&](const glm::dvec2& c) { return std::hypot(c.x, c.y) < foot + 0.005; });
  r.print("opaque glass");
  ASSERT_GT(r.shaded, 10) << "the grid misses the shadow";
  // Pointwise: the noise of both estimates (together about 2 % rms of the open light here;
  // the largest of 150 points reaches 3 sigma) and the kernel's blur of the penumbra.
  EXPECT_LT(r.worst, 0.08);
  EXPECT_NEAR(r.blocked_map, r.blocked_back, 0.03 * std::fabs(r.blocked_back));
}

TEST(FloorLight, TheChangeIntegratesToMinusThePowerAbsorbedAndSentAway) {
  const FrameState f = pint();
  const FloorLightMap m = compute_floor_light(f, budget(200000));
  glm::dvec3 change(0.0);
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) change += (m.at(i, j) - open_light(f, m, i, j)) * m.texel_area();
  const FloorLightStats& s = m.stats;
  const glm::dvec3 lost = s.absorbed + s.escaped;
  std::printf("energy: hit %.4f W, landed %.4f, absorbed %.4f, escaped %.4f, outside %.2e; change %.4f W\n", mean(s.hit),
              mean(s.landed), mean(s.absorbed), mean(s.escaped), mean(s.outside), mean(change));
  ASSERT_GT(mean(lost), 0.05 * mean(s.hit)) << "the lager absorbs too little to test";
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(change[c], -lost[c], 0.02 * s.hit[c]) << "channel " << c;
    EXPECT_NEAR(s.landed[c] + s.absorbed[c] + s.escaped[c], s.hit[c], 0.02 * s.hit[c]) << "channel " << c;
  }
  EXPECT_LT(mean(s.outside), 3e-3 * mean(s.hit)) << "the rect misses where the light lands";
}

// A decal on the wall is in the photons' way as the reference meets it: a black enamel
// band round an empty pint absorbs what it catches, so the shadow deepens and the energy
// still adds up; the map's inputs follow the decal.
TEST(FloorLight, ADecalCastsItsShadowAndTheEnergyAddsUp) {
  const std::vector<std::string> band = {"liquid.fill=0", "decal_outer.file=gold-band", "decal_outer.width=0",
                                         "decal_outer.height=0.07", "decal_outer.color=0,0,0"};
  const FrameState clear = pint({"liquid.fill=0"}), banded = pint(band);
  const FloorLightMap a = compute_floor_light(clear, budget(200000)), b = compute_floor_light(banded, budget(200000));
  glm::dvec3 change_a(0.0), change_b(0.0);
  for (int j = 0; j < a.height; ++j)
    for (int i = 0; i < a.width; ++i) {
      change_a += (a.at(i, j) - open_light(clear, a, i, j)) * a.texel_area();
      change_b += (b.at(i, j) - open_light(banded, b, i, j)) * b.texel_area();
    }
  std::printf("clear pint: absorbed %.4f W of %.4f, change %.4f W; with a black band: absorbed %.4f W, change %.4f W\n",
              mean(a.stats.absorbed), mean(a.stats.hit), mean(change_a), mean(b.stats.absorbed), mean(change_b));
  EXPECT_GT(mean(b.stats.absorbed), mean(a.stats.absorbed) + 0.05 * mean(b.stats.hit)) << "the band absorbs";
  EXPECT_LT(mean(change_b), mean(change_a) - 0.05 * mean(b.stats.hit)) << "the shadow deepens";
  const glm::dvec3 lost = b.stats.absorbed + b.stats.escaped;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(change_b[c], -lost[c], 0.02 * b.stats.hit[c]) << "channel " << c;
    EXPECT_NEAR(b.stats.landed[c] + b.stats.absorbed[c] + b.stats.escaped[c], b.stats.hit[c], 0.02 * b.stats.hit[c]);
  }
  EXPECT_NE(floor_light_inputs(clear), floor_light_inputs(banded));
  EXPECT_NE(floor_light_inputs(banded), floor_light_inputs(pint({"liquid.fill=0", "decal_outer.file=gold-band",
                                                                 "decal_outer.width=0", "decal_outer.height=0.05",
                                                                 "decal_outer.color=0,0,0"})));
}

// What the picture reads is the map over the exact open light, where a photon changed it
// (the open light there interpolated between exact texels 1 cm apart), and 1 elsewhere.
TEST(FloorLight, TheFactorIsTheMapOverTheOpenLight) {
  const FrameState f = pint({}, "stout");
  const FloorLightMap m = compute_floor_light(f, budget(50000));
  double worst = 0;
  int changed = 0;
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) {
      const size_t k = size_t(j) * size_t(m.width) + size_t(i);
      const glm::dvec3 open = m.unoccluded(i, j), exact = m.at(i, j) / open;
      if (m.change[k] == glm::vec3(0.0f)) {
        EXPECT_EQ(m.factor[k], glm::vec3(1.0f));
        continue;
      }
      ++changed;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(double(m.factor[k][c]) - exact[c]));
    }
  std::printf("factor: %d of %d texels changed; largest |factor - map / open light| %.2e\n", changed,
              m.width * m.height, worst);
  ASSERT_GT(changed, 100);
  EXPECT_LT(worst, 2e-4);
}

TEST(FloorLight, AFullLagerFocusesACausticBrighterThanTheOpenFloor) {
  const FrameState f = pint();
  const FloorLightMap m = compute_floor_light(f, budget(200000));
  double brightest = 0, darkest = 1e9;
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) {
      const double ratio = mean(m.at(i, j)) / mean(open_light(f, m, i, j));
      brightest = std::max(brightest, ratio);
      darkest = std::min(darkest, ratio);
    }
  std::printf("lager: the floor's light from %.2f to %.2f of the open floor's\n", darkest, brightest);
  EXPECT_GT(brightest, 1.1);  // the rig's key is a 0.6 m softbox a metre away: a soft caustic
  EXPECT_LT(darkest, 0.6);
}

// The centre of the light a glass takes from the floor (x, z).
glm::dvec2 shadow_centre(const FrameState& f, const FloorLightMap& m) {
  glm::dvec2 c(0.0);
  double w = 0;
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) {
      const double d = std::max(0.0, mean(open_light(f, m, i, j) - m.at(i, j)));
      c += d * m.texel_centre(i, j);
      w += d;
    }
  return c / w;
}

TEST(FloorLight, ATippedGlassShadowMoves) {
  FrameState f = pint({"liquid.fill=0"});
  const glm::dvec2 upright = shadow_centre(f, compute_floor_light(f, budget(60000)));
  VesselFrame& v = f.vessels[0];
  v.pose = tipped_on_floor(tilt_orientation(0.5, 0.0), v.vessel.r_outer.front());  // towards +x
  const glm::dvec2 tipped = shadow_centre(f, compute_floor_light(f, budget(60000)));
  std::printf("shadow centre upright (%.4f, %.4f), tipped (%.4f, %.4f)\n", upright.x, upright.y, tipped.x, tipped.y);
  EXPECT_GT(tipped.x - upright.x, 0.02);
}

TEST(FloorLight, AGlassCutAwayEntirelyCastsNoShadow) {
  const FrameState whole = pint();
  const FrameState cut = pint({"clip.enabled=true", "clip.normal=0,1,0", "clip.offset=-0.05"});
  const FloorLightMap mw = compute_floor_light(whole, budget(20000)), mc = compute_floor_light(cut, budget(20000));
  EXPECT_GT(largest_change(whole, mw), 0.3);
  EXPECT_EQ(mean(mc.stats.hit), 0.0);
  EXPECT_LT(largest_change(cut, mc), 1e-5);
}

TEST(FloorLight, OneSeedGivesOneMapWhateverTheThreads) {
  const FrameState f = pint();
  FloorLightSettings one = budget(20000, 5), two = budget(20000, 5), other = budget(20000, 6);
  one.threads = 1;
  two.threads = 2;
  const FloorLightMap a = compute_floor_light(f, one), b = compute_floor_light(f, two), c = compute_floor_light(f, other);
  EXPECT_EQ(a.change, b.change);
  EXPECT_EQ(a.factor, b.factor);
  EXPECT_EQ(a.surround_factor, b.surround_factor);
  EXPECT_NE(a.change, c.change);
  EXPECT_NE(a.surround_factor, c.surround_factor);
}

// The surroundings' shadow (gathered: FloorLightMap::surround_factor) near the foot of the
// default pint: its mean and its darkest over a ring of the floor 1-3 cm from the foot.
struct Contact {
  glm::dvec3 mean{0.0};
  double darkest = 1, brightest = 0;
};
Contact contact_ring(const FrameState& f, const FloorLightMap& m) {
  Contact r;
  const double foot = f.vessels[0].vessel.r_outer.front();
  int n = 0;
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) {
      const glm::dvec3 s(m.surround_factor[size_t(j) * size_t(m.width) + size_t(i)]);
      r.darkest = std::min(r.darkest, std::min({s.x, s.y, s.z}));
      r.brightest = std::max(r.brightest, std::max({s.x, s.y, s.z}));
      const double d = glm::length(m.texel_centre(i, j)) - foot;
      if (d < 0.01 || d > 0.03) continue;
      r.mean += s;
      ++n;
    }
  r.mean /= std::max(n, 1);
  return r;
}

// A glass of index 1 that absorbs nothing leaves the surroundings' light as it is: the
// gathered factor is exactly 1 (its ratio of sums over the same directions).
TEST(FloorLight, AClearGlassOfIndexOneCastsNoSoftShadow) {
  FrameState f = pint({"glass.ior=1", "liquid.ior=1", "glass.absorption=0,0,0", "liquid.haze=0"});
  f.vessels[0].liquid_absorption = DrinkAbsorption::uniform(glm::vec3(0.0f));
  f.vessels[0].foam.thickness = 0;
  const Contact c = contact_ring(f, compute_floor_light(f, budget(5000)));
  std::printf("index-1 glass: surroundings' factor %.9f .. %.9f\n", c.darkest, c.brightest);
  EXPECT_NEAR(c.darkest, 1.0, 1e-9);
  EXPECT_NEAR(c.brightest, 1.0, 1e-9);
}

// The soft shadow round a foot follows what the glass and its drink take from the light:
// under an even sky (the furnace) an empty glass takes nothing, a lager's is amber (its
// blue darkest, as dark as the stout's: the lager takes nearly all its blue too), a
// stout's darkest of all; never below 0. (1-3 cm from the foot: stout 0.844, lager 0.886 /
// 0.869 / 0.846, empty 1.000, at 20,000 photons' 32 rays a node.)
TEST(FloorLight, TheSoftShadowRoundTheFootFollowsTheDrink) {
  const std::vector<std::string> even = {"env.mode=constant", "env.color=1,1,1"};
  std::vector<std::string> empty_sets = even;
  empty_sets.push_back("liquid.fill=0");
  const FrameState lager = pint(even), stout = pint(even, "stout"), empty = pint(empty_sets);
  const Contact l = contact_ring(lager, compute_floor_light(lager, budget(20000)));
  const Contact s = contact_ring(stout, compute_floor_light(stout, budget(20000)));
  const Contact e = contact_ring(empty, compute_floor_light(empty, budget(20000)));
  std::printf("surroundings' factor 1-3 cm from the foot: stout %.3f %.3f %.3f, lager %.3f %.3f %.3f, empty %.3f %.3f %.3f\n",
              s.mean.x, s.mean.y, s.mean.z, l.mean.x, l.mean.y, l.mean.z, e.mean.x, e.mean.y, e.mean.z);
  EXPECT_LT(mean(s.mean), mean(l.mean) - 0.01);
  EXPECT_LT(mean(l.mean), mean(e.mean) - 0.05);
  EXPECT_LT(l.mean.z, l.mean.x - 0.02) << "the lager's shadow is amber: its blue darkest";
  EXPECT_NEAR(mean(e.mean), 1.0, 0.03) << "an empty glass takes (almost) nothing";
  for (const Contact* c : {&l, &s, &e}) EXPECT_GE(c->darkest, 0.0);
}

// Under an environment image the photons trace its brightest patches, and the soft shadow
// is gathered from the rest of the image: as a share of the image's whole light, so never
// below 1 less that share (what the patches give the floor); a stout's ring darker than
// an empty glass's, with a real shadow at its darkest. (Above 1 on average beside the
// foot: under the studio image the patches give the floor three quarters of its light,
// and the glass turns the lit floor, brighter than the rest of the image, onto it.)
TEST(FloorLight, UnderAnImageTheSoftShadowIsGatheredFromTheRestOfTheImage) {
  const std::vector<std::string> image = {"env.mode=image", "env.image=studio"};
  std::vector<std::string> empty_sets = image;
  empty_sets.push_back("liquid.fill=0");
  const FrameState stout = pint(image, "stout"), empty = pint(empty_sets);
  const FloorLightMap s = compute_floor_light(stout, budget(20000)), e = compute_floor_light(empty, budget(20000));
  ASSERT_TRUE(s.even);
  const glm::dvec3 patches = unoccluded_floor_irradiance(floor_emitters(stout), {0, 0, 0});
  const double share = 1 - mean(patches) / mean(s.even_light);
  const Contact cs = contact_ring(stout, s), ce = contact_ring(empty, e);
  std::printf("under the studio image: the rest's share %.3f; 1-3 cm from the foot: stout %.3f (darkest %.3f), empty %.3f\n",
              share, mean(cs.mean), cs.darkest, mean(ce.mean));
  EXPECT_GT(share, 0.05);
  EXPECT_LT(share, 0.95);
  EXPECT_LT(mean(cs.mean), mean(ce.mean) - 0.01);
  EXPECT_LT(cs.darkest, 1.0 - 0.5 * share);
  EXPECT_GE(cs.darkest, 1.0 - share - 1e-9);
  EXPECT_GE(ce.darkest, 1.0 - share - 1e-9);
}

// Interactive apps refine a still's map over frames: a batch is compute_floor_light's map,
// and batches go on where the last stopped, so four of them are as good as one four times
// the size (the noise against a map of many photons falls by about two).
TEST(FloorLight, BatchesRefineTheMap) {
  const FrameState f = pint();
  FloorLightTrace trace(f, budget(20000));
  trace.add_batch();
  const FloorLightMap one = compute_floor_light(f, budget(20000));
  EXPECT_EQ(trace.map().change, one.change);
  EXPECT_EQ(trace.map().factor, one.factor);
  const FloorLightMap truth = compute_floor_light(f, budget(800000, 9));
  auto rms = [&](const FloorLightMap& m) {
    EXPECT_EQ(m.width, truth.width);
    double sum = 0;
    int n = 0;
    for (int j = 0; j < m.height; ++j)
      for (int i = 0; i < m.width; ++i) {
        const double t = mean(truth.at(i, j)), open = mean(truth.unoccluded(i, j));
        if (std::fabs(t - open) < 0.02 * open) continue;  // where the glass changes the light
        sum += std::pow((mean(m.at(i, j)) - t) / open, 2);
        ++n;
      }
    return std::sqrt(sum / std::max(n, 1));
  };
  const double after_one = rms(trace.map());
  for (int b = 1; b < 4; ++b) trace.add_batch();
  const double after_four = rms(trace.map());
  std::printf("batches: rms noise %.4f of the open light after one batch of 20,000, %.4f after four\n", after_one,
              after_four);
  EXPECT_EQ(trace.batches(), 4);
  EXPECT_EQ(trace.map().stats.photons, 4 * one.stats.photons);
  EXPECT_LT(after_four, after_one / 1.6);
  // The means keep the energy: the change still integrates to minus what was lost.
  glm::dvec3 change(0.0);
  const FloorLightMap& m = trace.map();
  for (int j = 0; j < m.height; ++j)
    for (int i = 0; i < m.width; ++i) change += (m.at(i, j) - m.unoccluded(i, j)) * m.texel_area();
  EXPECT_NEAR(mean(change), -mean(m.stats.absorbed + m.stats.escaped), 0.02 * mean(m.stats.hit));
}

// An interactive app's trace gathers the surroundings' shadow a few rays a batch: after
// each batch the factor is already a shadow round the foot (every power-of-two prefix of
// the directions is even), and with every ray in it is the one compute_floor_light
// gathers at once, to the bit, however the rays were split.
TEST(FloorLight, TheSoftShadowIsGatheredAFewRaysABatch) {
  const FrameState f = pint({"env.mode=constant", "env.color=1,1,1"});
  const FloorLightMap once = compute_floor_light(f, budget(2000));
  FloorLightSettings s = budget(2000);
  s.gather_rays_per_batch = 3;  // 32 rays: 11 batches, the last of 2
  FloorLightTrace trace(f, s);
  trace.add_batch();
  trace.add_batch();
  const Contact early = contact_ring(f, trace.map()), full = contact_ring(f, once);
  std::printf("1-3 cm from the foot: %.3f after 6 rays, %.3f after all 32\n", mean(early.mean), mean(full.mean));
  EXPECT_NEAR(mean(early.mean), mean(full.mean), 0.03);
  EXPECT_NE(trace.map().surround_factor, once.surround_factor);
  for (int b = 2; b < 10; ++b) trace.add_batch();
  EXPECT_NE(trace.map().surround_factor, once.surround_factor) << "30 rays of 32";
  trace.add_batch();
  EXPECT_EQ(trace.map().surround_factor, once.surround_factor);
  trace.add_batch();
  EXPECT_EQ(trace.map().surround_factor, once.surround_factor) << "no rays after the 32nd";
}


TEST(FloorLight, TheInputsChangeWithWhatTheMapDependsOn) {
  const FrameState f = pint();
  const std::vector<double> k = floor_light_inputs(f);
  EXPECT_EQ(k, floor_light_inputs(pint()));
  FrameState moved = f;
  moved.vessels[0].pose.position.x += 0.001;
  EXPECT_NE(k, floor_light_inputs(moved));
  FrameState lit = f;
  lit.lights.lights[0].radiance *= 2.0;
  EXPECT_NE(k, floor_light_inputs(lit));
  EXPECT_NE(k, floor_light_inputs(pint({"clip.enabled=true", "clip.normal=1,0,0"})));
  EXPECT_NE(k, floor_light_inputs(pint({}, "stout")));
  // A head collapsing by a hundredth of a millimetre a frame leaves the map as it is; by a
  // millimetre, not.
  FrameState settling = f;
  settling.vessels[0].foam.thickness += 1e-5;
  EXPECT_EQ(k, floor_light_inputs(settling));
  settling.vessels[0].foam.thickness += 1e-3;
  EXPECT_NE(k, floor_light_inputs(settling));
}

// A still pint whose head collapses (a few mm a minute) traces its floor light again a
// few times a minute, not every frame (a minute at 5 frames a second).
TEST(FloorLight, AStillPintsCollapsingHeadRetracesRarely) {
  SceneSimulation sim(single_glass_scene(resolve_scene({"lager", "pint", {}, {}})));
  struct Still : InputDriver {
    const char* name() const override { return "still"; }
    MotionSample sample(double) override { return {}; }
  } still;
  std::vector<double> last;
  int traced = 0;
  double head0 = 0, head1 = 0;
  for (int i = 1; i <= 300; ++i) {
    sim.advance(still, 0.2 * i, 0.0);
    const FrameState f = sim.frame();
    (i == 1 ? head0 : head1) = f.vessels[0].foam.thickness;
    std::vector<double> k = floor_light_inputs(f);
    traced += k != last;
    last = std::move(k);
  }
  std::printf("the head %.2f -> %.2f mm over 60 s; the floor light traced %d times in 300 frames\n", 1e3 * head0,
              1e3 * head1, traced);
  EXPECT_LT(head1, head0 - 1e-3);  // it did collapse
  EXPECT_LE(traced, 12);
}

// A scene of droplets or clouds (a preset), lit by the key light only, as it stands at t = 0.
FrameState scene_frame(const std::string& preset) {
  Scene scene = resolve_scene_objects({preset, "", {"strips.power=0", "backlight.power=0"}, {}});
  SceneSimulation sim(scene);
  return sim.frame();
}

TEST(FloorLight, OpaqueDropletsShadowIsWhatShadowRaysFind) {
  // Index 1 (no reflection, no bending) and black: all the light that meets them is absorbed.
  FrameState f = scene_frame("droplets-seed");
  ASSERT_EQ(f.droplets.size(), 1u);
  f.droplets[0].params.ior = 1.0f;
  f.droplets[0].params.absorption = glm::vec3(1e5f);
  const FloorLightMap m = compute_floor_light(f, budget(400000));
  ASSERT_FALSE(m.empty()) << "droplets alone get a map";
  ASSERT_GT(mean(m.stats.hit), 0.0) << "no photon met the droplets";
  // The shadow rays meet the droplets' own march, the noise left out as the photons take it.
  DropletField field = f.droplets.front().field;
  field.noise_amplitude = 0;
  Rng rng(7, 1, 0);
  const ShadowComparison r = compare_with_shadow_rays(
      f, m, 4, 0.01, 0.9, rng,
      [&](const glm::dvec3& o, const glm::dvec3& d, double dist) {
        return march_droplets(field, o, d, 1e-7, dist, false).has_value();
      },
      [](const glm::dvec2&) { return false; });
  r.print("opaque droplets");
  ASSERT_GT(r.shaded, 5) << "the grid misses the shadow";
  EXPECT_LT(r.worst, 0.06);
  EXPECT_NEAR(r.blocked_map, r.blocked_back, 0.05 * std::fabs(r.blocked_back));
}

// Water droplets (their own index and absorption) and a gob of glass: each takes light from
// the floor under it, and what the photons carried is all accounted for.
TEST(FloorLight, DropletsAndCloudsShadowsKeepTheEnergy) {
  for (const char* preset : {"droplets-seed", "gob-cooled"}) {
    const FrameState f = scene_frame(preset);
    ASSERT_TRUE(f.vessels.empty()) << preset;
    const FloorLightMap m = compute_floor_light(f, budget(100000));
    ASSERT_FALSE(m.empty()) << preset;
    glm::dvec3 change(0.0);
    double darkest = 1e9;
    for (int j = 0; j < m.height; ++j)
      for (int i = 0; i < m.width; ++i) {
        const glm::dvec3 open = open_light(f, m, i, j);
        change += (m.at(i, j) - open) * m.texel_area();
        darkest = std::min(darkest, mean(m.at(i, j)) / mean(open));
      }
    const FloorLightStats& s = m.stats;
    const glm::dvec3 lost = s.absorbed + s.escaped;
    std::printf("%s: darkest %.2f of the open floor; hit %.4f W, landed %.4f, absorbed %.4f, escaped %.4f; change %.4f W (%.1f s)\n",
                preset, darkest, mean(s.hit), mean(s.landed), mean(s.absorbed), mean(s.escaped), mean(change), s.seconds);
    ASSERT_GT(mean(s.hit), 0.0) << preset;
    EXPECT_LT(darkest, 0.9) << preset << ": no shadow";
    // The change on the map is what the objects took: absorbed (a cloud point's colour
    // included) or sent off the map.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(change[c], -lost[c], 0.03 * s.hit[c]) << preset << " channel " << c;
    // Every photon that met the droplets ends somewhere (the gob's blowpipe reaches over the
    // sweep's curve, where straight lines count as escaped too: no such sum there).
    if (f.clouds.empty()) {
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(s.landed[c] + s.absorbed[c] + s.escaped[c], s.hit[c], 0.02 * s.hit[c]) << preset << " channel " << c;
    }
    // A sphere of water reflects a few per cent of what meets it every way, some of it far
    // over the floor, thinly: the rect keeps the shadow and the caustic, not all of that.
    EXPECT_LT(mean(s.outside), 0.03 * mean(s.hit)) << preset << ": the rect misses where the light lands";
  }
}

TEST(FloorLight, TheInputsFollowTheDropletsAndTheClouds) {
  const FrameState f = scene_frame("droplets-seed");
  const std::vector<double> k = floor_light_inputs(f);
  FrameState moved = f;
  moved.droplets[0].field.spheres[3].centre.x += 0.001;
  EXPECT_NE(k, floor_light_inputs(moved));
  FrameState murky = f;
  murky.droplets[0].params.absorption.x += 1.0f;
  EXPECT_NE(k, floor_light_inputs(murky));
  const FrameState g = scene_frame("gob-cooled");
  ASSERT_FALSE(g.clouds.empty());
  const std::vector<double> kg = floor_light_inputs(g);
  FrameState next = g;
  next.clouds[0].version += 1;  // its points moved
  EXPECT_NE(kg, floor_light_inputs(next));
  EXPECT_EQ(kg, floor_light_inputs(g));
}

}  // namespace
}  // namespace draught
