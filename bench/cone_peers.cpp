#include "bench/cone_peers.h"

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

}  // namespace contactcert::bench
