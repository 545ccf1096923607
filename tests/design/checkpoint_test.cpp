// Design checkpoints as hostile input: a written checkpoint reads back as it was; an edit without a new content
// digest is refused; an edit with a recomputed digest is refused by the field it breaks (indices out of range,
// repeated, fractional or unsorted; counts that do not add up; a figure that is not the placement's own; done
// ranges out of range or overlapping; another problem). Also the index arithmetic the reader relies on.
#include "solvers/design/checkpoint.h"

#include <gtest/gtest.h>

#include <climits>
#include <fstream>
#include <nlohmann/json.hpp>

#include "exact/json_input.h"
#include "exact/rational_text.h"

namespace contactcert::solvers {
namespace {

using exact::Q;

/// The pentagon of Figure 10, mu = 1/5, 8 candidates, strongly stable under gravity, ranked by margin.
DesignProblem pentagon() {
  DesignProblem p;
  const std::vector<geometry::Point2> V{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 2}};
  p.workpiece.shape = geometry::PolygonShape{V};
  p.workpiece.com = geometry::polygon_centroid(V);
  p.workpiece.inertia_per_mass = geometry::polygon_inertia_per_mass(V, p.workpiece.com);
  p.mu_s = p.mu_k = Q(1, 5);
  p.candidates = arc_length_candidates(p.workpiece.shape, 8);
  p.wrenches.kind = WrenchSet::Kind::kList;
  p.wrenches.rows = exact::Mat<Q>(1, 3);
  p.wrenches.rows << 0, -1, 0;
  return p;
}

constexpr long kChunk = 8;
constexpr std::size_t kTop = 3;
const std::string kKey = "key-of-the-pentagon";

class Checkpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    total_ = placement_count(static_cast<long>(problem_.candidates.size()), problem_.fixels);
    c_ = {kKey, kChunk, chunk_count(total_, kChunk), {}, {TopK(kTop), {}}};
    for (long chunk : {0L, 1L, 2L, 3L, 6L}) {  // chunks 4 and 5 not done
      bool complete = false;
      c_.result.merge(run_chunk(problem_, symmetry_, chunk, kChunk, total_, kTop, nullptr, &complete));
      c_.done.insert(chunk);
    }
    write_checkpoint(path_, c_);
    std::ifstream in(path_);
    written_ = nlohmann::json::parse(in);
  }
  std::optional<DesignCheckpoint> read() const {
    return read_checkpoint(path_, kKey, problem_, symmetry_, kChunk, total_, kTop);
  }
  /// Writes j with its content digest recomputed (a forger who knows the format).
  void forge(nlohmann::json j) const {
    j["content_digest"] = exact::JsonInput::parse(j.dump(), path_).at("content").canonical_sha256();
    std::ofstream(path_) << j.dump();
  }
  /// The message of the InputError that reading gives.
  std::string refusal() const {
    try {
      read();
    } catch (const exact::InputError& e) {
      return e.what();
    }
    return "accepted";
  }

  DesignProblem problem_ = pentagon();
  CandidateSymmetry symmetry_ = candidate_symmetry(problem_);
  long total_ = 0;
  DesignCheckpoint c_;
  std::string path_ = ::testing::TempDir() + "/design_checkpoint_test.json";
  nlohmann::json written_;
};

TEST_F(Checkpoint, ReadsBackAsWritten) {
  ASSERT_FALSE(c_.result.top.items().empty());
  const std::optional<DesignCheckpoint> back = read();
  ASSERT_TRUE(back);
  EXPECT_EQ(back->done.ranges(), c_.done.ranges());
  EXPECT_EQ(back->done.ranges().size(), 2u);  // [0, 3] and [6, 6]
  ASSERT_EQ(back->result.top.items().size(), c_.result.top.items().size());
  for (std::size_t i = 0; i < c_.result.top.items().size(); ++i) {
    EXPECT_EQ(back->result.top.items()[i].placement, c_.result.top.items()[i].placement);
    EXPECT_EQ(back->result.top.items()[i].figure, c_.result.top.items()[i].figure);
  }
  EXPECT_EQ(back->result.statistics.by_status, c_.result.statistics.by_status);
  EXPECT_EQ(back->result.statistics.lps, c_.result.statistics.lps);
  EXPECT_EQ(placements_in(back->done, kChunk, total_), 4 * kChunk + (total_ - 6 * kChunk));
}

TEST_F(Checkpoint, NoFileIsAFreshStart) {
  EXPECT_FALSE(read_checkpoint(path_ + ".absent", kKey, problem_, symmetry_, kChunk, total_, kTop));
}

TEST_F(Checkpoint, AnEditWithoutANewDigestIsRefused) {
  nlohmann::json j = written_;
  j["content"]["result"]["lps"] = j["content"]["result"]["lps"].get<long>() + 1;
  std::ofstream(path_) << j.dump();
  EXPECT_NE(refusal().find("$.content_digest: the SHA-256 of $.content"), std::string::npos) << refusal();
}

TEST_F(Checkpoint, EveryPlacementIndexIsRangeChecked) {
  const std::vector<std::pair<nlohmann::json, std::string>> bad = {
      {{0, 1, 99999}, "$.content.result.top[0].placement[2]: expected an integer from 0 to 7"},
      {{-1, 1, 2}, "$.content.result.top[0].placement[0]: expected an integer from 0 to 7"},
      {{0, 1, INT_MAX}, "placement[2]: expected an integer from 0 to 7"},
      {{0, 1, 1}, "placement[2]: candidate indices in increasing order"},
      {{2, 1, 3}, "placement[1]: candidate indices in increasing order"},
      {{0, 1.5, 3}, "placement[1]: expected an integer"},
      {{0, 1}, "placement: 3 candidate indices"},
      {{0, 1, 2, 3}, "placement: 3 candidate indices"},
      {"0,1,2", "placement: 3 candidate indices"},
  };
  for (const auto& [placement, message] : bad) {
    nlohmann::json j = written_;
    j["content"]["result"]["top"][0]["placement"] = placement;
    forge(j);
    EXPECT_NE(refusal().find(message), std::string::npos) << placement.dump() << ": " << refusal();
  }
}

TEST_F(Checkpoint, AForgedFigureIsRefused) {
  for (const std::string figure : {"1000", "2/4", "1e3", "", "-0"}) {
    nlohmann::json j = written_;
    j["content"]["result"]["top"][0]["figure"] = figure;
    forge(j);
    EXPECT_NE(refusal().find("$.content.result.top[0].figure: "), std::string::npos) << figure << ": " << refusal();
  }
}

TEST_F(Checkpoint, APlacementOfAChunkNotDoneOrNotAcceptedIsRefused) {
  nlohmann::json j = written_;
  j["content"]["done"] = nlohmann::json::array({nlohmann::json::array({6, 6})});
  forge(j);  // the top placements are in chunks 0-3, now not done: the counts no longer add up
  EXPECT_NE(refusal().find("$.content.result.by_status"), std::string::npos) << refusal();
  // A placement of chunk 4, which is not done.
  const long n = static_cast<long>(problem_.candidates.size());
  j = written_;
  j["content"]["result"]["top"][0]["placement"] = placement_at(4 * kChunk, n, 3);
  forge(j);
  EXPECT_NE(refusal().find("top[0].placement: a placement of a done chunk (this one is in chunk 4"), std::string::npos)
      << refusal();
  // A rejected placement listed as the best: re-decided, it is not accepted.
  for (long i = 0; i < 4 * kChunk; ++i) {
    const Placement p = placement_at(i, n, 3);
    if (evaluate_placement(problem_, symmetry_, p).status == PlacementStatus::kAccepted) continue;
    j = written_;
    j["content"]["result"]["top"][0]["placement"] = p;
    forge(j);
    EXPECT_NE(refusal().find("top[0].placement: an accepted placement (re-decided, it is "), std::string::npos)
        << refusal();
    break;
  }
}

TEST_F(Checkpoint, CountsMustAddUp) {
  nlohmann::json j = written_;
  j["content"]["result"]["by_status"][0] = j["content"]["result"]["by_status"][0].get<long>() + 1;
  forge(j);
  EXPECT_NE(refusal().find("$.content.result.by_status: counts adding up to the"), std::string::npos) << refusal();
  j = written_;
  j["content"]["result"]["by_status"][1] = -1;
  forge(j);
  EXPECT_NE(refusal().find("by_status[1]: expected an integer from 0 to"), std::string::npos) << refusal();
  j = written_;
  j["content"]["result"]["by_status"].erase(7);
  forge(j);
  EXPECT_NE(refusal().find("by_status: 8 counts"), std::string::npos) << refusal();
  j = written_;
  j["content"]["result"]["top"].erase(0);
  forge(j);
  EXPECT_NE(refusal().find("$.content.result.top: the best"), std::string::npos) << refusal();
  if (written_["content"]["result"]["top"].size() < 2) return;
  j = written_;
  j["content"]["result"]["top"][1] = j["content"]["result"]["top"][0];
  forge(j);
  EXPECT_NE(refusal().find("top[1]: placements best first, each once"), std::string::npos) << refusal();
}

TEST_F(Checkpoint, DoneRangesAreChecked) {
  const std::vector<std::pair<nlohmann::json, std::string>> bad = {
      {{{0, 3}, {6, 7}}, "done[1][1]: expected an integer from 6 to 6"},
      {{{-1, 3}, {6, 6}}, "done[0][0]: expected an integer from 0 to 6"},
      {{{0, 3}, {2, 6}}, "done[1]: chunk ranges in increasing order"},
      {{{0, 3}, {4, 6}}, "done[1]: chunk ranges in increasing order"},
      {{{3, 0}, {6, 6}}, "done[0][1]: expected an integer from 3 to 6"},
      {{{0, 3, 4}}, "done[0]: a chunk range [first, last]"},
  };
  for (const auto& [done, message] : bad) {
    nlohmann::json j = written_;
    j["content"]["done"] = done;
    forge(j);
    EXPECT_NE(refusal().find(message), std::string::npos) << done.dump() << ": " << refusal();
  }
}

TEST_F(Checkpoint, AnotherProblemOrSplitIsRefused) {
  EXPECT_THROW(read_checkpoint(path_, "another", problem_, symmetry_, kChunk, total_, kTop), exact::InputError);
  try {
    read_checkpoint(path_, kKey, problem_, symmetry_, kChunk + 1, total_, kTop);
    ADD_FAILURE() << "another chunk size accepted";
  } catch (const exact::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("$.content.chunk_size: this run's --chunk-size 9"), std::string::npos);
  }
  nlohmann::json j = written_;
  j["content"]["chunks"] = 1000;
  forge(j);
  EXPECT_NE(refusal().find("$.content.chunks: this design's 7 chunks"), std::string::npos) << refusal();
}

TEST_F(Checkpoint, DeepNestingAndNonObjectsAreRefused) {
  std::ofstream(path_) << std::string(100000, '[') << std::string(100000, ']');
  EXPECT_NE(refusal().find("nesting deeper than"), std::string::npos) << refusal();
  std::ofstream(path_) << "[]";
  EXPECT_NE(refusal().find("a design checkpoint"), std::string::npos) << refusal();
  std::ofstream(path_) << written_.dump().substr(0, 100);
  EXPECT_NE(refusal().find(path_), std::string::npos) << refusal();
}

TEST(DesignPlacements, IndexInvertsUnranking) {
  for (long n : {3L, 7L, 12L})
    for (int k : {2, 3})
      for (long i = 0; i < placement_count(n, k); ++i) EXPECT_EQ(placement_index(placement_at(i, n, k), n), i);
  EXPECT_EQ(placement_index({99997, 99998, 99999}, 100000), placement_count(100000, 3) - 1);
}

TEST(DesignPlacements, ChunksCoverTheTotalWithoutOverflow) {
  EXPECT_EQ(chunk_count(56, 8), 7);
  EXPECT_EQ(chunk_count(57, 8), 8);
  EXPECT_EQ(chunk_count(56, LONG_MAX), 1);  // (total + size - 1) / size would wrap to 0 chunks
  EXPECT_EQ(chunk_length(7, 8, 57), 1);
  EXPECT_EQ(chunk_length(0, LONG_MAX, 56), 56);
}

TEST(DesignChunkSet, RangesMerge) {
  ChunkSet s;
  for (long c : {5L, 3L, 4L, 9L, 0L, 1L}) s.insert(c);
  EXPECT_EQ(s.ranges(), (std::map<long, long>{{0, 1}, {3, 5}, {9, 9}}));
  EXPECT_EQ(s.next_missing(0), 2);
  EXPECT_EQ(s.next_missing(3), 6);
  EXPECT_EQ(s.next_missing(6), 6);
  s.insert_range(2, 8);
  EXPECT_EQ(s.ranges(), (std::map<long, long>{{0, 9}}));
  EXPECT_TRUE(s.contains(7));
  EXPECT_FALSE(s.contains(10));
}

TEST(DesignRanking, FiguresOfAnyLengthReadBackExactly) {
  Q q;
  for (const std::string t : {"-7/20", "3", "0", "-1"}) {
    ASSERT_TRUE(figure_from_text(t, q)) << t;
    EXPECT_EQ(exact::to_string(q), t);
  }
  const std::string huge = "1" + std::string(5000, '0') + "/3";  // past the input parser's 4096-digit limit
  ASSERT_TRUE(figure_from_text(huge, q));
  EXPECT_EQ(exact::to_string(q), huge);
  for (const std::string t : {"2/4", "1/1", "-0", "01", "1/0", "0x10", "+3", "", "1.5", "1e3", "3/-4", "-", "1/"})
    EXPECT_FALSE(figure_from_text(t, q)) << t;
}

}  // namespace
}  // namespace contactcert::solvers
