#include "exact/json_input.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
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
  EXPECT_NE(
      error_of(R"({"a": 1, "b": 2})", [](const JsonInput& j) { j.expect_keys({"a"}); }).find("$.b: unknown field"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"s": 3})", [](const JsonInput& j) { j.at("s").string(); }).find("expected a string"),
            std::string::npos);
}

TEST(JsonInput, DeepNestingIsRejectedNotRecursed) {
  std::string deep(100000, '[');
  EXPECT_NE(error_of(deep, [](const JsonInput&) {}).find("nesting deeper"), std::string::npos);
}

TEST(JsonInput, BareNumbersBeyondDoubleAreExact) {
  JsonInput j = JsonInput::parse(R"({"big": 1e400, "tiny": -1E-400, "list": [1e4096, 0]})", "f.json");
  EXPECT_EQ(j.at("big").rational(), Q(Z("1" + std::string(400, '0'), 10)));
  EXPECT_EQ(j.at("tiny").rational(), Q(-1) / Q(Z("1" + std::string(400, '0'), 10)));
  EXPECT_EQ(j.at("list").size(), 2u);
  EXPECT_EQ(j.at("list").at(1).rational(), Q(0));
}

TEST(JsonInput, InvalidNumbersNulBytesAndNumericKeysAreRejected) {
  const auto parse = [](const std::string& text) { (void)JsonInput::parse(text, "f.json"); };
  for (const char* bad : {R"({"a": 01})", R"({"a": 1.})", R"({"a": .5})", R"({"a": 0x10})", R"({"a": 1e})"})
    EXPECT_THROW(parse(bad), InputError) << bad;
  EXPECT_THROW(parse(R"({1: 2})"), InputError);
  EXPECT_THROW(parse(std::string("{\"a\": 1}\0{", 11)), InputError);
  EXPECT_NE(error_of(std::string("{\"a\": 1}\0", 9), [](const JsonInput&) {}).find("a NUL byte at byte 8"),
            std::string::npos);
}

TEST(JsonInput, CanonicalTextIgnoresSpellingOrderAndLabels) {
  const JsonInput a = JsonInput::parse(R"({"mu": [0.50, "1/3"], "kind": "ucp", "source": "a", "x": null})", "a.json");
  const JsonInput b = JsonInput::parse(R"({"kind": "ucp", "mu": ["1/2", "2/6"], "note": "b"})", "b.json");
  const JsonInput c = JsonInput::parse(R"({"kind": "ucp", "mu": ["1/2", "1/4"]})", "c.json");
  EXPECT_EQ(a.canonical_text(), R"({"kind":"ucp","mu":["1/2","1/3"]})");
  EXPECT_EQ(a.canonical_text(), b.canonical_text());
  EXPECT_EQ(a.canonical_sha256(), b.canonical_sha256());
  EXPECT_NE(a.canonical_sha256(), c.canonical_sha256());
}

// Valid input is read in one pass and only rejected input is read again with its numbers quoted: the messages are
// those of the quoted reading, byte for byte (these are the messages of the build before the one-pass reading).
/// The InputError of reading `path`, or "" if it reads.
std::string read_error(const std::string& path) {
  try {
    JsonInput::read_text(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonInput, ReadingIsBoundedAndNeverBlocks) {
  EXPECT_EQ(read_error("/dev/zero"), "/dev/zero: larger than the input limit of 32 MiB");
  EXPECT_EQ(read_error("/"), "/: is a directory; expected a JSON file");
  EXPECT_NE(read_error("/no/such/file.json").find("/no/such/file.json: cannot open the file for reading"),
            std::string::npos);
  // A named pipe without a writer opens at once and reads as empty, which the parser refuses by name.
  char dir[] = "/tmp/json_input_testXXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  const std::string fifo = std::string(dir) + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(JsonInput::read_text(fifo), "");
  EXPECT_EQ(error_of(JsonInput::read_text(fifo), [](const JsonInput&) {}),
            "f.json: $: malformed JSON: no JSON text (the input is empty; a pipe without a writer reads as empty)");
  ::unlink(fifo.c_str());
  ::rmdir(dir);
}

TEST(JsonInput, DeepNestingNamesTheFieldWhereItStops) {
  const std::string deep = "{\"a\": " + std::string(100000, '[') + "}";
  std::string path = "$.a";
  for (std::size_t k = 0; k < kMaxJsonDepth - 1; ++k) path += "[0]";
  EXPECT_EQ(error_of(deep, [](const JsonInput&) {}), "f.json: " + path + ": nesting deeper than 64 levels");
  EXPECT_EQ(error_of(std::string(64, '[') + std::string(64, ']'), [](const JsonInput&) {}), "");
}

TEST(JsonInput, MessagesQuoteAtMostAnExcerpt) {
  EXPECT_EQ(quoted_excerpt("abc"), "\"abc\"");
  EXPECT_EQ(quoted_excerpt(std::string(5000, '7')), "\"" + std::string(40, '7') + "...\" (5000 characters)");
  const std::string huge = R"({"n": )" + std::string(4000, '9') + "}";
  EXPECT_EQ(
      error_of(huge, [](const JsonInput& j) { j.at("n").integer(0, 10); }),
      "f.json: $.n: expected an integer from 0 to 10, found \"" + std::string(40, '9') + "...\" (4000 characters)");
  const std::string token = R"({"n": )" + std::string(30000, 'x') + "}";
  const std::string e = error_of(token, [](const JsonInput&) {});
  EXPECT_EQ(e.find("json.exception"), std::string::npos);
  EXPECT_LT(e.size(), 200u) << e;
}

TEST(JsonInput, MalformedInputKeepsItsMessages) {
  const auto none = [](const JsonInput&) {};
  EXPECT_EQ(error_of(R"({"a": 1,})", none),
            "f.json: $: malformed JSON at byte 9: syntax error while parsing object key - unexpected '}'; expected "
            "string literal");
  EXPECT_EQ(error_of(R"({"a": 01})", none),
            "f.json: $.a: malformed JSON: not a JSON number (RFC 8259 section 6: e.g. 0.5, -3, 1e-9)");
  EXPECT_EQ(error_of("[1, 2", none),
            "f.json: $[2]: malformed JSON at byte 6: syntax error while parsing array - unexpected end of input; "
            "expected ']'");
  EXPECT_EQ(error_of(R"({"a": "\u0001x"})", none), "f.json: $.a: a string may not start with a control character");
  EXPECT_EQ(error_of(R"(["a", 0x10])", none),
            "f.json: $[1]: malformed JSON: not a JSON number (RFC 8259 section 6: e.g. 0.5, -3, 1e-9)");
}

TEST(JsonInput, CanonicalTextOfAValueBuiltInMemoryIsThatOfItsText) {
  nlohmann::ordered_json j;
  j["z"] = {"2/4", "7", "-0", "1/1", "007", "-3/9", "18446744073709551617/3", "x\"y", "\u00e9t\u00e9", "1e2"};
  j["a"] = {{"b", 3}, {"a", -4}, {"note", "left out"}, {"c", nullptr}, {"d", true}};
  j["\u00e9"] = std::uint64_t{18446744073709551615u};
  const JsonInput parsed = JsonInput::parse(j.dump(), "f.json");
  EXPECT_EQ(parsed.canonical_text(),
            R"({"a":{"a":"-4","b":"3","d":true},"z":["1/2","7","0","1","7","-1/3","18446744073709551617/3","x\"y",)"
            R"("été","100"],"é":"18446744073709551615"})");
  EXPECT_EQ(canonical_sha256(j), parsed.canonical_sha256());
}

}  // namespace
}  // namespace contactcert::exact
