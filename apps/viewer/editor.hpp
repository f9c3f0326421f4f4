// What the viewer edits: the parameters, the presets they came from, and an undo history.
// No GL and no ImGui here, so it is tested without a window. Every change is validated
// before it lands; a preset action that fails leaves everything as it was.
#pragma once

#include "core/params/params.hpp"

#include <cstddef>
#include <deque>
#include <string>

namespace draught::viewer {

class Editor {
 public:
  // The scene as `draught render --preset drink --glass glass` resolves it (glass empty:
  // the drink's suggested one). Throws InputError, for the command line to report.
  Editor(const std::string& drink, const std::string& glass);

  const Params& params() const { return now_.params; }
  // Bumped by every change, so the app knows when to hand the parameters on.
  unsigned revision() const { return revision_; }

  // A change from a widget or a gesture (already validated through set_param). Changes made
  // while the user is still busy (a slider held, a wheel turning) become one undo step at
  // the first settle(false).
  void change(const Params& p);
  void settle(bool busy);
  bool undo();  // false: nothing to undo
  std::size_t undo_depth() const { return history_.size() + (pending_ ? 1 : 0); }

  // Presets. Choosing a drink brings its suggested glass (as the CLI does); choosing either
  // resets the other parameters to the presets' values. Load picks the role by the file's
  // kind. Each returns false and sets an error status when anything is wrong.
  bool choose_drink(const std::string& name_or_path);
  bool choose_glass(const std::string& name_or_path);
  bool load(const std::string& path);
  // kind: "scene" (every parameter), "drink" (liquid, foam, bubbles) or "glass". Validated
  // and written atomically; the file then is what save() writes.
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
  // What an undo step restores: the parameters and the presets they came from.
  struct State {
    Params params;
    std::string drink, glass;  // as resolve_scene takes them: names or paths
    std::string drink_label, glass_label;
  };
  static State resolve_named(const std::string& drink, const std::string& glass);
  bool resolve(const std::string& drink, const std::string& glass, const char* what);
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
