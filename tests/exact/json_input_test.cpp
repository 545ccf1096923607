#include "exact/json_input.h"

#include <gtest/gtest.h>

#include <string>

namespace contactcert::exact {
namespace {

std::string error_of(const std::string& text, void (*use)(const JsonInput&)) {
  try {
    use(JsonInput::parse(text, "f.json"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonInput, NumbersKeepTheirLiteralText) {
  JsonInput j = JsonInput::parse(R"({"a": 0.966, "b": "0.966", "c": 1e-3, "d": "1/5",
                                     "e": 123456789012345678901234567890})",
                                 "f.json");
  EXPECT_EQ(j.at("a").rational(), Q(966) / 1000);
  EXPECT_EQ(j.at("b").rational(), Q(966) / 1000);
  EXPECT_EQ(j.at("c").rational(), Q(1) / 1000);
  EXPECT_EQ(j.at("d").rational(), Q(1) / 5);
  EXPECT_EQ(j.at("e").rational(), Q(Z("123456789012345678901234567890", 10)));
}

TEST(JsonInput, MatricesAndVectors) {
  JsonInput j = JsonInput::parse(R"({"P": [[1, "1/2"], [0.25, -3]], "v": [1, 2, 3]})", "f.json");
  Mat<Q> P = j.at("P").rational_matrix(2, 2);
  EXPECT_EQ(P(0, 1), Q(1) / 2);
  EXPECT_EQ(P(1, 0), Q(1) / 4);
  EXPECT_EQ(j.at("v").rational_vector(3)(2), Q(3));
}

TEST(JsonInput, ErrorsNameTheFileThePathAndWhatWasExpected) {
  EXPECT_NE(error_of(R"({"P": [[1, 2], [3]]})", [](const JsonInput& j) { j.at("P").rational_matrix(); })
                .find("f.json: $.P[1]: expected a row of 2 numbers"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"mu": "abc"})", [](const JsonInput& j) { j.at("mu").rational(); }).find("$.mu"),
            std::string::npos);
  EXPECT_NE(error_of(R"({})", [](const JsonInput& j) { j.at("nc"); }).find("$.nc: required field is missing"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"nc": 2.5})", [](const JsonInput& j) { j.at("nc").integer(0, 10); }).find("integer"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"x": 1, "x": 2})", [](const JsonInput&) {}).find("duplicate key"), std::string::npos);
  EXPECT_NE(error_of(R"({"a": 1,})", [](const JsonInput&) {}).find("malformed JSON"), std::string::npos);
  EXPECT_NE(error_of("\x01\x02garbage", [](const JsonInput&) {}).find("malformed JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"a": NaN})", [](const JsonInput&) {}).find("malformed JSON"), std::string::npos);
  EXPECT_NE(error_of(R"({"a": 1, "b": 2})", [](const JsonInput& j) { j.expect_keys({"a"}); })
                .find("$.b: unknown field"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"s": 3})", [](const JsonInput& j) { j.at("s").string(); }).find("expected a string"),
            std::string::npos);
}

TEST(JsonInput, DeepNestingIsRejectedNotRecursed) {
  std::string deep(100000, '[');
  EXPECT_NE(error_of(deep, [](const JsonInput&) {}).find("nesting deeper"), std::string::npos);
}

}  // namespace
}  // namespace contactcert::exact
