// A basis is a folder and a line of the list (docs/ARCHITECTURE.md, "Adding a basis"): this
// program is built with src/bases/list.cpp plus one line naming tests/basis/stub_basis/ and
// nothing else changed (tests/basis/CMakeLists.txt), and every command takes the stub as it takes
// the bases of src/: its name, its help, its own option, its refusals and its frames.
#include <doctest/doctest.h>

#include <filesystem>

#include "app/commands.h"
#include "app/scene_options.h"
#include "bases/list.h"
#include "io/png_io.h"
#include "tests/test_support.h"

namespace prt {
namespace {

/// Frame 0 of `prt render` on the demo scene with `extra` options, under a white furnace.
Image8 StubFrame(const std::string& dir, const std::vector<std::string>& extra) {
  std::vector<std::string> tokens = {"--env",      "furnace:1", "--size",     "48x36", "--frames", "1",     "--ssaa",
                                     "1",          "--exposure", "0",         "--background", "black", "--quiet",
                                     "--out",      dir};
  tokens.insert(tokens.end(), extra.begin(), extra.end());
  REQUIRE(RunRender(tokens) == 0);
  return ReadPng(dir + "/frame_0000.png");
}

}  // namespace

TEST_SUITE("basis") {
  TEST_CASE("stub basis: a third basis is listed, documented and read by every command without their change") {
    CHECK(BasisNames() == std::vector<std::string>{"sh", "wavelet", "stub"});
    REQUIRE(FindBasis("stub") != nullptr);
    std::string help;  // the help with its wrapping undone
    for (const char c : FormatHelp(RenderSpec()))
      if (!(c == ' ' || c == '\n') || help.empty() || help.back() != ' ') help += c == '\n' ? ' ' : c;
    CHECK(help.find("sh | wavelet | stub: the basis of the transport.") != std::string::npos);
    CHECK(help.find("stub gives every vertex the light's mean") != std::string::npos);
    CHECK(help.find("--stub-gain G") != std::string::npos);

    Args args("render", {"--basis", "stub", "--stub-gain", "2"}, RenderSpec());
    const SceneOptions o = ReadSceneOptions(args);
    CHECK(o.basis == FindBasis("stub"));
    // Its own option with another basis, another basis's with it: refused by the list's rule.
    CHECK(test::ErrorMessage([] {
            Args a("render", {"--stub-gain", "2"}, RenderSpec());
            ReadSceneOptions(a);
          }) == "--stub-gain: applies to --basis stub only");
    CHECK(test::ErrorMessage([] {
            Args a("render", {"--basis", "stub", "--cube-size", "16"}, RenderSpec());
            ReadSceneOptions(a);
          }) == "--cube-size: applies to --basis wavelet only");
    CHECK(test::ErrorMessage([] {
            Args a("render", {"--basis", "stub", "--stub-gain", "11"}, RenderSpec());
            ReadSceneOptions(a);
          }).find("--stub-gain") == 0);
  }

  TEST_CASE("stub basis: its traits refuse what it cannot do, as the bases of src/ are refused") {
    const std::string dir = test::ScratchDir("stub_refusals");
    CHECK(test::ErrorMessage([&] { RunPrecompute({"--basis", "stub", "--out", dir}); })
              .find("--basis stub: precompute writes the course's SH files") == 0);
    CHECK(test::ErrorMessage([&] { RunRender({"--basis", "stub", "--material", "phong:20,0.1", "--out", dir}); })
              .find("--basis stub: glossy materials are not built in the stub basis") == 0);
    CHECK(test::ErrorMessage([&] { RunRender({"--basis", "stub", "--view", "transport:1", "--out", dir}); })
              .find("--view transport: shows one SH transfer coefficient per vertex; --basis stub has none") == 0);
  }

  TEST_CASE("stub basis: render draws its frame light, with its own option read") {
    const Image8 half = StubFrame(test::ScratchDir("stub_half"), {"--basis", "stub", "--stub-gain", "0.5"});
    const Image8 full = StubFrame(test::ScratchDir("stub_full"), {"--basis", "stub"});
    const Image8 sh = StubFrame(test::ScratchDir("stub_sh"), {"--transport", "unshadowed"});
    REQUIRE(half.width == full.width);
    REQUIRE(half.rgb.size() == full.rgb.size());
    int lit = 0, brighter = 0, flat_differs = 0;
    for (std::size_t i = 0; i < half.rgb.size(); ++i) {
      if (full.rgb[i] == 0) continue;
      ++lit;
      brighter += full.rgb[i] > half.rgb[i];
      flat_differs += full.rgb[i] != sh.rgb[i];
    }
    CHECK(lit > int(half.rgb.size() / 10));  // the mesh covers the frame's middle
    CHECK(brighter == lit);                     // --stub-gain reached the stub's frame light
    // The furnace's unshadowed SH frame is the same mean light with cosine-weighted transfer: the
    // stub's, which ignores the normals, is not that picture.
    CHECK(flat_differs > 0);
  }
}

}  // namespace prt
