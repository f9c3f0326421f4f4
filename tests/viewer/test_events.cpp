// Keys typed faster than the viewer draws frames: the real Dear ImGui (Debian's 1.86) and its
// SDL backend, a text field, and SDL events made by hand, as a slow frame would poll them
// all at once. SDL's dummy video driver gives a window without a display.
#include "events.hpp"

#include <imgui.h>
#include <imgui_impl_sdl.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace draught::viewer {
namespace {

SDL_Event key(Uint32 type, SDL_Scancode s, SDL_Keycode sym, Uint16 mod = KMOD_NONE) {
  SDL_Event e{};
  e.type = type;
  e.key.type = type;
  e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
  e.key.keysym.scancode = s;
  e.key.keysym.sym = sym;
  e.key.keysym.mod = mod;
  return e;
}

// A key pressed and released, with these modifiers held.
void tap(std::vector<SDL_Event>& out, SDL_Scancode s, SDL_Keycode sym, Uint16 mod = KMOD_NONE) {
  out.push_back(key(SDL_KEYDOWN, s, sym, mod));
  out.push_back(key(SDL_KEYUP, s, sym, mod));
}

// A character typed: its key down, its text, its key up (the order SDL sends them).
void type(std::vector<SDL_Event>& out, const std::string& text) {
  for (char c : text) {
    const SDL_Scancode s = c >= 'a' && c <= 'z' ? SDL_Scancode(SDL_SCANCODE_A + (c - 'a')) : SDL_SCANCODE_SLASH;
    out.push_back(key(SDL_KEYDOWN, s, SDL_Keycode(c)));
    SDL_Event t{};
    t.type = SDL_TEXTINPUT;
    t.text.text[0] = c;
    out.push_back(t);
    out.push_back(key(SDL_KEYUP, s, SDL_Keycode(c)));
  }
}

// Ctrl+A as a quick hand types it: Ctrl down, A down and up, Ctrl up.
void select_all(std::vector<SDL_Event>& out) {
  out.push_back(key(SDL_KEYDOWN, SDL_SCANCODE_LCTRL, SDLK_LCTRL, KMOD_LCTRL));
  tap(out, SDL_SCANCODE_A, SDLK_a, KMOD_LCTRL);
  out.push_back(key(SDL_KEYUP, SDL_SCANCODE_LCTRL, SDLK_LCTRL, KMOD_NONE));
}

class SlowFrames : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("SDL_VIDEODRIVER", "dummy", 0);
    ASSERT_EQ(SDL_Init(SDL_INIT_VIDEO), 0) << SDL_GetError();
    window = SDL_CreateWindow("test", 0, 0, 400, 300, SDL_WINDOW_HIDDEN);
    ASSERT_NE(window, nullptr) << SDL_GetError();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::GetIO().Fonts->Build();
    ImGui_ImplSDL2_InitForOpenGL(window, nullptr);
  }
  void TearDown() override {
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    SDL_DestroyWindow(window);
    SDL_Quit();
  }

  // One frame of the viewer's panel: its file field, focused on the first frame.
  void frame(const std::vector<SDL_Event>& events, bool trickle = true) {
    for (const SDL_Event& e : events) trickle ? feed_imgui(e) : (void)ImGui_ImplSDL2_ProcessEvent(&e);
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
    ImGui::Begin("panel");
    if (frames++ == 0) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("file", path, sizeof path);
    ImGui::End();
    ImGui::Render();
  }

  // Starts with `text` in the field, focused, the cursor at its end.
  void start(const char* text) {
    std::strcpy(path, text);
    for (int i = 0; i < 3; ++i) frame({});  // focus asked for, taken, reported
    ASSERT_TRUE(ImGui::GetIO().WantTextInput) << "the field did not take the keyboard";
    std::vector<SDL_Event> end;
    tap(end, SDL_SCANCODE_END, SDLK_END);
    for (const SDL_Event& e : end) queue.push(e);
    drain();
  }

  // Everything the slow frame polled at once, then frames until the queue is empty.
  void slow_frame(const std::vector<SDL_Event>& events) {
    for (const SDL_Event& e : events) queue.push(e);
    drain();
  }
  void drain() {
    for (int n = 0; n < 100 && queue.waiting() > 0; ++n) frame(queue.take_frame());
    frame({});
  }

  SDL_Window* window = nullptr;
  FrameEvents queue;
  char path[256] = "";
  int frames = 0;
};

TEST_F(SlowFrames, CtrlAThenTypingReplacesThePath) {
  start("presets/drinks/lager.json");
  std::vector<SDL_Event> events;
  type(events, "x");  // nothing selected yet: typing appends
  slow_frame(events);
  ASSERT_STREQ(path, "presets/drinks/lager.jsonx");
  events.clear();
  select_all(events);
  type(events, "my/stout.json");
  slow_frame(events);
  EXPECT_STREQ(path, "my/stout.json");
}

TEST_F(SlowFrames, CtrlReleasedBeforeAStillSelectsAll) {
  start("lager.json");
  std::vector<SDL_Event> events;
  events.push_back(key(SDL_KEYDOWN, SDL_SCANCODE_LCTRL, SDLK_LCTRL, KMOD_LCTRL));
  events.push_back(key(SDL_KEYDOWN, SDL_SCANCODE_A, SDLK_a, KMOD_LCTRL));
  events.push_back(key(SDL_KEYUP, SDL_SCANCODE_LCTRL, SDLK_LCTRL, KMOD_NONE));
  events.push_back(key(SDL_KEYUP, SDL_SCANCODE_A, SDLK_a, KMOD_NONE));
  type(events, "stout.json");
  slow_frame(events);
  EXPECT_STREQ(path, "stout.json");
}

TEST_F(SlowFrames, QuickBackspacesEachDeleteACharacter) {
  start("lager.json");
  std::vector<SDL_Event> events;
  for (int i = 0; i < 5; ++i) tap(events, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE);
  type(events, "stout");
  slow_frame(events);
  EXPECT_STREQ(path, "lagerstout");
}

TEST_F(SlowFrames, TypedTextBeforeABackspaceStaysInOrder) {
  start("");
  std::vector<SDL_Event> events;
  type(events, "abc");
  tap(events, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE);
  type(events, "d");
  slow_frame(events);
  EXPECT_STREQ(path, "abd");
}

// The bug, for the record: fed as they come, the same events lose the quick presses.
TEST_F(SlowFrames, WithoutTricklingQuickPressesAreLost) {
  start("lager.json");
  std::vector<SDL_Event> events;
  select_all(events);
  type(events, "x");
  frame(events, false);
  frame({}, false);
  EXPECT_STREQ(path, "lager.jsonx");
}

TEST(FrameEvents, AKeyDownAndUpTakeTwoFrames) {
  FrameEvents q;
  q.push(key(SDL_KEYDOWN, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE));
  q.push(key(SDL_KEYUP, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE));
  EXPECT_EQ(q.take_frame().size(), 1u);
  EXPECT_EQ(q.take_frame().size(), 1u);
  EXPECT_EQ(q.waiting(), 0u);
}

TEST(FrameEvents, TypingAndMotionGoInOneFrame) {
  // Character keys act through their text, so a word typed between two frames goes in one
  // frame, a capital's Shift too; key repeats and mouse motion change no key.
  FrameEvents q;
  std::vector<SDL_Event> events;
  type(events, "path");
  events.push_back(key(SDL_KEYDOWN, SDL_SCANCODE_LSHIFT, SDLK_LSHIFT, KMOD_LSHIFT));
  type(events, "x");
  events.push_back(key(SDL_KEYUP, SDL_SCANCODE_LSHIFT, SDLK_LSHIFT));
  type(events, "aa");
  SDL_Event repeat = key(SDL_KEYDOWN, SDL_SCANCODE_A, SDLK_a);
  repeat.key.repeat = 1;
  events.insert(events.end() - 2, repeat);  // held a moment before its release
  SDL_Event motion{};
  motion.type = SDL_MOUSEMOTION;
  events.push_back(motion);
  for (const SDL_Event& e : events) q.push(e);
  EXPECT_EQ(q.take_frame().size(), events.size());
}

TEST(FrameEvents, AnEditWaitsForTheTextBeforeItAndHoldsTheTextAfterIt) {
  FrameEvents q;
  std::vector<SDL_Event> events;
  type(events, "ab");                                   // 6 events
  tap(events, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE);  // its down goes with them
  type(events, "c");
  for (const SDL_Event& e : events) q.push(e);
  EXPECT_EQ(q.take_frame().size(), 7u);
  EXPECT_EQ(q.take_frame().size(), 4u);  // the Backspace's release, then "c"
  EXPECT_EQ(q.waiting(), 0u);
}

TEST(FrameEvents, EveryFrameTakesSomething) {
  FrameEvents q;
  for (int i = 0; i < 50; ++i) {
    q.push(key(SDL_KEYDOWN, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE));
    q.push(key(SDL_KEYUP, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE));
  }
  int frames = 0;
  while (q.waiting() > 0 && frames < 1000) {
    EXPECT_FALSE(q.take_frame().empty());
    ++frames;
  }
  EXPECT_EQ(frames, 100);
}

}  // namespace
}  // namespace draught::viewer
