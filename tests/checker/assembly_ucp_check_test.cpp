// The checker's own Pang-Trinkle-Lo problem of an assembly (checker/assembly_ucp_check.h): it agrees entry for entry
// with the solver's builder (solvers/assembly/assembly_ucp.h) on every bundled assembly with fingers, and a problem
// with one entry off (a solver that built P, Jn, d, mu or the joints wrongly) is refused, naming the entry.
#include "checker/assembly_ucp_check.h"

#include <gtest/gtest.h>

#include "exact/json_input.h"
#include "runtime/scenes.h"
#include "solvers/assembly/assembly_ucp.h"

namespace contactcert::checker {
namespace {

using exact::Q;

geometry::Assembly bundled(const std::string& name) {
  const std::string path = runtime::bundled_scenes_dir() + "/" + name + ".json";
  return geometry::read_assembly(exact::JsonInput::parse(exact::JsonInput::read_text(path), path));
}

TEST(AssemblyUcpCheck, AgreesWithTheSolversBuilderOnTheBundledAssemblies) {
  for (const char* name : {"assembly_pushed_boxes", "assembly_pushed_boxes_wall"}) {
    const geometry::Assembly a = bundled(name);
    EXPECT_EQ(assembly_problem_violation(a, solvers::assembly::assembly_quasistatic(a)), "") << name;
  }
}

TEST(AssemblyUcpCheck, RefusesAProblemWithOneEntryOff) {
  const geometry::Assembly a = bundled("assembly_pushed_boxes");
  const solvers::ucp::QuasistaticProblem right = solvers::assembly::assembly_quasistatic(a);
  auto p = right;
  p.P(4, 2) += 1;  // a torque arm of the contact between the boxes
  EXPECT_NE(assembly_problem_violation(a, p).find("P[4][2] is"), std::string::npos) << assembly_problem_violation(a, p);
  p = right;
  p.Jn = -p.Jn;  // the finger's joint pushing the other way
  EXPECT_NE(assembly_problem_violation(a, p).find("Jn["), std::string::npos);
  p = right;
  p.d(p.nc + 1) = 0;  // no gravity on body 0
  EXPECT_NE(assembly_problem_violation(a, p).find("d["), std::string::npos);
  p = right;
  p.mu(0) = Q(1, 2);
  EXPECT_NE(assembly_problem_violation(a, p).find("mu["), std::string::npos);
  p = right;
  std::swap(p.alpha, p.abar);  // the finger force-controlled
  EXPECT_NE(assembly_problem_violation(a, p), "");
  // A contact whose normal the file states wrongly is refused before any matrix is compared.
  geometry::Assembly bent = a;
  bent.contacts[4].normal = {Q(1), Q(1)};
  EXPECT_NE(assembly_problem_violation(bent, right).find("contact 4"), std::string::npos);
}

}  // namespace
}  // namespace contactcert::checker
