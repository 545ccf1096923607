// SHA-256 (FIPS 180-4), to bind a certificate to the canonical text of its problem.
#pragma once

#include <string>
#include <string_view>

namespace contactcert::exact {

/// The SHA-256 digest of `data` as 64 lower-case hexadecimal digits.
std::string sha256_hex(std::string_view data);

}  // namespace contactcert::exact
