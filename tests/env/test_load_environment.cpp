#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfRgbaFile.h>

#include "core/atomic_file.h"
#include "core/constants.h"
#include "core/error.h"
#include "env/load_environment.h"
#include "precompute/light.h"
#include "precompute_io/light_txt.h"
#include "sh/basis.h"
#include "sh/zonal.h"
#include "tests/env/env_test_util.h"
#include "tests/test_support.h"

using namespace prt;
namespace fs = std::filesystem;

namespace {

/// A scratch folder `name` with six PNG faces of `size`; `skip` names a face to leave out.
std::string MakeCubeFolder(const std::string& name, int size, const std::string& skip = "") {
  return test::WritePngCube(test::ScratchDir(name), size, skip);
}

/// Writes an EXR (half floats) with the given compression; `value(x, y)` gives every channel.
template <class F>
void WriteExr(const std::string& path, int w, int h, Imf::Compression compression, F value) {
  std::vector<Imf::Rgba> px(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = value(x, y);
      px[std::size_t(y) * w + x] = Imf::Rgba(v, v, v, 1.0f);
    }
  Imf::Header header(w, h);
  header.compression() = compression;
  Imf::RgbaOutputFile out(path.c_str(), header, Imf::WRITE_RGBA);
  out.setFrameBuffer(px.data(), 1, w);
  out.writePixels(h);
}

std::string ErrorOf(const std::string& spec) {
  return test::ErrorMessage([&] { LoadEnvironment(spec, CubeLayout::kStandard); });
}

}  // namespace

TEST_SUITE("env") {
  TEST_CASE("cubemap failure modes give one clear error naming the file or folder") {
    const std::string missing = MakeCubeFolder("cube_missing", 4, "negy");
    CHECK(ErrorOf(missing).find("missing face 'negy'") != std::string::npos);

    const std::string mixed = MakeCubeFolder("cube_mixed", 4);
    test::WriteGreyPng(mixed + "/posz.png", 8, 8);
    CHECK(ErrorOf(mixed).find("expected six faces of one size") != std::string::npos);

    const std::string oblong = MakeCubeFolder("cube_oblong", 4);
    test::WriteGreyPng(oblong + "/negx.png", 4, 6);
    CHECK(ErrorOf(oblong).find("expected a square face") != std::string::npos);

    const std::string twice = MakeCubeFolder("cube_twice", 4);
    test::WriteGreyPng(twice + "/posx.jpg", 4, 4);  // a PNG inside, the name is what matters here
    CHECK(ErrorOf(twice).find("several formats") != std::string::npos);

    const std::string truncated = MakeCubeFolder("cube_truncated", 16);
    const std::string bytes = ReadFile(truncated + "/posy.png");
    WriteFileAtomic(truncated + "/posy.png", bytes.substr(0, bytes.size() / 2));
    CHECK(ErrorOf(truncated).find("posy.png") != std::string::npos);

    const std::string garbage = MakeCubeFolder("cube_garbage", 4);
    WriteFileAtomic(garbage + "/posz.png", "this is not an image");
    CHECK(ErrorOf(garbage).find("posz.png: not a readable image") != std::string::npos);

    const std::string empty = MakeCubeFolder("cube_empty", 4);
    WriteFileAtomic(empty + "/negz.png", "");
    CHECK(ErrorOf(empty).find("negz.png: empty file") != std::string::npos);
  }

  TEST_CASE("a cubemap folder's files land on the faces OpenGL gives their names, unturned") {
    // Six .hdr faces whose texels hold (face + 1, row + 1, column + 1): small integers, which
    // RGBE stores exactly. Each texel must be found at the spec's direction of its centre.
    const int size = 4;
    const std::string dir = test::WriteHdrCube(test::ScratchDir("cube_named"), size, [](int k, int row, int col) {
      return glm::vec3(k + 1, row + 1, col + 1);
    });
    const auto env = LoadEnvironment(dir, CubeLayout::kStandard);
    for (int k = 0; k < 6; ++k)
      for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
          const glm::dvec3 d = glm::normalize(test::OpenGlCubeDirection(k, (col + 0.5) / size, (row + 0.5) / size));
          CAPTURE(kFaceNames[k]);
          CAPTURE(row);
          CAPTURE(col);
          CHECK(glm::length(env->Radiance(d) - glm::dvec3(k + 1, row + 1, col + 1)) < 1e-6);
        }
  }

  TEST_CASE("1x1 faces are a valid (if coarse) cubemap") {
    const std::string dir = MakeCubeFolder("cube_1x1", 1);
    const auto env = LoadEnvironment(dir, CubeLayout::kStandard);
    const ShRgb L = ProjectLight(*env, 2);
    // Grey 128 in sRGB is 0.2158605 linear; six equal faces are a furnace.
    CHECK(L[0].x == doctest::Approx(2 * std::sqrt(kPi) * 0.2158605).epsilon(1e-6));
    // The course's decoding is pow(128/255, 2.2) = 0.2195 instead (CONVENTIONS.md).
    const ShRgb course = ProjectLight(*LoadEnvironment(dir, CubeLayout::kGames202), 2);
    CHECK(course[0].x == doctest::Approx(2 * std::sqrt(kPi) * std::pow(128.0 / 255.0, 2.2)).epsilon(1e-6));
  }

  TEST_CASE("unknown names and bad sky parameters are errors, not crashes") {
    CHECK(ErrorOf("no_such_place").find("no such file, folder or built-in") != std::string::npos);
    CHECK(ErrorOf("sky:sun=-1").find("sun '-1' is out of range") != std::string::npos);
    CHECK(ErrorOf("sky:moon=1").find("unknown sky parameter 'moon'") != std::string::npos);
    CHECK(ErrorOf("furnace:abc").find("value 'abc' is not a number") != std::string::npos);
    CHECK(ErrorOf("sky:sun").find("sun has no value") != std::string::npos);
    CHECK(ErrorOf("sky:sun=1,sun=2").find("sun is given twice") != std::string::npos);
    CHECK(ErrorOf("furnace:0x10").find("is not a number") != std::string::npos);
  }

  TEST_CASE("EXR: DWAB and ZIP files load, NaN, Inf and negative texels are sanitised to zero") {
    const std::string dir = test::ScratchDir("exr");
    for (auto compression : {Imf::DWAB_COMPRESSION, Imf::ZIP_COMPRESSION, Imf::PIZ_COMPRESSION}) {
      const std::string path = dir + "/env.exr";
      WriteExr(path, 64, 32, compression, [](int, int) { return 2.0f; });
      const ShRgb L = ProjectLight(*LoadEnvironment(path, CubeLayout::kStandard), 2);
      // Half floats store 2.0 exactly; DWAB is lossy (a quantised DCT): 0.1% on a flat image.
      const double tolerance = compression == Imf::DWAB_COMPRESSION ? 2e-3 : 1e-9;
      CHECK(L[0].x == doctest::Approx(2 * std::sqrt(kPi) * 2.0).epsilon(tolerance));
    }
    const std::string bad = dir + "/bad.exr";
    WriteExr(bad, 64, 32, Imf::ZIP_COMPRESSION, [](int x, int y) {
      if (x == 3 && y == 3) return std::numeric_limits<float>::quiet_NaN();
      if (x == 4 && y == 3) return std::numeric_limits<float>::infinity();
      if (x == 5 && y == 3) return -5.0f;
      return 1.0f;
    });
    const auto env = LoadEnvironment(bad, CubeLayout::kStandard);
    // Exactly the three bad texels (row 3, columns 3..5) became 0, in every channel; every other
    // texel kept its 1.
    std::vector<Texel> texels;
    int zeros = 0, ones = 0;
    for (std::size_t r = 0; r < env->RowCount(); ++r) {
      env->Row(r, texels);
      for (std::size_t i = 0; i < texels.size(); ++i) {
        const glm::dvec3 v = texels[i].radiance;
        if (v == glm::dvec3(0.0)) {
          ++zeros;
          CHECK(r == 3);
          CHECK((i >= 3 && i <= 5));
        } else {
          ones += v == glm::dvec3(1.0);
        }
      }
    }
    CHECK(zeros == 3);
    CHECK(ones == 64 * 32 - 3);
    const ShRgb L = ProjectLight(*env, 4);
    for (const auto& c : L) CHECK(std::isfinite(c.x));
  }

  TEST_CASE("truncated EXR and a directory named .exr give errors") {
    const std::string dir = test::ScratchDir("exr_bad");
    const std::string path = dir + "/env.exr";
    WriteExr(path, 64, 32, Imf::ZIP_COMPRESSION, [](int, int) { return 1.0f; });
    const std::string bytes = ReadFile(path);
    WriteFileAtomic(path, bytes.substr(0, bytes.size() / 2));
    CHECK(ErrorOf(path).find("env.exr: cannot read OpenEXR file") != std::string::npos);
    fs::create_directories(dir + "/folder.exr");
    CHECK(ErrorOf(dir + "/folder.exr").find("missing face") != std::string::npos);
  }

  TEST_CASE("course cubemaps with --games202-faces reproduce the published light.txt to 5e-4" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    // JPEG decoders differ in their last bit; the course used float arithmetic throughout.
    constexpr double kCourseTolerance = 5e-4;
    for (const char* name : {"GraceCathedral", "Indoor", "Skybox", "CornellBox"}) {
      const std::string published = data + "/games202/peer-outputs/DrFlower_GAMES_101_202_Homework/" + name + "/light.txt";
      const ShRgb expected = ParseLightTxt(ReadFile(published), published);
      const auto env = LoadEnvironment(data + "/games202/cubemap/" + name, CubeLayout::kGames202);
      const ShRgb got = ProjectLight(*env, 2);
      REQUIRE(expected.size() == got.size());
      double worst = 0.0;
      for (std::size_t k = 0; k < got.size(); ++k)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[k][c] - expected[k][c]));
      MESSAGE(std::string(name) << ": max |ours - published| = " << worst);
      CHECK(worst < kCourseTolerance);
    }
  }

  TEST_CASE("the standard face table is the one whose faces join without seams" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    // Compare radiance just either side of every cube edge: with the right table the two
    // sides show the same scene. CONVENTIONS.md: 0.006-0.027 (right) vs 0.14-0.37 (course).
    for (const char* name : {"GraceCathedral", "Indoor"}) {
      double seam[2];
      for (CubeLayout layout : {CubeLayout::kStandard, CubeLayout::kGames202}) {
        const auto env = LoadEnvironment(data + "/games202/cubemap/" + name, layout);
        double sum = 0.0;
        int n = 0;
        const double e = 1e-3;
        for (int i = 0; i < 200; ++i) {
          const double t = -0.99 + 1.98 * i / 199.0;
          // Points on the 12 cube edges, nudged to either side.
          const glm::dvec3 edges[12][2] = {
              {{1, 1 - e, t}, {1 - e, 1, t}}, {{1, -1 + e, t}, {1 - e, -1, t}}, {{-1, 1 - e, t}, {-1 + e, 1, t}},
              {{-1, -1 + e, t}, {-1 + e, -1, t}}, {{t, 1, 1 - e}, {t, 1 - e, 1}}, {{t, 1, -1 + e}, {t, 1 - e, -1}},
              {{t, -1, 1 - e}, {t, -1 + e, 1}}, {{t, -1, -1 + e}, {t, -1 + e, -1}}, {{1, t, 1 - e}, {1 - e, t, 1}},
              {{1, t, -1 + e}, {1 - e, t, -1}}, {{-1, t, 1 - e}, {-1 + e, t, 1}}, {{-1, t, -1 + e}, {-1 + e, t, -1}}};
          for (auto& edge : edges) {
            const glm::dvec3 a = env->Radiance(glm::normalize(edge[0])), b = env->Radiance(glm::normalize(edge[1]));
            sum += (std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z)) / 3.0;
            ++n;
          }
        }
        seam[layout == CubeLayout::kStandard ? 0 : 1] = sum / n;
      }
      MESSAGE(std::string(name) << ": mean seam jump standard " << seam[0] << ", course " << seam[1]);
      CHECK(seam[0] * 3.0 < seam[1]);
    }
  }

  TEST_CASE("Grace Cathedral is bright above with the standard faces, below with the course's" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    // Irradiance on a surface facing n: E(n) = sum_lm A_l L_lm Y_lm(n) (R&H 2001). The
    // cathedral's lamps and windows are overhead, so E(up) > E(down); the course's face table
    // swaps up and down (CONVENTIONS.md) and must show the opposite.
    auto irradiance = [](const ShRgb& L, const glm::dvec3& n) {
      double y[9], e = 0.0;
      EvalBasisBand2(n, y);
      for (int k = 0; k < 9; ++k) e += ClampedCosineBand(k < 1 ? 0 : k < 4 ? 1 : 2) * L[k].x * y[k];
      return e;
    };
    const std::string folder = data + "/games202/cubemap/GraceCathedral";
    const ShRgb standard = ProjectLight(*LoadEnvironment(folder, CubeLayout::kStandard), 2);
    const ShRgb course = ProjectLight(*LoadEnvironment(folder, CubeLayout::kGames202), 2);
    const glm::dvec3 up(0, 1, 0), down(0, -1, 0);
    MESSAGE("red irradiance up/down: standard " << irradiance(standard, up) << " / " << irradiance(standard, down)
                                                << ", course " << irradiance(course, up) << " / " << irradiance(course, down));
    CHECK(irradiance(standard, up) > 1.5 * irradiance(standard, down));
    CHECK(irradiance(course, up) < irradiance(course, down));
  }
}
