// What the viewer edits: the scene (its objects and their parameters), the presets it came
// from, which object is selected, and an undo history. No GL and no ImGui here, so it is
// tested without a window. Every change is validated before it lands; a preset action that
// fails leaves everything as it was.
#pragma once

#include "core/params/params.hpp"
#include "core/scene/scene.hpp"

#include <cstddef>
#include <deque>
#include <string>

namespace draught::viewer {

class Editor {
 public:
  // The scene as `draught render --preset preset --glass glass` resolves it (glass empty:
  // the drink's suggested one); a scene preset with objects places several glasses. Throws
  // InputError, for the command line to report.
  Editor(const std::string& preset, const std::string& glass);

  // scene().selected is the selected object (see select()).
  const Scene& scene() const { return now_.scene; }
  // The selected object with the scene's parameters: one glass as a single-glass preset
  // describes it (what Save as drink/glass writes; the whole scene when it has one object).
  Params document() const { return vessel_document(now_.scene, now_.scene.selected); }
  // Bumped by every change, so the app knows when to hand the scene on. Selecting is not a
  // change.
  unsigned revision() const { return revision_; }

  // The object that input drives and the panel edits. Not an undo step; it survives edits,
  // undo and preset switches, clamped to the objects there are.
  int selected() const { return now_.scene.selected; }
  void select(int object);

  // A change from a widget or a gesture (already validated through set_param); the
  // selection in `s` is ignored. Changes made while the user is still busy (a slider held,
  // a wheel turning) become one undo step at the first settle(false).
  void change(const Scene& s);
  void settle(bool busy);
  bool undo();  // false: nothing to undo
  std::size_t undo_depth() const { return history_.size() + (pending_ ? 1 : 0); }

  // Presets, resolved as the CLI resolves --preset and --glass: choosing a drink brings its
  // suggested glass; choosing either resets the other parameters to the presets' values; a
  // scene preset brings its objects. Load picks the role by the file's kind. Each returns
  // false and sets an error status when anything is wrong.
  bool choose_drink(const std::string& name_or_path);
  bool choose_glass(const std::string& name_or_path);
  bool load(const std::string& path);
  // An HDR environment (a .hdr or .exr file, or a shipped name) as the surroundings:
  // env.mode image with env.image the file, one undo step. A file that cannot be used sets
  // an error status and changes nothing.
  bool use_environment(const std::string& path);
  // kind: "scene" (every parameter), "drink" (liquid, foam, bubbles) or "glass", of the
  // selected object; a scene of several objects cannot be saved as one preset yet.
  // Validated and written atomically; the file then is what save() writes.
  bool save_as(const std::string& path, const std::string& kind);
  bool save();

  const std::string& drink_label() const { return now_.drink_label; }
  const std::string& glass_label() const { return now_.glass_label; }
  const std::string& file() const { return file_; }
  const std::string& file_kind() const { return file_kind_; }

  struct Status {
    std::string text;
    bool error = false;
  };
  const Status& status() const { return status_; }

 private:
  // What an undo step restores: the scene and the presets it came from.
  struct State {
    Scene scene;
    std::string drink, glass;  // as resolve_scene_objects takes them: names or paths
    std::string drink_label, glass_label;
  };
  static State resolve_named(const std::string& drink, const std::string& glass);
  bool resolve(const std::string& drink, const std::string& glass, const char* what);
  void restore(State st);  // now_ becomes st, keeping the selection (clamped)
  void replace(const State&);  // one undo step at once (presets, loads)
  bool fail(const std::string& message);

  static constexpr std::size_t kHistory = 100;
  State now_, committed_;  // committed_: what the last undo step ends with
  std::deque<State> history_;
  bool pending_ = false;
  unsigned revision_ = 0;
  std::string file_, file_kind_;
  Status status_;
};

}  // namespace draught::viewer
