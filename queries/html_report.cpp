#include "queries/html_report.h"

#include <filesystem>
#include <sstream>

#include "queries/json_out.h"

namespace contactcert::queries {

std::string html_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void HtmlReport::heading(const std::string& text) { body_ += "<h2>" + html_escape(text) + "</h2>\n"; }

void HtmlReport::paragraph(const std::string& text) { body_ += "<p>" + html_escape(text) + "</p>\n"; }

void HtmlReport::preformatted(const std::string& text) { body_ += "<pre>" + html_escape(text) + "</pre>\n"; }

namespace {

/// Whether a cell reads as a number or a count ("0.0815", "4.7e-17", "2e+02x", "3+1u", "1/2", "-"): it then never
/// breaks (a browser may break a line after the '-' of "4.7e-17").
bool numeric(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789.eE+-x/u%") == std::string::npos;
}

/// The text with a line break opportunity after each '/' (a header "verified/float" may wrap there).
std::string wrappable(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '/' ? std::string("/<wbr/>") : std::string(1, c);
  return out;
}

}  // namespace

void HtmlReport::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  // Columns of numbers are right-aligned and nowrap; the others (class "t") left-aligned and wrapped at spaces;
  // headers wrap at spaces and after '/'; a table wider than the page scrolls in its own box.
  std::vector<bool> text(header.size(), false);
  for (const auto& r : rows)
    for (std::size_t c = 0; c < r.size() && c < text.size(); ++c) text[c] = text[c] || !numeric(r[c]);
  body_ += "<div class=\"tw\"><table><tr>";
  for (std::size_t c = 0; c < header.size(); ++c)
    body_ += (text[c] ? "<th class=\"t\">" : "<th>") + wrappable(html_escape(header[c])) + "</th>";
  body_ += "</tr>\n";
  for (const auto& r : rows) {
    body_ += "<tr>";
    for (std::size_t c = 0; c < r.size(); ++c)
      body_ += (c < text.size() && text[c] ? "<td class=\"t\">" : "<td>") + html_escape(r[c]) + "</td>";
    body_ += "</tr>\n";
  }
  body_ += "</table></div>\n";
}

void HtmlReport::figure(const std::string& svg, const std::string& caption) {
  body_ += "<figure>" + svg + "<figcaption>" + html_escape(caption) + "</figcaption></figure>\n";
}

std::string HtmlReport::write(const std::string& dir) const {
  std::filesystem::create_directories(dir);
  const std::string path = (std::filesystem::path(dir) / "index.html").string();
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"/><title>" << html_escape(title_)
      << "</title>\n<style>body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}"
         ".tw{overflow-x:auto;max-width:100%}table{border-collapse:collapse;margin:1em 0}"
         "td,th{border:1px solid #bbb;padding:3px 8px;font-family:monospace;text-align:right;white-space:nowrap}"
         "td.t,th.t{white-space:normal;text-align:left}th{background:#eee;white-space:normal}"
         "pre{background:#f6f6f6;padding:.6em;"
         "overflow-x:auto}figure{display:inline-block;margin:.5em;vertical-align:top}"
         "figcaption{font-size:90%;max-width:420px}</style></head><body>\n<h1>"
      << html_escape(title_) << "</h1>\n"
      << body_ << "</body></html>\n";
  write_text_file(path, out.str());
  return path;
}

}  // namespace contactcert::queries
