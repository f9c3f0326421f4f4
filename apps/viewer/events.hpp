// SDL events, handed out a frame at a time so that Dear ImGui sees every key press.
//
// Debian 12's Dear ImGui is 1.86, whose SDL backend only sets the state of each key
// (io.KeysDown) as events arrive; ImGui reads that state once per frame. A key pressed and
// released between two frames (Backspace, Ctrl+A typed at a few frames per second) therefore
// never looked pressed, and a typed path was appended to instead of replacing the text.
// ImGui 1.87 added an input queue that "trickles" such events over frames; FrameEvents does
// the same in front of 1.86: each frame takes events from the front of the queue until one
// would hide an earlier one, and the rest wait, in order, for the next frame.
//
// The backend also takes the modifiers from SDL_GetModState(), which is the state after all
// pending events (Ctrl already released); feed_imgui uses each key event's own modifiers.
#pragma once

#include <SDL2/SDL.h>

#include <deque>
#include <vector>

namespace draught::viewer {

class FrameEvents {
 public:
  void push(const SDL_Event& e) { queue_.push_back(e); }
  // The events of this frame, in order: the longest run from the front in which
  //  - no key that edits text (Backspace, Enter, arrows, anything with Ctrl, Alt or GUI
  //    held) changes twice (the first change would not be seen; character keys may, their
  //    text carries them, so typing keeps up),
  //  - no modifier changes after a key edited text (ImGui reads the modifiers once a frame),
  //  - no text follows a key that edited text (ImGui's text field takes a frame's
  //    characters before its keys: Backspace then "x" would become "x" then Backspace).
  // Each frame takes at least one event when any wait, so nothing waits for ever.
  std::vector<SDL_Event> take_frame();
  std::size_t waiting() const { return queue_.size(); }

 private:
  std::deque<SDL_Event> queue_;
  std::vector<bool> down_ = std::vector<bool>(SDL_NUM_SCANCODES, false);  // as ImGui last saw the keys
};

// ImGui_ImplSDL2_ProcessEvent, with a key event's modifiers taken from the event itself.
void feed_imgui(const SDL_Event&);

}  // namespace draught::viewer
