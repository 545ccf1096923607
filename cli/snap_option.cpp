#include "cli/snap_option.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/snap.h"

namespace contactcert::cli {

void add_snap_option(CLI::App& sub, std::string& snap) {
  sub.add_option("--snap", snap,
                 "Read float input on purpose: put fixel points exactly on the boundary and numbers on the simplest "
                 "rational within TOL (e.g. 1e-9); every snap is reported on stderr");
}

std::string read_scene_text(const std::string& file, const std::string& snap) {
  std::string text = exact::JsonInput::read_text(file);  // read once: a pipe cannot be read again
  if (snap.empty()) return text;
  exact::Q tol;
  if (!exact::parse_rational_into(snap, tol) || sgn(tol) <= 0)
    throw exact::InputError("command line", "--snap",
                            "a tolerance > 0 such as 1e-9, got " + exact::quoted_excerpt(snap));
  const geometry::SnappedScene s = geometry::snap_planar_scene(text, file, tol);
  for (const geometry::Snap& x : s.snaps)
    std::cerr << "snapped " << x.field << ": " << x.original << " -> " << x.snapped << " (moved ~"
              << std::sqrt(x.distance_squared.get_d()) << ")\n";
  return s.text;
}

}  // namespace contactcert::cli
