// One headless context and renderer per test process (software rasterizer, pinned by
// DRAUGHT_DEVICE=software in CTest), and scene set-up shared by the GPU tests.
#pragma once

#include "core/frame.hpp"
#include "core/preset.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <memory>

namespace draught::test {

struct Gpu {
  std::unique_ptr<gpu::HeadlessContext> context;
  std::unique_ptr<gpu::Renderer> renderer;
};

inline Gpu& gpu_instance() {
  static Gpu g = [] {
    Gpu out;
    out.context = gpu::HeadlessContext::create(gpu::DevicePreference::Software);
    out.renderer = std::make_unique<gpu::Renderer>();
    return out;
  }();
  return g;
}

inline FrameState scene_frame(const SceneRequest& req) { return make_frame(resolve_scene(req)); }

// Set by gpu_tests --bless: golden tests write their renders as the new goldens.
extern bool g_bless;

}  // namespace draught::test
