// The picture of an assembly (docs/formats.md section 3a): its bodies, obstacles, fixels and fingers, each contact
// with its normal, and a witness's contact forces.
#pragma once

#include <string>
#include <vector>

#include "queries/assembly_query.h"

namespace contactcert::queries {

/// SVG text: bodies (numbered, com marked), obstacles (grey), fixels and fingers (dots), each contact's point and
/// normal (from `from` into `to`), and `forces` (a witness's world forces: f on `to` drawn at the contact point,
/// scaled so that the largest is a fixed fraction of the drawing; empty: none). `title` is printed above.
std::string assembly_svg(const geometry::Assembly& a, const std::vector<AssemblyContactForce>& forces,
                         const std::string& title);

/// The picture of a stability answer: the moving witness's forces, else the resting ones, titled with the verdict.
std::string to_svg(const AssemblyInput& in, const AssemblyStabilityAnswer& answer);
/// The picture of a quasistatic answer: the solution's contact forces, titled with the status.
std::string to_svg(const AssemblyInput& in, const AssemblyUcpAnswer& answer);

/// Writes an answer's files where the options ask: its certificate text (when there is one) and its picture, and
/// records their paths in the answer; a certificate too large for `check` is refused naming the command that ran.
template <class Answer, class Options>
void write_files(const AssemblyInput& in, const Options& options, Answer& answer) {
  if (!options.certificate.empty() && !answer.certificate_text.empty()) {
    write_certificate_file(command_name(options), options.certificate, answer.certificate_text,
                           "the verdict was found");
    answer.certificate = options.certificate;
  }
  if (!options.svg.empty()) {
    write_text_file(options.svg, to_svg(in, answer));
    answer.svg = options.svg;
  }
}

}  // namespace contactcert::queries
