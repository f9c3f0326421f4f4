#include "core/sim/scene_simulation.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace draught {

MotionSample placed(const MotionSample& m, const Placement& at) {
  if (at.yaw == 0 && at.position == glm::vec3(0.0f)) return m;
  MotionSample out = m;
  const glm::dquat yaw = glm::angleAxis(glm::radians(double(at.yaw)), glm::dvec3(0, 1, 0));
  out.pose.orientation = m.pose.orientation * yaw;
  out.pose.position = m.pose.position + glm::dvec3(at.position);
  return out;
}

SceneSimulation::SceneSimulation(const Scene& s) { set_scene(s); }

void SceneSimulation::set_scene(const Scene& s) {
  const bool same_list = s.objects.size() == scene_.objects.size() && sims_.size() == s.objects.size();
  if (!same_list) {
    sims_.assign(s.objects.size(), std::nullopt);
    trails_.assign(s.objects.size(), std::nullopt);
    clouds_.clear();  // (sources move, they do not copy)
    clouds_.resize(s.objects.size());
    releases_.assign(s.objects.size(), Release{});
  }
  for (size_t i = 0; i < s.objects.size(); ++i) {
    const VesselObject* v = as_vessel(s.objects[i]);
    if (const PointCloudObject* c = as_cloud(s.objects[i])) {
      // A new source when its parameters or placement changed (a cloud has no state worth
      // keeping across an edit: a gob restarts, a file is read again).
      const Placement& at = s.objects[i].placement;
      const bool same = clouds_[i] && same_list && as_cloud(scene_.objects[i]) &&
                        point_cloud_params_json(as_cloud(scene_.objects[i])->params) == point_cloud_params_json(c->params) &&
                        scene_.objects[i].placement.position == at.position && scene_.objects[i].placement.yaw == at.yaw;
      if (!same) {
        clouds_[i].emplace(c->params, at.position, at.yaw);
        clouds_[i]->advance_to(time() - clock_origin_);
      }
    } else {
      clouds_[i].reset();
    }
    if (!v) {
      sims_[i].reset();
      if (const DropletsObject* d = as_droplets(s.objects[i])) {
        if (trails_[i]) trails_[i]->set_params(d->params);
        else trails_[i].emplace(d->params, pointer_);
      } else {
        trails_[i].reset();
      }
      continue;
    }
    trails_[i].reset();
    if (sims_[i]) {
      sims_[i]->set_params(v->params);
    } else {
      sims_[i].emplace(v->params);
    }
    // At rest at its placement until motion arrives.
    if (!same_list) sims_[i]->place(placed(MotionSample{}, s.objects[i].placement).pose);
  }
  scene_ = s;
  scene_.selected = std::clamp(s.selected, 0, std::max(0, int(s.objects.size()) - 1));
}

void SceneSimulation::select(int object) {
  const int next = std::clamp(object, 0, std::max(0, int(scene_.objects.size()) - 1));
  const size_t prev = size_t(scene_.selected);
  if (next != scene_.selected && prev < releases_.size()) releases_[prev] = {time(), last_input_.pose};
  scene_.selected = next;
  last_input_ = MotionSample{};
}

MotionSample SceneSimulation::released(size_t i, double t) {
  MotionSample m;
  m.time = t;
  if (i >= releases_.size() || releases_[i].start < 0) return m;
  const Release r = releases_[i];
  // Eased from where it was let go to upright; velocities by central differences.
  auto pose_at = [&](double time) {
    const double u = std::clamp((time - r.start) / kSettleSeconds, 0.0, 1.0);
    const double s = u * u * (3 - 2 * u);
    return Pose{glm::slerp(r.from.orientation, glm::dquat(1, 0, 0, 0), s), r.from.position * (1 - s)};
  };
  if (t - r.start >= kSettleSeconds) {
    releases_[i].start = -1;
    return m;
  }
  return sample_path(t, pose_at);
}

Simulation* SceneSimulation::vessel(int i) {
  return i >= 0 && i < int(sims_.size()) && sims_[size_t(i)] ? &*sims_[size_t(i)] : nullptr;
}
const Simulation* SceneSimulation::vessel(int i) const {
  return i >= 0 && i < int(sims_.size()) && sims_[size_t(i)] ? &*sims_[size_t(i)] : nullptr;
}

Simulation& SceneSimulation::selected_vessel() {
  if (Simulation* s = vessel(scene_.selected)) return *s;
  for (auto& s : sims_)
    if (s) return *s;
  throw std::logic_error("the scene has no vessel");
}

void SceneSimulation::settle_bubbles(double seconds) {
  for (auto& s : sims_)
    if (s) s->settle_bubbles(seconds);
}

const CloudSource* SceneSimulation::cloud(int i) const {
  return i >= 0 && i < int(clouds_.size()) && clouds_[size_t(i)] ? &*clouds_[size_t(i)] : nullptr;
}

void SceneSimulation::begin_at(double t) {
  if (!std::isfinite(t)) return;
  for (auto& s : sims_)
    if (s) s->skip_to(t);
  trail_time_ = t;
  clock_origin_ = t;
}

void SceneSimulation::step_clouds() {
  const double t = time() - clock_origin_;
  for (auto& c : clouds_)
    if (c) c->advance_to(t);
}

const DropletTrail* SceneSimulation::trail(int i) const {
  return i >= 0 && i < int(trails_.size()) && trails_[size_t(i)] ? &*trails_[size_t(i)] : nullptr;
}

void SceneSimulation::step_trails(const std::vector<MotionSample>* each, const MotionSample* all) {
  for (size_t i = 0; i < trails_.size(); ++i) {
    if (!trails_[i]) continue;
    const MotionSample* m = each ? (i < each->size() ? &(*each)[i] : nullptr) : all;
    trails_[i]->step(m && m->pointer ? *m->pointer : pointer_);
  }
  trail_time_ += Simulation::kStep;
}

void SceneSimulation::step(const MotionSample& m, double drink_rate) {
  step_trails(nullptr, &m);
  for (size_t i = 0; i < sims_.size(); ++i) {
    if (!sims_[i]) continue;
    const Placement& at = scene_.objects[i].placement;
    if (int(i) == scene_.selected) {
      last_input_ = m;
      sims_[i]->step(placed(m, at), drink_rate);
    } else {
      sims_[i]->step(placed(released(i, m.time), at), 0);
    }
  }
  step_clouds();
}

void SceneSimulation::step_each(const std::vector<MotionSample>& motions, const std::vector<double>& drink_rates) {
  const double time = motions.empty() ? this->time() + Simulation::kStep : motions.front().time;
  step_trails(&motions, nullptr);
  for (size_t i = 0; i < sims_.size(); ++i) {
    if (!sims_[i]) continue;
    const Placement& at = scene_.objects[i].placement;
    MotionSample m;
    if (i < motions.size()) {
      m = motions[i];
    } else {
      m.time = time;
    }
    sims_[i]->step(placed(m, at), i < drink_rates.size() ? drink_rates[i] : 0.0);
  }
  step_clouds();
}

void SceneSimulation::advance(InputDriver& driver, double t, double drink_rate) {
  // Fixed steps as Simulation::advance, every object on the same clock.
  if (!std::isfinite(t) || scene_.objects.empty()) return;
  if (t - time() > Simulation::kMaxCatchUp) {
    for (auto& s : sims_)
      if (s) s->skip_to(t - Simulation::kMaxCatchUp);
    trail_time_ = std::max(trail_time_, t - Simulation::kMaxCatchUp);
  }
  while (time() + Simulation::kStep <= t + 1e-9) step(driver.sample(time() + Simulation::kStep), drink_rate);
}

FrameState SceneSimulation::frame() const {
  std::vector<VesselFrame> vessels;
  for (size_t i = 0; i < sims_.size(); ++i)
    if (sims_[i]) {
      vessels.push_back(sims_[i]->frame());
      vessels.back().placement = scene_.objects[i].placement;
    }
  FrameState f = assemble_frame(scene_.params, std::move(vessels), scene_.selected, time(), &environment_cache_);
  for (size_t i = 0; i < trails_.size(); ++i)
    if (trails_[i]) {
      const Placement& at = scene_.objects[i].placement;
      const DropletParams& p = as_droplets(scene_.objects[i])->params;
      f.droplets.push_back({p, at.position, at.yaw, droplet_field_of(p, trails_[i]->spheres(at.position, at.yaw))});
    }
  for (const auto& c : clouds_)
    if (c)
      for (CloudFrame& k : c->frames())
        if (int(f.clouds.size()) < contract::kMaxClouds) f.clouds.push_back(std::move(k));
  // The vessels' streams (a pour, a spill), as long as there is room for them.
  for (const auto& s : sims_)
    if (s)
      for (CloudFrame& c : s->streams())
        if (int(f.clouds.size()) < contract::kMaxClouds) f.clouds.push_back(std::move(c));
  return f;
}

double SceneSimulation::time() const {
  for (const auto& s : sims_)
    if (s) return s->time();
  return trail_time_;
}

}  // namespace draught
