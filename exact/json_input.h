// Reading input files: JSON whose numbers keep their literal text, so that "0.966" and 0.966 both
// parse to 966/1000 (SPEC section 1). Every accessor knows its JSON path and throws InputError
// naming the file, the path and what was expected. Also the JSON text written: canonical (for digests) and as
// nlohmann's dump() writes it.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exact/input_error.h"
#include "exact/number.h"

namespace contactcert::exact {

/// Deepest nesting accepted; deeper input is rejected rather than recursed into.
inline constexpr std::size_t kMaxJsonDepth = 64;
/// Largest input file accepted (32 MiB: its JSON tree then stays well under 2 GB); reading stops one byte past it.
inline constexpr std::size_t kMaxInputBytes = std::size_t{32} << 20;

/// One node of a parsed input file, with its JSON path for error messages.
class JsonInput {
 public:
  /// Parses text; `file` is only used in messages. Numbers are kept as their literal text.
  static JsonInput parse(const std::string& text, const std::string& file);
  /// Reads and parses a file ("-" reads standard input).
  static JsonInput load(const std::string& path);
  /// The whole text of a file ("-" = standard input), at most kMaxInputBytes; InputError if it cannot be read, is
  /// larger, or is not a regular file, a character device or a pipe. Opening never blocks: a named pipe without a
  /// writer reads as empty.
  static std::string read_text(const std::string& path);
  /// "larger than the input limit of 32 MiB".
  static std::string too_large_text();

  const std::string& file() const { return *file_; }
  const std::string& path() const { return path_; }

  bool is_object() const;
  bool is_array() const;
  bool is_null() const;
  bool is_string_or_number() const;
  std::size_t size() const;  ///< elements of an array (error otherwise)

  JsonInput at(std::string_view key) const;                   ///< required member of an object
  std::optional<JsonInput> find(std::string_view key) const;  ///< optional member (absent or null -> nullopt)
  JsonInput at(std::size_t i) const;                          ///< element of an array
  std::vector<JsonInput> elements() const;                    ///< elements of an array
  /// Fails on any key not in `allowed` (catches typos such as "mu_S").
  void expect_keys(std::initializer_list<std::string_view> allowed) const;

  Q rational() const;                    ///< a number or numeric string, exactly
  long integer(long lo, long hi) const;  ///< an integer in [lo, hi]
  std::string string() const;            ///< a JSON string
  bool boolean() const;
  Vec<Q> rational_vector(std::optional<std::size_t> n = std::nullopt) const;
  Mat<Q> rational_matrix(std::optional<std::size_t> rows = std::nullopt,
                         std::optional<std::size_t> cols = std::nullopt) const;

  /// The canonical text of this value, for comparing problems and for their digest: compact JSON with sorted
  /// keys, every number and numeric string as its exact value in lowest terms ("0.50" and 1/2 both "1/2"),
  /// null members and the free-text labels "source", "note", "name" and "description" left out.
  std::string canonical_text() const;
  /// SHA-256 (hex) of canonical_text(): the digest of a problem that every certificate carries.
  std::string canonical_sha256() const;

  /// Throws InputError for this field: "<file>: <path>: <expected>".
  [[noreturn]] void fail(const std::string& expected) const;

 private:
  JsonInput(std::shared_ptr<const nlohmann::json> root, const nlohmann::json* node,
            std::shared_ptr<const std::string> file, std::string path)
      : root_(std::move(root)), node_(node), file_(std::move(file)), path_(std::move(path)) {}
  std::string kind() const;
  std::shared_ptr<const nlohmann::json> root_;
  const nlohmann::json* node_;
  std::shared_ptr<const std::string> file_;
  std::string path_;
};

/// A text as a message quotes it: in double quotes, cut after 40 characters ("1234...", 5000 characters), so that
/// no message repeats a huge input.
std::string quoted_excerpt(std::string_view text);

/// The digest JsonInput::canonical_sha256 gives the text value.dump(), without writing and parsing that text (for a
/// value built in memory, such as a problem a certificate embeds).
std::string canonical_sha256(const nlohmann::ordered_json& value);

/// The bytes of value.dump(indent) (compact for indent < 0, else one member or element per line indented by `indent`
/// spaces per level), written directly for objects, arrays, integers and printable ASCII strings (exact numbers are
/// strings such as "-7/20"); strings that need escaping, floats and other rare values are written by nlohmann itself.
std::string json_text(const nlohmann::ordered_json& value, int indent = -1);

}  // namespace contactcert::exact
