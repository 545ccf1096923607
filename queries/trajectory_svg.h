// The animated picture of `contactcert simulate --svg`: an SVG whose frames (SMIL, one per step and the final pose)
// show the body at its pose, the finger tips, each contact (a dot coloured by its mode) and the world force on the
// body there (an arrow), with a caption; about 20 poses along the run as faint outlines, so that a still picture shows
// the path; with --compare, the float run's body as a dashed outline. Doubles: a picture, not a verdict.
#pragma once

#include <string>

namespace contactcert::queries {

struct SimulateAnswer;

/// A complete <svg> element (at most 400 frames: a longer run is drawn at every k-th step).
std::string trajectory_svg(const SimulateAnswer& a);

}  // namespace contactcert::queries
