// `check FILE [--problem PROBLEM]`: independent verification of a certificate, the one checker module under the CLI
// and Python. The certificate's top-level "kind" selects its checker (a table, check.cpp); each re-derives
// everything from the embedded problem and trusts nothing else. The embedded problem's digest (problem_sha256) is
// reported; with a problem file the certificate must also be about that problem, compared as canonical text after
// exact parsing. A malformed certificate throws InputError naming the field.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "exact/json_input.h"
#include "queries/json_out.h"

namespace contactcert::queries {

enum class CheckVerdict { kValid, kInvalid };

/// One answer for every certificate kind: the verdict and why, the digest of the embedded problem, the evidence a
/// person reads (details: the checker's counts, the world forces of a witness) and the same as text lines.
struct CheckResult {
  CheckVerdict verdict = CheckVerdict::kInvalid;
  std::string kind, reason, digest;
  std::string problem;  ///< the name of the problem file it was checked against ("" = none)
  nlohmann::ordered_json details = nlohmann::ordered_json::object();
  std::string text;  ///< readable lines of the evidence (two-space indent), shown for a valid certificate
  bool valid() const { return verdict == CheckVerdict::kValid; }
};

/// Checks `certificate`, and against the problem (or scene) file `problem` too unless it is null.
CheckResult check(const exact::JsonInput& certificate, const exact::JsonInput* problem = nullptr);
/// The same on a certificate's text read from `file`: a certificate in lines (checker/certificate_lines.h: the
/// spatial_stability one) line by line, without a JSON tree of the whole text; any other parsed as a whole.
CheckResult check_text(const std::string& text, const std::string& file, const exact::JsonInput* problem = nullptr);

/// The object `check --json` prints: valid, kind, reason, problem_sha256, problem (with a problem file), details.
json to_json(const CheckResult& c);

}  // namespace contactcert::queries
