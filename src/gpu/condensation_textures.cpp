#include "gpu/condensation_textures.hpp"

#include "core/condensation/wall_grid.hpp"

#include <GLES3/gl3.h>

#include <algorithm>

namespace draught::gpu {
namespace {

constexpr int kBeadWidth = contract::kCondensationAngles * contract::kCondensationSlots;
constexpr int kBeadRows = contract::kCondensationRows;
constexpr int kFogWidth = contract::kCondensationFogAngles, kFogRows = contract::kCondensationFogRows;

bool condensed(const VesselFrame& v) { return v.condensation && !v.condensation->band.empty(); }

// A texture of immutable storage on `unit`; s repeats (round the axis), t is clamped.
unsigned storage(int unit, GLenum internal, int width, int height, GLint filter) {
  unsigned tex = 0;
  glActiveTexture(GL_TEXTURE0 + GLenum(unit));
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexStorage2D(GL_TEXTURE_2D, 1, internal, width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return tex;
}

}  // namespace

int condensation_band(const FrameState& f, int row) {
  if (row < 0 || row >= int(f.vessels.size()) || !condensed(f.vessels[size_t(row)])) return -1;
  int band = 0;
  for (int i = 0; i < row; ++i) band += condensed(f.vessels[size_t(i)]) ? 1 : 0;
  return band < contract::kMaxCondensed ? band : -1;
}

void pack_condensation(const FrameState& f, int row, contract::ObjectRecord& r) {
  const int band = condensation_band(f, row);
  r.condensation_band = band;
  r.condensation_y0 = r.condensation_y1 = r.contact_angle = 0.0f;
  if (band < 0) return;
  const CondensationState& c = *f.vessels[size_t(row)].condensation;
  r.condensation_y0 = float(c.band.y0);
  r.condensation_y1 = float(c.band.y1);
  r.contact_angle = c.contact_angle;
}

CondensationTextures::~CondensationTextures() {
  if (beads_tex_) glDeleteTextures(1, &beads_tex_);
  if (fog_tex_) glDeleteTextures(1, &fog_tex_);
}

bool CondensationTextures::update(const FrameState& f) {
  uploads_ = 0;
  std::vector<const VesselFrame*> bands;
  for (size_t i = 0; i < f.vessels.size(); ++i)
    if (condensation_band(f, int(i)) >= 0) bands.push_back(&f.vessels[i]);
  if (bands.empty()) return false;
  if (int(bands.size()) > capacity_ || !beads_tex_) {
    // Immutable storage: new textures for more bands (room for a few more at once).
    capacity_ = std::min(contract::kMaxCondensed, std::max(int(bands.size()), 2 * capacity_));
    if (beads_tex_) glDeleteTextures(1, &beads_tex_);
    if (fog_tex_) glDeleteTextures(1, &fog_tex_);
    beads_tex_ = storage(contract::kCondensationBeadsSampler.unit, GL_RGBA32F, kBeadWidth, kBeadRows * capacity_, GL_NEAREST);
    fog_tex_ = storage(contract::kCondensationFogSampler.unit, GL_R8, kFogWidth, kFogRows * capacity_, GL_LINEAR);
    held_.assign(size_t(capacity_), nullptr);
    versions_.assign(size_t(capacity_), 0);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (size_t b = 0; b < bands.size(); ++b) {
    const VesselFrame& v = *bands[b];
    const CondensationState* s = v.condensation.get();
    if (held_[b] == s && versions_[b] == s->version) continue;
    const std::vector<glm::vec4> grid = bead_grid(*s, v.vessel);
    glActiveTexture(GL_TEXTURE0 + GLenum(contract::kCondensationBeadsSampler.unit));
    glBindTexture(GL_TEXTURE_2D, beads_tex_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, int(b) * kBeadRows, kBeadWidth, kBeadRows, GL_RGBA, GL_FLOAT, grid.data());
    const std::vector<std::uint8_t> fog = fog_texels(*s);
    glActiveTexture(GL_TEXTURE0 + GLenum(contract::kCondensationFogSampler.unit));
    glBindTexture(GL_TEXTURE_2D, fog_tex_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, int(b) * kFogRows, kFogWidth, kFogRows, GL_RED, GL_UNSIGNED_BYTE, fog.data());
    held_[b] = s;
    versions_[b] = s->version;
    ++uploads_;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glActiveTexture(GL_TEXTURE0);
  return true;
}

void CondensationTextures::bind() const {
  glActiveTexture(GL_TEXTURE0 + GLenum(contract::kCondensationBeadsSampler.unit));
  glBindTexture(GL_TEXTURE_2D, beads_tex_);
  glActiveTexture(GL_TEXTURE0 + GLenum(contract::kCondensationFogSampler.unit));
  glBindTexture(GL_TEXTURE_2D, fog_tex_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace draught::gpu
