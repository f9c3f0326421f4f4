#include "events.hpp"

#include <imgui.h>
#include <imgui_impl_sdl.h>

#include <algorithm>

namespace draught::viewer {

namespace {

bool is_modifier(SDL_Scancode s) { return s >= SDL_SCANCODE_LCTRL && s <= SDL_SCANCODE_RGUI; }

// A character key alone (no Ctrl, Alt or GUI): a text field takes it from its text event,
// not from the key, so the key may go down and up unseen.
bool plain_character(const SDL_KeyboardEvent& k) {
  if (is_modifier(k.keysym.scancode) || (k.keysym.mod & (KMOD_CTRL | KMOD_ALT | KMOD_GUI))) return false;
  const SDL_Keycode sym = k.keysym.sym;
  return sym >= SDLK_SPACE && sym != SDLK_DELETE && !(sym & SDLK_SCANCODE_MASK);
}

// A key that a text field acts on: Backspace, Enter, arrows, ... and anything with Ctrl,
// Alt or the GUI key held.
bool edit_key(const SDL_KeyboardEvent& k) { return !is_modifier(k.keysym.scancode) && !plain_character(k); }

}  // namespace

std::vector<SDL_Event> FrameEvents::take_frame() {
  std::vector<SDL_Event> out;
  // Edit keys that changed this frame: ImGui must see each state. Character keys may go
  // down and up freely (their text carries them), modifiers too until an edit uses them.
  std::vector<SDL_Scancode> held;
  bool edited = false;  // an edit key went down this frame
  while (!queue_.empty()) {
    const SDL_Event& e = queue_.front();
    if (e.type == SDL_KEYDOWN || e.type == SDL_KEYUP) {
      const SDL_Scancode s = e.key.keysym.scancode;
      const bool down = e.type == SDL_KEYDOWN;
      if (s >= 0 && s < SDL_NUM_SCANCODES && down_[size_t(s)] != down) {  // a repeat changes nothing
        if (std::find(held.begin(), held.end(), s) != held.end()) break;  // its first change would be missed
        if (is_modifier(s) && edited) break;  // the edit would see the new modifiers
        down_[size_t(s)] = down;
        if (edit_key(e.key)) held.push_back(s);
        edited = edited || (down && edit_key(e.key));
      }
    } else if ((e.type == SDL_TEXTINPUT || e.type == SDL_TEXTEDITING) && edited) {
      break;  // ImGui would insert it before the edit
    }
    out.push_back(e);  // whatever stops a frame follows an event taken: every frame takes one
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
