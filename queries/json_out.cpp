#include "queries/json_out.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/nearest_double.h"
#include "exact/rational_text.h"

namespace contactcert::queries {

using exact::Q;

json exact_json(const Q& x) { return exact::to_string(x); }

json exact_json(const exact::Vec<Q>& v) {
  json a = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(exact::to_string(v(i)));
  return a;
}

json exact_json(const exact::Mat<Q>& M) {
  json rows = json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    json row = json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(exact::to_string(M(r, c)));
    rows.push_back(row);
  }
  return rows;
}

json approx_json(const exact::Vec<Q>& v) { return approx_json(exact::nearest_doubles(v)); }

json approx_json(const exact::Vec<double>& v) {
  json a = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v(i));
  return a;
}

json approx_json(const exact::Mat<double>& M) {
  json rows = json::array();
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    json row = json::array();
    for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
    rows.push_back(row);
  }
  return rows;
}

json primitive_json(const exact::Vec<Q>& v) {
  json a = json::array();
  for (const exact::Z& z : exact::primitive(v)) a.push_back(z.get_str());
  return a;
}

std::string tuple_text(const exact::Vec<Q>& v) {
  std::string s = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + exact::to_string(v(i));
  return s + ")";
}

std::string tuple_text(const exact::Vec<double>& v) {
  std::string s = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v(i));
  return s + ")";
}

std::string tuple_text(const std::vector<exact::Z>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i].get_str();
  return s + ")";
}

exact::Vec<Q> parse_number_list(const std::string& text, const std::string& option, long expected_size) {
  std::vector<Q> values;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      values.push_back(exact::parse_rational(item));
    } catch (const exact::NumberSyntaxError& e) {
      throw exact::InputError("command line", option, e.what());
    }
  }
  if (static_cast<long>(values.size()) != expected_size || (!text.empty() && text.back() == ','))
    throw exact::InputError(
        "command line", option,
        "expected " + std::to_string(expected_size) + " comma-separated numbers, found " + exact::quoted_excerpt(text));
  exact::Vec<Q> v(expected_size);
  for (long i = 0; i < expected_size; ++i) v(i) = values[static_cast<size_t>(i)];
  return v;
}

void write_certificate_file(const std::string& command, const std::string& path, const std::string& text,
                            const std::string& covered) {
  if (text.size() > exact::kMaxInputBytes)
    throw exact::BudgetExceeded(command + " --certificate: the certificate would take " + std::to_string(text.size()) +
                                    " bytes, more than the " + std::to_string(exact::kMaxInputBytes >> 20) +
                                    " MiB that check reads",
                                covered + "; no certificate written");
  write_text_file(path, text);
}

void write_text_file(const std::string& path, const std::string& text) {
  if (path == "-") {
    if (!(std::cout << text).flush()) throw exact::InputError("standard output", "", "cannot write the output");
    return;
  }
  std::ofstream f(path, std::ios::binary);
  if (!f) throw exact::InputError(path, "", "cannot open the file for writing");
  errno = 0;
  f << text;
  f.close();  // flushes: a full disk shows here
  if (f.fail())
    throw exact::InputError(
        path, "", std::string("cannot write the file (") + (errno ? std::strerror(errno) : "write error") + ")");
}

void create_output_dir(const std::string& dir, const std::string& field) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw exact::InputError(dir, field, "a folder that can be created (" + ec.message() + ")");
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace contactcert::queries
