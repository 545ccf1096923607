// A wall-clock budget for exponential work (ARCHITECTURE principle 7: never a hang). Work loops test
// `expired()` between units (search nodes, bilinear pairs, enumerated modes) and then stop with what they
// covered; the command ends with exit code 3.
#pragma once

#include <chrono>
#include <sstream>
#include <string>

namespace contactcert::exact {

class Deadline {
 public:
  /// No limit.
  Deadline() = default;
  /// Expires `seconds` from now; seconds <= 0 means no limit.
  static Deadline after(double seconds) {
    Deadline d;
    if (seconds > 0) {
      d.limited_ = true;
      d.seconds_ = seconds;
      d.end_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    }
    return d;
  }
  bool limited() const { return limited_; }
  double seconds() const { return seconds_; }
  bool expired() const { return limited_ && Clock::now() >= end_; }
  /// "time limit of 2.5 s reached", for the reason of an `unknown` verdict.
  std::string reached_text() const {
    std::ostringstream os;
    os << "time limit of " << seconds_ << " s reached";
    return os.str();
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool limited_ = false;
  double seconds_ = 0;
  Clock::time_point end_{};
};

}  // namespace contactcert::exact
