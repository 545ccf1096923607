// Sparse Motzkin vectors: written as the weighted rows of the primitive integer multiple (solvers' writer), read
// back by the checker's reader (sparse_motzkin_reader.h) to the same direction, every other spelling refused with
// the entry named.
#include "checker/sparse_motzkin_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using exact::Vec;

Vec<Q> read(const std::string& text, std::size_t rows) {
  return read_sparse_motzkin(exact::JsonInput::parse(text, "y.json"), rows);
}

// The message of the InputError that reading `text` throws, or "" if it reads.
std::string refusal(const std::string& text, std::size_t rows) {
  try {
    read(text, rows);
  } catch (const exact::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SparseMotzkin, WritesTheWeightedRowsOfThePrimitiveMultiple) {
  const Vec<Q> y = (Vec<Q>(6) << 0, 0, Q(-1, 2), 0, Q(3, 2), 0).finished();
  EXPECT_EQ(solvers::sparse_motzkin_json(y).dump(), R"([[2,"-1"],[4,"3"]])");
  const Vec<Q> back = read(solvers::sparse_motzkin_json(y).dump(), 6);
  EXPECT_EQ(back, Vec<Q>(2 * y));  // the same direction, scaled by 2 > 0
  EXPECT_EQ(solvers::sparse_motzkin_json((Vec<Q>(3) << 6, 0, -4).finished()).dump(), R"([[0,"3"],[2,"-2"]])");
}

TEST(SparseMotzkin, RefusesEveryOtherSpelling) {
  EXPECT_EQ(refusal(R"([[0, "1"], [3, "-2"]])", 4), "");
  EXPECT_NE(refusal("[]", 4).find("at least one [row, weight] pair"), std::string::npos);
  EXPECT_NE(refusal(R"([[1, "1"], [1, "2"]])", 4).find("$[1][0]: a row above 1"), std::string::npos);
  EXPECT_NE(refusal(R"([[1, "1"], [1, "2"]])", 4).find("(row 1 is repeated)"), std::string::npos);
  EXPECT_NE(refusal(R"([[2, "1"], [1, "2"]])", 4).find("$[1][0]: a row above 2"), std::string::npos);
  EXPECT_NE(refusal(R"([[4, "1"]])", 4).find("$[0][0]: expected an integer from 0 to 3"), std::string::npos);
  EXPECT_NE(refusal(R"([[-1, "1"]])", 4).find("$[0][0]: expected an integer"), std::string::npos);
  EXPECT_NE(refusal(R"([[0, "1"]])", 0).find("which has none"), std::string::npos);
  EXPECT_NE(refusal(R"([[0, "0"]])", 4).find("$[0][1]: a non-zero integer weight"), std::string::npos);
  EXPECT_NE(refusal(R"([[0, "1/2"]])", 4).find("$[0][1]: a non-zero integer weight"), std::string::npos);
  EXPECT_NE(refusal(R"([[0, "2"], [1, "-4"]])", 4).find("common factor 2"), std::string::npos);
  EXPECT_NE(refusal(R"(["1", "0"])", 4).find("$[0]: a pair [row, weight]"), std::string::npos);
  EXPECT_NE(refusal(R"([[0, "1", "2"]])", 4).find("$[0]: a pair [row, weight]"), std::string::npos);
}

}  // namespace
}  // namespace contactcert::checker
