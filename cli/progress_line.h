// Progress of long runs (sweeps, complete search, benchmarks) on stderr, only when stderr is a terminal:
// one line rewritten in place at most ten times a second and erased when the run ends, so that pipes, files
// and CI logs never see it.
#pragma once

#include <chrono>
#include <string>

namespace contactcert::cli {

class ProgressLine {
 public:
  /// `label` starts every line, e.g. "ucp data.json".
  explicit ProgressLine(std::string label);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool enabled() const { return enabled_; }
  /// Shows "label: text" if at least 0.1 s passed since the last line shown (or `force`).
  void update(const std::string& text, bool force = false);
  /// Erases the line (before the report is printed); also done by the destructor.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string label_;
  bool enabled_ = false;
  bool shown_ = false;
  Clock::time_point start_, last_{};
};

}  // namespace contactcert::cli
