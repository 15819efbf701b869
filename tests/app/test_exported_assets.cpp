// Artists' assets as exporters write them, through the binary: a library name with spaces, a
// texture path from another machine, map_Kd options, the .mtl fields prt uses and ignores,
// --albedo on a textured mesh, and a textured mesh under a glossy coat (the per-texel energy
// rule, texture/albedo_limit.h). Every asset is written by the test itself.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/atomic_file.h"
#include "io/image_load.h"
#include "io/obj_loader.h"
#include "io/png_io.h"
#include "raster/tonemap.h"
#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// Four quadrants of distinct colours, 8 x 8 texels each (a flipped or shifted v, swapped channels
// or a lost texture show): red, green / blue, near-white (top row of the image first).
constexpr std::uint8_t kQuadrant[4][3] = {{200, 30, 30}, {30, 200, 30}, {30, 30, 200}, {240, 240, 240}};

void WriteQuadrants(const std::string& path) {
  Image8 texture(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) texture.rgb[3 * (y * 16 + x) + c] = kQuadrant[(y / 8) * 2 + x / 8][c];
  WritePng(path, texture);
}

// A 2 x 2 square at z = 0 facing +z, texture coordinates 0..1 over it, material `coat`.
std::string WriteSquare(const std::string& dir, const std::string& mtllib_line) {
  WriteFileAtomic(dir + "/square.obj", mtllib_line + "\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nusemtl coat\nf 1/1/1 2/2/1 3/3/1 4/4/1\n");
  return dir + "/square.obj";
}

// The square filling the middle of a 64 x 64 frame under the white furnace, unshadowed, with the
// linear radiance written as sRGB at exposure `ev`: a diffuse pixel is its albedo x 2^ev.
test::RunResult RenderSquare(const std::string& obj, const std::string& out, const std::string& extra = "",
                             const std::string& ev = "0") {
  return test::RunPrt("render --mesh " + test::Q(obj) + " --env furnace --transport unshadowed --exposure " + ev +
                      " --tonemap srgb --ssaa 1 --frames 1 --size 64x64 --eye 0,0,3 --target 0,0,0 --fov 30 --out " +
                      test::Q(out) + " " + extra);
}

// Quadrant q's centre block (x, y = +-0.5 are 20 pixels from the centre), image row 0 at the top.
constexpr int kCentre[4][2] = {{12, 12}, {52, 12}, {12, 52}, {52, 52}};

// Every pixel of quadrant q's 5 x 5 centre block is `rgb`.
void CheckQuadrant(const Image8& frame, int q, const glm::ivec3& rgb) {
  CAPTURE(q);
  for (int y = kCentre[q][1] - 2; y <= kCentre[q][1] + 2; ++y)
    for (int x = kCentre[q][0] - 2; x <= kCentre[q][0] + 2; ++x) CHECK(test::PixelAt(frame, x, y) == rgb);
}

float Linear(std::uint8_t code) { return static_cast<float>(SrgbToLinear(code / 255.0)); }

// --vertex-radiance writes 9 significant digits.
constexpr float kRadianceFileRounding = 1e-6f;

glm::ivec3 Code(const std::uint8_t* rgb) { return glm::ivec3(rgb[0], rgb[1], rgb[2]); }

// The sRGB code of a linear Kd under the white furnace at exposure 0.
glm::ivec3 KdCode(float r, float g, float b) { return glm::ivec3(EncodeSrgb8(r), EncodeSrgb8(g), EncodeSrgb8(b)); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("exported assets: `mtllib My Scene.mtl` is one library with a space, not two names") {
    const std::string dir = test::ScratchDir("assets_spaced_mtllib");
    WriteFileAtomic(dir + "/My Scene.mtl", "newmtl coat\nKd 0.2 0.4 0.6\n");
    const test::RunResult r = RenderSquare(WriteSquare(dir, "mtllib My Scene.mtl"), dir + "/out");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    // Read as two names ("My", "Scene.mtl"), the material would be missing: default grey 0.8.
    CHECK(r.err.find("not defined") == std::string::npos);
    CHECK(r.err.find("materials: My Scene.mtl: used Kd") != std::string::npos);
    CheckQuadrant(ReadPng(dir + "/out/frame_0000.png"), 0, KdCode(0.2f, 0.4f, 0.6f));
    // A line of two library names still reads them as two: the first missing, the second read.
    WriteFileAtomic(dir + "/b.mtl", "newmtl coat\nKd 0.6 0.4 0.2\n");
    const test::RunResult two = RenderSquare(WriteSquare(dir, "mtllib missing.mtl b.mtl"), dir + "/out2");
    REQUIRE_MESSAGE(two.exit_code == 0, two.err);
    CheckQuadrant(ReadPng(dir + "/out2/frame_0000.png"), 0, KdCode(0.6f, 0.4f, 0.2f));
  }

  TEST_CASE("exported assets: a texture path from another machine falls back to the file beside the .mtl, then textures/") {
    const std::string dir = test::ScratchDir("assets_foreign_path");
    WriteQuadrants(dir + "/quadrants.png");
    fs::create_directories(dir + "/textures");
    WriteQuadrants(dir + "/textures/only_here.png");
    struct Case {
      const char* map_kd;
      const char* found;  // the fallback the warning names; "" = as written
    } cases[] = {{"C:\\Users\\art\\tex\\quadrants.png", "using quadrants.png beside the .mtl"},
                 {"/home/nobody/tex/quadrants.png", "using quadrants.png beside the .mtl"},
                 {"D:\\textures\\only_here.png", "using only_here.png in textures/ beside the .mtl"},
                 {"textures\\only_here.png", "using only_here.png with '\\' read as '/'"},
                 {"-halo 2 quadrants.png", "using quadrants.png after the unknown option '-halo 2' (ignored)"},
                 {"quadrants.png", ""}};
    for (const Case& c : cases) {
      CAPTURE(c.map_kd);
      WriteFileAtomic(dir + "/coat.mtl", std::string("newmtl coat\nKd 0.5 0.5 0.5\nmap_Kd ") + c.map_kd + "\n");
      const test::RunResult r = RenderSquare(WriteSquare(dir, "mtllib coat.mtl"), dir + "/out");
      REQUIRE_MESSAGE(r.exit_code == 0, r.err);
      if (*c.found) CHECK(r.err.find(c.found) != std::string::npos);
      else CHECK(r.err.find("is not at that path") == std::string::npos);
      // The texture itself, not the Kd 0.5 that a missing texture leaves.
      const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
      for (int q = 0; q < 4; ++q) CheckQuadrant(frame, q, Code(kQuadrant[q]));
    }
    // Nowhere at all: the Kd, and a warning that says where it looked.
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 0.5 0.5 0.5\nmap_Kd C:\\elsewhere\\gone.png\n");
    const test::RunResult r = RenderSquare(WriteSquare(dir, "mtllib coat.mtl"), dir + "/out");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("was not found (nor its file name beside the .mtl or in textures/ there)") != std::string::npos);
    CheckQuadrant(ReadPng(dir + "/out/frame_0000.png"), 0, KdCode(0.5f, 0.5f, 0.5f));
  }

  TEST_CASE("exported assets: map_Kd -s and -o place the texture, other options are named as ignored") {
    const std::string dir = test::ScratchDir("assets_map_options");
    WriteQuadrants(dir + "/quadrants.png");
    // In the loader: (u, v) -> (s_u u + o_u, s_v v + o_v) at every corner, w ignored.
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd -s 2 3 1 -o 0.25 0.5 0 quadrants.png\n");
    const LoadedMesh loaded = LoadObj(WriteSquare(dir, "mtllib coat.mtl"));
    REQUIRE(loaded.mesh.textured());
    const glm::vec2 file_uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (std::size_t t = 0; t < loaded.mesh.triangle_count(); ++t)
      for (int c = 0; c < 3; ++c) {
        const glm::vec2 mapped = loaded.mesh.corner_uv[3 * t + c];
        // Which file corner: the mapped value must be one of the four mapped file corners.
        bool found = false;
        for (const glm::vec2& f : file_uv) found = found || mapped == glm::vec2(2 * f.x + 0.25f, 3 * f.y + 0.5f);
        CHECK(found);
      }
    // Through the binary: -o 0.5 0 shifts u by half a repeat, so left and right quadrants swap;
    // -clamp is named as ignored, and neither option is read as part of the file name.
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd -clamp on -o 0.5 0 0 quadrants.png\n");
    const test::RunResult r = RenderSquare(WriteSquare(dir, "mtllib coat.mtl"), dir + "/out");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("map_Kd options ignored (prt reads -s and -o): -clamp of material 'coat'") != std::string::npos);
    CHECK(r.err.find("was not found") == std::string::npos);
    const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
    const int swapped[4] = {1, 0, 3, 2};
    for (int q = 0; q < 4; ++q) CheckQuadrant(frame, q, Code(kQuadrant[swapped[q]]));
  }

  TEST_CASE("exported assets: a textured face without texture coordinates takes the texture's mean, as warned") {
    const std::string dir = test::ScratchDir("assets_no_vt");
    WriteQuadrants(dir + "/quadrants.png");
    // Kd far from the texture's colours: a face that fell back to Kd would show it.
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 0.05 0.05 0.05\nmap_Kd quadrants.png\n");
    // Two triangles apart: the first with vt at its corners, the second (vertices 4 to 6) without.
    WriteFileAtomic(dir + "/square.obj", "mtllib coat.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
                                         "vt 0.1 0.1\nvt 0.2 0.1\nvt 0.1 0.2\nusemtl coat\nf 1/1 2/2 3/3\nf 4 5 6\n");
    const LoadedMesh loaded = LoadObj(dir + "/square.obj");
    REQUIRE(loaded.mesh.textured());
    // The mean of the texture's linear colours, computed here from its four equal quadrants.
    glm::vec3 mean(0.0f);
    for (const auto& q : kQuadrant) mean += glm::vec3(Linear(q[0]), Linear(q[1]), Linear(q[2])) / 4.0f;
    constexpr float kMeanTolerance = 1e-5f;  // float sums of 256 texels
    int untextured = 0;
    for (std::size_t v = 0; v < loaded.mesh.vertex_count(); ++v) {
      if (loaded.mesh.positions[v].x < 4.0f) continue;  // the first triangle
      ++untextured;
      for (int c = 0; c < 3; ++c) CHECK(std::abs(loaded.mesh.albedo[v][c] - mean[c]) < kMeanTolerance);
    }
    CHECK(untextured == 3);
    int said = 0;
    for (const std::string& w : loaded.report.warnings)
      said += w == dir + "/square.obj: 1 textured face has no texture coordinates (vt); they use the texture's mean colour";
    CHECK(said == 1);
  }

  TEST_CASE("exported assets: every map_Kd option written but -s and -o is named, whatever its value") {
    const std::string dir = test::ScratchDir("assets_map_options_written");
    WriteQuadrants(dir + "/quadrants.png");
    // The warning of the OBJ's map_Kd options, or "" when none (at most one).
    const auto warning = [&](const std::string& material, const std::string& map_kd) {
      WriteFileAtomic(dir + "/coat.mtl", "newmtl " + material + "\nKd 1 1 1\nmap_Kd " + map_kd + "\n");
      WriteFileAtomic(dir + "/square.obj", "mtllib coat.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                                           "usemtl " + material + "\nf 1/1 2/2 3/3\n");
      const LoadedMesh loaded = LoadObj(dir + "/square.obj");
      CHECK(loaded.mesh.textured());  // the file is found after the options, whatever they are
      std::string found;
      for (const std::string& w : loaded.report.warnings)
        if (w.find("map_Kd options ignored") != std::string::npos) {
          CHECK(found.empty());  // one warning at most
          found = w;
        }
      return found;
    };
    const std::string prefix = dir + "/square.obj: map_Kd options ignored (prt reads -s and -o): ";
    // Written at their defaults (-bm 1, -clamp off), after -s's three words: named all the same.
    CHECK(warning("coat", "-s 2 2 1 -bm 1.0 -clamp off quadrants.png") == prefix + "-clamp -bm of material 'coat'");
    CHECK(warning("coat", "-bm 1.0 -clamp on quadrants.png") == prefix + "-clamp -bm of material 'coat'");
    CHECK(warning("coat", "-mm 0 1 -imfchan m -boost 1 -texres 512 quadrants.png") ==
          prefix + "-mm -boost -texres -imfchan of material 'coat'");
    CHECK(warning("coat", "-blendu on -blendv on -t 0 0 0 -type sphere -colorspace sRGB quadrants.png") ==
          prefix + "-t -blendu -blendv -type -colorspace of material 'coat'");
    CHECK(warning("Coat Mat", "-clamp on quadrants.png") == prefix + "-clamp of material 'Coat Mat'");
    // Options apart by tabs, as a tab is a blank to the format; and the last of two map_Kd lines
    // of one material is the one read, its options too.
    CHECK(warning("coat", "-clamp\ton\t-bm 1 quadrants.png") == prefix + "-clamp -bm of material 'coat'");
    CHECK(warning("coat", "-o 0.5 0 0 -bm 1 quadrants.png") == prefix + "-bm of material 'coat'");  // -o's three words
    CHECK(warning("coat", "-clamp on quadrants.png\nmap_Kd -bm 1 quadrants.png") == prefix + "-bm of material 'coat'");
    // -s and -o alone, and no option: nothing to name.
    CHECK(warning("coat", "-s 2 2 1 -o 0 0 0 quadrants.png") == "");
    CHECK(warning("coat", "quadrants.png") == "");
  }

  TEST_CASE("exported assets: the summary names the .mtl fields used and ignored, and offers the gloss as --material") {
    const std::string dir = test::ScratchDir("assets_mtl_fields");
    WriteFileAtomic(dir + "/coat.mtl", "# Blender MTL\nnewmtl coat\nNs 200\nKa 1 1 1\nKd 0.8 0.8 0.8\nKs 0.5 0.5 0.5\n"
                                       "d 1\nillum 2\n");
    const std::string obj = WriteSquare(dir, "mtllib coat.mtl");
    const test::RunResult r = RenderSquare(obj, dir + "/out");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    // Ks 0.5 beside Kd 0.8 would exceed 1: the offer lowers KS to 0.2, and the offer works.
    CHECK(r.err.find("materials: coat.mtl: used Kd; ignored Ka, Ks, Ns, d, illum (shading comes from --material: "
                     "material 'coat' (Ks 0.5, Ns 200) as a glossy coat is --material phong:200,0.2, KS lowered to "
                     "fit beside the brightest Kd 0.8)") != std::string::npos);
    const test::RunResult offered = RenderSquare(obj, dir + "/out_glossy", "--material phong:200,0.2");
    CHECK_MESSAGE(offered.exit_code == 0, offered.err);
    CHECK(offered.err.find("as a glossy coat") == std::string::npos);  // glossy already: no offer
    // --albedo replaces Kd: the summary says Kd was not used.
    const test::RunResult albedo = RenderSquare(obj, dir + "/out_albedo", "--albedo 0.3,0.3,0.3");
    REQUIRE_MESSAGE(albedo.exit_code == 0, albedo.err);
    CHECK(albedo.err.find("used none; ignored Ka, Kd (--albedo), Ks") != std::string::npos);
    CHECK(albedo.err.find("--material phong:200,0.5)") != std::string::npos);  // 0.3 + 0.5 fits
  }

  TEST_CASE("exported assets: every gloss the materials line offers is accepted when passed back") {
    const std::string dir = test::ScratchDir("assets_offer_accepted");
    WriteQuadrants(dir + "/quadrants.png");
    // Exponents outside prt's range, weights that cannot fit beside Kd, a Kd whose float is just
    // above its decimal, a coloured Ks, a textured coat.
    const char* const materials[] = {
        "Kd 0.8 0.8 0.8\nKs 0.5 0.5 0.5\nNs 0.25",
        "Kd 0.8 0.8 0.8\nKs 0.5 0.5 0.5\nNs 100000",
        "Kd 0.9 0.3 0.1\nKs 1 1 1\nNs 50",
        "Kd 0.7 0.7 0.7\nKs 0.3 0.3 0.3\nNs 20",
        "Kd 0.33 0.33 0.33\nKs 0.9 0.1 0.2\nNs 7",
        "Kd 1 1 1\nKs 0.6 0.6 0.6\nNs 300\nmap_Kd quadrants.png"};
    int n = 0;
    for (const char* fields : materials) {
      CAPTURE(fields);
      WriteFileAtomic(dir + "/coat.mtl", std::string("newmtl coat\n") + fields + "\n");
      const std::string obj = WriteSquare(dir, "mtllib coat.mtl");
      const std::string out = dir + "/out" + std::to_string(n++);
      const test::RunResult r = RenderSquare(obj, out);
      REQUIRE_MESSAGE(r.exit_code == 0, r.err);
      const std::size_t at = r.err.find("as a glossy coat is --material ");
      REQUIRE(at != std::string::npos);
      const std::size_t begin = at + std::string("as a glossy coat is --material ").size();
      const std::string offer = r.err.substr(begin, r.err.find_first_of(",)", r.err.find(',', begin) + 1) - begin);
      CAPTURE(offer);
      REQUIRE(offer.rfind("phong:", 0) == 0);
      const test::RunResult back = RenderSquare(obj, out + "_glossy", "--material " + offer);
      CHECK_MESSAGE(back.exit_code == 0, back.err);
    }
  }

  TEST_CASE("exported assets: --albedo on a textured mesh replaces its textures, and the summary says so") {
    const std::string dir = test::ScratchDir("assets_albedo_textured");
    WriteQuadrants(dir + "/quadrants.png");
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd quadrants.png\n");
    const test::RunResult r = RenderSquare(WriteSquare(dir, "mtllib coat.mtl"), dir + "/out", "--albedo 0.2,0.4,0.6");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("texture: not used: --albedo 0.2,0.4,0.6 replaces the textures of") != std::string::npos);
    CHECK(r.err.find("frames shade each pixel as the texture's albedo") == std::string::npos);
    const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
    for (int q = 0; q < 4; ++q) CheckQuadrant(frame, q, KdCode(0.2f, 0.4f, 0.6f));
  }

  TEST_CASE("exported assets: a textured mesh can be glossy; texels above 1 - KS are scaled to it, the furnace stays within 1") {
    const std::string dir = test::ScratchDir("assets_textured_glossy");
    WriteQuadrants(dir + "/quadrants.png");
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd quadrants.png\n");
    const std::string obj = WriteSquare(dir, "mtllib coat.mtl");
    constexpr float kKs = 0.3f;
    // Exposure -1 halves everything, so a pixel at the promised albedo + KS = 1 is 0.5, not clipped.
    const test::RunResult r = RenderSquare(obj, dir + "/out", "--material phong:10,0.3", "-1");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    // One warning: how many texels of which texture (the near-white quadrant, 64 of 256: its
    // linear 0.87 is above 0.7; the other quadrants' brightest channel, 0.58, is not).
    CHECK(r.err.find("phong:10,0.3 keeps albedo + KS <= 1 per texel: texels brighter than 1 - KS = 0.7 were scaled "
                     "down to it, hue kept (64 of 256 texels of '" + dir + "/quadrants.png')") != std::string::npos);
    // Each quadrant is 0.5 (fitted albedo + KS g), g the lobe's furnace value at the view: 1 at
    // normal view, less as the horizon and the cosine cut the lobe. The fixed camera's glossy
    // term is per vertex, and the square's corners are seen 25 degrees off their normal, where
    // g = 0.896 was measured; 0.85 leaves room and still fails if the coat is lost (g = 0).
    constexpr float kLobeFurnaceLow = 0.85f;
    const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
    for (int q = 0; q < 4; ++q) {
      CAPTURE(q);
      for (int c = 0; c < 3; ++c) {
        const float albedo = Linear(kQuadrant[q][c]);
        const float largest = std::max({Linear(kQuadrant[q][0]), Linear(kQuadrant[q][1]), Linear(kQuadrant[q][2])});
        const float fitted = albedo * std::min(1.0f, (1 - kKs) / largest);
        const int got = test::PixelAt(frame, kCentre[q][0], kCentre[q][1])[c];
        CHECK(got >= EncodeSrgb8(0.5f * (fitted + kKs * kLobeFurnaceLow)));
        CHECK(got <= EncodeSrgb8(0.5f * (fitted + kKs)));
      }
    }
    // The furnace, per pixel: nothing brighter than albedo + KS = 1 (0.5 here) anywhere.
    int brightest = 0;
    for (std::uint8_t v : frame.rgb) brightest = std::max(brightest, int(v));
    CHECK(brightest <= EncodeSrgb8(0.5f));

    // The vertices' albedo (bounces, --vertex-radiance, prt reference) is rebuilt from the fitted
    // texels: a white texture gives 0.7 + KS g toward the camera at each vertex, never above 1.
    Image8 white_texels(4, 4);
    std::fill(white_texels.rgb.begin(), white_texels.rgb.end(), std::uint8_t(255));
    WritePng(dir + "/white.png", white_texels);
    WriteFileAtomic(dir + "/coat.mtl", "newmtl coat\nKd 1 1 1\nmap_Kd white.png\n");
    const test::RunResult white = RenderSquare(obj, dir + "/out_white", "--material phong:10,0.3 --vertex-radiance " +
                                                                        test::Q(dir + "/white.txt"));
    REQUIRE_MESSAGE(white.exit_code == 0, white.err);
    std::ifstream rows(dir + "/white.txt");
    std::size_t vertices = 0, values = 0;
    rows >> vertices;
    for (float v; rows >> v; ++values) {
      CHECK(v <= 1.0f + kRadianceFileRounding);
      CHECK(v >= (1 - kKs) + kKs * kLobeFurnaceLow);
    }
    CHECK(values == 6 * 3);  // two triangles, three corners, R G B
  }

  TEST_CASE("exported assets: textured mary renders glossy, the texture named in the energy warning" * test::NeedsSharedData()) {
    const std::string mary = *test::SharedData() + "/games202/mary";
    const std::string dir = test::ScratchDir("assets_glossy_mary");
    const test::RunResult r = test::RunPrt("render --mesh " + test::Q(mary + "/mary.obj") + " --texture " +
                                           test::Q(mary + "/MC003_Kozakura_Mari.png") +
                                           " --material phong:30,0.1 --env furnace --transport unshadowed --exposure -1"
                                           " --tonemap srgb --frames 1 --size 96x96 --out " + test::Q(dir + "/out"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("phong:30,0.1 keeps albedo + KS <= 1 per texel") != std::string::npos);
    CHECK(r.err.find("MC003_Kozakura_Mari.png')") != std::string::npos);
    // The white furnace: no pixel above albedo + KS = 1 (0.5 at -1 EV), one code of rounding.
    const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
    int brightest = 0;
    for (std::uint8_t v : frame.rgb) brightest = std::max(brightest, int(v));
    CHECK(brightest <= EncodeSrgb8(0.5f) + 1);
  }
}

TEST_SUITE("texture") {
}

}  // namespace prt
