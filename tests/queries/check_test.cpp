#include "queries/check.h"

#include <gtest/gtest.h>

#include "exact/input_error.h"
#include "queries/ucp_query.h"
#include "runtime/scenes.h"

namespace contactcert::queries {
namespace {

std::string scene(const std::string& name) { return runtime::bundled_scenes_dir() + "/" + name; }

/// The certificate `ucp FILE --certificate` writes for a bundled problem.
std::string ucp_certificate(const std::string& name) {
  return solvers::ucp::certificate_text(load_ucp(scene(name)).problem, run_ucp(load_ucp(scene(name)), {})->report);
}

TEST(Check, UcpCertificateAgainstItsProblemAndAnother) {
  const exact::JsonInput cert = exact::JsonInput::parse(ucp_certificate("pang1994_dataset4.json"), "cert");
  const CheckResult alone = check(cert);
  EXPECT_TRUE(alone.valid()) << alone.reason;
  EXPECT_EQ(alone.kind, "ucp_jammed");
  EXPECT_EQ(alone.digest.size(), 64u);
  EXPECT_TRUE(alone.problem.empty());
  EXPECT_GT(alone.details["nodes"].get<long>(), 0);

  const exact::JsonInput own = exact::JsonInput::load(scene("pang1994_dataset4.json"));
  EXPECT_TRUE(check(cert, &own).valid());
  const exact::JsonInput other = exact::JsonInput::load(scene("pang1994_dataset1.json"));
  const CheckResult c = check(cert, &other);
  EXPECT_FALSE(c.valid());
  EXPECT_NE(c.reason.find("is about another problem than"), std::string::npos);
  const json j = to_json(c);
  EXPECT_EQ(j["valid"], false);
  EXPECT_EQ(j["problem"], other.file());
  EXPECT_EQ(j["problem_sha256"], alone.digest);
  EXPECT_EQ(j["nodes"], alone.details["nodes"]);
}

TEST(Check, UnknownKindNamesEveryKindOfTheTable) {
  const exact::JsonInput cert = exact::JsonInput::parse(R"({"kind": "ucp_maybe"})", "cert");
  try {
    check(cert);
    FAIL() << "no error";
  } catch (const exact::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "expected a certificate kind: ucp_jammed, ucp_solvable, stability, modes, "
                  "cone_empty, cone_nonempty, goal_nonempty, assembly_stability, assembly_modes, "
                  "spatial_modes, spatial_stability, spatial_cone or motion_uniqueness, found \"ucp_maybe\""),
              std::string::npos)
        << e.what();
  }
}

TEST(Check, ForgedPairIsInvalid) {
  std::string text = ucp_certificate("pang1994_dataset1.json");
  const exact::JsonInput genuine = exact::JsonInput::parse(text, "cert");
  EXPECT_TRUE(check(genuine).valid());
  const std::size_t x = text.find("\"x\"");
  ASSERT_NE(x, std::string::npos);
  const std::size_t first = text.find('"', text.find('[', x));  // the first entry of x, bumped
  text.insert(first + 1, "12345");
  EXPECT_FALSE(check(exact::JsonInput::parse(text, "cert")).valid());
}

}  // namespace
}  // namespace contactcert::queries
