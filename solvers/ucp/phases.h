// Where the time of a UCP run goes: the phases `contactcert ucp` reports (docs/formats.md), in CPU seconds of the
// running thread, which the machine's load does not inflate.
#pragma once

#include <ctime>

namespace contactcert::solvers::ucp {

/// CPU seconds of the calling thread (CLOCK_THREAD_CPUTIME_ID).
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// CPU seconds of each phase of one run. The reader fills parse and build, solve_ucp fills solve, recover and
/// check, the caller that writes a certificate fills certificate.
struct UcpPhases {
  double parse = 0;        ///< reading and validating the problem (and building a scene's matrices)
  double build = 0;        ///< X and Y from the problem's data (section 2)
  double solve = 0;        ///< the method, with the exact proof of a float verdict (adaptive)
  double recover = 0;      ///< the exact pair and the physics of a solvable verdict
  double check = 0;        ///< conditions (2)-(10) on the recovered physics
  double certificate = 0;  ///< the certificate's text and its file
  double total() const { return parse + build + solve + recover + check + certificate; }
};

/// Adds the thread CPU seconds of its own lifetime to `into`.
class PhaseTimer {
 public:
  explicit PhaseTimer(double& into) : into_(into), start_(thread_cpu_seconds()) {}
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;
  ~PhaseTimer() { into_ += thread_cpu_seconds() - start_; }

 private:
  double& into_;
  double start_;
};

}  // namespace contactcert::solvers::ucp
