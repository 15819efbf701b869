// --start-angle: the light's turn at frame 0, so a sequence can start where prt view left it.
#include "core/constants.h"
#include "io/png_io.h"
#include "render/render_frames.h"
#include "tests/test_support.h"

namespace prt {

TEST_SUITE("render") {

TEST_CASE("FrameAngle: start_degrees at frame 0, then 2 pi turns i / frames on top") {
  RenderOptions o;
  o.frames = 8;
  o.turns = 0.5;
  CHECK(FrameAngle(o, 0) == 0.0);
  CHECK(FrameAngle(o, 4) == doctest::Approx(kPi / 2).epsilon(1e-15));
  o.start_degrees = 90.0;
  CHECK(FrameAngle(o, 0) == doctest::Approx(kPi / 2).epsilon(1e-15));
  CHECK(FrameAngle(o, 4) == doctest::Approx(kPi).epsilon(1e-15));
  o.start_degrees = -30.0;
  CHECK(FrameAngle(o, 8) == doctest::Approx(kPi - kPi / 6).epsilon(1e-15));
}

}  // TEST_SUITE

}  // namespace prt
