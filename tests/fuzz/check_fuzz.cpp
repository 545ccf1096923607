// libFuzzer target over the UCP certificate checker (`contactcert check`): JSON text -> JsonInput ->
// checker::check_ucp_certificate. A forged or malformed certificate must end as INVALID or exact::InputError; anything
// else (another exception, a crash, a sanitizer report, a hang, runaway memory) is a finding. Seeds: valid
// certificates (tests/fuzz/certificates).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "checker/ucp_check.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "solvers/ucp/certificate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using contactcert::exact::InputError;
  using contactcert::exact::JsonInput;
  try {
    const JsonInput cert = JsonInput::parse(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    if (contactcert::solvers::ucp::is_ucp_certificate_kind(cert.at("kind").string()))
      (void)contactcert::checker::check_ucp_certificate(cert);
  } catch (const InputError&) {
  }
  return 0;
}
