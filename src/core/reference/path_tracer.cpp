#include "core/reference/path_tracer.hpp"

#include "core/condensation/wall_grid.hpp"
#include "core/environment/environment_sampling.hpp"

#include "core/environment/lights.hpp"
#include "core/environment/studio.hpp"
#include "core/foam/head_volume.hpp"
#include "core/math/basis.hpp"
#include "core/math/channels.hpp"
#include "core/math/random.hpp"
#include "core/output/tonemap.hpp"
#include "core/reference/bodies.hpp"
#include "core/reference/decal_optics.hpp"
#include "core/reference/media.hpp"
#include "core/reference/free_flight.hpp"
#include "core/reference/optics.hpp"
#include "core/math/constants.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>
#include <thread>

namespace draught {

namespace {

// Henyey-Greenstein: phase value for the cosine between the incoming travel direction
// and the scattered one, and a sample of it.
double hg_phase(double c, double g) {
  const double g2 = g * g;
  return (1 - g2) / (4 * kPi * std::pow(std::max(1 + g2 - 2 * g * c, 1e-12), 1.5));
}
glm::dvec3 sample_hg(const glm::dvec3& d, double g, Rng& rng) {
  const double u = rng.uniform(), phi = 2 * kPi * rng.uniform();
  double c;
  if (std::fabs(g) < 1e-3) {
    c = 1 - 2 * u;
  } else {
    const double s = (1 - g * g) / (1 - g + 2 * g * u);
    c = (1 + g * g - s * s) / (2 * g);
  }
  return around(d, std::clamp(c, -1.0, 1.0), phi);
}

// Power heuristic (beta = 2) weight of a strategy with density a against one with b.
double power_weight(double a, double b) { return a * a / (a * a + b * b); }

// Everything the tracer needs of one vessel, prepared once per frame.
// A glass and its drink (VesselOptics) and what only paths see of them: the head's
// albedo and phase, and the beads and fog of condensation.
struct VesselMedia : VesselOptics {
  glm::dvec3 foam_albedo{1.0};
  double foam_g = 0;
  // Condensation on the outer wall (null: a dry glass): the picture's bead grid and fog
  // map (core/condensation/wall_grid, the twins of what its textures hold).
  std::shared_ptr<const CondensationState> cold;
  std::vector<glm::vec4> beads;
  std::vector<std::uint8_t> fog;
};

// Where the last vertex that sampled the lights was, so a path that then meets a light
// weighs that strategy against its own (multiple importance sampling).
struct MisVertex {
  double pdf = -1;  // density of the direction the path took there; < 0: no such vertex
  glm::dvec3 p{0.0};
  glm::dvec3 n{0.0};  // the surface's normal; 0 in a medium (a head)
};

// Where a path leaves a stretch of air: a scattering in a head, a big bubble's cap, or
// neither (it reached the stretch's end).
struct AirEvent {
  enum Kind { None, Scatter, Cap } kind = None;
  double t = kInf;
  int obj = -1;
  glm::dvec3 n{0.0};  // the cap's normal (world)
};

class Tracer {
 public:
  Tracer(const FrameState& f, const ReferenceSettings& s, const CameraBasis& cam)
      : frame_(f), settings_(s), geo_(scene_geometry(f, true)), studio_(f.params), environment_(studio_),
        lights_(f.lights.lights), cam_(cam), bodies_(f) {
    for (size_t i = 0; i < f.vessels.size(); ++i) {
      const VesselFrame& vf = f.vessels[i];
      heads_.emplace_back(vf, geo_.vessels[i]);
      VesselMedia m;
      static_cast<VesselOptics&>(m) = vessel_optics(vf);
      // foam.color is the colour a deep head shows: its reflectance, not one scattering's.
      m.foam_albedo = foam_single_scattering_albedo(glm::dvec3(vf.params.foam.color), vf.params.foam.anisotropy);
      m.foam_g = vf.params.foam.anisotropy;
      if (vf.condensation) {
        m.cold = vf.condensation;
        m.beads = bead_grid(*vf.condensation, vf.vessel);
        m.fog = fog_texels(*vf.condensation);
      }
      media_.push_back(std::move(m));
    }
  }

  // The radiance arriving at the eye along the camera ray.
  glm::dvec3 radiance(Ray ray, Rng& rng) const {
    glm::dvec3 L(0.0), thr(1.0);
    MediumKind medium = MediumKind::Air;
    int obj = -1;
    // Multiple importance sampling of the lights: the last vertex that sampled them
    // (backdrop or head); none for the camera, or after a mirror or a refraction.
    MisVertex mis;
    int surfaces = 0, scatters = 0;
    // The drink it was last in, and how its light is shared between that drink's colour
    // bands (DrinkAbsorption::onward).
    int drink_obj = -1;
    glm::dvec3 drink_left(0.5);
    // With the screen as background, a light is seen only as the picture's are: in a
    // reflection off a surface seen from the air, or by a path a head scattered (the other
    // half of its light sampling).
    bool sees_lights = false;
    // The camera's own ray, before it meets anything: it passes the lights kept out of
    // the shot (AreaLight::camera_visible; the picture's lights_seen the same).
    bool from_camera = true;
    const glm::dvec3 eye = ray.o;
    for (;;) {
      glm::dvec4 attrs(0.0);  // a cloud's surface: its temperature and colour there
      const Hit h = bodies_.nearest(geo_, ray, kRestartEps, medium, obj, attrs);
      // A path inside a glass or drink that meets none of its surfaces has slipped out
      // (a grazing turn about a smooth normal can leave the frustum's side), as has one in
      // a droplet or a blob whose march ran out of steps: it leaves into the studio from
      // where it is, as the picture's does.
      const double t_end = h.valid() ? h.t : (medium == MediumKind::Air ? kInf : 0.0);
      // The medium along the segment: absorption, or a scattering event before its end.
      if (medium == MediumKind::Glass) {
        thr *= glm::exp(-media_[size_t(obj)].glass_absorption * t_end);
      } else if (medium == MediumKind::Droplet || medium == MediumKind::Cloud) {
        bodies_.chord(medium, obj, t_end, attrs.x, thr, L);
      } else if (medium == MediumKind::Liquid) {
        const VesselMedia& m = media_[size_t(obj)];
        if (drink_obj != obj) {  // a drink the path has not crossed yet: its colour from the start
          drink_obj = obj;
          drink_left = glm::dvec3(media_[size_t(obj)].drink.colour.share);
        }
        double t_scatter;
        if (!liquid_free_flight(m.drink, drink_left, t_end, thr, t_scatter, rng)) {
          if (++scatters > settings_.max_scatters) break;
          ray.o = ray.at(t_scatter);
          ray.d = sample_hg(ray.d, 0.0, rng);  // haze: isotropic
          mis.pdf = -1;                        // no light sampling inside a drink (it sits behind an interface)
          continue;
        }
      } else {
        // A light's front before the next surface ends the stretch there.
        double t_light = t_end;
        const int light = nearest_light(ray, t_light, from_camera);
        // The screen card: an emitter found by the paths alone (no light sampling of it).
        double t_screen = 0;
        glm::dvec2 uv;
        const bool screen = frame_.screen.intersect(ray.o, ray.d, kRestartEps, t_screen, uv) && t_screen < t_light;
        if (screen) t_light = t_screen;
        const AirEvent e = air_segment(ray, t_light, rng);
        if (e.kind == AirEvent::Scatter) {
          from_camera = false;
          if (++scatters > settings_.max_scatters) break;
          const VesselMedia& m = media_[size_t(e.obj)];
          thr *= m.foam_albedo;
          const glm::dvec3 p = ray.at(e.t);
          L += thr * direct_light(p, glm::dvec3(0.0), ray.d, m.foam_g, rng);
          ray.o = p;
          const glm::dvec3 d = sample_hg(ray.d, m.foam_g, rng);
          mis = {hg_phase(glm::dot(ray.d, d), m.foam_g), p, glm::dvec3(0.0)};
          sees_lights = true;
          ray.d = d;
          if (!roulette(thr, surfaces + scatters, rng)) break;
          continue;
        }
        if (e.kind == AirEvent::Cap) {
          if (++surfaces > settings_.max_surfaces) break;
          // A thin film of the drink: reflected by both faces, else straight through.
          const double F = fresnel_dielectric(std::fabs(glm::dot(e.n, ray.d)), 1.0, media_[size_t(e.obj)].liquid_ior);
          ray.o = ray.at(e.t);
          if (rng.uniform() < 2 * F / (1 + F)) {
            from_camera = false;
            ray.d = reflect_dir(ray.d, e.n);
            mis.pdf = -1;
            sees_lights = false;
          }
          continue;
        }
        if (screen) {  // the path sees the screen
          L += thr * frame_.screen.card_radiance(uv);
          break;
        }
        if (light >= 0) {  // the path sees a light
          if (frame_.screen.mode != ScreenMode::Background || sees_lights)
            L += thr * lights_[size_t(light)].radiance * light_weight(mis, light, ray.d);
          break;
        }
      }
      if (!h.valid()) {  // out into the studio
        L += thr * surroundings(ray.d, mis);
        break;
      }
      const glm::dvec3 p = ray.at(h.t);
      from_camera = false;
      if (h.m == Material::Floor) {  // the backdrop: Lambertian
        // The checker floor fades into the studio with distance (as the picture's); under an
        // environment image the floor fades into the image: the path goes on through it.
        if (geo_.backdrop.plane &&
            rng.uniform() >= Studio::floor_visibility(glm::length(p - eye))) {
          if (studio_.image) {
            L += thr * studio_.sky(ray.d);
            break;
          }
          L += thr * glm::dvec3(studio_.env.ground);
          break;
        }
        const glm::dvec3 albedo = geo_.backdrop.albedo(p);
        L += thr * albedo * direct_light(p, h.n, ray.d, 0.0, rng);
        thr *= albedo;  // cosine-weighted bounce: albedo / pi x cos / pdf = albedo
        const double cos_t = std::sqrt(rng.uniform());
        ray.o = p;
        ray.d = around(h.n, cos_t, 2 * kPi * rng.uniform());
        mis = {cos_t / kPi, p, h.n};
        if (!roulette(thr, surfaces + scatters, rng)) break;
        continue;
      }
      if (++surfaces > settings_.max_surfaces) break;
      if (h.m == Material::Droplet || h.m == Material::Cloud) {  // water or a blob against the air
        sees_lights = bodies_.cross(h, attrs, ray, medium, obj, thr, rng);
        mis.pdf = -1;
        continue;
      }
      // A dielectric interface (glass, liquid surface, a cut face).
      const VesselMedia& m = media_[size_t(h.object)];
      const VesselGeometry& g = geo_.vessels[size_t(h.object)];
      const bool below = g.liquid.below(m.local_point(p));
      const MediumKind next = medium_across(h.m, medium, below);
      const glm::dvec3 n = glm::dot(h.n, ray.d) < 0 ? h.n : -h.n;
      const double n1 = m.ior(medium), n2 = m.ior(next);
      const double F = fresnel_dielectric(-glm::dot(n, ray.d), n1, n2);
      ray.o = p;
      if (h.m == Material::GlassOuter && m.cold) {
        const ColdWall turn = cold_wall(m, h.object, p, n, ray, medium, obj, thr, rng);
        if (turn == ColdWall::Absorbed) break;
        if (turn == ColdWall::Turned) {
          sees_lights = medium == MediumKind::Air;
          mis.pdf = -1;
          if (!roulette(thr, surfaces + scatters, rng)) break;
          continue;
        }
      }
      // A decal on the wall: from the air it lies under the surface's gloss (Fresnel
      // first); from inside the glass or the drink the ink, frost or metal meets the
      // path first (no total internal reflection off a painted face).
      double u = rng.uniform();
      const bool wall = h.m == Material::GlassOuter || h.m == Material::GlassInner;
      const DecalSample decal = g.decals && wall ? g.decals->sample(*g.vessel, h.m == Material::GlassInner, m.local_point(p))
                                                 : DecalSample{};
      if (meets_decal(u, F, decal.cover, medium == MediumKind::Air)) {
        if (!decal_event(decal, n, next, h.object, ray, medium, obj, thr, L, mis, rng)) break;
        if (!roulette(thr, surfaces + scatters, rng)) break;
        continue;
      }
      if (u >= F && h.m == Material::GlassBottom && on_floor(p)) {
        // Out through a foot's underside where it stands on the floor: the path meets the
        // floor at once (its intersection lies within kRestartEps, so the search would miss it).
        if (!floor_under_foot(p, m.ior(MediumKind::Glass), thr, ray, rng)) break;
        if (!roulette(thr, surfaces + scatters, rng)) break;
        sees_lights = false;
        mis.pdf = -1;
        continue;
      }
      sees_lights = fresnel_turn(ray, n, n1, n2, F, u, next, h.object, medium, obj);
      mis.pdf = -1;
    }
    return L;
  }

 private:
  enum class ColdWall { Bare, Turned, Absorbed };
  // A cold glass's outer wall at p (n: the wall's normal facing the path), from the air
  // or from inside the glass: the mist scatters FOG_SCATTER of the light of a fully
  // fogged point (cleared round the beads, as the picture's), diffusely, half back and
  // half on through the wall (the FOG_ALBEDO of it left); a bead is a water lens: its
  // cap (the picture's normal, core bead_at) and the water-glass face each reflect or pass
  // by Fresnel (a ray the cap turns back re-enters the glass). Turned: the path goes on
  // from p (the caller has set ray.o there; its direction, medium and throughput
  // updated); Bare: no mist met and no bead there, the bare wall as any other.
  ColdWall cold_wall(const VesselMedia& m, int object, const glm::dvec3& p, const glm::dvec3& n, Ray& ray,
                     MediumKind& medium, int& obj, glm::dvec3& thr, Rng& rng) const {
    const glm::dvec3 pl = m.local_point(p);
    glm::dvec3 nl = m.local_dir(n);
    if (nl.x * pl.x + nl.z * pl.z < 0) nl = -nl;  // outward
    const CondensationState& c = *m.cold;
    const BeadSample bead = bead_at(m.beads, c.band, c.contact_angle, glm::vec3(pl), glm::vec3(nl));
    const double mist = fog_at(m.fog, c.band, glm::vec3(pl)) * bead.clear * contract::kFogScatter;
    const glm::dvec3 out = m.to_world * nl;  // outward, world
    const double glass = m.glass_ior, water = contract::kWaterIor;
    if (mist > 0 && rng.uniform() < mist) {
      thr *= contract::kFogAlbedo;
      const bool outwards = rng.uniform() < 0.5;
      const double spin = rng.uniform(), cos_t = std::sqrt(rng.uniform());  // (drawn in this order)
      const glm::dvec3 d = around(outwards ? out : -out, cos_t, 2 * kPi * spin);
      if (outwards) {  // into the air
        ray.d = d;
        medium = MediumKind::Air;
        obj = -1;
      } else {  // into the glass, bent by its outer face (from the air: no total reflection)
        ray.d = glm::normalize(*refract_dir(d, out, 1.0 / glass));
        medium = MediumKind::Glass;
        obj = object;
      }
      return ColdWall::Turned;
    }
    if (!bead.found) return ColdWall::Bare;
    const glm::dvec3 nb = m.to_world * glm::dvec3(bead.normal);
    if (medium == MediumKind::Air) {
      const glm::dvec3 cap = glm::dot(nb, ray.d) < 0 ? nb : -nb;
      if (rng.uniform() < fresnel_dielectric(-glm::dot(cap, ray.d), 1.0, water)) {
        ray.d = reflect_dir(ray.d, cap);
        return ColdWall::Turned;
      }
      const glm::dvec3 in_water = glm::normalize(*refract_dir(ray.d, cap, 1.0 / water));
      const glm::dvec3 wall = glm::dot(n, in_water) < 0 ? n : -n;
      // (into denser glass: no total reflection; the water-glass face reflects 0.3 %)
      ray.d = glm::normalize(*refract_dir(in_water, wall, water / glass));
      medium = MediumKind::Glass;
      obj = object;
      return ColdWall::Turned;
    }
    if (medium != MediumKind::Glass) return ColdWall::Bare;
    // From the glass: the wall's face into the water, then the cap into the air.
    const double Fw = fresnel_dielectric(-glm::dot(n, ray.d), glass, water);
    if (rng.uniform() < Fw) {
      ray.d = reflect_dir(ray.d, n);
      return ColdWall::Turned;
    }
    const glm::dvec3 in_water = glm::normalize(*refract_dir(ray.d, n, glass / water));
    const glm::dvec3 cap = glm::dot(nb, in_water) < 0 ? nb : -nb;
    if (rng.uniform() < fresnel_dielectric(-glm::dot(cap, in_water), water, 1.0)) {
      // Turned back by the cap: through the wall into the glass again.
      const glm::dvec3 back = reflect_dir(in_water, cap);
      const glm::dvec3 wall = glm::dot(n, back) < 0 ? n : -n;
      const auto into = refract_dir(back, wall, water / glass);
      if (!into) return ColdWall::Absorbed;  // (cannot happen into denser glass)
      ray.d = glm::normalize(*into);
      return ColdWall::Turned;
    }
    ray.d = glm::normalize(*refract_dir(in_water, cap, water));
    medium = MediumKind::Air;
    obj = -1;
    return ColdWall::Turned;
  }

  // What a path sees when it leaves the scene: the studio's sky (an image's weighted
  // against the last vertex's sampling of it), or the screen when it is the background
  // (found by the paths alone: weight 1).
  glm::dvec3 surroundings(const glm::dvec3& d, const MisVertex& mis) const {
    if (frame_.screen.mode == ScreenMode::Background)
      return frame_.screen.background_radiance(d, cam_, frame_.params.render);
    return studio_.sky(d) * environment_weight(mis, d);
  }

  // Russian roulette once a path is long: survivors carry the lost weight.
  static bool roulette(glm::dvec3& thr, int events, Rng& rng) {
    if (events < 8) return true;
    const double q = std::min(1.0, max_component(thr));
    if (q <= 0 || rng.uniform() >= q) return false;
    thr /= q;
    return true;
  }

  // The path meets a decal at p (n: the surface's normal facing the path; next: the medium
  // beyond it): enamel reflects diffusely with the decal's colour; etched glass scatters
  // diffusely, a fifth back and the rest through to the far side; metal mirrors in its
  // colour. Diffuse vertices sample the lights (multiple importance sampling). False: the
  // path ends.
  bool decal_event(const DecalSample& decal, const glm::dvec3& n, MediumKind next, int object, Ray& ray,
                   MediumKind& medium, int& obj, glm::dvec3& thr, glm::dvec3& L, MisVertex& mis, Rng& rng) const {
    const glm::dvec3 p = ray.o;
    const std::optional<glm::dvec3> side = decal_turn(decal, n, next, object, ray, medium, obj, thr, rng);
    if (!side) {  // metal: a rough mirror
      mis.pdf = -1;
      return max_component(thr) > 0;
    }
    L += thr * direct_light(p, *side, ray.d, 0.0, rng);
    double cos_t;
    ray.d = decal_diffuse_direction(*side, rng, cos_t);
    mis = {cos_t / kPi, p, *side};
    return max_component(thr) > 0;
  }

  // The heads along the world ray over [0, t_end] in order of entry, as (t0, t1, object);
  // on the stack (a scene has at most kMaxSceneObjects), as this runs for every segment.
  struct Stretch {
    double t0, t1;
    int obj;
  };
  struct Stretches {
    std::array<Stretch, kMaxSceneObjects> at;
    int count = 0;
    const Stretch* begin() const { return at.data(); }
    const Stretch* end() const { return at.data() + count; }
  };
  Stretches heads_along(const Ray& ray, double t_end) const {
    Stretches out;
    for (size_t i = 0; i < heads_.size(); ++i) {
      if (heads_[i].empty()) continue;
      const VesselMedia& m = media_[i];
      double t0 = 0, t1 = t_end;
      if (heads_[i].interval(m.local_point(ray.o), m.local_dir(ray.d), t0, t1)) out.at[size_t(out.count++)] = {t0, t1, int(i)};
    }
    std::sort(out.at.begin(), out.at.begin() + out.count, [](const Stretch& a, const Stretch& b) { return a.t0 < b.t0; });
    return out;
  }

  // A stretch of air [0, t_end]: the first cap of a big bubble, and delta tracking through
  // the heads before it.
  AirEvent air_segment(const Ray& ray, double t_end, Rng& rng) const {
    AirEvent e;
    const Stretches stretches = heads_along(ray, t_end);
    double end = t_end;
    for (const Stretch& s : stretches) {
      const VesselMedia& m = media_[size_t(s.obj)];
      double t;
      glm::dvec3 n;
      if (heads_[size_t(s.obj)].hit_cap(m.local_point(ray.o), m.local_dir(ray.d), 0.0, end, t, n)) {
        end = t;
        e = {AirEvent::Cap, t, s.obj, m.to_world * n};
      }
    }
    for (const Stretch& s : stretches) {
      if (s.t0 >= end) break;
      const HeadVolume& head = heads_[size_t(s.obj)];
      const VesselMedia& m = media_[size_t(s.obj)];
      const glm::dvec3 o = m.local_point(ray.o), d = m.local_dir(ray.d);
      const double M = head.majorant(), t1 = std::min(s.t1, end);
      for (double t = s.t0;;) {
        t -= std::log(1 - rng.uniform()) / M;
        if (t >= t1) break;
        if (rng.uniform() * M < head.density(o + t * d)) return {AirEvent::Scatter, t, s.obj, {}};
      }
    }
    return e;
  }

  // Whether p lies on the floor (a foot's underside standing on it).
  bool on_floor(const glm::dvec3& p) const {
    if (!geo_.backdrop.present || !(std::fabs(p.y) < 1e-6)) return false;
    double t;
    glm::dvec3 n;
    return geo_.backdrop.intersect(p + glm::dvec3(0.0, 1e-4, 0.0), glm::dvec3(0.0, -1.0, 0.0), 0.0, t, n) &&
           n.y > 0.999 && t < 2e-4;
  }

  // A path that left a glass through its foot's underside onto the floor at p (Lambertian,
  // the thin air between them): it bounces off the floor, and back off the underside by
  // Fresnel's choice, until it crosses into the foot again (ray: up into the glass, still
  // in the glass it came from). No light is sampled there: the glass above blocks every
  // light's straight way (visibility), so their light arrives along the paths. The
  // photons of the floor's light map land the same way (core/environment/floor_light).
  // False when the path ends there (its light spent).
  bool floor_under_foot(const glm::dvec3& p, double glass_ior, glm::dvec3& thr, Ray& ray, Rng& rng) const {
    const glm::dvec3 up(0.0, 1.0, 0.0), albedo = geo_.backdrop.albedo(p);
    for (int bounce = 0; bounce < 64; ++bounce) {
      thr *= albedo;  // cosine-weighted bounce: albedo / pi x cos / pdf = albedo
      if (!(std::max({thr.x, thr.y, thr.z}) > 1e-6)) return false;
      const double cos_t = std::sqrt(rng.uniform());
      const glm::dvec3 d = around(up, cos_t, 2 * kPi * rng.uniform());
      if (rng.uniform() < fresnel_dielectric(cos_t, 1.0, glass_ior)) continue;  // back to the floor
      ray.o = p;
      ray.d = glm::normalize(*refract_dir(d, -up, 1.0 / glass_ior));
      return true;
    }
    return false;
  }

  // The nearest light front along the ray before `t` (updated), or -1; the camera's own
  // ray passes those kept out of the shot.
  int nearest_light(const Ray& ray, double& t, bool from_camera = false) const {
    int found = -1;
    for (size_t i = 0; i < lights_.size(); ++i) {
      if (from_camera && !lights_[i].camera_visible) continue;
      double tl;
      if (lights_[i].intersect(ray.o, ray.d, kRestartEps, tl) && tl < t) {
        t = tl;
        found = int(i);
      }
    }
    return found;
  }

  // The fraction of light that crosses the air from ray.o along ray.d for `dist`: 0 past
  // any surface (a dielectric bends it away) or another light's front, else the heads'
  // transmittance (ratio tracking) and the films of caps it passes straight through.
  double visibility(const Ray& ray, double dist, Rng& rng) const {
    if (first_hit(geo_, ray, kRestartEps).t < dist) return 0;
    Hit body;  // a droplet or a cloud in the way
    body.t = dist;
    glm::dvec4 attrs;
    bodies_.march(ray, MediumKind::Air, -1, body, attrs);
    if (body.valid()) return 0;
    double t_light = dist * (1 - 1e-9);
    if (nearest_light(ray, t_light) >= 0) return 0;
    double T = 1;
    for (const Stretch& s : heads_along(ray, dist)) {
      const HeadVolume& head = heads_[size_t(s.obj)];
      const VesselMedia& m = media_[size_t(s.obj)];
      const glm::dvec3 o = m.local_point(ray.o), d = m.local_dir(ray.d);
      T *= head_transmittance(head, o, d, s.t0, s.t1, rng);
      if (T <= 0) return 0;
      double from = 0, t;
      glm::dvec3 n;
      while (head.hit_cap(o, d, from, dist, t, n)) {
        const double F = fresnel_dielectric(std::fabs(glm::dot(n, d)), 1.0, m.liquid_ior);
        T *= 1 - 2 * F / (1 + F);
        from = t + kRestartEps;
      }
    }
    return T;
  }

  // How likely a vertex at p (a surface of normal n, or a medium where n = 0) picks each
  // light to sample: in proportion to the light it would get from each, unoccluded (a
  // medium: as a surface facing the light). False when no light reaches p.
  using Selection = std::array<double, kMaxRigLights>;
  bool selection(const glm::dvec3& p, const glm::dvec3& n, Selection& prob) const {
    prob.fill(0.0);
    double sum = 0;
    for (size_t i = 0; i < lights_.size(); ++i) {
      const AreaLight& l = lights_[i];
      const glm::dvec3 towards = glm::length(n) > 0 ? n : glm::normalize(l.center - p);
      prob[i] = channel_mean(l.radiance) * l.irradiance_factor(p, towards);
      sum += prob[i];
    }
    if (!(sum > 0)) return false;
    for (double& q : prob) q /= sum;
    return true;
  }

  // The MIS weight of a path that reached light `light` along d by the last vertex's own
  // sampling, against that vertex's sampling of the lights.
  double light_weight(const MisVertex& v, int light, const glm::dvec3& d) const {
    if (v.pdf < 0) return 1.0;
    Selection prob;
    if (!selection(v.p, v.n, prob)) return 1.0;
    return power_weight(v.pdf, prob[size_t(light)] * lights_[size_t(light)].pdf_from(v.p, d));
  }

  // Direct light of the rig at p, per unit albedo, towards -d (d: the direction the path
  // travelled to p): a Lambertian surface of normal n, or (n = 0) a head's
  // Henyey-Greenstein phase of anisotropy g. One light is sampled (selection), weighted
  // against the vertex's own sampling by the power heuristic.
  glm::dvec3 direct_light(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& d, double g, Rng& rng) const {
    if (samples_environment()) return environment_light(p, n, d, g, rng);
    Selection prob;
    if (!selection(p, n, prob)) return glm::dvec3(0.0);
    double u = rng.uniform();
    size_t j = 0;
    while (j + 1 < lights_.size() && u >= prob[j]) u -= prob[j++];
    AreaLight::Sample s;
    if (prob[j] <= 0) return glm::dvec3(0.0);
    const double v = rng.uniform(), u1 = rng.uniform();  // (drawn in this order)
    if (!lights_[j].sample_from(p, u1, v, s)) return glm::dvec3(0.0);
    const bool surface = glm::length(n) > 0;
    const double f = surface ? std::max(glm::dot(s.dir, n), 0.0) / kPi : hg_phase(glm::dot(d, s.dir), g);
    if (f <= 0) return glm::dvec3(0.0);
    const double vis = visibility({p, s.dir}, s.dist, rng);
    if (vis <= 0) return glm::dvec3(0.0);
    const double pdf_light = prob[j] * s.pdf;
    return lights_[j].radiance * (vis * f / pdf_light * power_weight(pdf_light, f));
  }

  // Under an environment image (which replaces the rig: no lights then) its light at p,
  // per unit albedo, towards -d: one direction sampled in proportion to the image's light
  // (core/environment/environment_sampling), weighted against the vertex's own sampling.
  // The floor blocks what lies below it (a path through its fading far part is not
  // counted by this strategy: it takes weight 1 there).
  glm::dvec3 environment_light(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& d, double g, Rng& rng) const {
    double pdf;
    const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform(), u4 = rng.uniform();
    const glm::dvec3 dir = environment_.sample(u1, u2, u3, u4, pdf);
    const bool surface = glm::length(n) > 0;
    const double f = surface ? std::max(glm::dot(dir, n), 0.0) / kPi : hg_phase(glm::dot(d, dir), g);
    if (f <= 0 || !(pdf > 0)) return glm::dvec3(0.0);
    const double vis = visibility({p, dir}, kEnvironmentShadowReach, rng);
    if (vis <= 0) return glm::dvec3(0.0);
    return studio_.sky(dir) * (vis * f / pdf * power_weight(pdf, f));
  }

  // The MIS weight of a path that left into an environment image along d, against the
  // last vertex's sampling of the image (1 without an image or such a vertex).
  double environment_weight(const MisVertex& v, const glm::dvec3& d) const {
    if (v.pdf < 0 || !samples_environment()) return 1.0;
    return power_weight(v.pdf, environment_.pdf(d));
  }
  static constexpr double kEnvironmentShadowReach = 1e5;  // m: anything in the way blocks
  // Whether vertices sample an environment image's light: there is one, and it is what
  // paths leaving the scene see (not a screen as the background).
  bool samples_environment() const { return !environment_.empty() && frame_.screen.mode != ScreenMode::Background; }

  const FrameState& frame_;
  ReferenceSettings settings_;
  SceneGeometry geo_;
  Studio studio_;
  EnvironmentSampler environment_;  // empty unless studio_ has an image
  const std::vector<AreaLight>& lights_;
  CameraBasis cam_;  // the picture's camera: the screen as background is seen across its picture plane
  std::vector<HeadVolume> heads_;
  std::vector<VesselMedia> media_;
  MarchedBodies bodies_;  // the droplets and the clouds
};

}  // namespace

RadianceImage render_reference(const FrameState& f, int width, int height, const ReferenceSettings& s) {
  const auto start = std::chrono::steady_clock::now();
  RadianceImage img;
  img.width = width;
  img.height = height;
  img.pixels.assign(size_t(width) * size_t(height), glm::dvec3(0.0));
  const CameraBasis cam = camera_basis(f, width, height);
  const Tracer tracer(f, s, cam);
  const int spp = std::max(1, s.samples);
  std::atomic<int> next_row{0};
  std::mutex progress_lock;
  int rows_done = 0;
  auto work = [&] {
    for (int y; (y = next_row.fetch_add(1)) < height;) {
      for (int x = 0; x < width; ++x) {
        Rng rng(s.seed, std::uint64_t(y) * std::uint64_t(width) + std::uint64_t(x), 0);
        glm::dvec3 sum(0.0);
        for (int i = 0; i < spp; ++i) {
          // A box filter over the pixel, as the picture's supersampling.
          const double jy = rng.uniform(), jx = rng.uniform();  // (drawn in this order)
          const Ray r = camera_ray(cam, x + jx, y + jy, width, height);
          const glm::dvec3 L = tracer.radiance(r, rng);
          if (std::isfinite(L.x) && std::isfinite(L.y) && std::isfinite(L.z)) sum += L;
        }
        img.at(x, y) = sum / double(spp);
      }
      if (s.progress) {
        std::lock_guard<std::mutex> lock(progress_lock);
        s.progress(++rows_done, height);
      }
    }
  };
  int threads = s.threads > 0 ? s.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, height);
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  img.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return img;
}

Image display_image(const RadianceImage& r, const RenderParams& params) {
  Image img;
  img.width = r.width;
  img.height = r.height;
  img.rgba.resize(size_t(r.width) * size_t(r.height) * 4);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const glm::u8vec3 c = display_rgb8(r.at(x, y), params);
      std::uint8_t* px = img.px(x, y);
      px[0] = c.r;
      px[1] = c.g;
      px[2] = c.b;
      px[3] = 255;
    }
  return img;
}

HdrImage radiance_hdr_image(const RadianceImage& r) {
  HdrImage img;
  img.width = r.width;
  img.height = r.height;
  img.rgb.reserve(r.pixels.size());
  for (const glm::dvec3& p : r.pixels) img.rgb.emplace_back(p);
  return img;
}

}  // namespace draught
