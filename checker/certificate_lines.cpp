#include "checker/certificate_lines.h"

#include <algorithm>

namespace contactcert::checker {
namespace {

/// The lines of a text, without their '\n' (a final '\n' ends the last line).
std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    out.push_back(text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return out;
}

/// The name of a list's opening line ` "name": [`, or nullopt if the line is not one.
std::optional<std::string> opening(std::string_view line) {
  constexpr std::string_view tail = "\": [";
  if (line.size() < 2 + tail.size() || line.substr(0, 2) != " \"" || line.substr(line.size() - tail.size()) != tail)
    return std::nullopt;
  const std::string_view name = line.substr(2, line.size() - 2 - tail.size());
  if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) { return (c >= 'a' && c <= 'z') || c == '_'; }))
    return std::nullopt;
  return std::string(name);
}

}  // namespace

bool CertificateLines::starts_as(std::string_view text, std::string_view kind) {
  const std::string start = "{\n \"kind\": \"" + std::string(kind) + "\",\n";
  return text.substr(0, start.size()) == start;
}

CertificateLines::CertificateLines(std::string_view text, const std::string& file) : file_(file) {
  const std::vector<std::string_view> lines = lines_of(text);
  auto fail = [&](std::size_t at, const std::string& expected) {
    throw exact::InputError(file_ + ", line " + std::to_string(at + 1), "",
                            expected + " (a certificate in lines: docs/formats.md section 5c)");
  };
  if (lines.size() < 2 || lines.front() != "{") fail(0, "'{' alone on the first line");
  if (lines.back() != "}") fail(lines.size() - 1, "'}' alone on the last line");
  const std::size_t end = lines.size() - 1;
  // One member a line (a comma after each but the last), or a list: its opening line, one element a line (a comma
  // after each but the last), and " ]" (" ]," if members follow).
  auto comma = [&](std::string_view& line, bool wanted, std::size_t at) {
    const bool has = !line.empty() && line.back() == ',';
    if (has != wanted) fail(at, wanted ? "a ',' at the end of the line: more follows" : "no ',' after the last entry");
    if (has) line.remove_suffix(1);
  };
  std::string head = "{";
  for (std::size_t at = 1; at < end; ++at) {
    std::string_view line = lines[at];
    if (const auto name = opening(line)) {
      if (list(*name) != nullptr) fail(at, "a list named once: \"" + *name + "\" again");
      List& l = lists_.emplace_back(List{*name, at + 2, {}});
      for (++at; at < end && lines[at] != " ]" && lines[at] != " ],"; ++at) {
        std::string_view e = lines[at];
        if (e.substr(0, 3) != "  {" && e.substr(0, 3) != "  [") fail(at, "an element of \"" + *name + "\" on one line");
        comma(e, at + 1 < end && lines[at + 1] != " ]" && lines[at + 1] != " ],", at);
        l.elements.push_back(e.substr(2));
      }
      if (at == end) fail(at, "the end of list \"" + *name + "\": \" ]\"");
      line = lines[at];
      comma(line, at + 1 < end, at);
      continue;
    }
    if (line.substr(0, 2) != " \"") fail(at, "a member on one line, as ' \"name\": value'");
    comma(line, at + 1 < end, at);
    head += std::string(head.size() > 1 ? "," : "") + std::string(line);
  }
  head_ = exact::JsonInput::parse(head + "}", file_);
  for (const List& l : lists_)
    if (head_->find(l.name)) fail(l.line - 2, "a member named once: \"" + l.name + "\" is also a list");
}

void CertificateLines::expect_lists(std::initializer_list<std::string_view> allowed) const {
  for (const List& l : lists_)
    if (std::find(allowed.begin(), allowed.end(), l.name) == allowed.end())
      throw exact::InputError(file_ + ", line " + std::to_string(l.line - 1), "",
                              "a known list, found \"" + l.name + "\"");
}

const CertificateLines::List* CertificateLines::list(std::string_view name) const {
  for (const List& l : lists_)
    if (l.name == name) return &l;
  return nullptr;
}

std::size_t CertificateLines::size(std::string_view name) const {
  const List* l = list(name);
  return l ? l->elements.size() : 0;
}

exact::JsonInput CertificateLines::element(std::string_view name, std::size_t i) const {
  const List* l = list(name);
  return exact::JsonInput::parse(std::string(l->elements[i]), file_ + ", line " + std::to_string(l->line + i));
}

}  // namespace contactcert::checker
