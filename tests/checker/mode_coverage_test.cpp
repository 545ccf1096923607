// The checker's mode letters (mode_letters.h) and the coverage walk of listed prefixes (mode_coverage.h): one
// reader for every certificate kind, each gap of a forged list found by walking only what the lists spell out.
#include "checker/mode_coverage.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "exact/input_error.h"

namespace contactcert::checker {
namespace {

// The first prefix a coverage gap names, or "" when the lists partition the modes.
std::string gap_prefix(const std::optional<CoverageGap>& gap, CoverageGap::Kind kind = CoverageGap::Kind::kMissing) {
  if (!gap) return "";
  EXPECT_EQ(gap->kind, kind) << coverage_gap_text(*gap);
  return gap->prefix;
}

TEST(ModeCoverage, CoverageWalksOnlyWhatTheListsSpellOut) {
  const ModeAlphabet four{};  // s l r n at every fixel, the letters of motion from rest
  // Forty fixels, nothing listed: the first uncovered prefix is found at once (no 4^40 walk).
  EXPECT_EQ(gap_prefix(mode_coverage(40, four, {}, {})), "s");
  // "s", "l", "r" dead and the n branch closed by n..n alone is not complete: "ns" is uncovered.
  EXPECT_EQ(gap_prefix(mode_coverage(3, ModeAlphabet{}, {"s", "l", "r"}, {"nnn"})), "ns");
  EXPECT_EQ(mode_coverage(1, ModeAlphabet{}, {"s", "l", "r"}, {"n"}), std::nullopt);
}

TEST(ModeCoverage, CoverageCountsEachModeOnce) {
  using Kind = CoverageGap::Kind;
  const ModeAlphabet two{};
  const std::vector<std::string> dead{"s", "l", "r"}, leaves{"ns", "nl", "nr", "nn"};
  EXPECT_EQ(mode_coverage(2, two, dead, leaves), std::nullopt);
  // A mode listed twice, or a thousand times: the count would be wrong.
  std::vector<std::string> twice = leaves;
  twice.push_back("nl");
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, dead, twice), Kind::kRepeated), "nl");
  std::vector<std::string> many = leaves;
  for (int i = 0; i < 1000; ++i) many.push_back("nn");
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, dead, many), Kind::kRepeated), "nn");
  // A dead prefix listed twice, or one inside another, or a listed mode inside a dead prefix: extra entries.
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, {"s", "l", "r", "l"}, leaves), Kind::kRepeated), "l");
  const auto inside = mode_coverage(2, two, {"s", "l", "r", "sl"}, leaves);
  EXPECT_EQ(gap_prefix(inside, Kind::kInside), "sl");
  EXPECT_EQ(inside->within, "s");
  std::vector<std::string> under_dead = leaves;
  under_dead.push_back("rn");
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, dead, under_dead), Kind::kInside), "rn");
  // A leaf equal to a full-length dead prefix is listed twice.
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, {"s", "l", "r", "nn"}, leaves), Kind::kRepeated), "nn");
  // A dropped entry leaves a gap.
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, {"s", "r"}, leaves)), "l");
  EXPECT_EQ(gap_prefix(mode_coverage(2, two, dead, {"ns", "nl", "nn"})), "nr");
}

// The message of the InputError that reading `text` as a mode (or prefix) of k fixels throws, or "" if it reads.
std::string refusal(const std::string& text, const ModeAlphabet& alphabet, std::size_t k, bool prefix) {
  try {
    read_mode_letters(exact::JsonInput::parse("\"" + text + "\"", "m.json"), alphabet, k, prefix);
  } catch (const exact::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ModeLetters, EachFixelAdmitsItsLettersOnly) {
  const ModeAlphabet touching{};  // every fixel touches: s l r n
  EXPECT_EQ(touching.letters(5), "slrn");
  EXPECT_EQ((ModeAlphabet{{true, false}, true}.letters(1)), "sau");
  EXPECT_EQ((ModeAlphabet{{true, false}, true, true}.letters(0)), "slrnmS");
  EXPECT_EQ(refusal("slrn", touching, 4, false), "");
  EXPECT_EQ(refusal("sl", touching, 4, true), "");
  EXPECT_NE(refusal("sla", touching, 3, false)
                .find("fixel 2's letter 'a' is not one of its letters in this alphabet "
                      "(s l r n)"),
            std::string::npos);
  EXPECT_EQ(refusal("al", ModeAlphabet{{false, true}}, 2, false), "");
  EXPECT_NE(refusal("ml", ModeAlphabet{{true, true}}, 2, false).find("(s l r n)"), std::string::npos);
  EXPECT_EQ(refusal("ml", ModeAlphabet{{true, true}, true}, 2, false), "");
  // Lengths: a mode has one letter per fixel, a prefix 1 to k.
  EXPECT_NE(refusal("sl", touching, 3, false).find("one letter per fixel (3)"), std::string::npos);
  EXPECT_NE(refusal("", touching, 3, true).find("a mode prefix of 1 to 3 letters"), std::string::npos);
  EXPECT_NE(refusal("slrn", touching, 3, true).find("a mode prefix of 1 to 3 letters"), std::string::npos);
}

}  // namespace
}  // namespace contactcert::checker
