#include "window.hpp"

#include <GLES3/gl3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>
#include <imgui_impl_sdl.h>

#include <stdexcept>

namespace draught::viewer {

namespace {

std::runtime_error sdl_error(const std::string& what) {
  const std::string why = SDL_GetError();
  return std::runtime_error(what + ": " + (why.empty() ? "SDL gave no reason" : why));
}

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "?";
}

}  // namespace

Window::Window(const std::string& title, int width, int height) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) throw sdl_error("SDL could not start its video subsystem");
  // Controllers are optional: a machine without them (or without udev) still gets a window.
  controllers_ = SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER | SDL_INIT_SENSOR) == 0;
  // The renderer's shaders are GLSL ES 3.00: ask for exactly that API, nothing desktop.
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);  // one fullscreen pass and ImGui: no depth test
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height,
                             SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (!window_) {
    SDL_Quit();
    throw sdl_error("could not open a window with OpenGL ES 3.0");
  }
  context_ = SDL_GL_CreateContext(window_);
  if (!context_) {
    const std::runtime_error e = sdl_error("could not create an OpenGL ES 3.0 context");
    SDL_DestroyWindow(window_);
    SDL_Quit();
    throw e;
  }
  SDL_GL_MakeCurrent(window_, context_);
  SDL_GL_SetSwapInterval(1);  // vsync where the driver has it; harmless where not
  renderer_ = gl_string(GL_RENDERER);
  version_ = gl_string(GL_VERSION);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForOpenGL(window_, context_);
  ImGui_ImplOpenGL3_Init("#version 300 es");
  imgui_ = true;
}

Window::~Window() {
  if (imgui_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
  }
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
  SDL_Quit();
}

void Window::drawable_size(int& width, int& height) const { SDL_GL_GetDrawableSize(window_, &width, &height); }

void Window::window_size(int& width, int& height) const { SDL_GetWindowSize(window_, &width, &height); }

void Window::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();
}

void Window::end_frame() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::swap() { SDL_GL_SwapWindow(window_); }

}  // namespace draught::viewer
