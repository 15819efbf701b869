// Goldens across CPUs: the built `prt` run at every kernel level this CPU has (PRT_CPU_LEVEL,
// core/simd.h) must write the same bytes: frames of the golden kinds of scene (diffuse
// unshadowed and shadowed, glossy, textured, interreflected), and precompute's light.txt and
// transport*.txt; `prt bench` shows that each level is the one used. A level this CPU lacks
// and an unknown level are refused before any work.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/simd.h"
#include "geometry/procedural.h"
#include "io/png_io.h"
#include "tests/env/env_test_util.h"
#include "tests/test_process.h"

using namespace prt;
namespace fs = std::filesystem;

TEST_SUITE_BEGIN("render");

namespace {

/// The levels this CPU runs, baseline first: all three on an AVX-512 machine.
std::vector<std::string> Levels() {
  std::vector<std::string> levels;
  for (VectorLevel level : {VectorLevel::kBaseline, VectorLevel::kAvx2, VectorLevel::kX86_64V4})
    if (level <= CpuMaxVectorLevel()) levels.push_back(VectorLevelName(level));
  return levels;
}

/// Runs `prt arguments` with PRT_CPU_LEVEL=level. At the baseline, the C library's maths
/// functions are also kept off their FMA versions (glibc picks them by the CPU, whatever
/// PRT_CPU_LEVEL says), as on a CPU without AVX2 and FMA.
test::RunResult RunAtLevel(const std::string& level, const std::string& arguments) {
  const std::string libm = level == "baseline" ? "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA,-FMA4 " : "";
  return test::RunCommand(libm + "PRT_CPU_LEVEL=" + level + " " + test::Q(test::PrtBinary()) + " " + arguments);
}

/// Writes dir/scene.obj (+ .mtl): a sphere (Kd reddish) resting on a floor (grey), with texture
/// coordinates (longitude/latitude on the sphere, x/z on the floor), a 16 x 16 checker
/// dir/checker.png, and a 32^2 cube map dir/cube with a bright patch on its top face.
void WriteInputs(const std::string& dir) {
  Mesh sphere = MakeSphere(32, 1.0f, glm::vec3(0.f, 1.f, 0.f));
  const Mesh floor = MakePlane(5.0f, 12);
  std::string obj = "mtllib scene.mtl\n", mtl;
  std::size_t base = 1;
  const struct {
    const Mesh* mesh;
    const char* name;
    const char* kd;
  } parts[] = {{&sphere, "ball", "0.8 0.35 0.2"}, {&floor, "floor", "0.6 0.6 0.6"}};
  for (const auto& part : parts) {
    const Mesh& m = *part.mesh;
    obj += std::string("o ") + part.name + "\nusemtl " + part.name + "\n";
    mtl += std::string("newmtl ") + part.name + "\nKd " + part.kd + "\n";
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      const glm::vec3 p = m.positions[v], n = m.normals[v], d = p - glm::vec3(0.f, 1.f, 0.f);
      const bool ball = part.mesh == &sphere;
      const float u = ball ? 0.5f + std::atan2(d.x, d.z) / 6.2831853f : p.x / 5.f;
      const float w = ball ? std::acos(std::clamp(d.y, -1.f, 1.f)) / static_cast<float>(kPi) : p.z / 5.f;
      obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
      obj += "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
      obj += "vt " + std::to_string(u) + " " + std::to_string(w) + "\n";
    }
    for (const auto& t : m.triangles) {
      obj += "f";
      for (std::uint32_t v : t) obj += " " + std::to_string(base + v) + "/" + std::to_string(base + v) + "/" +
                                       std::to_string(base + v);
      obj += "\n";
    }
    base += m.vertex_count();
  }
  WriteFileAtomic(dir + "/scene.obj", obj);
  WriteFileAtomic(dir + "/scene.mtl", mtl);
  Image8 checker(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c)
        checker.rgb[3 * (y * 16 + x) + c] = static_cast<std::uint8_t>((x / 4 + y / 4) % 2 ? 230 : 40 + 60 * c);
  WritePng(dir + "/checker.png", checker);
  test::WriteHdrCube(dir + "/cube", 32, [](int face, int row, int col) {
    const bool sun = face == 2 && row >= 10 && row < 15 && col >= 18 && col < 23;  // on +Y
    const float f = float(face), r = float(row), c = float(col);
    return sun ? glm::vec3(40.f, 36.f, 30.f) : glm::vec3(0.2f + 0.05f * f, 0.3f + 0.01f * r, 0.5f - 0.01f * c + 0.1f * f);
  });
}

/// The paths of the files in `dir` whose names end in `suffix`, sorted.
std::vector<std::string> FilesEndingIn(const std::string& dir, const std::string& suffix) {
  std::vector<std::string> paths;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      paths.push_back(e.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

/// Runs `arguments` (which must not name --out) into dir/<level> at every level, and requires
/// the files there whose names end in `suffix` (".png", ".txt") to be byte for byte the
/// baseline's.
void RequireSameAtEveryLevel(const std::string& dir, const std::string& arguments, const std::string& suffix) {
  std::vector<std::string> baseline;
  for (const std::string& level : Levels()) {
    CAPTURE(level);
    const std::string out = dir + "/" + level;
    const test::RunResult r = RunAtLevel(level, arguments + " --quiet --out " + test::Q(out));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const std::vector<std::string> files = FilesEndingIn(out, suffix);
    REQUIRE(!files.empty());
    if (baseline.empty()) {
      baseline = files;
      continue;
    }
    REQUIRE(files.size() == baseline.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
      REQUIRE(fs::path(files[i]).filename() == fs::path(baseline[i]).filename());
      const bool same = ReadFile(files[i]) == ReadFile(baseline[i]);
      CHECK_MESSAGE(same, (files[i] + " differs from " + baseline[i]));
    }
  }
}

}  // namespace

TEST_CASE("cpu levels: frames of every golden kind are the same bytes at every level") {
  const std::string dir = test::ScratchDir("cpu_levels_frames");
  WriteInputs(dir);
  const std::string mesh = " --mesh " + test::Q(dir + "/scene.obj");
  const std::string cube = " --env " + test::Q(dir + "/cube");
  // Small frames of a turning light (tone curve and exposure left to render's defaults).
  const std::string frames = " --frames 3 --size 64x48 --cache none --lmax 4";
  const struct {
    std::string name;
    std::string options;
  } scenes[] = {
      {"unshadowed", mesh + cube + " --transport unshadowed"},
      {"shadowed", mesh + cube + " --transport shadowed --samples 256"},
      // Under the built-in sky; with --orbit the glossy part goes through transfer matrices.
      {"glossy", mesh + " --albedo 0.5,0.5,0.5 --material phong:20,0.4 --orbit 20 --samples 256"},
      {"textured", mesh + cube + " --texture " + test::Q(dir + "/checker.png") + " --samples 256"},
      {"interreflection", mesh + cube + " --transport interreflection --bounces 2 --samples 256"},
      // The demo's knot on its ground at a tenth of its vertices (the small scene), interreflected,
      // few rays.
      {"demo", test::SmallSceneOption("cpu_levels_small_scene") + " --transport interreflection --samples 32"},
  };
  for (const auto& scene : scenes) {
    CAPTURE(scene.name);
    RequireSameAtEveryLevel(dir + "/" + scene.name, "render" + scene.options + frames, ".png");
  }
}

TEST_CASE("cpu levels: precompute's light.txt and transport*.txt are the same bytes at every level") {
  const std::string dir = test::ScratchDir("cpu_levels_precompute");
  WriteInputs(dir);
  const std::string scene = " --mesh " + test::Q(dir + "/scene.obj") + " --env " + test::Q(dir + "/cube");
  // Coloured albedo and bounces: transport_r/g/b.txt besides transport.txt.
  RequireSameAtEveryLevel(dir + "/interreflection",
                          "precompute" + scene + " --transport interreflection --samples 128 --cache none", ".txt");
  RequireSameAtEveryLevel(dir + "/textured",
                          "precompute" + scene + " --texture " + test::Q(dir + "/checker.png") +
                              " --transport shadowed --lmax 4 --samples 128 --cache none",
                          ".txt");
}

TEST_CASE("cpu levels: the cap reaches the kernel choices (prt bench's printout)") {
  const std::string best = VectorLevelName(CpuMaxVectorLevel());
  for (const std::string& level : Levels()) {
    CAPTURE(level);
    // The machine lines alone: a timed benchmark added 37 s a level under ThreadSanitizer.
    const test::RunResult r = RunAtLevel(level, "bench machine");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const std::string capped = level == best ? "" : " (capped by PRT_CPU_LEVEL; this CPU runs " + best + ")";
    CHECK_MESSAGE(r.out.find("\ncpu_vector_level=" + level + capped + "\n") != std::string::npos, r.out);
    CHECK_MESSAGE(r.out.find("\nisa_bvh=" + level + "\n") != std::string::npos, r.out);
  }
}

TEST_CASE("prt bench machine: the machine lines that start every benchmark, and nothing timed") {
  // The keys every benchmark prints before its first measurement (bench/timing.cpp's
  // PrintMachine), then the process's page faults and memory: catches a machine row that runs a
  // measurement (the cap test above relies on it staying instant) or leaves a machine line out.
  const auto keys = [](const std::string& out) {
    std::vector<std::string> k;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) k.push_back(line.substr(0, line.find('=')));
    return k;
  };
  const test::RunResult machine = test::RunPrt("bench machine --threads 3");
  REQUIRE_MESSAGE(machine.exit_code == 0, machine.err);
  const std::vector<std::string> expected = {"cpu_model", "cpu_vector_level", "isa_bvh", "threads", "page_faults",
                                             "peak_memory_mib"};
  CHECK(keys(machine.out) == expected);
  CHECK(machine.out.find("\nthreads=3\n") != std::string::npos);
  // An option it does not read is refused, as for every benchmark.
  const test::RunResult runs = test::RunPrt("bench machine --runs 2");
  CHECK(runs.exit_code == 2);
  CHECK(runs.err.find("--runs: not used by prt bench machine") != std::string::npos);
}

TEST_CASE("cpu levels: PRT_CPU_LEVEL names a level this CPU runs, else a one-line error") {
  const VectorLevel all = VectorLevel::kX86_64V4, avx2 = VectorLevel::kAvx2, base = VectorLevel::kBaseline;
  CHECK(RequestedVectorLevel(nullptr, all) == all);  // unset or empty: the CPU's best
  CHECK(RequestedVectorLevel("", avx2) == avx2);
  CHECK(RequestedVectorLevel("baseline", all) == base);
  CHECK(RequestedVectorLevel("avx2", all) == avx2);
  CHECK(RequestedVectorLevel("avx512", all) == all);
  CHECK(RequestedVectorLevel("avx2", avx2) == avx2);
  CHECK_THROWS_WITH_AS(RequestedVectorLevel("sse9", all),
                       "PRT_CPU_LEVEL=sse9: unknown level (expected baseline, avx2 or avx512)", Error);
  CHECK_THROWS_WITH_AS(RequestedVectorLevel("AVX2", all),
                       "PRT_CPU_LEVEL=AVX2: unknown level (expected baseline, avx2 or avx512)", Error);
  CHECK_THROWS_WITH_AS(RequestedVectorLevel("avx512", avx2),
                       "PRT_CPU_LEVEL=avx512: this CPU cannot run it (expected one of: baseline, avx2)", Error);
  CHECK_THROWS_WITH_AS(RequestedVectorLevel("avx2", base),
                       "PRT_CPU_LEVEL=avx2: this CPU cannot run it (expected one of: baseline)", Error);
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  // The levels the tests above run at are what GCC's own CPU checks say.
  const VectorLevel expected = __builtin_cpu_supports("x86-64-v4")   ? all
                               : __builtin_cpu_supports("x86-64-v3") ? avx2
                                                                     : base;
  CHECK(CpuMaxVectorLevel() == expected);
#endif
}

TEST_CASE("cpu levels: prt refuses an unknown level, and one this CPU lacks, before any work") {
  const std::string dir = test::ScratchDir("cpu_levels_refused");
  std::vector<std::pair<std::string, std::string>> refused = {
      {"sse9", "PRT_CPU_LEVEL=sse9: unknown level (expected baseline, avx2 or avx512)"}};
  if (CpuMaxVectorLevel() < VectorLevel::kX86_64V4)
    refused.emplace_back("avx512", "PRT_CPU_LEVEL=avx512: this CPU cannot run it (expected one of: ");
  for (const auto& refusal : refused) {
    const std::string& level = refusal.first;
    const std::string& message = refusal.second;
    CAPTURE(level);
    const test::RunResult r = RunAtLevel(level, "render " + test::QuickScene() + " --frames 1 --size 8x8 --out " +
                                                    test::Q(dir + "/out"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.rfind("prt: error: " + message, 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(dir + "/out"));  // before any work
  }
  // Set but empty: the CPU's best, as if unset.
  const test::RunResult r = RunAtLevel("''", "render " + test::QuickScene() + " --frames 1 --size 8x8 --quiet --out " +
                                                  test::Q(dir + "/empty"));
  CHECK_MESSAGE(r.exit_code == 0, r.err);
}

TEST_SUITE_END();
