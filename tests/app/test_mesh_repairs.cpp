// Meshes from elsewhere, through the binary: an inside-out closed mesh (clockwise winding without
// normals, or inward normals from the file) renders as its right-way-out twin and the summary
// says what was repaired; an open mesh whose normals disagree with its winding is warned about;
// --max-edge splits a one-quad floor so that it shows a contact shadow; lines of an OBJ that are
// not understood are counted on the summary; index errors quote the index as written.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/atomic_file.h"
#include "core/image.h"
#include "geometry/mesh.h"
#include "geometry/procedural.h"
#include "io/obj_writer.h"
#include "io/png_io.h"
#include "raster/image_diff.h"
#include "tests/test_process.h"

namespace prt {
namespace {

using test::Q;

/// `mesh` with every triangle's winding reversed (clockwise seen from outside).
Mesh Reversed(Mesh mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

/// `mesh` with every normal negated (pointing inward).
Mesh Inward(Mesh mesh) {
  for (auto& n : mesh.normals) n = -n;
  return mesh;
}

enum class Normals { kNone, kWritten };

/// Writes `mesh` to `path` (an .obj, its .mtl beside it): with its normals as prt writes OBJ
/// files (io/obj_writer.h), or positions and faces only (the loader then computes normals from
/// the winding).
void WriteObj(const std::string& path, const Mesh& mesh, Normals normals) {
  if (normals == Normals::kWritten) {
    const std::string mtl = std::filesystem::path(path).stem().string() + ".mtl";
    WriteFileAtomic(path, FormatObj({{"part", mesh}}, mtl));
    WriteFileAtomic(std::filesystem::path(path).replace_filename(mtl).string(), FormatMtl({{"part", mesh}}));
    return;
  }
  std::string text;
  char line[128];
  for (const auto& p : mesh.positions) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
    text += line;
  }
  for (const auto& t : mesh.triangles) {
    std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    text += line;
  }
  WriteFileAtomic(path, text);
}

/// A sphere of radius 1 under the furnace, seen head-on on black, untouched by tone mapping
/// (srgb at exposure 0): every covered pixel is the albedo 0.8 in sRGB, 231, when the sphere
/// faces outward, and black when its inside faces the light.
std::string SphereFrame(const std::string& mesh, const std::string& out) {
  return "render --mesh " + Q(mesh) + " --env furnace --transport shadowed --samples 64 --background black " +
         "--tonemap srgb --exposure 0 --ssaa 1 --size 64x64 --frames 1 --eye 0,0,4 --target 0,0,0 --out " + Q(out);
}

/// The pixel at the image centre, which the sphere covers.
int CentreRed(const Image8& image) {
  return image.rgb[3 * (static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2)];
}

// sRGB of 0.8 is 231.1; shading interpolated between vertices of a 32-segment sphere and the
// transport's sampling error (64 directions, closed form where unoccluded) keep it within 2.
constexpr int kAlbedoSrgb = 231;
constexpr int kShadingSlack = 2;

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("mesh repairs: an inside-out sphere renders like the right-way-out one, and says so") {
    const std::string dir = test::ScratchDir("inside_out");
    const Mesh sphere = MakeSphere(32);
    WriteObj(dir + "/good.obj", sphere, Normals::kNone);
    WriteObj(dir + "/clockwise.obj", Reversed(sphere), Normals::kNone);
    WriteObj(dir + "/inward_normals.obj", Inward(sphere), Normals::kWritten);
    WriteObj(dir + "/both.obj", Reversed(Inward(sphere)), Normals::kWritten);
    const auto good = test::RunPrt(SphereFrame(dir + "/good.obj", dir + "/good"));
    REQUIRE(good.exit_code == 0);
    CHECK(good.err.find("orientation:") == std::string::npos);
    const Image8 expected = ReadPng(dir + "/good/frame_0000.png");
    CHECK(std::abs(CentreRed(expected) - kAlbedoSrgb) <= kShadingSlack);

    const struct {
      const char* name;
      const char* says;
    } cases[] = {
        {"clockwise", "orientation: reversed the winding of"},
        {"inward_normals", "orientation: negated 482 normals from the file that pointed into their closed part"},
        {"both", "orientation: reversed the winding of"},
    };
    for (const auto& c : cases) {
      CAPTURE(c.name);
      const std::string out = dir + "/" + c.name;
      const auto r = test::RunPrt(SphereFrame(dir + "/" + c.name + ".obj", out));
      CAPTURE(r.err);
      REQUIRE(r.exit_code == 0);
      CHECK(r.err.find(c.says) != std::string::npos);
      CHECK(r.err.find("see almost no sky") == std::string::npos);
      const Image8 image = ReadPng(out + "/frame_0000.png");
      CHECK(std::abs(CentreRed(image) - kAlbedoSrgb) <= kShadingSlack);
      CHECK(CompareImages(expected, image).max_abs <= kShadingSlack);
    }
  }

  TEST_CASE("mesh repairs: an open mesh whose normals oppose its winding is warned about, not changed") {
    const std::string dir = test::ScratchDir("open_inward");
    WriteObj(dir + "/floor.obj", Inward(MakePlane(2.0f, 4)), Normals::kWritten);
    const auto r = test::RunPrt("render --mesh " + Q(dir + "/floor.obj") +
                                " --env furnace --transport unshadowed --frames 1 --size 32x24 --out " + Q(dir + "/out"));
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("prt: warning: " + dir + "/floor.obj: the file's normals point against the triangle winding on 100% "
                      "of the area") != std::string::npos);
    CHECK(r.err.find("orientation:") == std::string::npos);
  }

  TEST_CASE("mesh repairs: --max-edge splits a one-quad floor so that it shows the contact shadow") {
    // A red block on a white floor made of one quad, under the furnace. Without splitting, the
    // floor's only vertices are its four corners, equally occluded: the floor is one flat grey.
    // Split, its vertices near the block see less sky and the floor darkens around the block.
    const std::string dir = test::ScratchDir("max_edge");
    const ObjPart floor{"floor", MakePlane(4.0f, 1), glm::vec3(0.9f)};
    const ObjPart block{"block", MakeBox(glm::vec3(-0.4f, 0.0f, -0.4f), glm::vec3(0.4f, 0.8f, 0.4f)),
                        glm::vec3(0.9f, 0.05f, 0.05f)};
    WriteFileAtomic(dir + "/scene.obj", FormatObj({floor, block}, "scene.mtl"));
    WriteFileAtomic(dir + "/scene.mtl", FormatMtl({floor, block}));
    const std::string base = "render --mesh " + Q(dir + "/scene.obj") +
                             " --env furnace --samples 256 --background black --tonemap srgb --exposure 0 --ssaa 1 " +
                             "--size 96x72 --frames 1 --eye 0,4,3 --target 0,0,0";
    const auto whole = test::RunPrt(base + " --out " + Q(dir + "/whole"));
    const auto split = test::RunPrt(base + " --max-edge 2% --out " + Q(dir + "/split"));
    CAPTURE(split.err);
    REQUIRE(whole.exit_code == 0);
    REQUIRE(split.exit_code == 0);
    CHECK(whole.err.find("split:") == std::string::npos);
    CHECK(split.err.find("split: no edge longer than") != std::string::npos);

    // The darkest and brightest floor pixel: the floor is grey (R = G = B), the block red.
    const auto floor_range = [](const Image8& image) {
      int lo = 255, hi = 0;
      for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        const int r = image.rgb[i], g = image.rgb[i + 1];
        if (r == 0 || r - g > 8) continue;  // background or block
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
      return std::pair<int, int>(lo, hi);
    };
    const auto [whole_lo, whole_hi] = floor_range(ReadPng(dir + "/whole/frame_0000.png"));
    const auto [split_lo, split_hi] = floor_range(ReadPng(dir + "/split/frame_0000.png"));
    CAPTURE(whole_lo);
    CAPTURE(whole_hi);
    CAPTURE(split_lo);
    CAPTURE(split_hi);
    // Measured: one flat 243 whole; 183..243 split.
    CHECK(whole_hi - whole_lo <= 1);     // one flat grey: four equally occluded corners
    CHECK(split_lo + 40 < whole_lo);     // a real shadow where the block meets the floor
    CHECK(split_hi + 2 >= whole_lo);     // far from the block the floor is as bright as before
  }

  TEST_CASE("mesh repairs: lines not understood are counted on the summary, index errors quote the index") {
    const auto garbage = test::RunPrt("render --mesh " + Q(test::Fixture("obj/garbage_lines.obj")) +
                                      " --env furnace --transport unshadowed --frames 1 --size 32x24 --out " +
                                      Q(test::ScratchDir("garbage_lines")));
    CAPTURE(garbage.err);
    CHECK(garbage.exit_code == 0);
    CHECK(garbage.err.find("3 lines not understood, skipped (first: line 5: 'hello world')") != std::string::npos);
    const auto index = test::RunPrt("render --mesh " + Q(test::Fixture("obj/index_written.obj")) + " --out " +
                                    Q(test::ScratchDir("index_written")));
    CAPTURE(index.err);
    CHECK(index.exit_code == 1);
    CHECK(index.err.find("line 9: face uses vertex -7, out of bounds") != std::string::npos);
  }
}

}  // namespace prt
