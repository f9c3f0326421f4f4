// Scenes of several objects: object-addressed parameter paths (objects[2].liquid.fill),
// reading and writing them, and their errors.
#include "core/scene/scene.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <string>

namespace draught {
namespace {

// Three glasses of the default drink, each with its own fill, and the second selected.
Scene three_glasses() {
  Scene s;
  s.params = default_params();
  for (int i = 0; i < 3; ++i) {
    VesselParams v;
    v.liquid.fill = 0.2f + 0.1f * float(i);
    s.objects.push_back(SceneObject{"g" + std::to_string(i), Placement{glm::vec3(0.2f * float(i), 0, 0), 0}, VesselObject{v}});
  }
  s.selected = 1;
  return s;
}

float fill_of(const Scene& s, int i) { return as_vessel(s.objects[size_t(i)])->params.liquid.fill; }

std::string error_of(const Scene& s, const std::string& path) {
  try {
    parse_param_ref(s, path);
  } catch (const ParamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ObjectPath, SplitsThePrefix) {
  ObjectPath p = split_object_path("objects[2].liquid.fill");
  EXPECT_EQ(p.object, 2);
  EXPECT_EQ(p.param, "liquid.fill");
  p = split_object_path("objects[17].glass.profile");
  EXPECT_EQ(p.object, 17);
  EXPECT_EQ(p.param, "glass.profile");
  p = split_object_path("liquid.fill");
  EXPECT_EQ(p.object, -1);
  EXPECT_EQ(p.param, "liquid.fill");
  for (const char* bad : {"objects[].liquid.fill", "objects[x].liquid.fill", "objects[-1].liquid.fill",
                          "objects[1]", "objects[1].", "objects[1]liquid.fill", "objects[1.5].liquid.fill",
                          "objects[2", "objects[+1].liquid.fill", "objects[99999999999].liquid.fill"}) {
    try {
      split_object_path(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const ParamError& e) {
      EXPECT_EQ(e.field, bad);
      EXPECT_NE(std::string(e.what()).find("objects[2].liquid.fill"), std::string::npos) << e.what();
    }
  }
}

TEST(ObjectPath, ParseRefAddressesOneObjectEveryObjectOrTheScene) {
  const Scene s = three_glasses();
  ParamRef r = parse_param_ref(s, "objects[2].liquid.fill");
  EXPECT_EQ(r.object, 2);
  EXPECT_EQ(r.desc, find_param("liquid.fill"));
  r = parse_param_ref(s, "liquid.fill");
  EXPECT_EQ(r.object, -1);
  EXPECT_EQ(r.desc, find_param("liquid.fill"));
  r = parse_param_ref(s, "env.floor");
  EXPECT_EQ(r.object, -1);
  EXPECT_EQ(r.desc->scope, ParamScope::Scene);
}

TEST(ObjectPath, ErrorsNameThePathAndWhatWasExpected) {
  const Scene s = three_glasses();
  const std::string range = error_of(s, "objects[3].liquid.fill");
  EXPECT_NE(range.find("objects[3].liquid.fill"), std::string::npos) << range;
  EXPECT_NE(range.find("from 0 to 2"), std::string::npos) << range;
  EXPECT_NE(range.find("3 objects"), std::string::npos) << range;
  const std::string scope = error_of(s, "objects[1].env.floor");
  EXPECT_NE(scope.find("env.floor belongs to the whole scene"), std::string::npos) << scope;
  const std::string unknown = error_of(s, "objects[1].liquid.fil");
  EXPECT_NE(unknown.find("did you mean 'liquid.fill'"), std::string::npos) << unknown;
  EXPECT_NE(error_of(s, "objects[a].liquid.fill").find("a path like objects[2].liquid.fill"), std::string::npos);
  Scene empty;
  EXPECT_NE(error_of(empty, "objects[0].liquid.fill").find("the scene has no objects"), std::string::npos);
  // One object: singular.
  Scene one = single_glass_scene(default_params());
  EXPECT_NE(error_of(one, "objects[1].liquid.fill").find("from 0 to 0 (the scene has 1 object)"), std::string::npos)
      << error_of(one, "objects[1].liquid.fill");
}

TEST(ObjectPath, SetReachesOneObjectOrEvery) {
  Scene s = three_glasses();
  set_param(s, parse_param_ref(s, "objects[2].liquid.fill"), 0.5f);
  EXPECT_EQ(fill_of(s, 0), 0.2f);
  EXPECT_EQ(fill_of(s, 1), 0.3f);
  EXPECT_EQ(fill_of(s, 2), 0.5f);
  set_param(s, parse_param_ref(s, "liquid.fill"), 0.7f);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(fill_of(s, i), 0.7f) << i;
  set_param(s, parse_param_ref(s, "env.floor"), false);
  EXPECT_FALSE(s.params.env.floor);
  set_param(s, parse_param_ref(s, "objects[0].glass.ior"), 1.9f);
  EXPECT_EQ(as_vessel(s.objects[0])->params.glass.ior, 1.9f);
  EXPECT_EQ(as_vessel(s.objects[1])->params.glass.ior, 1.52f);
}

TEST(ObjectPath, GetReadsTheObjectOrTheSelectedOne) {
  const Scene s = three_glasses();
  EXPECT_TRUE(get_param(s, parse_param_ref(s, "objects[0].liquid.fill")) == ParamValue(0.2f));
  EXPECT_TRUE(get_param(s, parse_param_ref(s, "objects[2].liquid.fill")) == ParamValue(0.4f));
  EXPECT_TRUE(get_param(s, parse_param_ref(s, "liquid.fill")) == ParamValue(0.3f)) << "the selected object (1)";
  EXPECT_TRUE(get_param(s, parse_param_ref(s, "render.tonemap")) == ParamValue(std::string("aces")));
}

TEST(ObjectPath, BadValuesChangeNothing) {
  Scene s = three_glasses();
  EXPECT_THROW(set_param(s, parse_param_ref(s, "objects[1].liquid.fill"), 2.0f), ParamError);
  EXPECT_THROW(set_param(s, parse_param_ref(s, "liquid.fill"), std::string("full")), ParamError);
  EXPECT_THROW(set_param(s, ParamRef{7, find_param("liquid.fill")}, 0.5f), std::out_of_range);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(fill_of(s, i), 0.2f + 0.1f * float(i)) << i;
}

TEST(SingleGlassScene, RoundTripsItsDocument) {
  Params p = default_params();
  p.liquid.fill = 0.4f;
  p.env.floor = false;
  p.glass.profile = {{0.03f, 0.0f}, {0.04f, 0.12f}};
  const Scene s = single_glass_scene(p);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].placement.position, glm::vec3(0.0f));
  EXPECT_EQ(s.objects[0].placement.yaw, 0.0f);
  const Params back = vessel_document(s, 0);
  for (const auto& d : param_table()) EXPECT_TRUE(get_param(back, d) == get_param(p, d)) << d.path;
  EXPECT_THROW(vessel_document(s, 1), std::out_of_range);
}

}  // namespace
}  // namespace draught
