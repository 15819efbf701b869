#pragma once
/// \file
/// The report's own scene (report_sweep.h, stability.h).

#include "geometry/mesh.h"

namespace prt {

/// The small default scene of the report: a (2, 3) torus knot of 128 x 16 segments standing on
/// a 24 x 24 ground plane (about 2,700 vertices): the demo scene's shapes, fast enough to sweep.
Mesh MakeReportScene();

}  // namespace prt
