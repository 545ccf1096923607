#include <chrono>
#include <iostream>

#include "solvers/assembly/assembly_check.h"
#include "tests/solvers/assembly/assembly_fixtures.h"
using namespace contactcert::solvers::assembly;
void run(const char* name, const contactcert::geometry::Assembly& a) {
  auto t0 = std::chrono::steady_clock::now();
  auto r = assembly_stability(a);
  auto t1 = std::chrono::steady_clock::now();
  auto why = check_assembly_stability(a, r);
  auto t2 = std::chrono::steady_clock::now();
  std::cout << name << " N=" << a.bodies.size() << " k=" << a.contacts.size() << " " << verdict_name(r.verdict) << " "
            << status_name(r.status) << " nodes=" << r.nodes << " lps=" << r.lps << " dead=" << r.dead.size()
            << " t=" << std::chrono::duration<double>(t1 - t0).count()
            << " check=" << std::chrono::duration<double>(t2 - t1).count() << " " << (why.empty() ? "valid" : why)
            << std::endl;
}
int main() {
  for (std::size_t n : {2, 4, 8, 16}) {
    run("stack", testing::box_stack(n).read());
    run("row", testing::box_row(n).read());
  }
  run("arch", testing::corbel_arch().read());
  for (std::size_t n : {2, 4, 8, 16}) {
    auto s = testing::box_stack(n);
    for (auto& b : s.bodies) b.insert(b.size() - 1, ", \"load\": [\"1/2\", -2, 0]");
    run("windstack", s.read());
    for (auto& c : s.contacts) {
      auto p = c.find("\"mu\"");
      c = c.substr(0, p) + "\"mu_s\": \"1/2\", \"mu_k\": \"1/3\"}";
    }
    run("windstack_muk", s.read());
  }
}
