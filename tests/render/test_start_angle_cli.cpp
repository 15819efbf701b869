// render --start-angle: the light's turn at frame 0, so a sequence can start where prt view left
// it. (FrameAngle in-process: test_start_angle.cpp.)
#include <doctest/doctest.h>

#include "io/png_io.h"
#include "render/render_frames.h"
#include "tests/test_process.h"

namespace prt {

TEST_SUITE("render") {
TEST_CASE("render --start-angle 135 draws as frame 0 what --frames 8 draws as frame 3") {
  const std::string dir = test::ScratchDir("start_angle");
  const std::string scene = "render --mesh " + test::Q(test::WriteSmallScene(dir)) +
                            " --transport unshadowed --size 48x36 --exposure 0 --quiet --axis 0.2,1,0.1";
  REQUIRE(test::RunPrt(scene + " --frames 8 --out " + test::Q(dir + "/eight")).exit_code == 0);
  REQUIRE(test::RunPrt(scene + " --frames 1 --start-angle 135 --out " + test::Q(dir + "/one")).exit_code == 0);
  REQUIRE(test::RunPrt(scene + " --frames 2 --turns 0.25 --start-angle -225 --out " + test::Q(dir + "/two")).exit_code == 0);
  const Image8 third = ReadPng(test::FramePath(dir + "/eight", 3, 8));
  CHECK(ReadPng(test::FramePath(dir + "/one", 0, 1)).rgb == third.rgb);
  CHECK(ReadPng(test::FramePath(dir + "/two", 0, 2)).rgb == third.rgb);  // -225 degrees is 135
  CHECK(ReadPng(test::FramePath(dir + "/eight", 0, 8)).rgb != third.rgb);
  const test::RunResult bad = test::RunPrt(scene + " --start-angle x --out " + test::Q(dir + "/bad"));
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("--start-angle") != std::string::npos);
}
}

}  // namespace prt
