// SHA-256 (FIPS 180-4), to bind a certificate to the canonical text of its problem.
#pragma once

#include <string>
#include <string_view>

namespace contactcert::exact {

/// How the 64-byte blocks are compressed: by the CPU's SHA instructions where it has them (x86-64), else portably.
/// The digests are the same; kPortable lets tests compare the two.
enum class Sha256Engine { kFastest, kPortable };

/// The SHA-256 digest of `data` as 64 lower-case hexadecimal digits.
std::string sha256_hex(std::string_view data, Sha256Engine engine = Sha256Engine::kFastest);

}  // namespace contactcert::exact
