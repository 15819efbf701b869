// --start-angle: the light's turn at frame 0, so a sequence can start where prt view left it; and
// the frames' file names.
#include <doctest/doctest.h>

#include "core/constants.h"
#include "render/render_frames.h"

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


TEST_CASE("frame names: IsFrameName takes what FrameName gives, in any case only when asked") {
  for (int count : {1, 120, 10001, 1000000}) CHECK(IsFrameName(FrameName(count - 1, count)));
  CHECK(IsFrameName("frame_7.png"));
  CHECK_FALSE(IsFrameName("FRAME_0001.PNG"));
  CHECK(IsFrameName("FRAME_0001.PNG", true));
  CHECK(IsFrameName("Frame_0001.Png", true));
  for (const char* other : {"frame_.png", "frame_12a.png", "frame_0001.png.tmp", "xframe_0001.png", "frame_0001.jpg",
                            "frame0001.png", "frame_-1.png", ".png", ""}) {
    CAPTURE(other);
    CHECK_FALSE(IsFrameName(other));
    CHECK_FALSE(IsFrameName(other, true));
  }
}
}  // TEST_SUITE

}  // namespace prt
