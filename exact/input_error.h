// Typed errors for bad input and exhausted budgets (ARCHITECTURE principles 6 and 7).
#pragma once

#include <stdexcept>
#include <string>

namespace contactcert::exact {

/// Bad input: names the file, the JSON path of the field and what was expected. The CLI maps it to
/// exit code 2.
struct InputError : std::runtime_error {
  InputError(std::string file, std::string json_path, std::string expected)
      : std::runtime_error(compose(file, json_path, expected)),
        file(std::move(file)),
        json_path(std::move(json_path)),
        expected(std::move(expected)) {}
  std::string file, json_path, expected;

 private:
  static std::string compose(const std::string& f, const std::string& p, const std::string& e) {
    std::string s = f.empty() ? std::string("input") : f;
    if (!p.empty()) s += ": " + p;
    return s + ": " + e;
  }
};

/// A time or node budget ran out before an answer; `covered` says how far the work got. Exit code 3.
struct BudgetExceeded : std::runtime_error {
  BudgetExceeded(const std::string& what, std::string covered)
      : std::runtime_error(what), covered(std::move(covered)) {}
  std::string covered;
};

}  // namespace contactcert::exact
