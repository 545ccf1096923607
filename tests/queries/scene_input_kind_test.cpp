// The query layer's reading of a file's kind (queries/scene_input_kind.h): an assembly is read as one whatever the
// command, a one-workpiece scene or a UCP problem as before, and an assembly refuses a snap tolerance; the modes
// query of N bodies counts as its tree does.
#include "queries/scene_input_kind.h"

#include <gtest/gtest.h>

#include "exact/input_error.h"
#include "queries/assembly_modes_query.h"
#include "runtime/scenes.h"

namespace contactcert::queries {
namespace {

std::string bundled(const std::string& name) { return runtime::bundled_scenes_dir() + "/" + name + ".json"; }

TEST(SceneInputKind, AssembliesAndScenesAreTold) {
  EXPECT_TRUE(std::holds_alternative<AssemblyInput>(load_scene_or_assembly(bundled("assembly_two_boxes"))));
  EXPECT_TRUE(std::holds_alternative<SceneInput>(load_scene_or_assembly(bundled("bt2002_fig4a_lla"))));
  EXPECT_TRUE(std::holds_alternative<AssemblyInput>(load_ucp_or_assembly(bundled("assembly_pushed_boxes"))));
  EXPECT_TRUE(std::holds_alternative<UcpInput>(load_ucp_or_assembly(bundled("pang1994_dataset1_geometry"))));
  EXPECT_FALSE(is_assembly_text("{\"kind\": \"planar\", \"note\": \"no bodies here\"}", "t"));
  EXPECT_FALSE(is_assembly_text("not json, bodies", "t"));
  try {
    load_scene_or_assembly(bundled("assembly_two_boxes"), "1e-9");
    FAIL() << "no error";
  } catch (const exact::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--snap"), std::string::npos) << e.what();
  }
}

TEST(SceneInputKind, ModesOfAnAssembly) {
  const auto in = std::get<AssemblyInput>(load_scene_or_assembly(bundled("assembly_two_boxes")));
  const Limited<AssemblyModesAnswer> a = run_assembly_modes(in, {});
  ASSERT_TRUE(a) << a.limit().text();
  const json j = to_json(*a);
  EXPECT_EQ(j["modes"].size(), 100U);
  EXPECT_EQ(j["bodies"], 2);
  long total = 0;
  for (const auto& [group, count] : j["counts"].items()) total += count.get<long>();
  EXPECT_EQ(total, 100);
  AssemblyModesOptions bad;
  bad.common.arith = exact::Arith::kFloat;
  EXPECT_THROW(run_assembly_modes(in, bad), exact::InputError);
}

}  // namespace
}  // namespace contactcert::queries
