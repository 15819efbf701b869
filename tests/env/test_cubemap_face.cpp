// RefuseCubemapFace (env/cubemap.h): one face of a cubemap given where an image environment is
// expected is refused with "pass the folder"; every file that merely looks like one passes.
// LoadEnvironment refuses it too, so no caller can read a face as a stretched panorama.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "core/error.h"
#include "env/cube_faces.h"
#include "env/cubemap.h"
#include "env/load_environment.h"
#include "tests/env/env_test_util.h"
#include "tests/test_support.h"

using namespace prt;
namespace fs = std::filesystem;

namespace {

/// Writes dir/<name> as a grey width x height PNG; returns its path.
std::string WriteImage(const std::string& dir, const std::string& name, int width, int height) {
  return test::WriteGreyPng(dir + "/" + name, width, height);
}

/// Writes the six 4 x 4 faces of a cubemap folder `dir` as PNG files; returns `dir`.
std::string WriteCubeFolder(const std::string& dir) { return test::WritePngCube(dir, 4); }

/// The message RefuseCubemapFace throws for `path`, or "" when it passes.
std::string Refusal(const std::string& path) {
  return test::ErrorMessage([&] { RefuseCubemapFace(path); });
}

}  // namespace

TEST_SUITE("env") {
  TEST_CASE("RefuseCubemapFace: each face of a six-face folder is refused, naming the folder to pass") {
    const std::string dir = WriteCubeFolder(test::ScratchDir("cube_face") + "/Cathedral");
    for (const char* face : kFaceNames) {
      const std::string path = dir + "/" + face + ".png";
      CAPTURE(path);
      CHECK(Refusal(path) == path + ": is the " + face + " face of the cubemap in " + dir +
                                 " (expected the folder: --env " + dir + ")");
    }
    // The stem is compared in any case (a Windows export's POSX.png); catches a case-sensitive
    // compare.
    const std::string upper = WriteImage(dir, "POSX.png", 4, 4);
    CHECK(Refusal(upper).find("is the posx face of the cubemap in " + dir) != std::string::npos);
    // LoadEnvironment refuses it as well (the check stands before LoadEquirect): catches a check
    // made only by the command line's early input check.
    const std::string expected = "expected the folder: --env " + dir;
    CHECK_THROWS_WITH_AS(LoadEnvironment(dir + "/negy.png", CubeLayout::kStandard), doctest::Contains(expected.c_str()),
                         Error);
  }

  TEST_CASE("RefuseCubemapFace: files that only look like a face pass") {
    const std::string root = test::ScratchDir("cube_face_not");
    // A lone square posx.png: a panorama (or anything) named like a face, no siblings. Catches a
    // refusal by the name alone.
    CHECK(Refusal(WriteImage(root + "/lone", "posx.png", 4, 4)).empty());
    // A non-square posx beside its five siblings: an equirect that happens to sit there. Catches a
    // check that skips the square test.
    const std::string wide = WriteCubeFolder(root + "/wide");
    CHECK(Refusal(WriteImage(wide, "posx.png", 8, 4)).empty());
    // Four siblings only (negz missing): not a complete cubemap, so "pass the folder" would be
    // wrong advice. Catches a check that needs only some sibling.
    const std::string partial = WriteCubeFolder(root + "/partial");
    fs::remove(partial + "/negz.png");
    CHECK(Refusal(partial + "/posx.png").empty());
    // A sibling in a format the cubemap loader does not take (negz.bmp) is no sibling.
    fs::rename(partial + "/negy.png", partial + "/negy.bmp");
    WriteImage(partial, "negz.bmp", 4, 4);
    CHECK(Refusal(partial + "/posx.png").empty());
    // A name that only starts like a face.
    const std::string full = WriteCubeFolder(root + "/full");
    CHECK(Refusal(WriteImage(full, "posx_backup.png", 4, 4)).empty());
  }
}
