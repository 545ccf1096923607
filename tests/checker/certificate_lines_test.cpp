// A certificate in lines (checker/certificate_lines.h): the one-line members read as one object, each list's element
// lines parsed alone with messages naming the line, and every other layout of the same JSON refused naming the line.
#include "checker/certificate_lines.h"

#include <gtest/gtest.h>

#include <string>

namespace contactcert::checker {
namespace {

const std::string kText =
    "{\n"
    " \"kind\": \"spatial_stability\",\n"
    " \"wrench\": [\"0\",\"-1\"],\n"
    " \"vectors\": [\n"
    "  {\"rows\":[[0,\"s\",0]]},\n"
    "  {\"rows\":[]}\n"
    " ],\n"
    " \"dead\": [\n"
    " ],\n"
    " \"modes\": [\n"
    "  {\"mode\":\"ff\",\"vector\":7}\n"
    " ]\n"
    "}\n";

// The message of the InputError that reading `text` throws, or "" if it reads.
std::string refusal(const std::string& text) {
  try {
    CertificateLines(text, "c.json").expect_lists({"vectors", "dead", "modes"});
  } catch (const exact::InputError& e) {
    return e.what();
  }
  return "";
}

// Replaces the first `from` in kText by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string t = kText;
  t.replace(t.find(from), from.size(), to);
  return t;
}

TEST(CertificateLines, ReadsTheMembersAndEachElementAlone) {
  EXPECT_TRUE(CertificateLines::starts_as(kText, "spatial_stability"));
  EXPECT_FALSE(CertificateLines::starts_as(kText, "spatial_modes"));
  const CertificateLines c(kText, "c.json");
  EXPECT_EQ(c.head().canonical_text(), R"({"kind":"spatial_stability","wrench":["0","-1"]})");
  EXPECT_EQ(c.size("vectors"), 2u);
  EXPECT_EQ(c.size("dead"), 0u);
  EXPECT_EQ(c.size("modes"), 1u);
  EXPECT_EQ(c.size("proofs"), 0u);
  EXPECT_EQ(c.element("vectors", 1).at("rows").size(), 0u);
  try {
    c.element("modes", 0).at("vector").integer(0, 1);
    ADD_FAILURE() << "an index out of range read";
  } catch (const exact::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "c.json, line 11: $.vector: expected an integer from 0 to 1, found 7");
  }
}

TEST(CertificateLines, RefusesEveryOtherLayout) {
  EXPECT_EQ(refusal(kText), "");
  EXPECT_NE(refusal(edited("{\n \"kind\"", "{ \"kind\"")).find("line 1: '{' alone on the first line"),
            std::string::npos);
  EXPECT_NE(refusal(edited(" \"wrench\": [\"0\",\"-1\"],\n", " \"wrench\": [\"0\",\n  \"-1\"],\n"))
                .find("line 4: a member on one line"),
            std::string::npos);
  EXPECT_NE(refusal(edited("[0,\"s\",0]]},", "[0,\"s\",0]]}")).find("line 5: a ',' at the end of the line"),
            std::string::npos);
  EXPECT_NE(refusal(edited("\"rows\":[]}", "\"rows\":[]},")).find("line 6: no ',' after the last entry"),
            std::string::npos);
  EXPECT_NE(refusal(edited(" ]\n}", " ],\n}")).find("line 12: no ',' after the last entry"), std::string::npos);
  EXPECT_NE(refusal(edited("\"dead\": [", "\"vectors\": [")).find("line 8: a list named once"), std::string::npos);
  EXPECT_NE(refusal(edited("\"dead\": [", "\"proofs\": [")).find("line 8: a known list, found \"proofs\""),
            std::string::npos);
  EXPECT_NE(refusal(edited(" ]\n}", "")).find("'}' alone on the last line"), std::string::npos);
  EXPECT_NE(refusal(edited("{\"mode\"", "\n  {\"mode\"")).find("line 11: an element of \"modes\" on one line"),
            std::string::npos);
}

}  // namespace
}  // namespace contactcert::checker
