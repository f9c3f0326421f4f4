// The picture against the project's reference path tracer (core/reference/path_tracer),
// region by region: the glass, the drink seen through it, the head, the droplets, a point
// cloud. Each pixel is classified by the refracted path of its camera ray
// (tests/gpu/reference_path.hpp; the droplets or a cloud where the ray meets them first);
// pixels next to another region are left out (edges are where supersampling and the
// reference's jittered samples disagree by construction). The difference is CIEDE2000
// between the two 8-bit sRGB pictures, after the same exposure and tone map.
//
// The targets (docs/REFERENCE.md): mean <= 2 on glass and liquid, <= 4 on the
// head, 90th percentile <= 5. Where the picture does not meet them yet, the bounds below
// are today's figures plus a margin, so a change that moves the picture away from the
// reference fails, and docs/REFERENCE.md states both.
#include "color_difference.hpp"
#include "gpu_fixture.hpp"
#include "reference_path.hpp"
#include "stored_reference.hpp"

#include "core/droplets/field.hpp"
#include "core/foam/head_volume.hpp"
#include "core/io/image.hpp"
#include "core/pointcloud/cloud_scene.hpp"
#include "core/pointcloud/field.hpp"
#include "core/reference/path_tracer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

namespace draught::test {
namespace {

TEST(Ciede2000, MatchesSharmasTestData) {
  // Pairs 1, 7, 17 and 25 of Sharma, Wu and Dalal's table (2005).
  EXPECT_NEAR(ciede2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(ciede2000({50, 0, 0}, {50, -1, 2}), 2.3669, 1e-4);
  EXPECT_NEAR(ciede2000({50, 2.5, 0}, {73, 25, -18}), 27.1492, 1e-4);
  EXPECT_NEAR(ciede2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644, 1e-4);
  EXPECT_NEAR(ciede2000(srgb8_to_lab(255, 255, 255), {100, 0, 0}), 0.0, 1e-3);
}

enum class Region { Background, Glass, Liquid, Foam, Droplets, Cloud };
constexpr int kRegions = 6;
const char* region_name(Region r) {
  return r == Region::Glass      ? "glass"
         : r == Region::Liquid   ? "liquid"
         : r == Region::Foam     ? "foam"
         : r == Region::Droplets ? "droplets"
         : r == Region::Cloud    ? "cloud"
                                 : "background";
}

// What the camera ray sees: the droplets or a cloud when it meets them first (the
// nearer); the head when its refracted path crosses one (through air), the drink when it
// enters one, else the glass when it meets one.
Region region_of(const FrameState& f, const SceneGeometry& geo, const CloudScene& clouds,
                 const std::vector<HeadVolume>& heads, const Ray& ray) {
  double t = first_hit(geo, ray, 0.0).t;
  Region body = Region::Background;
  if (!f.droplets.empty())
    if (const auto d = march_droplets(f.droplets.front().field, ray.o, ray.d, 0.0, t, false)) {
      t = d->t;
      body = Region::Droplets;
    }
  for (size_t c = 0; c < clouds.ranges().size(); ++c)
    if (const auto k = march_cloud(clouds.texels(), cloud_ref(clouds.ranges()[c], f.clouds[c].threshold),
                                   glm::vec3(ray.o), glm::vec3(ray.d), 0.0f, float(t), false);
        k && k->t < t) {
      t = k->t;
      body = Region::Cloud;
    }
  if (body != Region::Background) return body;
  const std::vector<PathEvent> events = reference_path(f, geo, ray, 12);
  if (events.empty() || events[0].m == Material::None || events[0].m == Material::Floor)
    return Region::Background;
  for (const PathEvent& e : events) {
    if (e.medium == MediumKind::Liquid) return Region::Liquid;
    if (e.medium != MediumKind::Air) continue;
    const double len = e.m == Material::None ? 1.0 : e.t;
    for (size_t i = 0; i < heads.size(); ++i) {
      const VesselFrame& v = f.vessels[i];
      const glm::dquat to_local = glm::inverse(v.pose.orientation);
      const glm::dvec3 o = to_local * (e.ray.o - v.pose.position), d = to_local * e.ray.d;
      double t0 = 0, t1 = len;
      if (!heads[i].interval(o, d, t0, t1)) continue;
      for (int k = 0; k < 64; ++k)
        if (heads[i].density(o + (t0 + (t1 - t0) * (k + 0.5) / 64) * d) > 0) return Region::Foam;
    }
  }
  return Region::Glass;
}

struct RegionStats {
  std::vector<double> de;
  double mean() const {
    double s = 0;
    for (double d : de) s += d;
    return de.empty() ? 0 : s / double(de.size());
  }
  double p90() const {
    if (de.empty()) return 0;
    std::vector<double> v = de;
    std::nth_element(v.begin(), v.begin() + ptrdiff_t(v.size() * 9 / 10), v.end());
    return v[v.size() * 9 / 10];
  }
};

struct Bounds {
  double mean, p90;
};

// A case's name as its test and its stored reference are named (lager-pint: lager_pint).
std::string case_file_name(std::string name) {
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

struct ComparisonCase {
  const char* name;
  SceneRequest request;
  int size;  // the picture's width
  int spp;
  Bounds glass, liquid, foam;
  Bounds droplets{0, 0}, cloud{0, 0};
  int height = 0;  // 0: square
  const char* timeline = nullptr;  // set: the request is this shipped timeline's frame at `at` s
  double at = 0;
};

class ReferenceComparison : public ::testing::TestWithParam<ComparisonCase> {};

TEST_P(ReferenceComparison, RegionsAgreeWithinTheirBounds) {
  const ComparisonCase& c = GetParam();
  // The scene with every object (scene_frame keeps the first vessel alone): a scene's
  // droplets and clouds too; a drink in its glass is the same frame either way.
  const FrameState f = c.timeline ? timeline_frame(c.timeline, c.at, c.request.camera)
                                   : make_frame(resolve_scene_objects(c.request));
  const int n = c.size, rows = c.height > 0 ? c.height : n;
  const Image picture = gpu_instance().renderer->render(f, n, rows);
  ReferenceSettings settings;
  settings.samples = c.spp;
  // The reference as stored in tests/golden/reference/ and checked against this code
  // (stored_reference.hpp; gpu_tests --bless path-traces and stores it). Path-traced here
  // instead with DRAUGHT_COMPARISON_LIVE=1, or DRAUGHT_COMPARISON_SEED=n: the reference
  // with other random numbers (how much of a figure is its own noise).
  RadianceImage radiance;
  const char* seed = std::getenv("DRAUGHT_COMPARISON_SEED");
  if (seed || std::getenv("DRAUGHT_COMPARISON_LIVE")) {
    if (seed) settings.seed = std::strtoull(seed, nullptr, 10);
    radiance = render_reference(f, n, rows, settings);
    std::printf("%s: reference %dx%d at %d paths, path-traced in %.1f s\n", c.name, n, rows, c.spp, radiance.seconds);
  } else {
    StoredReference stored = stored_reference(std::filesystem::path(DRAUGHT_GOLDEN_DIR) / "reference",
                                              case_file_name(c.name), f, n, rows, settings, g_bless);
    ASSERT_TRUE(stored.error.empty()) << stored.error;
    radiance = std::move(stored.radiance);
    std::printf("%s: reference %dx%d at %d paths, %s\n", c.name, n, rows, c.spp, stored.how.c_str());
  }
  const Image reference = display_image(radiance, f.params.render);

  // Classify each pixel at four points inside it; keep those whose 3x3 neighbourhood
  // is one region throughout.
  const SceneGeometry geo = scene_geometry(f);
  CloudScene clouds;
  clouds.update(f.clouds);
  std::vector<HeadVolume> heads;
  for (size_t i = 0; i < f.vessels.size(); ++i) heads.emplace_back(f.vessels[i], geo.vessels[i]);
  const CameraBasis cam = camera_basis(f, n, rows);
  std::vector<int> region(size_t(n) * size_t(rows));
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < n; ++x) {
      int r = -1;
      for (double oy : {0.25, 0.75})
        for (double ox : {0.25, 0.75}) {
          const int here = int(region_of(f, geo, clouds, heads, camera_ray(cam, x + ox, y + oy, n, rows)));
          r = r == -1 || r == here ? here : -2;
        }
      region[size_t(y) * size_t(n) + size_t(x)] = r;
    }
  RegionStats stats[kRegions];
  // With DRAUGHT_COMPARISON_DUMP each pixel of one region is printed: the foam's, or
  // DRAUGHT_COMPARISON_REGION's (glass, liquid, foam, droplets, cloud).
  int listed = int(Region::Foam);
  if (const char* want = std::getenv("DRAUGHT_COMPARISON_REGION"))
    for (Region r : {Region::Glass, Region::Liquid, Region::Foam, Region::Droplets, Region::Cloud})
      if (std::string(want) == region_name(r)) listed = int(r);
  for (int y = 1; y + 1 < rows; ++y)
    for (int x = 1; x + 1 < n; ++x) {
      const int r = region[size_t(y) * size_t(n) + size_t(x)];
      bool inside = r >= 0;
      for (int dy = -1; dy <= 1 && inside; ++dy)
        for (int dx = -1; dx <= 1; ++dx) inside = inside && region[size_t(y + dy) * size_t(n) + size_t(x + dx)] == r;
      if (!inside) continue;
      const std::uint8_t* a = picture.px(x, y);
      const std::uint8_t* b = reference.px(x, y);
      stats[r].de.push_back(ciede2000(srgb8_to_lab(a[0], a[1], a[2]), srgb8_to_lab(b[0], b[1], b[2])));
      if (std::getenv("DRAUGHT_COMPARISON_DUMP") && r == listed)
        std::printf("  %s (%d, %d): picture %d %d %d, reference %d %d %d: %.2f\n", region_name(Region(r)), x, y, a[0],
                    a[1], a[2], b[0], b[1], b[2], stats[r].de.back());
    }

  // DRAUGHT_COMPARISON_DUMP=folder: the picture, the reference and a map of the
  // difference (grey where a pixel is left out, black to white for CIEDE2000 0 to 20),
  // for finding where a region differs.
  if (const char* dump = std::getenv("DRAUGHT_COMPARISON_DUMP")) {
    Image map = picture;
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < n; ++x) {
        std::uint8_t* m = map.px(x, y);
        const std::uint8_t* a = picture.px(x, y);
        const std::uint8_t* b = reference.px(x, y);
        const int r = region[size_t(y) * size_t(n) + size_t(x)];
        const double de = ciede2000(srgb8_to_lab(a[0], a[1], a[2]), srgb8_to_lab(b[0], b[1], b[2]));
        const auto v = std::uint8_t(std::clamp(de / 20.0 * 255.0, 0.0, 255.0));
        const std::uint8_t tint[kRegions][3] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 1}};
        for (int k = 0; k < 3; ++k)
          m[k] = r <= int(Region::Background) ? 64 : std::uint8_t(std::max<int>(v, tint[r][k] * 60));
      }
    const std::filesystem::path dir(dump);
    std::filesystem::create_directories(dir);
    write_png(dir / (std::string(c.name) + "-picture.png"), picture);
    write_png(dir / (std::string(c.name) + "-reference.png"), reference);
    write_png(dir / (std::string(c.name) + "-difference.png"), map);
  }

  const Bounds bounds[kRegions] = {{0, 0}, c.glass, c.liquid, c.foam, c.droplets, c.cloud};
  for (Region r : {Region::Glass, Region::Liquid, Region::Foam, Region::Droplets, Region::Cloud}) {
    const RegionStats& s = stats[int(r)];
    std::printf("%s %-7s %4zu px  CIEDE2000 mean %5.2f  p90 %5.2f\n", c.name, region_name(r), s.de.size(), s.mean(),
                s.p90());
    const Bounds& b = bounds[int(r)];
    if (b.mean <= 0) continue;  // no such region in this scene, or not checked in it
    EXPECT_GE(s.de.size(), 10u) << region_name(r) << ": too few pixels to compare";
    EXPECT_LE(s.mean(), b.mean) << region_name(r);
    EXPECT_LE(s.p90(), b.p90) << region_name(r);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ReferenceComparison,
    // Today (llvmpipe, 256 paths per pixel), mean / 90th percentile, 64x64, in the packshot
    // studio: lager-pint: glass 0.9 / 2.4, liquid 1.4 / 1.9 (2.0 / 3.7 before sub-pixel
    // rising bubbles faded instead of showing as dark dots), head 2.6 / 4.6 (16 pixels;
    // 2.7 / 6.3 while the head's faces took a light's whole irradiance beside its single
    // scattering, which sent part of it out a second time; 4.0 / 8.5 while the reference's
    // paths out through a base's underside missed the floor it stands on and saw the black
    // below the studio, so no light came up through it).
    // The glass and the liquid came from 1.8 / 4.4 and 3.2 / 4.8 when the sweep took its
    // own bounce (the surround's harmonics, core surround_irradiance: the paper lit by the
    // rig and by the sky and paper around it); the heads take the same surround, which
    // brightens them past the reference a little (docs/REFERENCE.md). The glass and the
    // drink's own optics (the checker studio's bright sky, no floor, no bubbles): glass
    // 0.6 / 0.8, liquid 0.5 / 0.9. The heads close up (only the head checked there, bounds
    // 0: not checked; 48x48): lager 2.9 / 5.9, stout 5.0 / 11.8 (they were 3.8 / 8.0 and
    // 6.0 / 10.8 with the sky alone for their even light). Under environment images (issue
    // 12), no floor and no bubbles in the studio image: glass 0.5 / 1.7, liquid 0.9 / 1.2,
    // head 2.8 / 7.2 (16 pixels; 2.9 / 7.5 before heads took the image's brightest patches
    // as lights, core/environment/media_light); the bar with its floor: glass 7.6 / 11.5,
    // liquid 3.3 / 7.7, head 12.9 / 16.7 at 256 paths: its small lamps (radiance 60) reach
    // the head and the glass in the reference mostly through the glass wall, along paths
    // no light sampling follows. Against 2048 paths (24 s): glass 7.53 / 11.23, liquid
    // 2.83 / 7.53, head 4.73 / 8.69 (10.49 / 17.15 at 256, 3.95 / 6.98 at 4096: the head's
    // gap is mostly the reference's noise, the glass's is the picture's).
    // docs/ENVIRONMENTS.md. The four pints are compared against 2048 paths since
    // 2026-11-28 (at 256 the reference's own noise was much of the heads' figures): the
    // default pint glass 0.81 / 2.10, liquid 1.15 / 1.32, head 2.18 / 5.04 (at 256: 0.85 /
    // 2.39, 1.38 / 1.89, 2.63 / 4.59); the optics glass 0.62 / 0.91, liquid 0.28 / 0.52,
    // head 2.45 / 5.64 (4.07 / 8.27); the studio image glass 0.47 / 1.13, liquid 0.58 /
    // 0.55, head 2.21 / 4.92 (2.67 / 6.94). Bounds: today's figures and about 10 %.
    // The heads of these pints are 16 pixels: their 90th percentile is the second worst
    // pixel, at the head's shaded edge, where 2048 paths are still grainy. With the drink's
    // colour in two bands (core DrinkAbsorption) the picture's head pixels moved by at
    // most one 8-bit level, the reference's by up to six (its random numbers reshuffled:
    // roulette follows the throughput): over the reference's seeds 1 to 4
    // (DRAUGHT_COMPARISON_SEED) the default pint's head is 1.87-2.43 / 5.01-6.45, the
    // studio image's 2.05-2.26 / 4.72-6.08, the bar's 4.70-5.93 / 7.92-10.39; the bounds
    // take the worst seed and about 10 %. The close-ups below (hundreds of head pixels)
    // are the heads' real measure. Since stop 44 these three pints are compared against
    // 8192 paths (a minute or two each to trace): the pint glass 0.87 / 2.08, liquid 1.13 /
    // 1.26, head 1.55 / 3.19 (against 2048: 0.86 / 2.10, 1.15 / 1.36, 1.64 / 4.11); the
    // optics 0.59 / 1.16, 0.19 / 0.47, 2.19 / 4.21 (0.64 / 0.91, 0.27 / 0.52, 2.40 /
    // 4.48: its glass is 12 pixels); the studio image 0.47 / 1.13, 0.43 / 0.43, 1.86 / 4.77
    // (0.43 / 1.14, 0.52 / 0.54, 2.10 / 5.01). Bounds about 10 % over.
    // Stop 48: the paper is lit by its own light where each point of it is
    // (core/environment/paper_bounce), not by the light round the scene's centre
    // everywhere, as the heads and the haze see it and as the picture draws it: the heads
    // (mean / p90) the default pint 1.52 / 3.08 -> 1.46 / 2.02, the hefeweizen 1.97 / 5.82
    // -> 1.36 / 2.13, the tulip 1.89 / 3.74 -> 1.60 / 2.23, the stout close up 2.81 / 5.87
    // -> 2.50 / 4.07, its key alone 3.50 / 7.42 -> 3.20 / 5.26, the pour 1.98 / 4.16 ->
    // 1.77 / 3.42, the lager close up 1.24 / 2.28 -> 1.49 / 2.31; the liquids seen against
    // that paper the default pint 1.12 / 1.26 -> 0.69 / 0.62, the stout close up 2.01 /
    // 3.35 -> 1.25 / 2.35, the tulip 1.74 / 2.87 -> 1.20 / 2.04, the cold pint 1.62 / 2.71
    // -> 1.40 / 2.54; the droplets 1.00 / 1.81 -> 0.55 / 0.95; the hefeweizen's haze 1.33 /
    // 2.46 -> 1.56 / 3.56 and the pour's base band 2.37 / 6.46 -> 2.66 / 8.01 the other way
    // (docs/REFERENCE.md, "The paper's own light").
    // Stop 50: what an internal reflection in a glass, a drink, a droplet or a cloud sees
    // on its way out includes the backdrop (the floor and the paper), not the sky alone,
    // whose lower half is the studio's dark: the pour's base band, which leads through the
    // thick base down to the floor, liquid 2.10 / 5.02 -> 1.47 / 3.05, its glass 0.69 /
    // 1.06 -> 0.57 / 0.91; the bar's glass 2.15 / 4.57 -> 1.98 / 4.43; the tulip's glass
    // 0.97 / 2.79 -> 0.85 / 2.20; the lager's head close up 1.49 / 2.31 -> 1.13 / 1.78;
    // the default pint's liquid 0.60 / 0.62 -> 0.46 / 0.69; the stouts' liquids the other
    // way (1.21 / 2.30 -> 1.52 / 3.14 close up, 0.77 / 1.42 -> 1.07 / 1.89 by the key
    // alone: the picture's stout a level or two brighter than the reference's already,
    // now two more).
    // Stop 51: a head's march places each step's sample by the attenuation into the step
    // (march_foam), not evenly along it: a ray into a head's side, whose steps are several
    // optical depths thick, took its light from twice too deep (too little single
    // scattering, too much tinted diffusion: the sides yellow). Heads (mean / p90): the
    // default pint 1.34 / 1.80 -> 1.00 / 1.55, the stout close up 2.52 / 4.24 -> 2.04 /
    // 3.43, by the key alone 3.23 / 5.26 -> 2.73 / 4.81, the cold pint 1.58 / 2.14 -> 1.23
    // / 1.60, the bar 1.74 / 3.06 -> 1.86 / 2.74; the optics 2.29 / 4.30 -> 2.43 / 4.48 the
    // other way; the rest within 0.1.
    ::testing::Values(
        ComparisonCase{"lager-pint", SceneRequest{"lager", "pint"}, 64, 8192, {1.0, 2.3}, {0.8, 0.7}, {1.2, 1.8}},
        ComparisonCase{"lager-pint-optics",
                       SceneRequest{"checker-studio", "pint", {"env.floor=false", "bubbles.carbonation=0"}},
                       64, 8192, {0.7, 1.3}, {0.3, 0.6}, {2.7, 4.9}},
        ComparisonCase{"lager-pint-studio-image",
                       SceneRequest{"lager", "pint", {"env.mode=image", "env.image=studio", "env.floor=false", "bubbles.carbonation=0"}},
                       64, 8192, {0.6, 1.3}, {0.5, 0.5}, {2.1, 5.3}},
        // The bar: glass 5.22 / 10.11, liquid 2.28 / 5.41 since supersamples are averaged in
        // scene-linear light (7.54 / 11.23 and 2.86 / 7.64 averaged after the tone map: the
        // base's band of bright stripes came out 15 levels dark). Against 16384 paths (stop
        // 44; 2048 before, whose lamps' fireflies were most of the head's figure): glass
        // 5.15 / 10.11, liquid 2.20 / 5.36, head 1.82 / 3.57 (4.44 / 7.89 against 2048). The
        // glass is its 28 pixels of rim and base band: one base pixel where the picture's
        // refracted stripes fall a pixel from the reference's (43.8) is a third of its mean.
        // With adaptive supersampling (the pixels whose 2 x 2 samples disagree, and their
        // neighbours, drawn again at 4 x 4: core/output/refine): glass 2.31 / 4.97, liquid
        // 0.97 / 2.13 (4.15 / 6.97 and 1.18 / 2.32 without the neighbours). With the way out
        // of an internal reflection taking its Fresnel: 2.16 / 4.57 and 0.93 / 2.12.
        ComparisonCase{"lager-pint-bar", SceneRequest{"lager", "pint", {"env.mode=image", "env.image=bar"}},
                       64, 16384, {2.2, 4.9}, {1.0, 2.2}, {2.0, 4.0}},
        // A hazy drink (a nearly white haze, 30 /m): its liquid 4.03 / 7.46 (4.6 / 8.6 while
        // the drink's colour was one coefficient per channel, fitted at 4 cm). With the
        // preset's old haze (45 /m, albedo [0.95, 0.72, 0.38]) 5.9 / 11.1 since the lights
        // reach the haze with their irradiance over 4 pi, 9.3 / 16.6 with pi times that,
        // 31.5 / 42.0 when the haze's light decayed along a straight chord, not as
        // diffusion's kappa. The reference's own noise in a scattering drink is part of
        // it: against 256 paths the liquid was 4.05 / 7.47 and the head 3.45 / 10.65;
        // against 1024, 3.12 / 5.85 and 2.36 / 7.27; against the 4096 stored since stop 43,
        // 2.80 / 4.83 and 2.39 / 7.37; the head 2.03 / 6.08 since it sees the surroundings
        // from its own middle. Glass (4 pixels) not checked here. The liquid 2.82 / 4.90 ->
        // 1.31 / 2.45 since the haze's light falls off from the wall inwards (a cylinder's
        // diffusion field, each light from its side: core/liquid/haze.hpp) instead of one
        // tint at 0.7 of the mean radius for the whole drink (1.51 / 2.46 with 8 parts a
        // segment instead of 4).
        ComparisonCase{"hefeweizen-weizen", SceneRequest{"hefeweizen", "weizen", {"bubbles.carbonation=0"}}, 64, 4096,
                       {0, 0}, {1.7, 3.9}, {1.5, 2.4}},
        // A thinly hazy, strongly absorbing drink (haze 4 /m), against 1024 paths (7.6 s):
        // glass 1.60 / 5.59, liquid 1.66 / 3.23, head 2.65 / 7.21 (1.62 / 5.78, 1.73 / 3.41,
        // 2.62 / 7.45 with the reference's seed 2). The liquid was 2.66 / 4.81 while the
        // reference sampled its free flights through the drink's absorption and the haze
        // together: most of that was the reference's grain; now it samples the haze and
        // weighs the colour (core free_flight). Before: glass 2.92 / 9.76, head 2.71 / 7.61
        // (the liquid was 3.13 / 5.53
        // while the reference's paths out through the foot missed the floor: the bowl's
        // underside mirrors the foot and the floor under it, which came out black; at 256
        // paths 5.1 / 10.1: half of it the reference's noise; 5.8 / 11.8 with the lights pi
        // times too bright in the haze, 8.6 / 15.3 along a straight chord). (The hefeweizen
        // above at 1024 paths, 66 s: liquid 3.10 / 5.73; 3.30 / 5.61 before.) The head was 3.55 / 9.39 while
        // the diffusion's faces took a light's whole irradiance beside its single scattering.
        // Since supersamples are averaged in scene-linear light: glass 1.20 / 3.04 (the foot's
        // bright far edge no longer dimmed by the tone map of each sample), liquid 1.65 /
        // 3.19, head 2.70 / 7.24. Against 4096 paths (stop 43, after the head's wall
        // boundary): glass 1.15 / 2.56, liquid 1.38 / 2.99, head 2.25 / 5.31 (1.77 / 3.92
        // since it sees the surroundings from its own middle). The liquid 1.30 / 2.82 ->
        // 1.82 / 2.87 since the haze's light falls off from the wall (a thin haze in a deep
        // colour: a little less red scattered than the reference's).
        ComparisonCase{"amber-tulip", SceneRequest{"amber-ale", "tulip", {"bubbles.carbonation=0"}}, 64, 4096,
                       {1.0, 2.5}, {1.4, 2.3}, {1.8, 2.5}},
        // The heads close up against a reference of 1024 paths (at 256 its own noise was
        // half the figure: lager 2.86 / 5.91, stout 4.97 / 11.84): lager 1.84 / 4.31, within
        // the target; stout 3.74 / 9.34, its mean within it, its head's lower side
        // more saturated than the reference's (docs/REFERENCE.md). (Before the head's faces
        // took a light's irradiance less what its single scattering sends out: 2.46 / 4.84
        // and 4.27 / 11.27.)
        // Since supersamples are averaged in scene-linear light: lager 1.83 / 3.78, stout 3.70
        // / 9.61, the stout lit by the key alone 4.30 / 10.05. Since the glass wall is the
        // side's diffusion boundary (its light held at T / T_d, its extrapolation A zb) and
        // the top's key light takes the dome's slope (docs/REFERENCE.md, stop 43): 1.68 /
        // 3.39, 3.38 / 7.71 and 3.91 / 8.80; against references of 4096 paths (1024
        // before): 1.51 / 3.01, 3.13 / 7.86 and 3.70 / 9.09 (the stouts' liquids 2.49 /
        // 4.45 -> 2.20 / 3.45 and 1.56 / 2.82 -> 1.39 / 2.20: the reference's grain). Since
        // each head sees the surroundings from its own middle (VesselFrame::head_surround):
        // 1.40 / 2.59, 2.87 / 6.37 and 3.58 / 7.54; with the glasses' shadows in that view
        // (drink_columns) 1.40 / 2.60, 2.83 / 5.85 and 3.51 / 7.54; with the bubbles
        // pressed on the glass keeping the side's mean (cell_border_mean) 1.24 / 2.32, the
        // stouts' unchanged.
        ComparisonCase{"lager-head", SceneRequest{"lager", "pint", {}, {"eye=0,0.17,0.2", "target=0,0.14,0", "vfov=25"}},
                       48, 4096, {0, 0}, {0, 0}, {1.6, 2.5}},
        ComparisonCase{"stout-head", SceneRequest{"stout", "nonic", {}, {"eye=0,0.2,0.3", "target=0,0.14,0", "vfov=22"}},
                       48, 4096, {0, 0}, {0, 0}, {2.3, 3.8}},
        // The stout's head lit by the key alone (no strips, no backlight, a black sky: the
        // sweep lit by the key is the only other light), where a light's single
        // scattering counted twice shows: 4.31 / 10.04 (4.71 / 12.38 while it was).
        ComparisonCase{"stout-head-key",
                       SceneRequest{"stout", "nonic", {"strips.power=0", "backlight.power=0", "env.mode=constant", "env.color=0,0,0"},
                                    {"eye=0,0.2,0.3", "target=0,0.14,0", "vfov=22"}},
                       48, 4096, {0, 0}, {0, 0}, {3.0, 5.3}},
        // Condensation (the reference's beads are the picture's water lenses, its mist
        // scatters diffusely to either side): the cold pint glass 1.37 / 3.05, liquid 3.21 /
        // 6.62 (at 64 x 64 a bead is a pixel or two: the picture's few samples a pixel catch
        // a bead or miss it, the reference's 512 average them), head 2.81 / 5.56 (not
        // checked: 16 pixels); close up on the wall (beads several pixels wide) the drink
        // through the beads and the mist 2.89 / 5.35 (4.89 / 8.75 and 4.63 / 7.87 while the
        // picture lost the half of the mist's light that goes on through the wall). Against
        // 4096 paths (512 before, stop 43): glass 1.13 / 2.35, liquid 3.25 / 5.94, close up
        // 2.97 / 4.43. Since what a bead's steep rim reflects down into the wall stays with
        // the path (stop 44; it showed the studio's white, a speckle the reference has not):
        // glass 1.15 / 2.35, liquid 3.06 / 5.32, close up 2.86 / 4.47. Since the mist is lit
        // by all around it, the backdrop's lit paper included, not by the sky alone (stop
        // 46): glass 1.03 / 2.35, liquid 2.23 / 4.00, close up 1.74 / 2.85. With adaptive
        // supersampling (a bead's pixels drawn again at 4 x 4): glass 1.05 / 2.27, liquid
        // 1.64 / 2.77, close up 1.49 / 2.38.
        ComparisonCase{"cold-lager", SceneRequest{"cold-lager"}, 64, 4096, {1.2, 2.6}, {1.6, 2.8}, {0, 0}},
        ComparisonCase{"cold-lager-close", SceneRequest{"cold-lager", "", {}, {"eye=0,0.08,0.22", "target=0,0.08,0", "vfov=16"}},
                       64, 4096, {0, 0}, {1.5, 2.4}, {0, 0}},
        // The objects the reference marches (64x48): the droplets (the preset's view, and
        // close up), 1.16 / 2.04 and 1.87 / 3.87 (1.19 / 2.05 and 1.87 / 3.74 at 1024 and
        // 512 paths: what is left is the picture's, not the reference's noise); the molten
        // gob and its blowpipe 1.12 / 2.30 (1.39 / 2.91 at 32 paths). Since supersamples are
        // averaged in scene-linear light: 1.00 / 1.93, 1.62 / 3.03 and 1.22 / 1.71. Bounds:
        // about 10 % (the gob's a little more: its figure moves by a tenth with any change
        // in the last micrometre of its hits).
        ComparisonCase{"droplets-seed", SceneRequest{"droplets-seed"}, 64, 128, {0, 0}, {0, 0}, {0, 0}, {0.7, 1.1}, {0, 0}, 48},
        ComparisonCase{"droplets-seed-close",
                       SceneRequest{"droplets-seed", "", {}, {"eye=0,0.13,0.62", "target=-0.02,0.1,0.1", "vfov=7"}},
                       64, 128, {0, 0}, {0, 0}, {0, 0}, {1.1, 2.0}, {0, 0}, 48},
        ComparisonCase{"molten-gob", SceneRequest{"molten-gob"}, 64, 64, {0, 0}, {0, 0}, {0, 0}, {0, 0}, {1.4, 2.1}, 48},
        // A moment of a pour (fresh-pour at 1.5 s; 80 x 80, 12 s of reference): the stream,
        // a cloud drawn in the drink's material, falling into the head it builds. Over the
        // reference's seeds 1-3: glass 0.87-0.88 / 1.38-1.41, liquid 3.16-3.27 / 7.55-8.38
        // (a pour's bubbles all through it, each a few pixels of the reference's grain),
        // head 3.19-3.86 / 7.60-8.66 (a head still building), the stream (22 pixels)
        // 0.83-1.07 / 1.24-2.00: the stream as pale a cream as the picture draws it.
        // Bounds: the worst seed and about 10 %. Against 1536 paths (192 before, stop 43,
        // after the head's wall boundary): glass 0.84 / 1.22, liquid 2.59 / 7.70, head 2.05
        // / 4.43, the stream 0.85 / 1.23; bounds about 10 % over.
        // Wines and champagne in their own glasses (stop 51: scenes none of the changes above
        // was made against). Red wine against 16384 paths (1.90 / 4.87, 1.68 / 3.92 and
        // 1.93 / 5.34 for its liquid against 4096 paths of seeds 1-3: its 104 pixels are
        // few, the reference's grain a good part of that): glass 0.27 / 0.62, liquid 1.70 /
        // 4.75, 1.62 / 3.67 since the drink's surface mirrors the bowl's far wall from
        // inside (the light through it, `surface_reflection_out`), not the open studio; what
        // is left is the bowl's tip above the stem (five pixels 6-10 lighter than the
        // reference's) and the surface's band (about 12 lighter). Rose and champagne against
        // 4096 paths: glass 0.28 / 0.58 and liquid 0.97 / 2.61; glass 0.51 / 1.58 (1.05-1.88
        // over seeds 1-3) and liquid 0.38 / 0.69. Bounds about 10 % over (more on the
        // champagne's 76 pixels of glass).
        // The default pint from above (the golden pint_lager_above's view; stop 51), where
        // the head fills the picture and the rim rings it, against 2048 paths (165 s to
        // trace): glass (its 20 pixels clear of an edge: the rim is thinner than a pixel
        // here) 0.25 / 0.90, liquid 1.44 / 3.11, head 1.80 / 2.69 over 478 pixels.
        ComparisonCase{"lager-pint-above", SceneRequest{"lager", "pint", {}, {"eye=0.08,0.32,0.2", "target=0,0.07,0"}},
                       64, 2048, {0.4, 1.1}, {1.6, 3.4}, {2.0, 3.0}},
        ComparisonCase{"red-wine", SceneRequest{"red-wine"}, 64, 16384, {0.4, 1.0}, {1.8, 4.1}, {0, 0}},
        ComparisonCase{"rose-wine", SceneRequest{"rose-wine"}, 64, 4096, {0.4, 0.9}, {1.1, 2.9}, {0, 0}},
        ComparisonCase{"champagne", SceneRequest{"champagne"}, 64, 4096, {0.6, 2.0}, {0.5, 0.8}, {0, 0}},
        ComparisonCase{"fresh-pour", SceneRequest{}, 80, 1536, {0.7, 1.1}, {1.7, 3.4}, {2.0, 4.0}, {0, 0}, {0.5, 0.9}, 0,
                       "fresh-pour", 1.5}),
    [](const ::testing::TestParamInfo<ComparisonCase>& i) { return case_file_name(i.param.name); });

}  // namespace
}  // namespace draught::test
