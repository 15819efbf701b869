#include "render/render_options.h"

namespace prt {

RenderOptions WithDemoCamera(RenderOptions o) {
  o.eye = glm::dvec3(6.0, 3.2, 9.0);
  o.target = glm::dvec3(0.0, 1.5, 0.0);
  o.fov = 36.0;
  return o;
}

}  // namespace prt
