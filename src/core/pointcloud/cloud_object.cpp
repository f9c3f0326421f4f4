#include "core/pointcloud/cloud_object.hpp"

#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/pointcloud/blackbody.hpp"
#include "core/pointcloud/cloud_files.hpp"
#include "core/pointcloud/glass_heat.hpp"
#include "core/pointcloud/gob.hpp"
#include "core/pointcloud/stream.hpp"
#include "core/text/suggest.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <optional>

namespace draught {

const std::vector<ObjectParamInfo>& point_cloud_param_table() {
  static const std::vector<ObjectParamInfo> table = {
      {"source", 0, 2, "", "\"gob\" (molten glass on a turning blowpipe, the default), \"stream\" (a falling stream) or "
                           "\"file\""},
      {"file", 0, 0, "", "file source: a .ply, .xyz or .csv cloud, or one frame of a numbered sequence "
                         "(frame_0001.ply ...), relative to the scene file"},
      {"rate", 0.1, 240, "1/s", "file sequences: frames per second"},
      {"loop", 0, 1, "", "file sequences: true loops, false holds the last frame"},
      {"scale", 1e-6, 1e3, "m", "file source: metres per unit of the file's coordinates"},
      {"blob_radius", 0, 0.1, "m", "a lone point's radius (points without their own, the gob's particles); 0: "
                                   "automatic (files 2 mm, the gob 1.7 x its particles' spacing, which blends them smooth)"},
      {"threshold", 0.05, 0.95, "", "level of the summed field that is the surface"},
      {"material", 0, 1, "", "\"molten_glass\" (the default) or \"drink\""},
      {"temperature", 250, 2500, "K", "the gob's start temperature; file points without their own"},
      {"cooling", 0, 3600, "s", "time constant of the cooling towards the room (0: none)"},
      {"glow", 0, 100, "", "multiplies the blackbody emission of hot glass"},
      {"glow_depth", 0.001, 1, "m", "hot glass's visible extinction is 1 / glow_depth at 1100 C and above (falling to 0 "
                                    "at 700 K): how deep the glow builds, and how little is seen through"},
      {"ior", 1, 2.5, "", "index of refraction (glass 1.5, a drink 1.34)"},
      {"roughness", 0, 1, "", "GGX roughness of the surface"},
      {"absorption", 0, 1000, "1/m", "Beer-Lambert absorption per metre, [r, g, b]"},
      // (The gob's own model, core/pointcloud/gob, takes every value of these ranges.)
      {"count", 500, 50000, "", "gob: particles"},
      {"gob_radius", 0.01, 0.2, "m", "gob: its radius when gathered"},
      {"turn", -20, 20, "rad/s", "gob: how fast the blowpipe turns"},
      {"flow", 1e-6, 1e-3, "m^3/s", "stream: volume per second"},
      {"height", 0.01, 2, "m", "stream: the spout above the placement"},
      {"age", 0, 60, "s", "seconds the source has run before the scene begins (a still shows a gob that has turned "
                          "and sagged, a stream that has landed); files and their cooling start at 0"},
  };
  return table;
}

namespace {

const char* source_name(int s) { return s == 1 ? "stream" : s == 2 ? "file" : "gob"; }
const char* material_name(int m) { return m == 1 ? "drink" : "molten_glass"; }

}  // namespace

PointCloudParams parse_point_cloud_params(const nlohmann::json& j, const std::string& file, const std::string& at,
                                          const std::string& base_dir) {
  if (!j.is_object())
    throw InputError(file + ": field '" + at + "': expected an object of point-cloud parameters, got " + short_dump(j));
  PointCloudParams p;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = it.key(), name = at + "." + key, field = file + ": field '" + name + "': ";
    const ObjectParamInfo* info = &find_object_param(point_cloud_param_table(), key, file, at, "point-cloud");
    const nlohmann::json& v = it.value();
    auto choice = [&](std::initializer_list<const char*> options) {
      int k = 0;
      std::string list;
      for (const char* o : options) {
        if (v.is_string() && v.get<std::string>() == o) return k;
        list += std::string(k ? " or " : "") + "\"" + o + "\"";
        ++k;
      }
      throw InputError(field + "expected " + list + ", got " + short_dump(v));
    };
    if (key == "source") {
      p.source = choice({"gob", "stream", "file"});
    } else if (key == "material") {
      p.material = choice({"molten_glass", "drink"});
    } else if (key == "file") {
      if (!v.is_string() || v.get<std::string>().empty())
        throw InputError(field + "expected the path of a .ply, .xyz or .csv file, got " + short_dump(v));
      std::filesystem::path f = v.get<std::string>();
      if (f.is_relative() && !base_dir.empty()) f = std::filesystem::path(base_dir) / f;
      p.file = f.lexically_normal().string();
    } else if (key == "loop") {
      if (!v.is_boolean()) throw InputError(field + "expected true or false, got " + short_dump(v));
      p.loop = v.get<bool>();
    } else if (key == "count") {
      p.count = object_param_int(v, *info, file, name);
    } else if (key == "absorption") {
      p.absorption = object_param_rgb(v, *info, file, name);
    } else {
      const float x = float(object_param_number(v, *info, file, name));
      if (key == "rate") p.rate = x;
      else if (key == "scale") p.scale = x;
      else if (key == "blob_radius") p.blob_radius = x;
      else if (key == "threshold") p.threshold = x;
      else if (key == "temperature") p.temperature = x;
      else if (key == "cooling") p.cooling = x;
      else if (key == "glow") p.glow = x;
      else if (key == "glow_depth") p.glow_depth = x;
      else if (key == "ior") p.ior = x;
      else if (key == "roughness") p.roughness = x;
      else if (key == "gob_radius") p.gob_radius = x;
      else if (key == "turn") p.turn = x;
      else if (key == "flow") p.flow = x;
      else if (key == "height") p.height = x;
      else if (key == "age") p.age = x;
    }
  }
  if (p.source == int(CloudSourceKind::File) && p.file.empty())
    throw InputError(file + ": field '" + at + ".file': missing; a \"file\" source needs the path of a .ply, .xyz or "
                     ".csv file");
  if (p.source != int(CloudSourceKind::File) && !p.file.empty())
    throw InputError(file + ": field '" + at + ".file': only a \"file\" source reads a file (this one is \"" +
                     source_name(p.source) + "\")");
  return p;
}

nlohmann::json point_cloud_params_json(const PointCloudParams& p) {
  nlohmann::json j = {{"source", source_name(p.source)},
                      {"blob_radius", p.blob_radius},
                      {"threshold", p.threshold},
                      {"material", material_name(p.material)},
                      {"temperature", p.temperature},
                      {"cooling", p.cooling},
                      {"glow", p.glow},
                      {"glow_depth", p.glow_depth},
                      {"ior", p.ior},
                      {"roughness", p.roughness},
                      {"absorption", {p.absorption.x, p.absorption.y, p.absorption.z}},
                      {"age", p.age}};
  if (p.source == int(CloudSourceKind::File)) {
    j["file"] = p.file;
    j["rate"] = p.rate;
    j["loop"] = p.loop;
    j["scale"] = p.scale;
  } else if (p.source == int(CloudSourceKind::Gob)) {
    j["count"] = p.count;
    j["gob_radius"] = p.gob_radius;
    j["turn"] = p.turn;
  } else {
    j["flow"] = p.flow;
    j["height"] = p.height;
  }
  return j;
}

// ---- the source at run time ----

struct CloudSource::State {
  std::optional<MoltenGob> gob;
  GobParams gob_params;
  std::shared_ptr<const PointCloud> pipe;  // the gob's blowpipe, placed once
  std::uint64_t pipe_version = 0;
  std::optional<PourStream> stream;
  std::optional<PointCloudSequence> sequence;  // a numbered run of files
  std::shared_ptr<const PointCloud> still;      // one file, placed once
  std::size_t shown_frame = std::size_t(-1);
  mutable std::shared_ptr<const PointCloud> placed;  // the last world cloud (rebuilt when dirty)
  mutable bool dirty = true;
  mutable std::uint64_t version = 0;
};

namespace {

// A name with a number before its extension ("frame_0012.ply") or a %d pattern is one
// frame of a sequence (a lone numbered file is a sequence of one).
bool numbered(const std::string& file) {
  const std::filesystem::path f(file);
  const std::string stem = f.stem().string();
  return f.filename().string().find('%') != std::string::npos ||
         (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back())));
}

// The gob's blowpipe, a cloud of its own beside the gob (so that its field does not blend
// into the gob's, nor its colour into the glass's): a row of points along -x up to the
// gob, cold (no glow) and nearly black (their colour darkens the light that enters
// them): a dark, glossy steel tube under the same reflections.
PointCloud blowpipe(const GobParams& g) {
  constexpr double kPipeLength = 0.3;  // m shown behind the gob
  const double r = g.pipe_radius, spacing = 0.5 * r;
  PointCloud c;
  for (double x = g.pipe_depth - r; x > -kPipeLength; x -= spacing) {
    c.position.push_back(glm::vec3(float(x), 0.0f, 0.0f));
    c.radius.push_back(float(r));
    c.temperature.push_back(float(g.ambient_kelvin));
    c.color.push_back(glm::vec3(0.04f));
  }
  c.default_radius = float(r);
  return c;
}

std::uint64_t next_version() {
  static std::uint64_t counter = 0;  // one sequence for every source: versions never repeat
  return ++counter;
}

// The file's points in the world: scaled, turned by yaw about +y, moved to the placement;
// defaults filled in so that every point has a radius and a temperature.
std::shared_ptr<const PointCloud> place_cloud(const PointCloud& in, const PointCloudParams& p, glm::vec3 at,
                                              float yaw, double cooled_kelvin) {
  auto out = std::make_shared<PointCloud>(in);
  const float c = std::cos(glm::radians(yaw)), s = std::sin(glm::radians(yaw));
  for (glm::vec3& q : out->position) {
    const glm::vec3 v = q * p.scale;
    q = at + glm::vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
  }
  const float blob = p.blob_radius > 0 ? p.blob_radius : 0.002f;  // (automatic for files: 2 mm)
  if (out->radius.empty()) out->radius.assign(out->size(), blob);
  else  // (scaled to metres and held to what a blob of a scene can be: 1 um to 1 m)
    for (float& r : out->radius) r = std::clamp(r * p.scale, 1e-6f, 1.0f);
  if (out->temperature.empty()) out->temperature.assign(out->size(), float(cooled_kelvin));
  out->default_radius = blob;
  return out;
}

}  // namespace

CloudSource::CloudSource(const PointCloudParams& p, glm::vec3 position, float yaw)
    : params_(p), position_(position), yaw_(yaw), state_(std::make_unique<State>()) {
  switch (CloudSourceKind(p.source)) {
    case CloudSourceKind::Gob: {
      GobParams g;
      g.count = p.count;
      // (the table's float ends may fall a hair outside the model's double range)
      g.radius = std::clamp(double(p.gob_radius), 0.01, 0.2);
      // (0: the gob's own choice, replaced below; a blob wider than the gob's model takes, 5 cm, is held there)
      g.blob_radius = p.blob_radius > 0 ? std::clamp(double(p.blob_radius), 1e-4, 0.05) : 0.0;
      g.pipe_radius = std::min(g.pipe_radius, 0.5 * g.radius);
      g.pipe_depth = std::min(g.pipe_depth, 0.5 * g.radius);
      g.turn_rate = p.turn;
      g.start_kelvin = std::clamp(double(p.temperature), 293.0, 2000.0);
      state_->gob_params = g;
      state_->gob.emplace(g);
      PointCloudParams unit = p;
      unit.scale = 1.0f;
      state_->pipe = place_cloud(blowpipe(g), unit, position, yaw, g.ambient_kelvin);
      state_->pipe_version = next_version();
      state_->gob->advance(p.age);
      break;
    }
    case CloudSourceKind::Stream: {
      state_->stream.emplace();
      const glm::dvec3 spout = glm::dvec3(position) + glm::dvec3(0, p.height, 0);
      state_->stream->set_origin(spout, glm::dvec3(0.0));
      state_->stream->set_target_height(double(position.y));
      state_->stream->set_flow(0, p.flow);
      state_->stream->advance(p.age);
      break;
    }
    case CloudSourceKind::File: {
      if (numbered(p.file)) state_->sequence.emplace(p.file);
      else state_->still = std::make_shared<const PointCloud>(load_point_cloud(p.file));
      break;
    }
  }
}

CloudSource::~CloudSource() = default;
CloudSource::CloudSource(CloudSource&&) noexcept = default;
CloudSource& CloudSource::operator=(CloudSource&&) noexcept = default;

void CloudSource::advance_to(double t) {
  if (!(t > time_)) return;
  State& s = *state_;
  if (s.gob) s.gob->advance(t - time_);
  if (s.stream) s.stream->advance(t - time_);
  if (s.sequence) {
    const std::size_t k = s.sequence->frame_index(t, params_.rate, params_.loop);
    if (k != s.shown_frame) s.dirty = true;
  }
  if (s.gob || s.stream || (s.still && params_.cooling > 0)) s.dirty = true;
  time_ = t;
}

std::vector<CloudFrame> CloudSource::frames() const {
  State& s = *state_;
  const double room = kZeroCelsius + 20.0;
  const double kelvin = params_.cooling > 0 ? cooled_temperature(params_.temperature, room, time_, params_.cooling)
                                            : double(params_.temperature);
  if (s.dirty || !s.placed) {
    if (s.gob) {
      PointCloudParams unit = params_;
      unit.scale = 1.0f;
      PointCloud gob = s.gob->cloud();
      // Automatic: blobs 1.7 spacings wide blend the particles into one glossy surface
      // (0.8, the gob's own choice, leaves a crumpled skin of particle bumps, 1.35 a light
      // hammered one; wider blobs are smoother but every sample then sums more points, and
      // llvmpipe stops a pixel's loops after 65535 iterations in all: docs/POINT_CLOUDS.md).
      if (params_.blob_radius == 0) gob.default_radius = float(1.7 * s.gob->spacing());
      unit.blob_radius = gob.default_radius;
      s.placed = place_cloud(gob, unit, position_, yaw_, kelvin);
    } else if (s.stream) {
      auto c = std::make_shared<PointCloud>(s.stream->cloud());  // already in the world
      if (c->temperature.empty()) c->temperature.assign(c->size(), float(kelvin));
      s.placed = c;
    } else if (s.sequence) {
      s.shown_frame = s.sequence->frame_index(time_, params_.rate, params_.loop);
      s.placed = place_cloud(s.sequence->frame(s.shown_frame), params_, position_, yaw_, kelvin);
    } else {
      s.placed = place_cloud(*s.still, params_, position_, yaw_, kelvin);
    }
    s.dirty = false;
    s.version = next_version();
  }
  CloudFrame f;
  f.points = s.placed;
  f.version = s.version;
  f.material = params_.material;
  f.threshold = params_.threshold;
  const bool glass = params_.material == int(CloudMaterial::MoltenGlass);
  f.glow = glass ? params_.glow : 0.0f;
  f.glow_depth = glass ? params_.glow_depth : 0.0f;
  f.ior = params_.ior;
  f.roughness = params_.roughness;
  f.absorption = params_.absorption;
  f.temperature = float(kelvin);
  f.placement = position_;
  std::vector<CloudFrame> out{f};
  if (s.pipe) {  // the blowpipe: steel, cold, glossy
    CloudFrame pipe;
    pipe.points = s.pipe;
    pipe.version = s.pipe_version;
    pipe.material = int(CloudMaterial::MoltenGlass);
    pipe.threshold = params_.threshold;
    pipe.ior = 1.5f;
    pipe.roughness = 0.15f;
    pipe.temperature = float(s.gob_params.ambient_kelvin);
    pipe.placement = position_;
    out.push_back(pipe);
  }
  return out;
}

}  // namespace draught
