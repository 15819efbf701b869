// The wavelet transport cache through the binary: a run from the cache draws the bytes of the run
// that wrote it, a linked cache is read and never replaced, the SH and wavelet caches stay side
// by side, a transport of every vertex serves a run that asks for the seen ones. (In the library:
// test_wavelet_cache.cpp.)
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "core/atomic_file.h"
#include "precompute_io/transport_cache.h"
#include "tests/test_process.h"
#include "tests/wavelet/synthetic_transport.h"
#include "wavelet/transport_cache.h"

namespace prt {
namespace {


/// The floor and wall of test_support under the built-in sky, the wavelets on a small cube:
/// shadows and coloured bounces in a run of a fraction of a second, `terms` kept a vertex.
/// `extra` options follow.
std::string WaveletRender(const std::string& dir, const std::string& out, const std::string& extra = "",
                          int terms = 24) {
  return "render --mesh " + test::Q(dir + "/scene.obj") +
         " --env sky --transport interreflection --samples 64 --basis wavelet --cube-size 8 --size 48x36 --frames 2"
         " --exposure 0 --wavelet-terms " + std::to_string(terms) + " --out " + test::Q(out) + " " + extra;
}

/// The bytes of both frames of a run into `out`.
std::string Frames(const std::string& out) {
  return ReadFile(test::FramePath(out, 0, 2)) + ReadFile(test::FramePath(out, 1, 2));
}

/// Runs prt with `arguments`, which must succeed; its run summary.
std::string RunSummary(const std::string& arguments) {
  const test::RunResult r = test::RunPrt(arguments);
  CAPTURE(arguments);
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
  return r.err;
}

bool Says(const std::string& summary, const std::string& words) { return summary.find(words) != std::string::npos; }

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("wavelet cache cli: a --cache that is a symbolic link is read but never replaced") {
    // The plan says read-only (app/pipeline.h PlanCache): a stale cache behind the link is
    // ignored and the transport recomputed, but the file the link names keeps its bytes and the
    // link stays a link.
    const std::string dir = test::ScratchDir("wavelet_cache_link");
    test::WriteFloorAndWall(dir, glm::vec3(0.8f), glm::vec3(0.9f, 0.2f, 0.1f));
    const std::string target = dir + "/target.cache", link = dir + "/link.cache";
    WriteWaveletCache(target, test::SyntheticWaveletTransport(), 7);  // made from other inputs
    const std::string before = ReadFile(target);
    std::filesystem::create_symlink(target, link);
    const std::string summary = RunSummary(WaveletRender(dir, dir + "/out", "--cache " + test::Q(link)));
    CHECK(Says(summary, "is a symbolic link"));
    CHECK(!Says(summary, "taken from the cache"));
    CHECK(std::filesystem::is_symlink(link));
    CHECK(ReadFile(target) == before);
  }

  TEST_CASE("wavelet cache cli: a second run takes the transport from the cache and draws the same bytes") {
    const std::string dir = test::ScratchDir("wavelet_cache_cli");
    test::WriteFloorAndWall(dir, glm::vec3(0.8f), glm::vec3(0.9f, 0.2f, 0.1f));
    const std::string out = dir + "/out", cache = out + "/wavelet.cache";
    const std::string first = RunSummary(WaveletRender(dir, out));
    CHECK(!Says(first, "taken from the cache"));
    CHECK(std::filesystem::exists(cache));
    CHECK(!std::filesystem::exists(out + "/transport.cache"));  // the SH basis's name is not taken
    const std::string frames = Frames(out), written = ReadFile(cache);

    const std::string second = RunSummary(WaveletRender(dir, out));
    CHECK(Says(second, "transport: taken from the cache " + cache + " (same mesh and options)"));
    CHECK(!Says(second, "jittered rays per texel"));  // nothing traced
    CHECK(Frames(out) == frames);
    CHECK(ReadFile(cache) == written);  // reused as it is, not rewritten

    // The light's kept terms are each frame's: the transport is reused.
    CHECK(Says(RunSummary(WaveletRender(dir, out, "--light-terms 16")), "taken from the cache"));

    // Other terms per vertex: recomputed, said, and rewritten; the frames change with them (so
    // the comparison above could fail).
    const std::string other = RunSummary(WaveletRender(dir, out, "", 32));
    CHECK(!Says(other, "taken from the cache"));
    CHECK(Says(other, "cache: " + cache + " ignored (made from other inputs), recomputed"));
    CHECK(Frames(out) != frames);
    CHECK(ReadFile(cache) != written);
    CHECK(Says(RunSummary(WaveletRender(dir, out, "", 32)), "taken from the cache"));

    // --cache none: neither read nor written.
    const std::string none = RunSummary(WaveletRender(dir, dir + "/none", "--cache none"));
    CHECK(!Says(none, "taken from the cache"));
    CHECK(!std::filesystem::exists(dir + "/none/wavelet.cache"));
  }

  TEST_CASE("wavelet cache cli: the SH and wavelet caches stay side by side, and each refuses the other's file") {
    const std::string dir = test::ScratchDir("wavelet_cache_sh");
    test::WriteFloorAndWall(dir, glm::vec3(0.8f), glm::vec3(0.9f, 0.2f, 0.1f));
    const std::string out = dir + "/out";
    // One folder, both bases in turn: neither run removes the other's cache, each reuses its own.
    const std::string sh = "render --mesh " + test::Q(dir + "/scene.obj") +
                           " --env sky --transport interreflection --samples 64 --size 48x36 --frames 2 --exposure 0"
                           " --out " + test::Q(out);
    RunSummary(sh);
    RunSummary(WaveletRender(dir, out));
    CHECK(std::filesystem::exists(out + "/transport.cache"));
    CHECK(std::filesystem::exists(out + "/wavelet.cache"));
    CHECK(Says(RunSummary(sh), "transport: taken from the cache " + out + "/transport.cache"));
    CHECK(std::filesystem::exists(out + "/wavelet.cache"));
    CHECK(Says(RunSummary(WaveletRender(dir, out)), "transport: taken from the cache " + out + "/wavelet.cache"));

    // One --cache file for both: each basis refuses the other's, says why, and replaces it.
    const std::string shared = dir + "/shared.cache";
    RunSummary(sh + " --cache " + test::Q(shared));
    CHECK(Says(RunSummary(WaveletRender(dir, out, "--cache " + test::Q(shared))),
               "cache: " + shared + " ignored (an SH transport cache (--basis sh), not a wavelet one), recomputed"));
    CHECK(StartsLikeWaveletCache(shared));
    CHECK(Says(RunSummary(sh + " --cache " + test::Q(shared)),
               "cache: " + shared + " ignored (a wavelet transport cache (--basis wavelet), not an SH one), recomputed"));
    CHECK(StartsLikeTransportCache(shared));
  }

  TEST_CASE("wavelet cache cli: a transport of every vertex serves a run that asks for the seen ones, not the reverse") {
    // --hidden-samples below --samples: the vertices no frame shows take one ray a texel. A cache
    // whose every vertex took the seen ones' rays holds more than that run needs and is taken;
    // one with the hidden vertices cut short is not taken for a run that needs them all.
    const std::string dir = test::ScratchDir("wavelet_cache_seen");
    test::WriteFloorAndWall(dir, glm::vec3(0.8f), glm::vec3(0.9f, 0.2f, 0.1f));
    const std::string every = dir + "/every", split = dir + "/split";
    RunSummary(WaveletRender(dir, every, "--hidden-samples 64"));
    const std::string frames = Frames(every);
    const std::string reused = RunSummary(WaveletRender(dir, every, "--hidden-samples 8"));
    CHECK(Says(reused, "taken from the cache " + every + "/wavelet.cache (same mesh and options, with 4 rays a texel at "
                       "every vertex, not only those the camera sees)"));
    CHECK(Frames(every) == frames);

    const std::string cut = RunSummary(WaveletRender(dir, split, "--hidden-samples 8"));
    CHECK(Says(cut, "vertices no frame shows"));  // the camera does hide some: the two transports differ
    CHECK(!Says(RunSummary(WaveletRender(dir, split, "--hidden-samples 64")), "taken from the cache"));
    CHECK(Frames(split) == frames);  // recomputed for every vertex: the first run's transport
  }
}

}  // namespace prt
