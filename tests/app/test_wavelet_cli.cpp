// --basis wavelet from the command line: what is refused and why, the run summary, and a
// turning light that matches the environment turned beforehand.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "core/constants.h"
#include "env/equirect.h"
#include "io/hdr_writer.h"
#include "io/png_io.h"
#include "core/atomic_file.h"
#include "sh/rotation.h"
#include "tests/test_process.h"

using namespace prt;
using namespace prt::test;

namespace {

/// The sample scene's knot on its one-quad ground, split for shadows, as `sample-files` writes it.
std::string SampleScene(const std::string& dir) {
  const RunResult r = RunPrt("sample-files --quiet --out " + Q(dir));
  REQUIRE(r.exit_code == 0);
  return dir;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("wavelet cli: precompute, glossy materials and the transport view refuse --basis wavelet") {
    const std::string dir = ScratchDir("wavelet_refusals");
    RunResult r = RunPrt("precompute " + QuickScene() + " --basis wavelet --out " + Q(dir + "/p"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("course's SH files") != std::string::npos);
    CHECK(!std::filesystem::exists(dir + "/p/light.txt"));
    r = RunPrt(QuickRender(dir + "/g", 1) + " --basis wavelet --material phong:10,0.1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("glossy") != std::string::npos);
    r = RunPrt(QuickRender(dir + "/t", 1) + " --basis wavelet --view transport:1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--view transport") != std::string::npos);
    r = RunPrt(QuickRender(dir + "/c", 1) + " --basis wavelet --cube-size 48");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("power of two") != std::string::npos);
    r = RunPrt(QuickRender(dir + "/s", 1) + " --wavelet-terms 10");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--basis wavelet only") != std::string::npos);
  }

  TEST_CASE("wavelet cli: each of the wavelet's own options is refused with --basis sh") {
    // A table row whose options list lost one would let it pass silently with SH.
    const std::string dir = ScratchDir("wavelet_own_options");
    for (const std::string option : {"--cube-size 16", "--wavelet-terms 10", "--light-terms 8"}) {
      CAPTURE(option);
      const RunResult r = RunPrt(QuickRender(dir + "/o", 1) + " --basis sh " + option);
      CHECK(r.exit_code == 2);
      const std::string name = option.substr(0, option.find(' '));
      CHECK(r.err.find(name + ": applies to --basis wavelet only") != std::string::npos);
    }
    CHECK(!std::filesystem::exists(FramePath(dir + "/o", 0, 1)));
  }

  TEST_CASE("wavelet cli: --light-terms reaches the frames' light") {
    // The built-in sky kept to its 6 most important of 384 coefficients (--light-terms 6) against
    // the whole sky (0): the vertices' radiance must differ, or the option never reached the
    // frames, and so must the run summary's truncation cost. (A furnace would not do: its light
    // is the six faces' scaling coefficients alone.)
    const std::string dir = ScratchDir("wavelet_light_terms");
    auto radiance = [&](const std::string& terms) {
      const std::string file = dir + "/radiance_" + terms + ".txt";
      const RunResult r = RunPrt("render --mesh " + Q(Fixture("obj/tetra_no_normals.obj")) +
                                 " --env sky --transport unshadowed --size 16x12 --frames 1 --out " +
                                 Q(dir + "/out_" + terms) + " --basis wavelet --cube-size 8 --wavelet-terms 12" +
                                 " --light-terms " + terms + " --vertex-radiance " + Q(file));
      REQUIRE(r.exit_code == 0);
      // The run summary's truncation cost, in percent: "... differs from their unkept transport's by X% RMS".
      const std::string cue = "unkept transport's by ";
      const std::size_t at = r.err.find(cue);
      REQUIRE(at != std::string::npos);
      return std::make_pair(ReadFile(file), std::stod(r.err.substr(at + cue.size())));
    };
    const auto [few, few_cost] = radiance("6");
    const auto [all, all_cost] = radiance("0");
    CHECK(!few.empty());
    CHECK(few != all);
    // The summary's truncation cost is measured under the light the frames use. Each vertex keeps
    // its SH base and 12 wavelet coefficients, the 6 faces' means first: the whole sky sees the
    // lost details (measured 1.7 %), a sky kept to its 6 most important coefficients (here its
    // faces' means) almost none of them.
    CHECK(all_cost > 0.5);
    CHECK(few_cost < 0.01 * all_cost);
  }

  TEST_CASE("wavelet cli: the run summary says the cube, the terms kept, the bytes and the truncation's cost") {
    const std::string dir = ScratchDir("wavelet_summary");
    SampleScene(dir);
    const std::string directions = " --samples 64 --hidden-samples 16";
    const RunResult r = RunPrt("render --mesh " + Q(dir + "/scene.obj") + " --transport interreflection" + directions +
                               " --basis wavelet --cube-size 16 --wavelet-terms 64 --light-terms 128 --size 32x24 "
                               "--frames 2 --out " +
                               Q(dir + "/out"));
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("in Haar wavelets on a cube of 6 x 16^2 texels") != std::string::npos);
    CHECK(r.err.find("its smooth part in SH to lmax 4 (25 floats a vertex)") != std::string::npos);
    CHECK(r.err.find("most important of 1536 wavelet coefficients") != std::string::npos);
    CHECK(r.err.find("bytes a vertex") != std::string::npos);
    CHECK(r.err.find("wavelet truncation: frame 0's direct light at 64 sample vertices") != std::string::npos);
    CHECK(r.err.find("kept to its 128 most important") != std::string::npos);
    // Without --lmax the wavelets' bounces take lmax 4, and the summary says why.
    CHECK(r.err.find("bounced light: in SH at lmax 4") != std::string::npos);
    CHECK(r.err.find("\nbounce lmax: lmax 4 chosen for wavelet bounces") != std::string::npos);
    CHECK(r.err.find("\nbounces: ") != std::string::npos);  // the bounces' own line, each bounce's share
    CHECK(r.err.find(" of the direct energy; ") != std::string::npos);
    CHECK(r.err.find("ringing") == std::string::npos);
    CHECK(std::filesystem::exists(FramePath(dir + "/out", 1, 2)));
    CHECK(std::filesystem::exists(dir + "/out/wavelet.cache"));  // its own cache (tests/wavelet/test_wavelet_cache.cpp)
    CHECK(!std::filesystem::exists(dir + "/out/transport.cache"));
  }

  TEST_CASE("wavelet cli: a given --lmax sets the bounces' bands; SH keeps its own default") {
    const std::string dir = ScratchDir("wavelet_bounce_lmax");
    const std::string scene = "render --mesh " + Q(Fixture("obj/tetra_no_normals.obj")) +
                              " --env sky --transport interreflection --samples 64 --size 16x12 --frames 1 --cube-size 8 ";
    const RunResult given = RunPrt(scene + "--basis wavelet --lmax 3 --out " + Q(dir + "/given"));
    REQUIRE(given.exit_code == 0);
    CHECK(given.err.find("bounced light: in SH at lmax 3") != std::string::npos);
    CHECK(given.err.find("chosen for wavelet bounces") == std::string::npos);
    const std::string sh_scene = "render --mesh " + Q(Fixture("obj/tetra_no_normals.obj")) +
                                 " --env sky --transport interreflection --samples 64 --size 16x12 --frames 1 ";
    const RunResult sh = RunPrt(sh_scene + "--out " + Q(dir + "/sh"));
    REQUIRE(sh.exit_code == 0);
    CHECK(sh.err.find("lmax 2") != std::string::npos);
    CHECK(sh.err.find("chosen for wavelet bounces") == std::string::npos);
  }

  TEST_CASE("wavelet cli: frame 1 of 4 is frame 0 under the sky turned beforehand") {
    // An equirect sky turned a quarter about +Y is its columns shifted by a quarter: frame 1 of
    // a 4-frame turn must match frame 0 of the pre-turned file. A light turned the wrong way
    // puts the sun's shadow on the other side.
    const std::string dir = ScratchDir("wavelet_turn");
    SampleScene(dir);
    const auto sky = LoadEquirect(dir + "/sky.hdr");
    const glm::dmat3 quarter = AxisAngle({0, 1, 0}, kPi / 2);
    const ImageF turned = EquirectImage([&](const glm::dvec3& d) { return sky->Radiance(glm::transpose(quarter) * d); }, 1024, 512);
    WriteFileAtomic(dir + "/turned.hdr", EncodeHdr(turned));
    const ImageF wrong = EquirectImage([&](const glm::dvec3& d) { return sky->Radiance(quarter * d); }, 1024, 512);
    WriteFileAtomic(dir + "/wrong.hdr", EncodeHdr(wrong));
    const std::string common = " --mesh " + Q(dir + "/scene.obj") + " --max-edge 4% --basis wavelet --cube-size 16"
                               " --size 96x72 --exposure -1 --ssaa 1 ";
    REQUIRE(RunPrt("render" + common + "--env " + Q(dir + "/sky.hdr") + " --frames 4 --out " + Q(dir + "/a")).exit_code == 0);
    REQUIRE(RunPrt("render" + common + "--env " + Q(dir + "/turned.hdr") + " --frames 1 --out " + Q(dir + "/b")).exit_code == 0);
    REQUIRE(RunPrt("render" + common + "--env " + Q(dir + "/wrong.hdr") + " --frames 1 --out " + Q(dir + "/c")).exit_code == 0);
    const Image8 frame1 = ReadPng(FramePath(dir + "/a", 1, 4));
    const auto mean_levels = [&frame1](const Image8& other) {
      double sum = 0.0;
      for (std::size_t i = 0; i < frame1.rgb.size(); ++i) sum += std::abs(int(frame1.rgb[i]) - int(other.rgb[i]));
      return sum / double(frame1.rgb.size());
    };
    const double same = mean_levels(ReadPng(FramePath(dir + "/b", 0, 1)));
    const double opposite = mean_levels(ReadPng(FramePath(dir + "/c", 0, 1)));
    MESSAGE("frame 1 of 4 against the pre-turned sky: " << same << " levels (mean); against the sky turned the other way: "
                                                         << opposite);
    // The bound: half a level on average (the two lights differ by the equirect's
    // bilinear lookups at turned points).
    constexpr double kHalfLevel = 0.5;
    CHECK(same < kHalfLevel);
    CHECK(opposite > 2 * kHalfLevel);
  }
}
