// The GLSL twin of the cloud march (shaders/lib/pointcloud/march.glsl) against its C++
// float twin (core/pointcloud/field.cpp) on a grid of rays: a probe program draws, per
// pixel, (t, normal) or the hit's (temperature, r, g, b) into an RGBA32F target, with the
// cloud textures uploaded by gpu/cloud_textures from two clouds sharing them.
//
// Tolerances (two float implementations, different rounding): hit or miss agree on all but
// 0.5 % of the pixels (rays grazing the surface); where both hit, |dt| <= 10 um and the
// normal within 0.5 degree on 99 % of them, the temperature within 2 K, the colour 2e-3.
#include "core/pointcloud/bvh.hpp"
#include "core/pointcloud/cloud_texels.hpp"
#include "core/pointcloud/field.hpp"
#include "generated/objects.hpp"
#include "gpu/cloud_textures.hpp"
#include "gpu/program.hpp"
#include "gpu_fixture.hpp"
#include "../support/cloud_blob.hpp"

#include <gtest/gtest.h>

#include <GLES3/gl3.h>

#include <cstdio>

namespace draught::test {
namespace {

constexpr int kMarchW = 64, kMarchH = 48;

const char* kProbeMain = R"(
uniform vec3 u_eye, u_fwd, u_right, u_up;
uniform int u_root, u_mode;
uniform float u_threshold, u_min_support;
uniform vec3 u_lo, u_hi;
out vec4 o_color;
void main() {
  vec2 uv = gl_FragCoord.xy / vec2(64.0, 48.0) * 2.0 - 1.0;
  vec3 d = normalize(u_fwd + uv.x * u_right + uv.y * u_up);
  CloudRef c = CloudRef(u_root, u_threshold, u_min_support, u_lo, u_hi);
  float t;
  vec3 n;
  vec4 attrs;
  bool hit = march_cloud(c, u_eye, d, 0.0, 10.0, u_mode == 2, t, n, attrs);
  o_color = !hit ? vec4(-1.0) : u_mode == 1 ? attrs : vec4(t, n);
}
)";

// The probe: the march library under kProbeMain.
gpu::Program probe_program() {
  gpu::ShaderSource vert = gpu::assemble_shader("passes/fullscreen.vert.glsl");
  gpu::ShaderSource frag = gpu::assemble_shader("lib/pointcloud/march.glsl");
  frag.text = "#version 300 es\n" + frag.text + kProbeMain;
  return gpu::Program(vert, frag);
}

struct Camera {
  glm::vec3 eye, fwd, right, up;
  glm::vec3 dir(int x, int y) const {
    const glm::vec2 uv = glm::vec2((float(x) + 0.5f) / float(kMarchW), (float(y) + 0.5f) / float(kMarchH)) * 2.0f - 1.0f;
    return glm::normalize(fwd + uv.x * right + uv.y * up);
  }
};

std::vector<float> draw(gpu::Program& prog, const Camera& cam, const CloudRef& c, int mode) {
  GLuint tex = 0, fbo = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, kMarchW, kMarchH);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, kMarchW, kMarchH);
  glUseProgram(prog.id());
  const GLuint p = prog.id();
  glUniform3fv(glGetUniformLocation(p, "u_eye"), 1, &cam.eye.x);
  glUniform3fv(glGetUniformLocation(p, "u_fwd"), 1, &cam.fwd.x);
  glUniform3fv(glGetUniformLocation(p, "u_right"), 1, &cam.right.x);
  glUniform3fv(glGetUniformLocation(p, "u_up"), 1, &cam.up.x);
  glUniform1i(glGetUniformLocation(p, "u_root"), c.root);
  glUniform1i(glGetUniformLocation(p, "u_mode"), mode);
  glUniform1f(glGetUniformLocation(p, "u_threshold"), c.threshold);
  glUniform1f(glGetUniformLocation(p, "u_min_support"), c.min_support);
  glUniform3fv(glGetUniformLocation(p, "u_lo"), 1, &c.lo.x);
  glUniform3fv(glGetUniformLocation(p, "u_hi"), 1, &c.hi.x);
  for (const contract::Sampler& s :
       {contract::kCloudPointsSampler, contract::kCloudAttrsSampler, contract::kCloudNodesSampler})
    glUniform1i(glGetUniformLocation(p, s.name), s.unit);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> out(std::size_t(kMarchW) * kMarchH * 4);
  glReadPixels(0, 0, kMarchW, kMarchH, GL_RGBA, GL_FLOAT, out.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &tex);
  return out;
}

TEST(CloudMarch, GlslTwinMatchesCpp) {
  Gpu& g = gpu_instance();
  (void)g;
  // Two clouds in one set of textures: the probe marches the second (offset indices).
  const float scale = float(cloud_support_scale(kCloudThreshold));
  const PointCloud first = blob(300, 0.003f, {0.2f, 0.0f, 0.0f}, 1), second = blob(1200, 0.004f, {0.0f, 0.1f, 0.0f}, 2);
  CloudTexels tx;
  tx.append(first, build_cloud_bvh(first, scale));
  const CloudRange range = tx.append(second, build_cloud_bvh(second, scale));
  const CloudRef ref = cloud_ref(range);
  gpu::CloudTextures textures;
  textures.upload(tx);
  textures.bind();
  gpu::Program prog = probe_program();

  const Camera outside{{0.0f, 0.12f, 0.15f}, {0.0f, -0.02f / 0.15f, -1.0f}, {0.3f, 0.0f, 0.0f}, {0.0f, 0.225f, 0.0f}};
  const Camera inside{{0.003f, 0.101f, -0.002f}, {0.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.75f, 0.0f}};
  struct Case {
    const Camera* cam;
    int mode;
    const char* name;
  };
  for (const Case& cs : {Case{&outside, 0, "outside"}, Case{&outside, 1, "outside, attributes"},
                         Case{&inside, 2, "inside"}}) {
    const std::vector<float> img = draw(prog, *cs.cam, ref, cs.mode);
    int hits = 0, disagree = 0, far = 0, bent = 0, off_attr = 0;
    double worst_dt = 0, worst_deg = 0;
    for (int y = 0; y < kMarchH; ++y)
      for (int x = 0; x < kMarchW; ++x) {
        const float* px = &img[(std::size_t(y) * kMarchW + std::size_t(x)) * 4];
        const auto m = march_cloud(tx, ref, cs.cam->eye, cs.cam->dir(x, y), 0.0f, 10.0f, cs.mode == 2);
        const bool gpu_hit = px[0] != -1.0f || px[1] != -1.0f;
        if (bool(m) != gpu_hit) {
          ++disagree;
          continue;
        }
        if (!m) continue;
        ++hits;
        if (cs.mode == 1) {
          off_attr += std::abs(px[0] - m->attrs.x) > 2.0f || std::abs(px[1] - m->attrs.y) > 2e-3f ||
                      std::abs(px[2] - m->attrs.z) > 2e-3f || std::abs(px[3] - m->attrs.w) > 2e-3f;
          continue;
        }
        const double dt = std::abs(double(px[0]) - double(m->t));
        worst_dt = std::max(worst_dt, dt);
        far += dt > 1e-5;
        const double deg = glm::degrees(
            std::acos(std::clamp(double(glm::dot(glm::normalize(glm::vec3(px[1], px[2], px[3])), m->n)), -1.0, 1.0)));
        worst_deg = std::max(worst_deg, deg);
        bent += deg > 0.5;
      }
    std::printf("[%s] %d hits, %d disagree, |dt| > 10 um %d (worst %.3g m), normal > 0.5 deg %d (worst %.3g), "
                "attributes off %d\n",
                cs.name, hits, disagree, far, worst_dt, bent, worst_deg, off_attr);
    EXPECT_GT(hits, kMarchW * kMarchH / 4) << cs.name;
    EXPECT_LE(disagree, kMarchW * kMarchH / 200) << cs.name;
    EXPECT_LE(far, hits / 100) << cs.name;
    EXPECT_LE(bent, hits / 100) << cs.name;
    EXPECT_LE(off_attr, hits / 100) << cs.name;
  }
}

// Deep in a dense cloud (20,000 points, each support holding about 50 others) the march from
// inside strides where its lower bound on the field clears the threshold: the GLSL twin
// strides where the C++ does and finds the same exits.
TEST(CloudMarch, GlslTwinStridesAsTheCppDoesInsideADenseCloud) {
  Gpu& g = gpu_instance();
  (void)g;
  const PointCloud dense = blob(20000, 0.0022f, {0.0f, 0.1f, 0.0f}, 9);
  CloudTexels tx;
  const CloudRange range = tx.append(dense, build_cloud_bvh(dense, float(cloud_support_scale(kCloudThreshold))));
  const CloudRef ref = cloud_ref(range);
  gpu::CloudTextures textures;
  textures.upload(tx);
  textures.bind();
  gpu::Program prog = probe_program();
  const Camera inside{{0.002f, 0.101f, -0.001f}, {0.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.75f, 0.0f}};
  const std::vector<float> img = draw(prog, inside, ref, 2);
  int hits = 0, disagree = 0, far = 0, strided = 0;
  double worst_dt = 0;
  const float h = kCloudStepFraction * ref.min_support;
  for (int y = 0; y < kMarchH; ++y)
    for (int x = 0; x < kMarchW; ++x) {
      const float* px = &img[(std::size_t(y) * kMarchW + std::size_t(x)) * 4];
      const auto m = march_cloud(tx, ref, inside.eye, inside.dir(x, y), 0.0f, 10.0f, true);
      if (bool(m) != (px[0] != -1.0f || px[1] != -1.0f)) {
        ++disagree;
        continue;
      }
      if (!m) continue;
      ++hits;
      strided += float(m->steps) < 0.5f * m->t / h;
      const double dt = std::abs(double(px[0]) - double(m->t));
      worst_dt = std::max(worst_dt, dt);
      far += dt > 1e-5;
    }
  std::printf("[dense, inside] %d hits, %d strided, %d disagree, |dt| > 10 um %d (worst %.3g m)\n", hits, strided,
              disagree, far, worst_dt);
  EXPECT_EQ(hits, kMarchW * kMarchH);
  EXPECT_GT(strided, hits / 2);
  EXPECT_LE(disagree, kMarchW * kMarchH / 200);
  EXPECT_LE(far, hits / 100);
}

// A cloud moved in place and one appended after an upload: the textures then updated by the
// changed span only draw both clouds exactly as textures uploaded whole from the same arrays.
TEST(CloudMarch, ASpanUploadDrawsAsAWholeOne) {
  Gpu& g = gpu_instance();
  (void)g;
  const float scale = float(cloud_support_scale(kCloudThreshold));
  PointCloud first = blob(300, 0.003f, {0.0f, 0.1f, 0.0f}, 1);
  const PointCloud second = blob(1200, 0.004f, {0.01f, 0.1f, 0.0f}, 2), third = blob(500, 0.003f, {-0.01f, 0.11f, 0.0f}, 3);
  CloudTexels tx;
  tx.append(first, build_cloud_bvh(first, scale));
  tx.append(second, build_cloud_bvh(second, scale));
  gpu::CloudTextures updated;
  updated.upload(tx);

  for (glm::vec3& p : first.position) p += glm::vec3(0.004f, -0.002f, 0.001f);
  CloudBvh moved = build_cloud_bvh(first, scale);
  const CloudRange r0 = tx.rewrite(0, first, moved);
  CloudTexelSpan span{std::size_t(r0.first_point), std::size_t(r0.first_point + r0.point_count),
                      2 * std::size_t(r0.first_node), 2 * std::size_t(r0.first_node + r0.node_count)};
  const CloudTexelSpan before = CloudTexelSpan::all(tx);
  tx.append(third, build_cloud_bvh(third, scale));
  span |= {before.points_end, std::size_t(tx.point_count()), before.nodes_end, 2 * std::size_t(tx.node_count())};
  updated.upload(tx, span);
  gpu::CloudTextures whole;
  whole.upload(tx);

  gpu::Program prog = probe_program();
  const Camera cam{{0.0f, 0.12f, 0.15f}, {0.0f, -0.02f / 0.15f, -1.0f}, {0.3f, 0.0f, 0.0f}, {0.0f, 0.225f, 0.0f}};
  for (std::size_t k = 0; k < 3; ++k) {
    const CloudRef ref = cloud_ref(tx.clouds[k]);
    updated.bind();
    const std::vector<float> a = draw(prog, cam, ref, 0);
    whole.bind();
    const std::vector<float> b = draw(prog, cam, ref, 0);
    int hits = 0;
    for (std::size_t i = 0; i < a.size(); i += 4) hits += a[i] != -1.0f;
    EXPECT_GT(hits, kMarchW * kMarchH / 20) << "cloud " << k;
    EXPECT_EQ(a, b) << "cloud " << k;
  }
}

}  // namespace
}  // namespace draught::test
