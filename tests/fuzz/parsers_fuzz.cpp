// libFuzzer target over the input parsers: JSON text -> JsonInput -> the problem, scene and cone readers
// (SPEC sections 1-4). Bad input must end in exact::InputError; anything else (another exception, a
// crash, a sanitizer report, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/cone_json.h"
#include "geometry/scene_json.h"
#include "solvers/ucp/problem.h"

namespace {

using contactcert::exact::InputError;
using contactcert::exact::JsonInput;

/// Runs one reader; InputError is the expected outcome of bad input, so it is swallowed.
template <class Reader>
void expect_input_error_only(const JsonInput& in, Reader read) {
  try {
    read(in);
  } catch (const InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)contactcert::exact::parse_rational(text);
  } catch (const contactcert::exact::NumberSyntaxError&) {
  }
  std::optional<JsonInput> in;
  try {
    in = JsonInput::parse(text, "fuzz.json");
  } catch (const InputError&) {
    return 0;
  }
  expect_input_error_only(*in, [](const JsonInput& j) { (void)contactcert::solvers::ucp::read_ucp_problem(j); });
  expect_input_error_only(*in, [](const JsonInput& j) { (void)contactcert::geometry::read_planar_scene(j); });
  expect_input_error_only(*in, [](const JsonInput& j) { (void)contactcert::geometry::read_cone(j); });
  return 0;
}
