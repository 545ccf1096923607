// A self-contained HTML report (inline SVG, no network) for `contactcert demo`.
#pragma once

#include <string>
#include <vector>

namespace contactcert::queries {

/// Collects sections of text, aligned tables and inline SVG pictures, then writes one HTML file.
class HtmlReport {
 public:
  explicit HtmlReport(std::string title) : title_(std::move(title)) {}
  void heading(const std::string& text);
  void paragraph(const std::string& text);
  void preformatted(const std::string& text);
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  /// `svg` is a complete <svg> element; `caption` is shown under it.
  void figure(const std::string& svg, const std::string& caption);
  /// Writes DIR/index.html (creating DIR) and returns its path.
  std::string write(const std::string& dir) const;

 private:
  std::string title_;
  std::string body_;
};

/// Escapes &, <, > and quotes for HTML text.
std::string html_escape(const std::string& s);

}  // namespace contactcert::queries
