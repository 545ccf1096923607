// JSON output helpers shared by the subcommands (SPEC section 1): exact numbers as strings in lowest
// terms, float views beside them under `_approx` keys, and writing a result file.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "exact/number.h"
#include "geometry/point_text.h"
#include "geometry/workpiece.h"

namespace contactcert::queries {

using json = nlohmann::ordered_json;

/// "-7/20"-style strings.
json exact_json(const exact::Q& x);
json exact_json(const exact::Vec<exact::Q>& v);
json exact_json(const exact::Mat<exact::Q>& M);  ///< array of rows
/// Plain doubles (the float view of an exact value, or a float-path result).
json approx_json(const exact::Vec<exact::Q>& v);
json approx_json(const exact::Vec<double>& v);
json approx_json(const exact::Mat<double>& M);
/// A primitive integer direction vector (SPEC section 1) as strings.
json primitive_json(const exact::Vec<exact::Q>& v);
/// "(a, b, c)" for readable reports: exact entries in lowest terms, or doubles.
std::string tuple_text(const exact::Vec<exact::Q>& v);
std::string tuple_text(const exact::Vec<double>& v);
std::string tuple_text(const std::vector<exact::Z>& v);
/// Reads "a,b,c" (each an exact number, SPEC section 1) for option `option`; InputError names the option.
exact::Vec<exact::Q> parse_number_list(const std::string& text, const std::string& option, long expected_size);
/// Writes text to path ("-" = stdout), flushed and checked: InputError naming the file if it cannot be opened
/// or written (a full disk). Every file a command writes goes through here.
void write_text_file(const std::string& path, const std::string& text);
/// Writes a certificate only if `check` can read it back (at most exact::kMaxInputBytes): otherwise nothing is
/// written and exact::BudgetExceeded (exit 3) says "COMMAND --certificate: the certificate would take N bytes ..."
/// with `covered`, what the command found.
void write_certificate_file(const std::string& command, const std::string& path, const std::string& text,
                            const std::string& covered);
/// Creates the folder `dir` of a command's files (and its parents); InputError naming `field` otherwise.
void create_output_dir(const std::string& dir, const std::string& field = "--out");
/// Wall-clock seconds since t.
double seconds_since(std::chrono::steady_clock::time_point t);

}  // namespace contactcert::queries
