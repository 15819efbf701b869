#include "report/report_scene.h"

#include "geometry/procedural.h"

namespace prt {

Mesh MakeReportScene() {
  KnotOverGround s;  // the demo's scene, coarser
  s.segments = 128, s.sides = 16, s.ground_quads = 24;
  return MakeKnotOverGround(s);
}

}  // namespace prt
