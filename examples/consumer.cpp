// The C++ package in a few lines (docs/cpp.md, which shows this file and its output): the section 4 disk's wrench
// cone of mode "na", the section 7 disk's strong stability under g = (1, -2, 0), Data Set 4's jamming, and the
// independent check of both certificates. Usage: consumer SCENES_DIR (the installed PREFIX/share/contactcert/scenes).
#include <contactcert/contactcert.h>  // the whole public API; or one header, e.g. <contactcert/solvers/ucp/solve.h>

#include <iostream>
#include <string>
#include <vector>

using namespace contactcert;

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::cerr << "usage: consumer SCENES_DIR\n";
    return 2;
  }
  const std::string dir = argv[1];

  // Section 4: the cone of wrenches consistent with fixel 1 not touching and fixel 2 rolling ("na").
  const geometry::PlanarScene disk4 = geometry::load_planar_scene(dir + "/bt2002_section4_disk.json");
  std::vector<bool> touching;
  for (const auto& f : disk4.fixels) touching.push_back(f.frame.touching());
  const solvers::ModeParse mode = solvers::parse_mode("na", touching);
  if (mode.status != solvers::ModeStatus::kValid) throw exact::InputError("na", "--mode", mode.message);
  const auto cone = solvers::wrench_cone<exact::Q>(disk4, mode.mode, solvers::Route::kPaper);
  std::cout << "cone na: dimension " << cone.cone.dimension() << ", " << cone.cone.closure.rays.rows()
            << " generators, " << cone.cone.open_faces.size() << " open faces\n";

  // Section 7: strong stability of the disk on two fixels under g = (1, -2, 0), with its certificate.
  const std::string file = dir + "/bt2002_section7_disk.json";
  const std::string text = exact::JsonInput::read_text(file);
  const geometry::PlanarScene disk7 = geometry::read_planar_scene(exact::JsonInput::parse(text, file));
  exact::Vec<exact::Q> g(3);
  g << exact::parse_rational("1"), exact::parse_rational("-2"), exact::parse_rational("0");
  const auto r = solvers::strong_stability<exact::Q>(disk7, g);
  std::cout << "stability g = (1, -2, 0): " << solvers::verdict_name(r.verdict) << " (" << r.lps << " LPs)\n";
  const std::string cert = solvers::stability_certificate(text, g, r);
  const auto check = checker::check_stability_certificate(exact::JsonInput::parse(cert, "certificate"));
  std::cout << "certificate: " << (check.valid ? "VALID" : "INVALID") << " (" << check.reason << ")\n";

  // Pang, Trinkle and Lo's Data Set 4: the commanded motion jams; the search tree is the proof.
  const solvers::ucp::UcpProblem problem = solvers::ucp::load_ucp_problem(dir + "/pang1994_dataset4.json");
  const solvers::ucp::UcpReport ucp = solvers::ucp::solve_ucp(problem, {});
  std::cout << "ucp dataset 4: " << solvers::ucp::status_name(ucp.status) << " (" << ucp.nodes << " nodes)\n";
  const std::string jam = solvers::ucp::certificate_text(problem, ucp);
  const auto jam_check = checker::check_ucp_certificate(exact::JsonInput::parse(jam, "certificate"));
  const bool jam_valid = jam_check.verdict == checker::CertificateVerdict::kValid;
  std::cout << "certificate: " << (jam_valid ? "VALID" : "INVALID") << " (" << jam_check.reason << ")\n";

  return check.valid && r.verdict == solvers::StabilityVerdict::kStronglyStable && jam_valid ? 0 : 1;
} catch (const exact::InputError& e) {
  std::cerr << "consumer: " << e.what() << "\n";
  return 2;
}
