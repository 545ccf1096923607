// A certificate in lines (docs/formats.md section 5c, the spatial_stability certificate): one JSON object whose
// members are each written on one line, except its long lists, written one element a line:
//   {
//    "kind": "spatial_stability",
//    "verdict": "strongly_stable",
//    ...
//    "vectors": [
//     {"rows":[...],"motzkin":[...]},
//     ...
//    ],
//    "dead": [
//     ...
//    ]
//   }
// read without a JSON tree of the whole text: the one-line members as one small object (the head), and each list's
// element lines parsed one at a time as a checker walks them. The text is one JSON document as well (any JSON tool
// reads it); the same certificate respelt in another layout is refused, naming the line.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exact/json_input.h"

namespace contactcert::checker {

class CertificateLines {
 public:
  /// Splits `text` (read from `file`) into its head and its lists; InputError naming the line if it is not in the
  /// layout (a member or element over several lines, a comma missing or extra, a list named twice).
  CertificateLines(std::string_view text, const std::string& file);
  /// Whether `text` starts as a certificate of `kind` in lines: "{" alone, then ` "kind": "KIND",`.
  static bool starts_as(std::string_view text, std::string_view kind);

  /// The one-line members as one object.
  const exact::JsonInput& head() const { return *head_; }
  /// Fails (InputError naming the line) on a list not named in `allowed`.
  void expect_lists(std::initializer_list<std::string_view> allowed) const;
  /// The elements of list `name` (0 if the certificate has no such list).
  std::size_t size(std::string_view name) const;
  /// Element i of list `name`, parsed alone (its messages name the file and the line).
  exact::JsonInput element(std::string_view name, std::size_t i) const;

 private:
  struct List {
    std::string name;
    std::size_t line;  ///< 1-based line of its first element
    std::vector<std::string_view> elements;
  };
  const List* list(std::string_view name) const;
  std::string file_;
  std::optional<exact::JsonInput> head_;
  std::vector<List> lists_;
};

}  // namespace contactcert::checker
