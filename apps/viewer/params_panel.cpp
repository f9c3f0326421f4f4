#include "params_panel.hpp"

#include "core/liquid/beverage.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace draught::viewer {

namespace {

std::string group_of(const std::string& path) { return path.substr(0, path.find('.')); }

// One row of the panel: a parameter of the selected object or of the scene, and the path a
// user would type for it (objects[N]. only where the scene has several objects).
struct Row {
  Scene& scene;
  ParamRef ref;
  std::string path;
  const ParamDesc& desc() const { return *ref.desc; }
};

Row row_of(Scene& s, const ParamDesc& d) {
  const bool vessel = d.scope == ParamScope::Vessel;
  const ParamRef ref{vessel ? s.selected : -1, &d};
  const bool prefixed = vessel && s.objects.size() > 1;
  return {s, ref, prefixed ? "objects[" + std::to_string(s.selected) + "]." + d.path : d.path};
}

// "wall_thickness [m]##glass.wall_thickness": the unit in the label, the path as the id.
std::string label_of(const ParamDesc& d) {
  std::string l = d.path.substr(d.path.find('.') + 1);
  if (!d.unit.empty()) l += " [" + d.unit + "]";
  return l + "##" + d.path;
}

void tooltip(const Row& r) {
  const ParamDesc& d = r.desc();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\n%s\n\n%s", r.path.c_str(), d.doc.c_str(), ("expects " + expected_text(d)).c_str());
}

// The one way a value gets in: validated by set_param, rejected with the reason kept.
bool apply(Row& r, const ParamValue& v, ParamsPanelState& s) {
  try {
    set_param(r.scene, r.ref, v);
    s.error.clear();
    return true;
  } catch (const ParamError& e) {
    s.error = r.path + ": expected " + e.expected;
    return false;
  }
}

float clamp_to(const ParamDesc& d, float v) { return std::clamp(v, d.min, d.max); }  // NaN stays NaN: rejected

// Wide ranges (densities, half-lives, exposure) are unusable on a linear slider.
ImGuiSliderFlags float_flags(const ParamDesc& d) {
  const bool wide = d.min >= 0 && (d.max - d.min >= 100 || (d.min > 0 && d.max / d.min >= 1000));
  return ImGuiSliderFlags_AlwaysClamp | (wide ? ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_NoRoundToFormat : 0);
}

bool curve_widget(Row& r, ParamsPanelState& s) {
  const ParamDesc& d = r.desc();
  const bool open = ImGui::TreeNode(label_of(d).c_str());
  tooltip(r);
  if (!open) return false;
  Curve c = std::get<Curve>(get_param(r.scene, r.ref));
  bool edited = false;
  int remove = -1;
  const float speed = (d.max - d.min) * 1e-4f;
  if (ImGui::BeginTable("points", 3, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableSetupColumn("r [m]", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("y [m]", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableHeadersRow();
    for (int i = 0; i < int(c.size()); ++i) {
      ImGui::PushID(i);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-1);
      edited |= ImGui::DragFloat("##r", &c[i].x, speed, d.min, d.max, "%.4f", ImGuiSliderFlags_AlwaysClamp);
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-1);
      if (i == 0)
        ImGui::TextDisabled("0 (the foot)");  // the profile always starts at y = 0
      else
        edited |= ImGui::DragFloat("##y", &c[i].y, speed, 0.0f, d.max, "%.4f", ImGuiSliderFlags_AlwaysClamp);
      ImGui::TableNextColumn();
      ImGui::BeginDisabled(c.size() <= 2 || i == 0);  // the foot point stays
      if (ImGui::SmallButton("x")) remove = i;
      ImGui::EndDisabled();
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  if (remove >= 0) {
    c.erase(c.begin() + remove);
    edited = true;
  }
  ImGui::BeginDisabled(c.size() >= 32);
  if (ImGui::SmallButton("add a point on top")) {
    c.push_back({c.back().x, std::min(c.back().y + 0.01f, d.max)});
    edited = true;
  }
  ImGui::EndDisabled();
  ImGui::TreePop();
  for (auto& q : c) q.x = clamp_to(d, q.x);
  return edited && apply(r, c, s);
}

bool widget(Row r, ParamsPanelState& s) {
  const ParamDesc& d = r.desc();
  const std::string label = label_of(d);
  const ParamValue v = get_param(r.scene, r.ref);
  bool changed = false;
  switch (d.type) {
    case ParamType::Float: {
      float x = std::get<float>(v);
      if (ImGui::SliderFloat(label.c_str(), &x, d.min, d.max, "%.4g", float_flags(d)))
        changed = apply(r, clamp_to(d, x), s);
      break;
    }
    case ParamType::Int: {
      int x = std::get<int>(v);
      const int lo = int(d.min), hi = int(d.max);
      // Seeds span a million values: typed, not slid.
      const bool edited = hi - lo > 10000 ? ImGui::InputInt(label.c_str(), &x)
                                          : ImGui::SliderInt(label.c_str(), &x, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
      if (edited) changed = apply(r, std::clamp(x, lo, hi), s);
      break;
    }
    case ParamType::Bool: {
      bool x = std::get<bool>(v);
      if (ImGui::Checkbox(label.c_str(), &x)) changed = apply(r, x, s);
      break;
    }
    case ParamType::Vec3:
    case ParamType::Color: {
      glm::vec3 x = std::get<glm::vec3>(v);
      bool edited;
      if (d.type == ParamType::Color) {
        // Studio radiances go above 1: HDR lifts the 0..1 limit of the colour editor.
        const ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float | (d.max > 1 ? ImGuiColorEditFlags_HDR : 0);
        edited = ImGui::ColorEdit3(label.c_str(), &x.x, flags);
      } else {
        edited = ImGui::DragFloat3(label.c_str(), &x.x, (d.max - d.min) * 5e-4f, d.min, d.max, "%.4g",
                                   ImGuiSliderFlags_AlwaysClamp);
      }
      if (edited) changed = apply(r, glm::vec3(clamp_to(d, x.x), clamp_to(d, x.y), clamp_to(d, x.z)), s);
      break;
    }
    case ParamType::Enum: {
      const std::string& current = std::get<std::string>(v);
      if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
        for (const std::string& choice : d.choices)
          if (ImGui::Selectable(choice.c_str(), choice == current) && choice != current)
            changed = apply(r, choice, s);
        ImGui::EndCombo();
      }
      break;
    }
    case ParamType::Curve: return curve_widget(r, s);
    case ParamType::File: {
      // Typed or pasted, taken on Enter: a file is read (and refused if bad) once, not per key.
      char buf[kMaxFileParamBytes + 1] = {};
      const std::string& current = std::get<std::string>(v);
      current.copy(buf, kMaxFileParamBytes);
      if (ImGui::InputText(label.c_str(), buf, sizeof buf, ImGuiInputTextFlags_EnterReturnsTrue) &&
          current != buf)
        changed = apply(r, std::string(buf), s);
      break;
    }
  }
  tooltip(r);
  // Beside the drink's colour rows, what is in effect where this row is not (core
  // drink_colour_note, as the web page's panel): an EBC of 0 beside an SRM of 3.5 is not
  // a colourless beer.
  for (std::string_view field : kDrinkColourFields) {
    if (d.path != "liquid." + std::string(field)) continue;
    const std::string note = drink_colour_note(vessel_document(r.scene, r.ref.object).liquid, field);
    if (!note.empty()) ImGui::TextDisabled("  %s", note.c_str());
  }
  return changed;
}

// "amber-ale (objects[1])": an object by its name and the index its paths use.
std::string object_label(const Scene& s, int i) {
  return s.objects[size_t(i)].name + " (objects[" + std::to_string(i) + "])";
}

// The combo that picks the object the panel edits (and input drives).
void object_combo(Scene& s) {
  if (s.objects.size() < 2) return;
  if (ImGui::BeginCombo("object", object_label(s, s.selected).c_str())) {
    for (int i = 0; i < int(s.objects.size()); ++i)
      if (ImGui::Selectable(object_label(s, i).c_str(), i == s.selected)) s.selected = i;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The glass the panel edits and input drives (click it, or Tab)");
}

// The headers of the groups in one scope, in table order.
bool groups(Scene& s, ParamScope scope, ParamsPanelState& state) {
  std::vector<std::string> names;
  for (const ParamDesc& d : param_table())
    if (d.scope == scope && std::find(names.begin(), names.end(), group_of(d.path)) == names.end())
      names.push_back(group_of(d.path));
  bool changed = false;
  for (const std::string& g : names) {
    if (!ImGui::CollapsingHeader(g.c_str(), g == "liquid" ? ImGuiTreeNodeFlags_DefaultOpen : 0)) continue;
    for (const ParamDesc& d : param_table())
      if (group_of(d.path) == g) changed |= widget(row_of(s, d), state);
  }
  return changed;
}

}  // namespace

bool params_panel(Scene& s, ParamsPanelState& state) {
  if (!state.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", state.error.c_str());
    ImGui::PopStyleColor();
  }
  if (s.objects.empty()) return false;
  object_combo(s);
  // The selected object's groups (glass, liquid, foam, bubbles, clip, decals), then the scene's
  // (env, light, camera, render); ids differ by path, so both sets can be open at once.
  bool changed = false;
  if (as_vessel(s.objects[size_t(s.selected)])) {
    ImGui::TextDisabled("%s", s.objects.size() > 1 ? "the selected glass and its drink" : "the glass and its drink");
    changed = groups(s, ParamScope::Vessel, state);
  } else {
    // A droplets trail or a point cloud: its parameters are its own (the scene file's
    // "droplets" or "pointcloud" object), not the table's glass and drink.
    ImGui::TextDisabled("%s: a %s; its parameters are in the scene file", s.objects[size_t(s.selected)].name.c_str(),
                        as_cloud(s.objects[size_t(s.selected)]) ? "point cloud" : "droplets trail");
  }
  ImGui::Spacing();
  ImGui::TextDisabled("the scene");
  changed |= groups(s, ParamScope::Scene, state);
  return changed;
}

}  // namespace draught::viewer
