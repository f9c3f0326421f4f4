#include "core/scene/scene.hpp"

#include <charconv>
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

ObjectPath split_object_path(std::string_view path) {
  ObjectPath out{-1, path};
  if (!path.starts_with("objects[")) return out;
  const size_t close = path.find(']');
  const std::string_view index = path.substr(8, close == std::string_view::npos ? 0 : close - 8);
  int i = -1;
  const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), i);
  const bool number = !index.empty() && ec == std::errc() && end == index.data() + index.size() && i >= 0;
  if (close == std::string_view::npos || !number || path.substr(close, 2) != "]." || path.size() <= close + 2)
    throw ParamError(std::string(path), "a path like objects[2].liquid.fill (an object index from 0, then a parameter)");
  out.object = i;
  out.param = path.substr(close + 2);
  return out;
}

std::string object_range_text(const Scene& s) {
  const int n = int(s.objects.size());
  if (n == 0) return "no objects[N] prefix (the scene has no objects)";
  return "an object index from 0 to " + std::to_string(n - 1) + " (the scene has " + std::to_string(n) +
         (n == 1 ? " object)" : " objects)");
}

ParamRef parse_param_ref(const Scene& s, std::string_view path) {
  const ObjectPath split = split_object_path(path);
  ParamRef ref;
  ref.object = split.object;
  ref.desc = find_param(split.param);
  if (!ref.desc)
    throw ParamError(std::string(split.param),
                     "a parameter of the table (" + unknown_param_message(std::string(split.param)) + ")");
  if (ref.object >= 0 && ref.desc->scope == ParamScope::Scene)
    throw ParamError(std::string(path),
                     "no objects[N] prefix: " + ref.desc->path + " belongs to the whole scene, not to one object");
  if (ref.object >= int(s.objects.size())) throw ParamError(std::string(path), object_range_text(s));
  return ref;
}

ParamValue get_param(const Scene& s, const ParamRef& ref) {
  if (ref.desc->scope == ParamScope::Scene) return get_param(s.params, *ref.desc);
  const int object = ref.object >= 0 ? ref.object : s.selected;
  if (object < 0 || object >= int(s.objects.size()))
    throw std::out_of_range("no object " + std::to_string(object));
  const VesselObject* v = as_vessel(s.objects[size_t(object)]);
  if (!v) throw ParamError(ref.desc->path, "a vessel object (object " + std::to_string(object) + " is not one)");
  return get_param(v->params, *ref.desc);
}

void set_param(Scene& s, const ParamRef& ref, const ParamValue& v) {
  validate_value(*ref.desc, v);
  if (ref.desc->scope == ParamScope::Scene) {
    set_param(s.params, *ref.desc, v);
    return;
  }
  if (ref.object >= int(s.objects.size())) throw std::out_of_range("no object " + std::to_string(ref.object));
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (ref.object >= 0 && int(i) != ref.object) continue;
    if (VesselObject* vo = as_vessel(s.objects[i])) set_param(vo->params, *ref.desc, v);
  }
}

}  // namespace draught
