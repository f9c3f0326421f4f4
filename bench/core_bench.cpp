// Google Benchmark figures for the CPU side of a frame: building the vessel from a
// profile, solving the fill height, building the fill table, and the reference
// intersector per ray. GPU frame times come from `draught bench`. Results:
// docs/PERFORMANCE.md.
#include "core/bubbles/bubble_view.hpp"
#include "core/environment/floor_light.hpp"
#include "core/environment/matcap.hpp"
#include "core/environment/reflection.hpp"
#include "core/environment/studio.hpp"
#include "core/scene/camera.hpp"
#include "core/vessel/fill_table.hpp"
#include "core/scene/frame.hpp"
#include "core/params/preset.hpp"
#include "core/sim/scene_simulation.hpp"
#include "core/sim/simulation.hpp"
#include "core/params/timeline.hpp"

#include <benchmark/benchmark.h>

using namespace draught;

namespace {

Params glass_params(const char* glass) { return resolve_scene({"lager", glass, {}, {}}); }

void BM_BuildVessel(benchmark::State& state) {
  Params p = glass_params("wine");
  for (auto _ : state) benchmark::DoNotOptimize(build_vessel(p.glass));
}
BENCHMARK(BM_BuildVessel);

void BM_FillHeight(benchmark::State& state) {
  Vessel v = build_vessel(glass_params("wine").glass);
  double f = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(v.fill_height(f));
    f = f > 0.9 ? 0.1 : f + 0.01;
  }
}
BENCHMARK(BM_FillHeight);

// The 64 x 64 offset(tilt, volume) table, built whenever the glass changes; the budget is
// 20 ms on one core. Median: --benchmark_repetitions=9 --benchmark_report_aggregates_only.
void BM_BuildFillTable(benchmark::State& state, const char* glass) {
  const Vessel v = build_vessel(glass_params(glass).glass);
  for (auto _ : state) benchmark::DoNotOptimize(build_fill_table(v));
}
BENCHMARK_CAPTURE(BM_BuildFillTable, pint, "pint")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildFillTable, wine, "wine")->Unit(benchmark::kMillisecond);

void BM_MakeFrame(benchmark::State& state) {
  Params p = glass_params("pint");
  for (auto _ : state) benchmark::DoNotOptimize(make_frame(p));
}
BENCHMARK(BM_MakeFrame);

// What a head's surroundings cost a frame: the backdrop's share seen from one more point
// (16 x 32 directions, one pass), as environment_frame computes it for each head and once
// for the scene's centre (EnvironmentFrame::media_seen_from); against the scene's own
// surround (32 x 64, three rounds of the paper's bounce).
void BM_SurroundSeenFromAHead(benchmark::State& state) {
  const FrameState f = make_frame(glass_params("pint"));
  const Studio studio(f.params);
  const glm::dvec3 at = head_middle(f.vessels[0]);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        backdrop_share(studio, f.lights, f.backdrop, *f.environment.paper_bounce, at, 16, drink_columns(f.vessels)));
}
BENCHMARK(BM_SurroundSeenFromAHead)->Unit(benchmark::kMicrosecond);

void BM_SurroundOfTheScene(benchmark::State& state) {
  const FrameState f = make_frame(glass_params("pint"));
  const Studio studio(f.params);
  const SkyIrradiance sky = sky_irradiance(studio);
  for (auto _ : state) {
    const PaperBounceMap bounce = paper_bounce_map(f.lights, f.backdrop, sky, f.lights.aim);
    benchmark::DoNotOptimize(surround_irradiance(studio, sky, f.lights, f.backdrop, bounce, f.lights.aim));
  }
}
BENCHMARK(BM_SurroundOfTheScene)->Unit(benchmark::kMicrosecond);

// What an app's frame costs the CPU before it draws: SceneSimulation::frame() of a still
// scene (the objects' frames, the light rig, the studio's light and each head's view of it).
void BM_SceneFrame(benchmark::State& state, const char* preset) {
  const SceneSimulation sim(resolve_scene_objects({preset, "", {}, {}}));
  for (auto _ : state) benchmark::DoNotOptimize(sim.frame());
}
BENCHMARK_CAPTURE(BM_SceneFrame, pint, "lager")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SceneFrame, flight, "flight")->Unit(benchmark::kMicrosecond);

// One simulation second (240 fixed steps) of the shake timeline: what a viewer spends
// per second of motion on the CPU (surface, slosh, spill check with its exact capacity).
void BM_SimulateOneSecond(benchmark::State& state) {
  const Timeline tl = load_timeline("shake-and-settle");
  const Params base = glass_params("pint");
  for (auto _ : state) {
    state.PauseTiming();  // the glass's table is built once per glass, not per second
    Simulation sim(base);
    TimelineDriver driver(tl, sim.vessel().r_outer.front());
    state.ResumeTiming();
    for (int i = 0; i < 240; ++i) {
      const double t = sim.time() + Simulation::kStep;
      sim.step(driver.sample(t + 0.5));  // in the middle of the shake
    }
    benchmark::DoNotOptimize(sim.frame());
  }
}
BENCHMARK(BM_SimulateOneSecond)->Unit(benchmark::kMillisecond);

// Where a standing lager's bubbles appear at 512x512 (refraction solved per bubble on the
// CPU each frame), and one simulation step of the bubble field alone.
void BM_BubbleSprites(benchmark::State& state) {
  const FrameState f = make_frame(glass_params("pint"));
  state.counters["bubbles"] = double(f.vessels.front().bubbles.size());
  for (auto _ : state) benchmark::DoNotOptimize(bubble_sprites(f, 512, 512));
}
BENCHMARK(BM_BubbleSprites)->Unit(benchmark::kMillisecond);

// The reference intersector over a 64x64 view of the pint (rays per second).
void BM_ReferenceFirstHit(benchmark::State& state) {
  FrameState f = make_frame(glass_params("pint"));
  SceneGeometry geo = scene_geometry(f);
  CameraBasis cam = camera_basis(f, 64, 64);
  for (auto _ : state)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) benchmark::DoNotOptimize(first_hit(geo, camera_ray(cam, x + 0.5, y + 0.5, 64, 64)));
  state.SetItemsProcessed(state.iterations() * 64 * 64);
}
BENCHMARK(BM_ReferenceFirstHit);

// The floor's light map (shadows and caustics traced from the rig's lights) at a still's
// and an interactive budget: the default pint and the four-glass flight (threads 0: all).
void BM_FloorLight(benchmark::State& state, const char* preset, int photons, int threads = 0, bool draft = false) {
  const FrameState f = make_frame(resolve_scene_objects({preset, "", {}, {}}));
  FloorLightSettings s;
  s.photons = photons;
  s.threads = threads;
  if (draft) s = floor_light_draft(s, photons);  // as SceneTextures traces a draft
  for (auto _ : state) benchmark::DoNotOptimize(compute_floor_light(f, s));
}
BENCHMARK_CAPTURE(BM_FloorLight, pint_still, "lager", kFloorPhotonsStill)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, pint_interactive, "lager", kFloorPhotonsInteractive)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, flight_still, "flight", kFloorPhotonsStill)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, flight_interactive, "flight", kFloorPhotonsInteractive)->Unit(benchmark::kMillisecond)->UseRealTime();
// The marched bodies' shadows: the droplets in front of a pint (the web page's draft and
// still budgets: one thread there), the droplets alone, and a cooled gob on its blowpipe.
BENCHMARK_CAPTURE(BM_FloorLight, pint_web_draft, "lager", kFloorPhotonsStill / 100, 1, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, droplets_still, "droplets", kFloorPhotonsStill)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, droplets_web_draft, "droplets", kFloorPhotonsStill / 100, 1, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, droplets_seed_still, "droplets-seed", kFloorPhotonsStill)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLight, gob_cooled_still, "gob-cooled", kFloorPhotonsStill)->Unit(benchmark::kMillisecond)->UseRealTime();

// A still's map refined in the web page's batches (kFloorPhotonsStill / 500 photons, one
// thread): a batch traced alone (the map merged later), and a batch with the map merged
// after it, as each refining frame did before the merge waited for an upload.
void BM_FloorLightBatch(benchmark::State& state, bool merge) {
  const FrameState f = make_frame(resolve_scene_objects({"lager", "", {}, {}}));
  FloorLightSettings s;
  s.photons = kFloorPhotonsStill / 500;
  s.threads = 1;
  FloorLightTrace trace(f, s);
  for (auto _ : state) {
    trace.add_batch();
    if (merge) benchmark::DoNotOptimize(trace.map());
  }
}
BENCHMARK_CAPTURE(BM_FloorLightBatch, traced, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_FloorLightBatch, traced_and_merged, true)->Unit(benchmark::kMillisecond)->UseRealTime();

// What the MatCap tier pays each frame to learn that its baked MatCap still holds: the
// bake's key (the surroundings' and lights' parameters as text) against the last one.
void BM_MatCapStillHolds(benchmark::State& state) {
  const FrameState f = make_frame(resolve_scene_objects({"lager", "", {}, {}}));
  const glm::dvec3 centre = surroundings_centre(f);
  matcap_for(f.params, f.lights, f.backdrop, centre);  // baked once
  for (auto _ : state) benchmark::DoNotOptimize(matcap_for(f.params, f.lights, f.backdrop, centre));
}
BENCHMARK(BM_MatCapStillHolds)->Unit(benchmark::kMicrosecond);

// Loading a timeline of N tilts (parse, validate, chain the tilts): linear in N, so the
// time per tilt stays flat from 1,000 to 100,000.
void BM_ParseTimelineTilts(benchmark::State& state) {
  const int n = int(state.range(0));
  std::string text = R"({"draught_timeline": 1, "name": "many", "duration": 600, "actions": [)";
  for (int i = 0; i < n; ++i)
    text += (i ? "," : "") + std::string(R"({"at": )") + std::to_string(i * 0.005) +
            R"(, "action": "tilt", "angle": )" + std::to_string(i % 30) + R"(, "duration": 0.002})";
  text += "]}";
  for (auto _ : state) benchmark::DoNotOptimize(parse_timeline(text, "many.json"));
  state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_ParseTimelineTilts)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
