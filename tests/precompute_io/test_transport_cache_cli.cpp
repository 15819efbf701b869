// The transport cache through the binary: a render reuses precompute's transport, and a run from
// the cache gives the very bytes of a run without it, whatever input changed. (The key, one input
// at a time, in the library: test_transport_cache.cpp.)
#include <doctest/doctest.h>

#include <map>
#include <string>

#include "core/atomic_file.h"
#include "geometry/procedural.h"
#include "io/obj_writer.h"
#include "io/png_io.h"
#include "raster/image_diff.h"
#include "tests/precompute_io/sphere_on_floor.h"
#include "tests/test_process.h"

namespace prt {

using test::Q;

TEST_SUITE("precompute_io") {
  TEST_CASE("cache: a render reuses precompute's transport, whose every vertex took what the camera's take") {
    // precompute has no camera: every vertex takes --samples. A render of the same options
    // needs --samples only where the camera looks and fewer elsewhere, which that transport
    // exceeds everywhere: it is taken as it is, and the render then equals one whose hidden
    // vertices take --samples too.
    const std::string dir = test::ScratchDir("cache_precompute");
    ObjPart part{"part", test::SphereOnFloor(1.0f), glm::vec3(0.7f, 0.5f, 0.3f)};
    WriteFileAtomic(dir + "/scene.obj", FormatObj({part}, "scene.mtl"));
    WriteFileAtomic(dir + "/scene.mtl", FormatMtl({part}));
    const std::string scene = " --mesh " + Q(dir + "/scene.obj") + " --env sky --transport shadowed --samples 256";
    const std::string render = " --exposure 0 --size 48x36 --frames 1 --eye 3,3,5 --target 0,0.8,0";
    REQUIRE(test::RunPrt("precompute" + scene + " --out " + Q(dir + "/p")).exit_code == 0);
    const auto reused = test::RunPrt("render" + scene + render + " --hidden-samples 32 --out " + Q(dir + "/p"));
    REQUIRE(reused.exit_code == 0);
    CHECK(reused.err.find("transport: taken from the cache") != std::string::npos);
    CHECK(reused.err.find("256 directions at every vertex") != std::string::npos);
    const auto every = test::RunPrt("render" + scene + render + " --hidden-samples 256 --cache none --out " + Q(dir + "/e"));
    const auto split = test::RunPrt("render" + scene + render + " --hidden-samples 32 --cache none --out " + Q(dir + "/s"));
    REQUIRE(every.exit_code == 0);
    REQUIRE(split.exit_code == 0);
    CHECK(split.err.find("256 fibonacci directions for each of the") != std::string::npos);
    const Image8 from_cache = ReadPng(dir + "/p/frame_0000.png");
    CHECK(CompareImages(from_cache, ReadPng(dir + "/e/frame_0000.png")).differing_pixels == 0);
    // A cache of a split transport is not taken for one at every vertex.
    REQUIRE(test::RunPrt("render" + scene + render + " --hidden-samples 32 --out " + Q(dir + "/s2")).exit_code == 0);
    const auto other = test::RunPrt("render" + scene + render + " --hidden-samples 256 --out " + Q(dir + "/s2"));
    CHECK(other.err.find("taken from the cache") == std::string::npos);
  }

  TEST_CASE("cache: a render from the cache is byte for byte a render without it, whatever input changed") {
    const std::string dir = test::ScratchDir("cache_inputs");
    for (const auto& [name, radius] : {std::pair{"scene.obj", 1.0f}, std::pair{"moved.obj", 1.05f}}) {
      ObjPart part{"part", test::SphereOnFloor(radius), glm::vec3(0.7f, 0.5f, 0.3f)};
      WriteFileAtomic(dir + "/" + name, FormatObj({part}, "scene.mtl"));
      WriteFileAtomic(dir + "/scene.mtl", FormatMtl({part}));
    }
    // Options by name, so that a change replaces the base value (an option given twice is an error).
    using Options = std::map<std::string, std::string>;
    const Options base = {{"--mesh", Q(dir + "/scene.obj")}, {"--transport", "interreflection"},
                          {"--samples", "64"}, {"--hidden-samples", "16"}, {"--bounces", "1"}, {"--seed", "1"}, {"--direction-sets", "8"},
                          {"--env", "sky"}, {"--exposure", "0"}, {"--ssaa", "1"}, {"--size", "48x36"},
                          {"--frames", "1"}, {"--eye", "3,3,5"}, {"--target", "0,0.8,0"}, {"--lmax", "2"}};
    const auto line = [](const Options& options) {
      std::string text;
      for (const auto& [name, value] : options) text += " " + name + " " + value;
      return text;
    };
    const std::string cache = dir + "/transport.cache";
    const auto frame = [&](const Options& options, const std::string& cache_option) {
      const std::string out = dir + "/out";
      const auto r = test::RunPrt("render" + line(options) + " --cache " + cache_option + " --out " + Q(out));
      CAPTURE(line(options));
      CAPTURE(r.err);
      REQUIRE(r.exit_code == 0);
      return ReadPng(out + "/frame_0000.png");
    };
    // The cache is used when nothing changed.
    frame(base, Q(cache));
    const auto again = test::RunPrt("render" + line(base) + " --cache " + Q(cache) + " --out " + Q(dir + "/again"));
    CHECK(again.exit_code == 0);
    CHECK(again.err.find("transport: taken from the cache") != std::string::npos);
    const Options changes = {
        {"--mesh", Q(dir + "/moved.obj")}, {"--albedo", "0.2,0.5,0.9"}, {"--transport", "shadowed"},
        {"--lmax", "3"}, {"--samples", "96"}, {"--sampler", "stratified"}, {"--bounces", "2"}, {"--seed", "2"},
        {"--direction-sets", "3"}, {"--hidden-samples", "32"},
        // another camera sees other vertices: they take the 64 directions, the rest 16
        {"--eye", "-3,2,-5"},
    };
    const Image8 base_fresh = frame(base, "none");
    for (const auto& [option, value] : changes) {
      Options changed = base;
      changed[option] = value;
      frame(base, Q(cache));  // the cache holds the base transport again
      const Image8 cached = frame(changed, Q(cache));
      const Image8 fresh = frame(changed, "none");
      CAPTURE(option);
      CHECK(CompareImages(cached, fresh).differing_pixels == 0);
      // and the change matters at all, so the comparison above can fail
      CHECK(CompareImages(fresh, base_fresh).differing_pixels > 0);
    }
  }
}

}  // namespace prt
