#include "events.hpp"

#include <imgui.h>
#include <imgui_impl_sdl.h>

namespace draught::viewer {

namespace {

bool is_modifier(SDL_Scancode s) { return s >= SDL_SCANCODE_LCTRL && s <= SDL_SCANCODE_RGUI; }

// A key press that a text field acts on: not a character key alone (its character comes as
// text), but Backspace, Enter, arrows, ... and anything with Ctrl, Alt or the GUI key held.
bool edits_text(const SDL_KeyboardEvent& k) {
  if (k.type != SDL_KEYDOWN || is_modifier(k.keysym.scancode)) return false;
  if (k.keysym.mod & (KMOD_CTRL | KMOD_ALT | KMOD_GUI)) return true;
  const SDL_Keycode sym = k.keysym.sym;
  const bool character = sym >= SDLK_SPACE && sym != SDLK_DELETE && !(sym & SDLK_SCANCODE_MASK);
  return !character;
}

}  // namespace

std::vector<SDL_Event> FrameEvents::take_frame() {
  std::vector<SDL_Event> out;
  std::vector<SDL_Scancode> changed;
  bool other_key_changed = false, edit_pressed = false;
  while (!queue_.empty()) {
    const SDL_Event& e = queue_.front();
    bool wait = false;
    if (e.type == SDL_KEYDOWN || e.type == SDL_KEYUP) {
      const SDL_Scancode s = e.key.keysym.scancode;
      const bool down = e.type == SDL_KEYDOWN;
      if (s >= 0 && s < SDL_NUM_SCANCODES && down_[size_t(s)] != down) {  // a repeat changes nothing
        for (SDL_Scancode c : changed) wait = wait || c == s;
        wait = wait || (is_modifier(s) && other_key_changed);
        if (!wait) {
          down_[size_t(s)] = down;
          changed.push_back(s);
          other_key_changed = other_key_changed || !is_modifier(s);
        }
      }
      if (!wait) edit_pressed = edit_pressed || edits_text(e.key);
    } else if (e.type == SDL_TEXTINPUT || e.type == SDL_TEXTEDITING) {
      wait = edit_pressed;
    }
    if (wait) break;  // only ever after an event taken this frame: every frame takes one
    out.push_back(e);
    queue_.pop_front();
  }
  return out;
}

void feed_imgui(const SDL_Event& e) {
  ImGui_ImplSDL2_ProcessEvent(&e);
  if (e.type != SDL_KEYDOWN && e.type != SDL_KEYUP) return;
  ImGuiIO& io = ImGui::GetIO();
  const Uint16 mod = e.key.keysym.mod;
  io.KeyShift = (mod & KMOD_SHIFT) != 0;
  io.KeyCtrl = (mod & KMOD_CTRL) != 0;
  io.KeyAlt = (mod & KMOD_ALT) != 0;
  io.KeySuper = (mod & KMOD_GUI) != 0;
}

}  // namespace draught::viewer
