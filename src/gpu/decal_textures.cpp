#include "gpu/decal_textures.hpp"

#include "core/io/files.hpp"
#include "core/vessel/decal.hpp"
#include "core/vessel/decal_files.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <stdexcept>

namespace draught::gpu {

namespace {
const DecalParams& layer_params(const VesselParams& p, int layer) { return layer == 0 ? p.decal_outer : p.decal_inner; }
}  // namespace

std::vector<std::string> decal_image_names(const FrameState& f) {
  std::vector<std::string> names;
  for (const VesselFrame& v : f.vessels)
    for (int layer = 0; layer < kMaxDecalLayers; ++layer) {
      const std::string& file = layer_params(v.params, layer).file;
      if (!file.empty() && std::find(names.begin(), names.end(), file) == names.end()) names.push_back(file);
    }
  return names;
}

void pack_decals(const FrameState& f, int row, contract::ObjectRecord& r) {
  const VesselFrame& vf = f.vessels[size_t(row)];
  const std::shared_ptr<const VesselDecals> decals = vessel_decals(vf.vessel, vf.params);
  const std::vector<std::string> names = decals ? decal_image_names(f) : std::vector<std::string>{};
  int bits = 0;
  for (int layer = 0; layer < kMaxDecalLayers; ++layer) {
    r.decal_form[layer] = {-1.0f, 0.0f, 1.0f, 1.0f};
    if (!decals || !decals->layers[size_t(layer)].present) continue;
    const DecalPlacement& d = decals->layers[size_t(layer)];
    const std::string& file = layer_params(vf.params, layer).file;
    const int image = int(std::find(names.begin(), names.end(), file) - names.begin());
    r.decal_place[layer] = glm::vec4(glm::dvec4(d.angle, d.centre_s, d.width, d.extent));
    r.decal_look[layer] = glm::vec4(glm::dvec4(d.color, d.opacity));
    r.decal_form[layer] = glm::vec4(float(image), float(int(d.kind)), float(d.repeat), float(d.span));
    r.decal_finish[layer] = glm::vec4(float(d.roughness), 0.0f, 0.0f, 0.0f);
    bits |= 1 << layer;
  }
  r.decal_layers = bits;
}

std::vector<glm::vec4> pack_decal_arcs(const Vessel& v) {
  const WallArcLengths a = wall_arc_lengths(v);
  std::vector<glm::vec4> row(static_cast<size_t>(contract::kSegments));
  for (size_t k = 0; k < row.size(); ++k) row[k] = glm::vec4(glm::dvec4(a.outer[k], a.inner[k], a.outer[k + 1], a.inner[k + 1]));
  return row;
}

int decal_layer_size(int count, int longest) {
  int cap = count <= 16 ? 1024 : count <= 64 ? 512 : 256;
  int size = 64;
  while (size < longest && size < cap) size *= 2;
  return size;
}

DecalTextures::DecalTextures() = default;

DecalTextures::~DecalTextures() {
  if (images_tex_) glDeleteTextures(1, &images_tex_);
  if (arcs_tex_) glDeleteTextures(1, &arcs_tex_);
}

bool DecalTextures::update(const FrameState& f) {
  images_uploaded_ = arc_uploads_ = 0;
  const std::vector<std::string> names = decal_image_names(f);
  if (names.empty()) return false;
  // The images (read once by core, checked when they were set; one gone since is left
  // out: its layer stays clear, and pack_decals draws no decal there).
  std::vector<std::shared_ptr<const Image>> images;
  int longest = 1;
  for (const std::string& name : names) {
    std::shared_ptr<const Image> img;
    try {
      img = load_decal(name);
    } catch (const InputError&) {
    }
    if (img) longest = std::max({longest, img->width, img->height});
    images.push_back(std::move(img));
  }
  GLint max_size = 0, max_layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (int(names.size()) > max_layers)
    throw std::runtime_error("the scene uses " + std::to_string(names.size()) + " decal images; this GL driver holds " +
                             std::to_string(max_layers) + " in a texture array");
  const int size = std::min(decal_layer_size(int(names.size()), longest), int(max_size));
  if (images != images_ || names != names_ || size != layer_size_) {
    if (images_tex_) glDeleteTextures(1, &images_tex_);
    glGenTextures(1, &images_tex_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, images_tex_);
    int levels = 1;
    while ((size >> levels) > 0) ++levels;
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, levels, GL_SRGB8_ALPHA8, size, size, GLsizei(names.size()));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const std::vector<std::uint8_t> clear(size_t(size) * size_t(size) * 4, 0);
    for (size_t i = 0; i < images.size(); ++i) {
      const std::vector<std::uint8_t> texels = images[i] ? decal_layer_texels(*images[i], size) : clear;
      glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(i), size, size, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);  // a band joins round the glass
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    images_ = std::move(images);
    names_ = names;
    layer_size_ = size;
    images_uploaded_ = int(names.size());
  }
  // The walls' arc lengths, a row per vessel (as u_knots: the row is the object's).
  const int n = int(f.vessels.size());
  if (n > arc_capacity_ || !arcs_tex_) {
    int rows = std::max(arc_capacity_, 4);
    while (rows < n) rows *= 2;
    if (arcs_tex_) glDeleteTextures(1, &arcs_tex_);
    glGenTextures(1, &arcs_tex_);
    glBindTexture(GL_TEXTURE_2D, arcs_tex_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, contract::kSegments, rows);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    arc_capacity_ = rows;
    arcs_.clear();
  }
  arcs_.resize(size_t(n));
  glBindTexture(GL_TEXTURE_2D, arcs_tex_);
  for (int i = 0; i < n; ++i) {
    std::vector<glm::vec4> row = pack_decal_arcs(f.vessels[size_t(i)].vessel);
    if (row != arcs_[size_t(i)]) {
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, i, contract::kSegments, 1, GL_RGBA, GL_FLOAT, row.data());
      arcs_[size_t(i)] = std::move(row);
      ++arc_uploads_;
    }
  }
  return std::any_of(images_.begin(), images_.end(), [](const auto& img) { return img != nullptr; });
}

void DecalTextures::bind() const {
  glActiveTexture(GL_TEXTURE0 + contract::kDecalImagesSampler.unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, images_tex_);
  glActiveTexture(GL_TEXTURE0 + contract::kDecalArcsSampler.unit);
  glBindTexture(GL_TEXTURE_2D, arcs_tex_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace draught::gpu
