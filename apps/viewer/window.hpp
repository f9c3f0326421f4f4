// An SDL2 window with an OpenGL ES 3.0 context and Dear ImGui on it (SDL platform backend,
// OpenGL 3 renderer backend in its GLES 3 mode). Everything is torn down in reverse order.
#pragma once

#include <SDL2/SDL.h>

#include <string>

namespace draught::viewer {

class Window {
 public:
  // Throws std::runtime_error with SDL's own words when SDL, the window or the ES 3.0
  // context cannot be had.
  Window(const std::string& title, int width, int height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  SDL_Window* sdl() const { return window_; }
  bool has_game_controllers() const { return controllers_; }  // the subsystem started
  void drawable_size(int& width, int& height) const;  // pixels (HiDPI: more than the window's size)
  void window_size(int& width, int& height) const;    // what mouse coordinates refer to
  const std::string& renderer() const { return renderer_; }  // GL_RENDERER
  const std::string& version() const { return version_; }    // GL_VERSION

  void begin_frame();  // ImGui's new frame
  void end_frame();    // draws ImGui over whatever the frame drew; no swap
  void swap();

 private:
  SDL_Window* window_ = nullptr;
  SDL_GLContext context_ = nullptr;
  bool controllers_ = false, imgui_ = false;
  std::string renderer_, version_;
};

}  // namespace draught::viewer
