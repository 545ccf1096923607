#include "solvers/design/checkpoint.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "exact/input_error.h"
#include "exact/rational_text.h"

namespace contactcert::solvers {
namespace {

/// Done chunks as ranges "a-b" / "a" (a checkpoint of a long run stays small).
nlohmann::json done_ranges(const std::vector<bool>& done) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < done.size();) {
    if (!done[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < done.size() && done[j + 1]) ++j;
    out.push_back({i, j});
    i = j + 1;
  }
  return out;
}

}  // namespace

void write_checkpoint(const std::string& path, const DesignCheckpoint& c) {
  const nlohmann::json j = {
      {"kind", "design_checkpoint"}, {"problem", c.problem_key},
      {"chunk_size", c.chunk_size},  {"chunks", c.chunks},
      {"done", done_ranges(c.done)}, {"result", nlohmann::json::parse(chunk_result_text(c.result))}};
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << j.dump() << "\n";
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw exact::InputError(path, "", "a writable checkpoint file (--checkpoint)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw exact::InputError(path, "", "a checkpoint path that can be replaced by rename (--checkpoint)");
  }
}

std::optional<DesignCheckpoint> read_checkpoint(const std::string& path, const std::string& problem_key,
                                                long chunk_size, long chunks, std::size_t k) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  DesignCheckpoint c;
  try {
    const nlohmann::json j = nlohmann::json::parse(text.str());
    if (j.at("kind") != "design_checkpoint") throw exact::InputError(path, "$.kind", "\"design_checkpoint\"");
    if (j.at("problem").get<std::string>() != problem_key || j.at("chunk_size").get<long>() != chunk_size ||
        j.at("chunks").get<long>() != chunks)
      throw exact::InputError(
          path, "$.problem",
          "a checkpoint of this design (same scene, candidates and options); delete it to start over");
    c.problem_key = problem_key;
    c.chunk_size = chunk_size;
    c.chunks = chunks;
    c.done.assign(static_cast<std::size_t>(chunks), false);
    for (const auto& r : j.at("done")) {
      const long a = r.at(0).get<long>(), b = r.at(1).get<long>();
      if (a < 0 || b < a || b >= chunks) throw exact::InputError(path, "$.done", "chunk ranges within [0, chunks)");
      for (long i = a; i <= b; ++i) c.done[static_cast<std::size_t>(i)] = true;
    }
    c.result = parse_chunk_result(j.at("result").dump(), k);
  } catch (const nlohmann::json::exception& e) {
    throw exact::InputError(path, "$", std::string("a design checkpoint (") + e.what() + ")");
  } catch (const exact::NumberSyntaxError&) {
    throw exact::InputError(path, "$.result", "exact figures");
  }
  return c;
}

}  // namespace contactcert::solvers
