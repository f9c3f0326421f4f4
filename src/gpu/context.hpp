// A headless OpenGL ES 3.0 context through EGL: a GPU device where one exists,
// else Mesa's software rasterizer (llvmpipe). No window system needed.
#pragma once

#include <memory>
#include <string>

namespace draught::gpu {

enum class DevicePreference { Auto, Hardware, Software };

// DRAUGHT_DEVICE=auto|hardware|software overrides `pref` (tests pin software).
class HeadlessContext {
 public:
  static std::unique_ptr<HeadlessContext> create(DevicePreference pref = DevicePreference::Auto);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  const std::string& renderer() const { return renderer_; }  // GL_RENDERER
  const std::string& platform() const { return platform_; }  // how EGL was reached
  bool software() const { return software_; }

 private:
  HeadlessContext() = default;
  void* display_ = nullptr;
  void* context_ = nullptr;
  void* surface_ = nullptr;
  std::string renderer_, platform_;
  bool software_ = false;
};

}  // namespace draught::gpu
