// The row builder of the parameter table: a row names its field by member pointers
// (`&VesselParams::glass, &GlassParams::ior`), so the path, the type and the field cannot
// drift apart. A row whose ParamType does not match the field's C++ type (Float: float,
// Int and Enum: int, Bool: bool, Vec3 and Color: glm::vec3, Curve: Curve, File: std::string), or whose
// field does not belong to its group, does not compile (ParamRowMatches). The scope
// comes from the struct that holds the group: VesselParams rows are per object,
// SceneParams rows belong to the scene. The default is read from a default-constructed
// struct, so defaults live only in params.hpp.
#pragma once

#include "core/params/params.hpp"

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace draught {

template <ParamType T> struct ParamCppType;
template <> struct ParamCppType<ParamType::Float> { using type = float; };
template <> struct ParamCppType<ParamType::Int> { using type = int; };
template <> struct ParamCppType<ParamType::Bool> { using type = bool; };
template <> struct ParamCppType<ParamType::Vec3> { using type = glm::vec3; };
template <> struct ParamCppType<ParamType::Color> { using type = glm::vec3; };
template <> struct ParamCppType<ParamType::Enum> { using type = int; };  // the index into `choices`
template <> struct ParamCppType<ParamType::Curve> { using type = Curve; };
template <> struct ParamCppType<ParamType::File> { using type = std::string; };
template <ParamType T> using param_cpp_t = typename ParamCppType<T>::type;

// The class a member pointer belongs to and the member's type.
template <class M> struct MemberPointer {};
template <class C, class F> struct MemberPointer<F C::*> {
  using owner = C;
  using type = F;
};

template <class Root>
inline constexpr bool is_param_root = std::is_same_v<Root, VesselParams> || std::is_same_v<Root, SceneParams>;

// `Group` is a group of VesselParams or SceneParams, `Field` a field of that group, and
// the field's C++ type is the one the ParamType stands for.
template <ParamType T, auto Group, auto Field>
concept ParamRowMatches =
    std::is_member_object_pointer_v<decltype(Group)> && std::is_member_object_pointer_v<decltype(Field)> &&
    is_param_root<typename MemberPointer<decltype(Group)>::owner> &&
    std::is_same_v<typename MemberPointer<decltype(Field)>::owner, typename MemberPointer<decltype(Group)>::type> &&
    std::is_same_v<typename MemberPointer<decltype(Field)>::type, param_cpp_t<T>>;

namespace detail {
template <ParamType T, auto Group, auto Field, class Root>
ParamValue get_field(const ParamDesc& d, const Root& r) {
  const auto& x = r.*Group.*Field;
  if constexpr (T == ParamType::Enum) return d.choices.at(size_t(x));
  else return x;
}

template <ParamType T, auto Group, auto Field, class Root>
void set_field(const ParamDesc& d, Root& r, const ParamValue& v) {
  auto& x = r.*Group.*Field;
  if constexpr (T == ParamType::Enum) {
    for (size_t i = 0; i < d.choices.size(); ++i)
      if (d.choices[i] == std::get<std::string>(v)) x = int(i);
  } else {
    x = std::get<param_cpp_t<T>>(v);
  }
}
}  // namespace detail

template <ParamType T, auto Group, auto Field>
  requires ParamRowMatches<T, Group, Field>
ParamDesc param_row(std::string path, float lo, float hi, std::string unit, std::string doc,
                    std::vector<std::string> choices = {}) {
  using Root = typename MemberPointer<decltype(Group)>::owner;
  ParamDesc d;
  d.path = std::move(path);
  d.type = T;
  d.min = lo;
  d.max = hi;
  d.unit = std::move(unit);
  d.doc = std::move(doc);
  d.choices = std::move(choices);
  ParamAccess<Root> access{&detail::get_field<T, Group, Field, Root>, &detail::set_field<T, Group, Field, Root>};
  if constexpr (std::is_same_v<Root, VesselParams>) {
    d.scope = ParamScope::Vessel;
    d.vessel = access;
  } else {
    d.scope = ParamScope::Scene;
    d.scene = access;
  }
  d.def = access.get(d, Root{});
  return d;
}

// The table's rows: the path string and the member pointers from the same names.
#define DRAUGHT_PARAM_ROW(Root, group, name, type, ...)                                              \
  ::draught::param_row<::draught::ParamType::type, &Root::group, &decltype(Root::group)::name>( \
      #group "." #name, __VA_ARGS__)

}  // namespace draught
