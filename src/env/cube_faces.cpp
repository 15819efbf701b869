#include "env/cube_faces.h"

#include <cmath>

namespace prt {

const std::array<const char*, 6> kFaceNames = {"posx", "negx", "posy", "negy", "posz", "negz"};

const std::array<FaceFrame, 6>& FaceFrames(CubeLayout layout) {
  // Standard: OpenGL cube-map layout (N, U, V), CONVENTIONS.md.
  static const std::array<FaceFrame, 6> standard = {{
      {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // posx
      {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // negx
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},     // posy
      {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // negy
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // posz
      {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},  // negz
  }};
  // The course's ProjEnv: files loaded as (negx posx posy negy posz negz) but given the frames
  // of (negx posx negy posy negz posz); each frame there is (U, V, N) = rows of its table.
  static const std::array<FaceFrame, 6> games202 = {{
      {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}},    // posx: the course's posx row
      {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},   // negx: the course's negx row
      {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},   // posy: given the negy row
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},     // negy: given the posy row
      {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},  // posz: given the negz row
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},    // negz: given the posz row
  }};
  return layout == CubeLayout::kStandard ? standard : games202;
}

double FaceRectSolidAngle(double x0, double y0, double x1, double y1) {
  auto a = [](double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0)); };
  return a(x0, y0) - a(x0, y1) - a(x1, y0) + a(x1, y1);
}

double TexelSolidAngle(int col, int row, int size) {
  const double step = 2.0 / size;
  const double x0 = -1.0 + col * step, y0 = -1.0 + row * step;
  return FaceRectSolidAngle(x0, y0, x0 + step, y0 + step);
}

}  // namespace prt
