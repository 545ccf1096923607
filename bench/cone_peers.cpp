#include "bench/cone_peers.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#ifdef CONTACTCERT_HAVE_PPL
#include <ppl.hh>
#endif
#ifdef CONTACTCERT_HAVE_NORMALIZ
#include <libnormaliz/libnormaliz.h>
#endif

namespace contactcert::bench {

#ifdef CONTACTCERT_HAVE_PPL
namespace {
namespace ppl = Parma_Polyhedra_Library;
ppl::Linear_Expression expression(const std::vector<exact::Z>& row, long sign) {
  ppl::Linear_Expression e;
  for (std::size_t j = 0; j < row.size(); ++j)
    if (row[j] != 0) e += ppl::Coefficient(row[j] * sign) * ppl::Variable(static_cast<ppl::dimension_type>(j));
  return e;
}
}  // namespace

long ppl_facets(const IntRows& rays, long dim) {
  ppl::Generator_System gs;
  gs.insert(ppl::point());
  for (const auto& r : rays) gs.insert(ppl::ray(expression(r, 1)));
  ppl::C_Polyhedron p(static_cast<ppl::dimension_type>(dim), ppl::EMPTY);
  p.add_generators(gs);
  long n = 0;
  for (const auto& c : p.minimized_constraints()) n += c.is_inequality() ? 1 : 0;
  return n;
}

long ppl_rays(const IntRows& inequalities, long dim) {
  ppl::Constraint_System cs;
  cs.set_space_dimension(static_cast<ppl::dimension_type>(dim));
  for (const auto& f : inequalities) cs.insert(expression(f, -1) >= 0);  // f . x <= 0
  ppl::C_Polyhedron p(cs);
  long n = 0;
  for (const auto& g : p.minimized_generators()) n += g.is_ray() ? 1 : 0;
  return n;
}
#else
long ppl_facets(const IntRows&, long) { return -1; }
long ppl_rays(const IntRows&, long) { return -1; }
#endif

#ifdef CONTACTCERT_HAVE_NORMALIZ
long normaliz_facets(const IntRows& rays, long) {
  libnormaliz::set_thread_limit(1);
  libnormaliz::Cone<mpz_class> c(libnormaliz::Type::cone, rays);
  c.compute(libnormaliz::ConeProperty::SupportHyperplanes);
  return static_cast<long>(c.getSupportHyperplanes().size());
}

long normaliz_rays(const IntRows& inequalities, long) {
  libnormaliz::set_thread_limit(1);
  IntRows a = inequalities;  // Normaliz: a . x >= 0
  for (auto& r : a)
    for (auto& x : r) x = -x;
  libnormaliz::Cone<mpz_class> c(libnormaliz::Type::inequalities, a);
  c.compute(libnormaliz::ConeProperty::ExtremeRays);
  return static_cast<long>(c.getExtremeRays().size());
}
#else
long normaliz_facets(const IntRows&, long) { return -1; }
long normaliz_rays(const IntRows&, long) { return -1; }
#endif

namespace {

// The rows [lead | sign * row] of an lrs input (H-representation: lead + a . x >= 0; V-representation:
// lead 1 a vertex, 0 a ray), with the origin as the one vertex of a V-representation.
std::string lrs_input(const IntRows& rows, long dim, bool vertices) {
  std::ostringstream in;
  in << "cone\n"
     << (vertices ? "V" : "H") << "-representation\nbegin\n"
     << rows.size() + (vertices ? 1 : 0) << " " << dim + 1 << " integer\n";
  if (vertices) {
    in << 1;
    for (long j = 0; j < dim; ++j) in << " 0";
    in << "\n";
  }
  for (const auto& r : rows) {
    in << 0;
    for (const exact::Z& x : r) in << " " << (vertices ? x : exact::Z(-x));
    in << "\n";
  }
  in << "end\n";
  return in.str();
}

// An lrs output row without its lead entry, as a primitive integer row times `sign`.
std::vector<exact::Z> primitive(const std::vector<exact::Q>& row, long sign) {
  exact::Z den = 1, g = 0;
  for (std::size_t j = 1; j < row.size(); ++j) den = lcm(den, exact::Z(row[j].get_den()));
  std::vector<exact::Z> out;
  for (std::size_t j = 1; j < row.size(); ++j) {
    out.push_back(exact::Z(row[j] * den) * sign);
    g = gcd(g, out.back());
  }
  if (g > 1)
    for (auto& x : out) x /= g;
  return out;
}

// Runs `lrs in out` (its terminal output discarded) and reads the rows between begin and end of its
// output, keeping those whose lead entry is 0 (rays and cone facets; not the origin as a vertex).
std::optional<LrsOutput> run_lrs(const std::string& input, long sign) {
  char in_name[] = "/tmp/cone_bench_lrs_XXXXXX";
  const int fd = mkstemp(in_name);
  if (fd < 0) return std::nullopt;
  const bool written = write(fd, input.data(), input.size()) == static_cast<ssize_t>(input.size());
  close(fd);
  const std::string out_name = std::string(in_name) + ".out";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::string prog = "lrs", out_arg = out_name;
  char* argv[] = {prog.data(), in_name, out_arg.data(), nullptr};
  pid_t pid = 0;
  int status = 1;
  rusage usage{};
  const bool ran = written && posix_spawnp(&pid, "lrs", &actions, nullptr, argv, environ) == 0 &&
                   wait4(pid, &status, 0, &usage) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  posix_spawn_file_actions_destroy(&actions);
  std::ifstream out_file(out_name);
  std::optional<LrsOutput> out;
  if (ran && out_file) {
    out.emplace();
    out->cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                       1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    std::vector<long> linearity;
    std::string line;
    bool inside = false;
    long index = 0;
    while (std::getline(out_file, line)) {
      std::istringstream words(line);
      std::string first;
      if (!(words >> first) || first[0] == '*') continue;
      if (first == "linearity") {
        long count = 0, i = 0;
        words >> count;
        while (words >> i) linearity.push_back(i);
      } else if (first == "begin") {
        inside = true;
      } else if (first == "end") {
        inside = false;
      } else if (inside) {
        std::vector<exact::Q> row{exact::Q(first)};
        for (std::string w; words >> w;) row.emplace_back(w);
        for (auto& q : row) q.canonicalize();
        ++index;
        if (row[0] != 0) continue;
        const bool lineal = std::find(linearity.begin(), linearity.end(), index) != linearity.end();
        (lineal ? out->linearity : out->rows).push_back(primitive(row, sign));
      }
    }
  }
  std::remove(in_name);
  std::remove(out_name.c_str());
  return out;
}

}  // namespace

// lrs: facets as b + a . x >= 0 (b = 0), so f = -a.
std::optional<LrsOutput> lrs_facets(const IntRows& rays, long dim) { return run_lrs(lrs_input(rays, dim, true), -1); }
std::optional<LrsOutput> lrs_rays(const IntRows& inequalities, long dim) {
  return run_lrs(lrs_input(inequalities, dim, false), 1);
}

}  // namespace contactcert::bench
