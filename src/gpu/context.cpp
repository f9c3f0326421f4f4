#include "gpu/context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace draught::gpu {

namespace {

template <class F>
F egl_proc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

std::string egl_error() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", eglGetError());
  return buf;
}

struct Candidate {
  EGLDisplay display;
  std::string platform;
  bool software;
};

// Displays to try, best first: hardware devices, Mesa surfaceless, software devices.
std::vector<Candidate> candidates(DevicePreference pref) {
  std::vector<Candidate> hw, sw;
  auto get_platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_device_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (get_platform_display && query_devices && query_device_string) {
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (query_devices(16, devices, &n)) {
      for (EGLint i = 0; i < n; ++i) {
        const char* ext = query_device_string(devices[i], EGL_EXTENSIONS);
        bool software = ext && std::strstr(ext, "EGL_MESA_device_software");
        EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d == EGL_NO_DISPLAY) continue;
        (software ? sw : hw).push_back({d, "EGL device " + std::to_string(i), software});
      }
    }
  }
  if (get_platform_display) {
    EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY) sw.insert(sw.begin(), {d, "Mesa surfaceless", true});
  }
  std::vector<Candidate> out;
  if (pref != DevicePreference::Software) out.insert(out.end(), hw.begin(), hw.end());
  if (pref != DevicePreference::Hardware) out.insert(out.end(), sw.begin(), sw.end());
  return out;
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(DevicePreference pref) {
  if (const char* env = std::getenv("DRAUGHT_DEVICE")) {
    if (!std::strcmp(env, "software")) pref = DevicePreference::Software;
    else if (!std::strcmp(env, "hardware")) pref = DevicePreference::Hardware;
  }
  std::string tried;
  for (const Candidate& c : candidates(pref)) {
    EGLint major, minor;
    if (!eglInitialize(c.display, &major, &minor)) {
      tried += "\n  " + c.platform + ": eglInitialize failed (" + egl_error() + ")";
      continue;
    }
    eglBindAPI(EGL_OPENGL_ES_API);
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT,
                                     EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                     EGL_NONE};
    EGLConfig config;
    EGLint count = 0;
    if (!eglChooseConfig(c.display, config_attribs, &config, 1, &count) || count == 0) {
      tried += "\n  " + c.platform + ": no GLES 3 pbuffer config";
      eglTerminate(c.display);
      continue;
    }
    const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    EGLContext ctx = eglCreateContext(c.display, config, EGL_NO_CONTEXT, ctx_attribs);
    if (ctx == EGL_NO_CONTEXT) {
      tried += "\n  " + c.platform + ": eglCreateContext failed (" + egl_error() + ")";
      eglTerminate(c.display);
      continue;
    }
    EGLSurface surface = EGL_NO_SURFACE;
    if (!eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      const EGLint pb[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface = eglCreatePbufferSurface(c.display, config, pb);
      if (surface == EGL_NO_SURFACE || !eglMakeCurrent(c.display, surface, surface, ctx)) {
        tried += "\n  " + c.platform + ": eglMakeCurrent failed (" + egl_error() + ")";
        eglDestroyContext(c.display, ctx);
        eglTerminate(c.display);
        continue;
      }
    }
    std::unique_ptr<HeadlessContext> out(new HeadlessContext());
    out->display_ = c.display;
    out->context_ = ctx;
    out->surface_ = surface;
    out->platform_ = c.platform;
    const char* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    out->renderer_ = r ? r : "unknown";
    out->software_ = c.software || out->renderer_.find("llvmpipe") != std::string::npos;
    return out;
  }
  throw std::runtime_error(
      "no OpenGL ES 3.0 context could be created through EGL (install libegl-mesa0 and "
      "libgl1-mesa-dri for the software renderer)" +
      (tried.empty() ? std::string("; no EGL display found") : ":" + tried));
}

HeadlessContext::~HeadlessContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_) eglDestroySurface(display_, surface_);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace draught::gpu
