#include "preset_panel.hpp"

#include <imgui.h>

namespace draught::viewer {

namespace {

const char* const kKinds[] = {"scene", "drink", "glass"};

void red_text(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.35f, 1.0f));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

// A combo of presets; the preview is the editor's current choice. Returns the file picked.
const Preset* preset_combo(const char* label, const std::string& current, const std::vector<Preset>& presets) {
  const Preset* picked = nullptr;
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (const Preset& p : presets) {
      const std::string item = p.kind == "scene" ? p.name + " (scene)" : p.name;
      if (ImGui::Selectable(item.c_str(), p.name == current)) picked = &p;
      if (ImGui::IsItemHovered() && !p.description.empty()) ImGui::SetTooltip("%s", p.description.c_str());
    }
    ImGui::EndCombo();
  }
  return picked;
}

}  // namespace

PresetPanelState make_preset_panel_state() {
  PresetPanelState s;
  try {
    for (Preset& p : list_presets()) (p.kind == "glass" ? s.glasses : s.drinks).push_back(std::move(p));
  } catch (const std::exception& e) {
    s.list_error = e.what();
  }
  return s;
}

void preset_panel(Editor& ed, PresetPanelState& s) {
  if (!s.list_error.empty()) red_text("presets: " + s.list_error);
  // Files, not names: a preset's name need not match its file name.
  if (const Preset* p = preset_combo("drink##preset", ed.drink_label(), s.drinks)) ed.choose_drink(p->file);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A drink brings its suggested glass; other parameters reset");
  if (const Preset* p = preset_combo("glass##preset", ed.glass_label(), s.glasses)) ed.choose_glass(p->file);

  ImGui::InputText("file", s.path, sizeof s.path);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A preset JSON file, relative to the working directory");
  if (ImGui::Button("Load")) ed.load(s.path);
  ImGui::SameLine();
  ImGui::BeginDisabled(ed.file().empty());
  if (ImGui::Button("Save")) ed.save();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%s", ed.file().empty() ? "Load or Save as first"
                                              : ("Overwrite " + ed.file() + " (" + ed.file_kind() + ")").c_str());
  ImGui::SameLine();
  if (ImGui::Button("Save as")) ed.save_as(s.path, kKinds[s.save_kind]);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5);
  ImGui::Combo("##kind", &s.save_kind, kKinds, 3);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("What Save as writes: scene (every parameter), drink (liquid, foam, bubbles) or glass");
  ImGui::SameLine();
  ImGui::BeginDisabled(ed.undo_depth() == 0);
  if (ImGui::Button("Undo")) ed.undo();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Ctrl+Z");

  const Editor::Status& st = ed.status();
  if (st.error) red_text(st.text);
  else if (!st.text.empty()) ImGui::TextDisabled("%s", st.text.c_str());
}

}  // namespace draught::viewer
