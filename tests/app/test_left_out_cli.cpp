// What a run does not need is left out, and what it writes does not depend on what it left out:
// the light view computes no transport yet draws the frames of a run that computes one, and
// --vertex-radiance computes every vertex it writes as one the camera sees. For both bases.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "core/atomic_file.h"
#include "tests/test_process.h"

using namespace prt;
using namespace prt::test;

namespace {

/// Each basis with options of its own away from their defaults, which the light its frames keep
/// depends on: the SH bands (--lmax), the wavelet cube and its kept terms.
const std::pair<const char*, const char*> kBases[] = {
    {"sh", "--basis sh --lmax 4"},
    {"wavelet", "--basis wavelet --cube-size 8 --wavelet-terms 24 --light-terms 20"},
};

/// The floor and wall of test_support under the built-in sky, shadowed: a transport worth leaving
/// out, and vertices that fewer rays change.
std::string Scene(const std::string& dir) {
  return "render --mesh " + Q(dir + "/scene.obj") + " --env sky --transport shadowed --size 48x36 --exposure 0 ";
}

std::string RunSummary(const std::string& arguments) {
  const RunResult r = RunPrt(arguments);
  CAPTURE(arguments);
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
  return r.err;
}

bool Says(const std::string& summary, const std::string& words) { return summary.find(words) != std::string::npos; }

std::string Frames(const std::string& out, int count) {
  std::string bytes;
  for (int i = 0; i < count; ++i) bytes += ReadFile(FramePath(out, i, count));
  return bytes;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("light view: no transport is computed, and the frames are those of a run that computes one") {
    const std::string dir = ScratchDir("left_out_light_view");
    WriteFloorAndWall(dir, glm::vec3(0.8f), glm::vec3(0.9f, 0.2f, 0.1f));
    for (const auto& [name, options] : kBases) {
      CAPTURE(name);
      const std::string run = Scene(dir) + "--samples 64 --frames 3 --view light " + options;
      const std::string light = dir + "/" + name + "_light", both = dir + "/" + name + "_both";
      const std::string alone = RunSummary(run + " --out " + Q(light));
      CHECK(Says(alone, "transport: none computed (--view light draws the light as the basis keeps it"));
      CHECK(!Says(alone, "transport: shadowed"));
      // Nothing computed, so nothing cached.
      CHECK(!std::filesystem::exists(light + "/transport.cache"));
      CHECK(!std::filesystem::exists(light + "/wavelet.cache"));
      // --vertex-radiance needs the mesh's radiance: then the transport is computed, and the frames
      // of the light view must not change with it.
      const std::string computed = RunSummary(run + " --out " + Q(both) + " --vertex-radiance " + Q(dir + "/r.txt"));
      CHECK(!Says(computed, "none computed"));
      CHECK(Says(computed, "transport: shadowed"));
      CHECK(Frames(light, 3) == Frames(both, 3));
    }
  }

  TEST_CASE("--vertex-radiance: the vertices no frame shows are written as seen ones") {
    // A narrow view of the floor hides most vertices; with --hidden-samples below --samples they
    // would take fewer rays, and the file would depend on the camera. It must equal the file of a
    // run in which every vertex is a seen one (--hidden-samples = --samples).
    const std::string dir = ScratchDir("left_out_vertex_radiance");
    WriteFloorAndWall(dir, glm::vec3(0.8f), glm::vec3(0.9f, 0.2f, 0.1f));
    const std::string camera = "--eye 0.6,1.2,0.6 --target 0.6,0,0.6 --fov 20 --frames 1 --samples 64 ";
    for (const auto& [name, options] : kBases) {
      CAPTURE(name);
      const std::string run = Scene(dir) + camera + options;
      const std::string few = dir + "/" + name + "_few.txt", all = dir + "/" + name + "_all.txt";
      const std::string summary =
          RunSummary(run + " --hidden-samples 4 --vertex-radiance " + Q(few) + " --out " + Q(dir + "/" + name + "_a"));
      CHECK(Says(summary, "vertex radiance: every vertex computed as one the camera sees (--hidden-samples 4 not used)"));
      RunSummary(run + " --hidden-samples 64 --vertex-radiance " + Q(all) + " --out " + Q(dir + "/" + name + "_b"));
      CHECK(!ReadFile(few).empty());
      CHECK(ReadFile(few) == ReadFile(all));
      // Without the file the camera's hidden vertices do take fewer rays: the comparison above can fail.
      const std::string frames_only = RunSummary(run + " --hidden-samples 4 --out " + Q(dir + "/" + name + "_c"));
      CHECK((Says(frames_only, " it does not") || Says(frames_only, "vertices no frame shows")));
    }
  }
}
