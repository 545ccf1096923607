// The independent checker of the "goal_nonempty" certificate (its format: solvers/design/goal_certificate.h).
#pragma once

#include <string>

#include "exact/json_input.h"

namespace contactcert::checker {

struct GoalCertificateCheck {
  bool valid = false;
  std::string reason;
};

/// Verifies a "goal_nonempty" certificate exactly; a malformed one throws InputError.
GoalCertificateCheck check_goal_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
