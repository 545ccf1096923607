#include "exact/json_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <clocale>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "exact/rational_text.h"
#include "exact/sha256.h"

namespace contactcert::exact {
namespace {

using json = nlohmann::json;

// Numbers keep their literal text: a first pass (quote_numbers) rewrites every bare number token as a string
// token, so the JSON parser never converts a number to double (where 1e400 would overflow); the SAX handler
// below then stores those strings tagged by a leading '\x01', so that numbers and strings stay
// distinguishable. The handler also enforces the depth limit, rejects duplicate keys and keeps the JSON path of
// the value being read so that its errors can name it.
constexpr char kNumberTag = '\x01';
constexpr const char* kInvalidNumber = "malformed JSON: not a JSON number (RFC 8259 section 6: e.g. 0.5, -3, 1e-9)";

/// The text with its number tokens quoted; from_number[k] says whether the k-th string token (keys
/// included) was a number, and quote_ends the offsets in `text` just past each added pair of quotes.
struct QuotedText {
  std::string text;
  std::vector<bool> from_number;
  std::vector<std::size_t> quote_ends;
  /// The offset in the original text of offset `pos` of the quoted text.
  std::size_t original(std::size_t pos) const {
    const auto before = std::upper_bound(quote_ends.begin(), quote_ends.end(), pos) - quote_ends.begin();
    return pos - 2 * static_cast<std::size_t>(before);
  }
};

/// True if t is a JSON number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)? (RFC 8259 section 6).
bool is_json_number(std::string_view t) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i > from;
  };
  if (i < t.size() && t[i] == '-') ++i;
  if (i < t.size() && t[i] == '0')
    ++i;
  else if (!digits())
    return false;
  if (i < t.size() && t[i] == '.' && (++i, !digits())) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == t.size();
}

QuotedText quote_numbers(const std::string& in) {
  QuotedText q;
  q.text.reserve(in.size() + in.size() / 4);
  const auto number_char = [](char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
  };
  for (std::size_t i = 0; i < in.size();) {
    const char c = in[i];
    if (c == '"') {  // a string token, copied up to its unescaped closing quote
      std::size_t j = i + 1;
      while (j < in.size() && in[j] != '"') j += in[j] == '\\' ? 2 : 1;
      j = std::min(j + 1, in.size());
      q.text.append(in, i, j - i);
      q.from_number.push_back(false);
      i = j;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t j = i;
      while (j < in.size() && number_char(in[j])) ++j;
      const std::string_view token(in.data() + i, j - i);
      const bool glued = j < in.size() && std::isalnum(static_cast<unsigned char>(in[j]));  // "0x10", "1true"
      if (is_json_number(token) && !glued) {
        q.text += '"';
        q.text += token;
        q.text += '"';
        q.quote_ends.push_back(q.text.size());
        q.from_number.push_back(true);
      } else {
        q.text += token;  // left for the parser to report
      }
      i = j;
    } else {
      q.text += c;
      ++i;
    }
  }
  return q;
}

/// The JSON path piece of an object member, ".key", with a key longer than 40 characters cut short ("...").
std::string member_segment(std::string_view key) {
  constexpr std::size_t kShown = 40;
  return "." + std::string(key.substr(0, kShown)) + (key.size() > kShown ? "..." : "");
}

class LiteralNumberBuilder {
 public:
  /// quoted: the text as quote_numbers rewrote it; nullptr when the parser reads the original text, whose number
  /// tokens then arrive with their literal text (a float's) or as integers (whose decimal text is their value).
  LiteralNumberBuilder(json& root, const QuotedText* quoted) : root_(root), quoted_(quoted) {}

  bool null() { return put(json(nullptr)); }
  bool boolean(bool b) { return put(json(b)); }
  // quote_numbers quotes every valid number token: a bare number in quoted text is the valid head of an invalid
  // token ("01").
  bool number_integer(json::number_integer_t v) { return quoted_ ? fail(kInvalidNumber) : number(std::to_string(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return quoted_ ? fail(kInvalidNumber) : number(std::to_string(v)); }
  bool number_float(json::number_float_t, const std::string& text) {
    return quoted_ ? fail(kInvalidNumber) : number(text);
  }
  bool string(std::string& s) {
    if (next_from_number()) return put(json(kNumberTag + s));
    if (!s.empty() && s.front() == kNumberTag) return fail("a string may not start with a control character");
    return put(json(s));
  }
  bool binary(json::binary_t&) { return fail("binary values are not JSON text"); }
  bool start_object(std::size_t) { return open(json::object()); }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    if (next_from_number()) return fail("malformed JSON: an object key must be a string");
    key_ = k;
    if (stack_.back()->contains(k)) return fail("duplicate key " + quoted_excerpt(k));
    return true;
  }
  bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception& e) {
    error_byte_ = quoted_ ? quoted_->original(pos) : pos;
    // nlohmann's text without its "[json.exception.parse_error.101] parse error at line 1, column 5: " head, and
    // with the token it read cut short: "syntax error while parsing value - invalid literal; last read: 'tru!'".
    std::string what = e.what();
    const auto cut = what.find("syntax error");
    what = cut == std::string::npos ? "not JSON text" : what.substr(cut);
    if (const auto last = what.find("; last read: '"); last != std::string::npos) {
      const std::size_t from = last + 14, to = what.rfind('\'');
      if (to != std::string::npos && to > from + 40) what = what.substr(0, from + 40) + "...'";
    }
    return fail("malformed JSON at byte " + std::to_string(error_byte_) + ": " + what);
  }

  const std::string& error() const { return error_; }
  const std::string& error_path() const { return error_path_; }
  /// The byte of the input where the JSON syntax error was found (0 if none).
  std::size_t error_byte() const { return error_byte_; }

 private:
  bool next_from_number() {
    if (!quoted_) return false;
    const std::size_t k = strings_++;
    return k < quoted_->from_number.size() && quoted_->from_number[k];
  }
  bool number(std::string_view text) {
    std::string tagged;
    tagged.reserve(text.size() + 1);
    tagged += kNumberTag;
    tagged += text;
    return put(json(std::move(tagged)));
  }
  bool fail(std::string why) {
    if (error_.empty()) {
      error_ = std::move(why);
      error_path_ = here();
    }
    return false;
  }
  // The last path piece of the next value: its index in the open array or its key in the open object.
  std::string next_segment() const {
    if (stack_.empty()) return "";
    if (stack_.back()->is_array()) return "[" + std::to_string(stack_.back()->size()) + "]";
    return key_.empty() ? "" : member_segment(key_);
  }
  // The JSON path of the next value, e.g. "$.P[1]".
  std::string here() const {
    std::string p = "$";
    for (const std::string& s : segments_) p += s;
    return p + next_segment();
  }
  json* place(json v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    json* slot = &(top[key_] = std::move(v));
    key_.clear();
    return slot;
  }
  bool put(json v) {
    place(std::move(v));
    return true;
  }
  bool open(json v) {
    if (stack_.size() >= kMaxJsonDepth) return fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    segments_.push_back(next_segment());
    stack_.push_back(place(std::move(v)));
    return true;
  }
  bool close() {
    stack_.pop_back();
    segments_.pop_back();
    return true;
  }

  json& root_;
  const QuotedText* quoted_;
  std::size_t strings_ = 0;  // string tokens (keys included) read so far
  std::vector<json*> stack_;
  std::vector<std::string> segments_;  // path pieces of the open containers, e.g. ".P", "[1]"
  std::string key_;
  std::string error_;
  std::string error_path_;
  std::size_t error_byte_ = 0;
};

template <class J>
bool is_number_text(const J& j) {
  return j.is_string() && !j.template get_ref<const std::string&>().empty() &&
         j.template get_ref<const std::string&>().front() == kNumberTag;
}

/// Appends s as a JSON string, escaped as nlohmann's dump() escapes it.
void append_string(std::string_view s, std::string& out) {
  const bool plain =
      std::all_of(s.begin(), s.end(), [](char c) { return c >= 0x20 && c < 0x7f && c != '"' && c != '\\'; });
  if (!plain) {
    out += json(std::string(s)).dump();
    return;
  }
  out += '"';
  out += s;
  out += '"';
}

/// Writes ordered_json values as dump(indent) does.
class Writer {
 public:
  Writer(std::string& out, int indent) : out_(out), indent_(indent) {}

  void value(const nlohmann::ordered_json& j, int depth) {
    switch (j.type()) {
      case nlohmann::ordered_json::value_t::object:
        return container(j, depth, '{', '}');
      case nlohmann::ordered_json::value_t::array:
        return container(j, depth, '[', ']');
      case nlohmann::ordered_json::value_t::string:
        return string(j.get_ref<const std::string&>());
      case nlohmann::ordered_json::value_t::number_integer:
        return integer(j.get<std::int64_t>());
      case nlohmann::ordered_json::value_t::number_unsigned:
        return integer(j.get<std::uint64_t>());
      case nlohmann::ordered_json::value_t::boolean:
        out_ += j.get<bool>() ? "true" : "false";
        return;
      case nlohmann::ordered_json::value_t::null:
        out_ += "null";
        return;
      default:             // floats, binary, discarded
        out_ += j.dump();  // their own bytes
    }
  }

 private:
  void container(const nlohmann::ordered_json& j, int depth, char open, char close) {
    out_ += open;
    if (j.empty()) {
      out_ += close;
      return;
    }
    const bool object = j.is_object();
    bool first = true;
    for (auto it = j.cbegin(); it != j.cend(); ++it) {
      if (!first) out_ += ',';
      first = false;
      line(depth + 1);
      if (object) {
        string(it.key());
        out_ += indent_ < 0 ? ":" : ": ";
      }
      value(*it, depth + 1);
    }
    line(depth);
    out_ += close;
  }

  /// A new line indented to `depth` (nothing in compact text).
  void line(int depth) {
    if (indent_ < 0) return;
    out_ += '\n';
    out_.append(static_cast<std::size_t>(indent_) * static_cast<std::size_t>(depth), ' ');
  }

  void string(const std::string& s) { append_string(s, out_); }

  template <class Int>
  void integer(Int v) {
    char digits[24];
    out_.append(digits, std::to_chars(digits, digits + sizeof digits, v).ptr);
  }

  std::string& out_;
  int indent_;
};

/// Appends the canonical text (JsonInput::canonical_text) of a parsed value or of one built in memory (J =
/// ordered_json, whose integers are JSON numbers where a parsed file holds their text), as json(...).dump() of the
/// canonical value would write it, without building that value.
template <class J>
void append_canonical(const J& j, std::string& out) {
  if (j.is_object()) {
    std::vector<typename J::const_iterator> members;
    for (auto it = j.cbegin(); it != j.cend(); ++it) {
      const std::string& k = it.key();
      if (!it->is_null() && k != "source" && k != "note" && k != "name" && k != "description") members.push_back(it);
    }
    std::sort(members.begin(), members.end(), [](const auto& a, const auto& b) { return a.key() < b.key(); });
    out += '{';
    for (std::size_t m = 0; m < members.size(); ++m) {
      if (m > 0) out += ',';
      append_string(members[m].key(), out);
      out += ':';
      append_canonical(*members[m], out);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    for (auto it = j.cbegin(); it != j.cend(); ++it) {
      if (it != j.cbegin()) out += ',';
      append_canonical(*it, out);
    }
    out += ']';
  } else if (j.is_number_unsigned()) {
    append_string(std::to_string(j.template get<std::uint64_t>()), out);
  } else if (j.is_number_integer()) {
    append_string(std::to_string(j.template get<std::int64_t>()), out);
  } else if (j.is_number_float()) {
    throw std::logic_error("canonical text: a binary float has no exact text");
  } else if (j.is_boolean()) {
    out += j.template get<bool>() ? "true" : "false";
  } else if (j.is_string()) {
    std::string_view s = j.template get_ref<const std::string&>();
    if (is_number_text(j)) s.remove_prefix(1);
    Q q;
    if (is_lowest_terms_text(s))
      append_string(s, out);
    else if (parse_rational_into(s, q))
      append_string(to_string(q), out);
    else
      append_string(s, out);
  } else {
    out += "null";
  }
}

template <class J>
std::string canonical(const J& j) {
  std::string out;
  append_canonical(j, out);
  return out;
}

/// The exact number a node holds (a number token or a numeric string) into out; false if it holds none.
bool rational_of(const json& node, Q& out) {
  if (!node.is_string()) return false;
  std::string_view s = node.get_ref<const std::string&>();
  if (is_number_text(node)) s.remove_prefix(1);
  return parse_rational_into(s, out);
}

}  // namespace

std::string quoted_excerpt(std::string_view text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown) return "\"" + std::string(text) + "\"";
  return "\"" + std::string(text.substr(0, kShown)) + "...\" (" + std::to_string(text.size()) + " characters)";
}

std::string JsonInput::canonical_text() const { return canonical(*node_); }

std::string JsonInput::canonical_sha256() const { return sha256_hex(canonical_text()); }

std::string canonical_sha256(const nlohmann::ordered_json& value) { return sha256_hex(canonical(value)); }

std::string json_text(const nlohmann::ordered_json& value, int indent) {
  std::string out;
  Writer(out, indent).value(value, 0);
  return out;
}

JsonInput JsonInput::parse(const std::string& text, const std::string& file) {
  if (text.size() > kMaxInputBytes) throw InputError(file, "", too_large_text());
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(file, "$",
                     "malformed JSON: no JSON text (the input is empty; a pipe without a writer reads as empty)");
  auto root = std::make_shared<json>();
  auto f = std::make_shared<const std::string>(file);
  // Valid input is read in one pass, the parser handing over each number token's text. Input it rejects there (as it
  // rejects a number beyond double's range) is read again with its number tokens quoted first: that reading keeps
  // every number, and its errors name the byte of the original text.
  // The parser writes a float token's decimal point as the C locale's LC_NUMERIC has it ("0,966" under some
  // locales): the one pass needs '.', so any other setting takes the quoted reading.
  if (text.find('\0') == std::string::npos && std::strcmp(std::localeconv()->decimal_point, ".") == 0) {
    LiteralNumberBuilder builder(*root, nullptr);
    if (json::sax_parse(text, &builder, json::input_format_t::json, /*strict=*/true))
      return JsonInput(root, root.get(), f, "$");
    *root = json();
  }
  const QuotedText quoted = quote_numbers(text);
  LiteralNumberBuilder builder(*root, &quoted);
  bool ok = json::sax_parse(quoted.text, &builder, json::input_format_t::json, /*strict=*/true);
  // The parser takes a NUL byte for the end of the input: report it unless an error comes before it.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos && (ok || builder.error_byte() > nul))
    throw InputError(file, "", "a NUL byte at byte " + std::to_string(nul) + " (JSON text has none)");
  if (!ok) throw InputError(file, builder.error_path(), builder.error().empty() ? "malformed JSON" : builder.error());
  return JsonInput(root, root.get(), f, "$");
}

JsonInput JsonInput::load(const std::string& path) { return parse(read_text(path), path); }

namespace {

/// Opens `path` for reading without blocking: open(2) of a FIFO waits for a writer unless O_NONBLOCK is given, so
/// the file is opened non-blocking and made blocking again once it is known to be something readable. A FIFO (or
/// pipe) without a writer then reads as empty. Anything but a regular file, a character device or a FIFO is
/// refused (a directory, a block device).
int open_input(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw InputError(path, "", std::string("cannot open the file for reading (") + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !(S_ISREG(st.st_mode) || S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))) {
    const bool dir = S_ISDIR(st.st_mode);
    ::close(fd);
    throw InputError(path, "",
                     dir ? "is a directory; expected a JSON file"
                         : "is not a regular file, a character device or a pipe; expected a JSON file");
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
    ::close(fd);
    throw InputError(path, "", "cannot open the file for reading");
  }
  return fd;
}

}  // namespace

std::string JsonInput::read_text(const std::string& path) {
  const bool stdin_input = path == "-";
  const std::string name = stdin_input ? "standard input" : path;
  const int fd = stdin_input ? STDIN_FILENO : open_input(path);
  // Into a buffer doubled from 64 KiB whenever it is full (no buffer much larger than the file is touched), up to one
  // byte past the limit: an endless source (/dev/zero) stops there.
  std::string text;
  std::size_t filled = 0;
  int error = 0;
  while (filled <= kMaxInputBytes) {
    if (filled == text.size())
      text.resize(std::min(std::max(2 * text.size(), std::size_t{1} << 16), kMaxInputBytes + 1));
    const ssize_t got = ::read(fd, text.data() + filled, text.size() - filled);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      error = got < 0 ? errno : 0;
      break;
    }
    filled += static_cast<std::size_t>(got);
  }
  text.resize(filled);
  if (!stdin_input) ::close(fd);
  if (text.size() > kMaxInputBytes) throw InputError(name, "", too_large_text());
  if (error != 0) throw InputError(name, "", std::string("read error (") + std::strerror(error) + ")");
  return text;
}

std::string JsonInput::too_large_text() {
  return "larger than the input limit of " + std::to_string(kMaxInputBytes >> 20) + " MiB";
}

bool JsonInput::is_object() const { return node_->is_object(); }
bool JsonInput::is_array() const { return node_->is_array(); }
bool JsonInput::is_null() const { return node_->is_null(); }
bool JsonInput::is_string_or_number() const { return node_->is_string(); }

std::string JsonInput::kind() const {
  if (is_number_text(*node_)) return "a number";
  if (node_->is_string()) return "a string";
  return std::string(node_->is_object() || node_->is_array() ? "an " : "a ") + node_->type_name();
}

void JsonInput::fail(const std::string& expected) const { throw InputError(*file_, path_, expected); }

std::size_t JsonInput::size() const {
  if (!node_->is_array()) fail("expected an array, found " + kind());
  return node_->size();
}

JsonInput JsonInput::at(std::string_view key) const {
  auto j = find(key);
  if (!j) JsonInput(root_, node_, file_, path_ + member_segment(key)).fail("required field is missing");
  return *j;
}

std::optional<JsonInput> JsonInput::find(std::string_view key) const {
  if (!node_->is_object()) fail("expected an object, found " + kind());
  auto it = node_->find(std::string(key));
  if (it == node_->end() || it->is_null()) return std::nullopt;
  return JsonInput(root_, &*it, file_, path_ + member_segment(key));
}

JsonInput JsonInput::at(std::size_t i) const {
  if (i >= size()) fail("expected at least " + std::to_string(i + 1) + " elements");
  return JsonInput(root_, &(*node_)[i], file_, path_ + "[" + std::to_string(i) + "]");
}

std::vector<JsonInput> JsonInput::elements() const {
  std::vector<JsonInput> out;
  for (std::size_t i = 0, n = size(); i < n; ++i) out.push_back(at(i));
  return out;
}

void JsonInput::expect_keys(std::initializer_list<std::string_view> allowed) const {
  if (!node_->is_object()) fail("expected an object, found " + kind());
  for (auto it = node_->begin(); it != node_->end(); ++it) {
    bool known = false;
    for (auto a : allowed) known = known || a == it.key();
    if (!known) {
      std::string list;
      for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      JsonInput(root_, &*it, file_, path_ + member_segment(it.key())).fail("unknown field (allowed: " + list + ")");
    }
  }
}

Q JsonInput::rational() const {
  Q q;
  if (rational_of(*node_, q)) return q;
  if (!node_->is_string()) fail("expected a number or a numeric string, found " + kind());
  std::string_view s = node_->get_ref<const std::string&>();
  if (is_number_text(*node_)) s.remove_prefix(1);
  try {
    return parse_rational(s);  // throws: it accepts exactly what rational_of does
  } catch (const NumberSyntaxError& e) {
    fail(e.what());
  }
}

long JsonInput::integer(long lo, long hi) const {
  Q q = rational();
  if (q.get_den() != 1 || q < lo || q > hi) {
    const std::string found = to_string(q);
    fail("expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", found " +
         (found.size() <= 40 ? found : quoted_excerpt(found)));
  }
  return q.get_num().get_si();
}

std::string JsonInput::string() const {
  if (!node_->is_string() || is_number_text(*node_)) fail("expected a string, found " + kind());
  return node_->get<std::string>();
}

bool JsonInput::boolean() const {
  if (!node_->is_boolean()) fail("expected true or false, found " + kind());
  return node_->get<bool>();
}

Vec<Q> JsonInput::rational_vector(std::optional<std::size_t> n) const {
  std::size_t m = size();
  if (n && m != *n) fail("expected an array of " + std::to_string(*n) + " numbers, found " + std::to_string(m));
  Vec<Q> v(static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i)  // in place; the element's path is made only for an error
    if (!rational_of((*node_)[i], v(static_cast<Eigen::Index>(i)))) (void)at(i).rational();  // throws
  return v;
}

Mat<Q> JsonInput::rational_matrix(std::optional<std::size_t> rows, std::optional<std::size_t> cols) const {
  std::size_t r = size();
  if (rows && r != *rows) fail("expected " + std::to_string(*rows) + " rows, found " + std::to_string(r));
  std::optional<std::size_t> c = cols;
  if (!c && r > 0) c = at(0).size();
  Mat<Q> A(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c.value_or(0)));
  for (std::size_t i = 0; i < r; ++i) {
    JsonInput row = at(i);
    if (row.size() != *c)
      row.fail("expected a row of " + std::to_string(*c) + " numbers, found " + std::to_string(row.size()));
    for (std::size_t j = 0; j < *c; ++j)  // in place; the element's path is made only for an error
      if (!rational_of((*row.node_)[j], A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))))
        (void)row.at(j).rational();  // throws
  }
  return A;
}

}  // namespace contactcert::exact
