#include "core/scene/scene.hpp"

#include <stdexcept>

namespace draught {

Scene single_glass_scene(const Params& p) {
  Scene s;
  s.params = p;  // the SceneParams part
  s.objects.push_back(SceneObject{"glass", Placement{}, VesselObject{p}});
  return s;
}

Params vessel_document(const Scene& s, int object) {
  if (object < 0 || object >= int(s.objects.size())) throw std::out_of_range("no object " + std::to_string(object));
  Params p;
  static_cast<SceneParams&>(p) = s.params;
  if (const VesselObject* v = as_vessel(s.objects[size_t(object)])) static_cast<VesselParams&>(p) = v->params;
  return p;
}

ParamRef parse_param_ref(const Scene& s, std::string_view path) {
  ParamRef ref;
  if (path.substr(0, 8) == "objects[") {
    const size_t close = path.find("].");
    if (close == std::string_view::npos)
      throw ParamError(std::string(path), "a path like objects[2].liquid.fill");
    const std::string index(path.substr(8, close - 8));
    int i = -1;
    try {
      size_t used = 0;
      i = std::stoi(index, &used);
      if (used != index.size()) i = -1;
    } catch (const std::exception&) {
      i = -1;
    }
    if (i < 0 || i >= int(s.objects.size()))
      throw ParamError(std::string(path), "an object index from 0 to " + std::to_string(int(s.objects.size()) - 1));
    ref.object = i;
    path.remove_prefix(close + 2);
  }
  ref.desc = find_param(path);
  if (!ref.desc) throw ParamError(std::string(path), "a parameter of the table (" + unknown_param_message(std::string(path)) + ")");
  if (ref.object >= 0 && ref.desc->scope == ParamScope::Scene)
    throw ParamError(std::string(path), "no objects[N] prefix: " + ref.desc->path + " belongs to the whole scene");
  return ref;
}

ParamValue get_param(const Scene& s, const ParamRef& ref) {
  const int object = ref.object >= 0 ? ref.object : s.selected;
  return get_param(vessel_document(s, ref.desc->scope == ParamScope::Scene ? 0 : object), *ref.desc);
}

void set_param(Scene& s, const ParamRef& ref, const ParamValue& v) {
  validate_value(*ref.desc, v);
  if (ref.desc->scope == ParamScope::Scene) {
    Params p;
    static_cast<SceneParams&>(p) = s.params;
    set_param(p, *ref.desc, v);
    s.params = p;
    return;
  }
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (ref.object >= 0 && int(i) != ref.object) continue;
    if (VesselObject* vo = as_vessel(s.objects[i])) {
      Params p;
      static_cast<VesselParams&>(p) = vo->params;
      set_param(p, *ref.desc, v);
      vo->params = p;
    }
  }
}

}  // namespace draught
