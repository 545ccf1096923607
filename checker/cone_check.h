// The independent checker of the "cone_empty" and "cone_nonempty" certificates (their format:
// solvers/wrench_cone/cone_certificate.h): K and P are the checker's own (table2_rows.h, not cone_form.h), rebuilt
// from the embedded scene with the checker's own frames (frame_check.h).
#pragma once

#include <string>
#include <vector>

#include "exact/json_input.h"
#include "exact/number.h"

namespace contactcert::checker {

struct ConeCertificateCheck {
  bool valid = false;
  std::string reason;
  std::vector<Eigen::Index> touching{};  ///< a valid "cone_nonempty": the touching fixels (scene indices, in order)
  exact::Vec<exact::Q> forces{};         ///< and the contact forces (c_1n..c_kn, c_1t..c_kt) its z applies to them
};

/// Verifies a "cone_empty" or "cone_nonempty" certificate exactly; a malformed one throws InputError.
ConeCertificateCheck check_cone_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
