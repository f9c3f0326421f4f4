#include "params_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace draught::viewer {

namespace {

std::string group_of(const std::string& path) { return path.substr(0, path.find('.')); }

// "wall_thickness [m]##glass.wall_thickness": the unit in the label, the path as the id.
std::string label_of(const ParamDesc& d) {
  std::string l = d.path.substr(d.path.find('.') + 1);
  if (!d.unit.empty()) l += " [" + d.unit + "]";
  return l + "##" + d.path;
}

void tooltip(const ParamDesc& d) {
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s\n%s\n\n%s", d.path.c_str(), d.doc.c_str(), ("expects " + expected_text(d)).c_str());
}

// The one way a value gets in: validated by set_param, rejected with the reason kept.
bool apply(Params& p, const ParamDesc& d, const ParamValue& v, ParamsPanelState& s) {
  try {
    set_param(p, d, v);
    s.error.clear();
    return true;
  } catch (const ParamError& e) {
    s.error = e.what();
    return false;
  }
}

float clamp_to(const ParamDesc& d, float v) { return std::clamp(v, d.min, d.max); }  // NaN stays NaN: rejected

// Wide ranges (densities, half-lives, exposure) are unusable on a linear slider.
ImGuiSliderFlags float_flags(const ParamDesc& d) {
  const bool wide = d.min >= 0 && (d.max - d.min >= 100 || (d.min > 0 && d.max / d.min >= 1000));
  return ImGuiSliderFlags_AlwaysClamp | (wide ? ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_NoRoundToFormat : 0);
}

bool curve_widget(Params& p, const ParamDesc& d, ParamsPanelState& s) {
  const bool open = ImGui::TreeNode(label_of(d).c_str());
  tooltip(d);
  if (!open) return false;
  Curve c = std::get<Curve>(get_param(p, d));
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
  return edited && apply(p, d, c, s);
}

bool widget(Params& p, const ParamDesc& d, ParamsPanelState& s) {
  const std::string label = label_of(d);
  const ParamValue v = get_param(p, d);
  bool changed = false;
  switch (d.type) {
    case ParamType::Float: {
      float x = std::get<float>(v);
      if (ImGui::SliderFloat(label.c_str(), &x, d.min, d.max, "%.4g", float_flags(d)))
        changed = apply(p, d, clamp_to(d, x), s);
      break;
    }
    case ParamType::Int: {
      int x = std::get<int>(v);
      const int lo = int(d.min), hi = int(d.max);
      // Seeds span a million values: typed, not slid.
      const bool edited = hi - lo > 10000 ? ImGui::InputInt(label.c_str(), &x)
                                          : ImGui::SliderInt(label.c_str(), &x, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
      if (edited) changed = apply(p, d, std::clamp(x, lo, hi), s);
      break;
    }
    case ParamType::Bool: {
      bool x = std::get<bool>(v);
      if (ImGui::Checkbox(label.c_str(), &x)) changed = apply(p, d, x, s);
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
      if (edited) changed = apply(p, d, glm::vec3(clamp_to(d, x.x), clamp_to(d, x.y), clamp_to(d, x.z)), s);
      break;
    }
    case ParamType::Enum: {
      const std::string& current = std::get<std::string>(v);
      if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
        for (const std::string& choice : d.choices)
          if (ImGui::Selectable(choice.c_str(), choice == current) && choice != current)
            changed = apply(p, d, choice, s);
        ImGui::EndCombo();
      }
      break;
    }
    case ParamType::Curve: return curve_widget(p, d, s);
  }
  tooltip(d);
  return changed;
}

}  // namespace

bool params_panel(Params& p, ParamsPanelState& s) {
  if (!s.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", s.error.c_str());
    ImGui::PopStyleColor();
  }
  // Groups in table order: glass, liquid, foam, bubbles, env, light, camera, render.
  std::vector<std::string> groups;
  for (const ParamDesc& d : param_table())
    if (std::find(groups.begin(), groups.end(), group_of(d.path)) == groups.end()) groups.push_back(group_of(d.path));
  bool changed = false;
  for (const std::string& g : groups) {
    if (!ImGui::CollapsingHeader(g.c_str(), g == "liquid" ? ImGuiTreeNodeFlags_DefaultOpen : 0)) continue;
    for (const ParamDesc& d : param_table())
      if (group_of(d.path) == g) changed |= widget(p, d, s);
  }
  return changed;
}

}  // namespace draught::viewer
