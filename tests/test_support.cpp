#include "tests/test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include <unistd.h>

#include "core/atomic_file.h"
#include "core/child_process.h"
#include "core/error.h"
#include "geometry/procedural.h"
#include "io/obj_writer.h"
#include "render/render_frames.h"

namespace prt::test {
namespace fs = std::filesystem;

std::string SourceDir() { return PRT_SOURCE_DIR; }

std::string Fixture(const std::string& relative) { return SourceDir() + "/tests/data/" + relative; }

std::optional<std::string> SharedData() {
  const char* override_dir = std::getenv("PRT_SHARED_DATA");
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(override_dir ? override_dir : PRT_SHARED_DATA_DIR, ec);
  if (ec || !fs::is_directory(p / "games202")) return std::nullopt;
  return p.string();
}

std::string ScratchDir(const std::string& name) {
  const char* root = std::getenv("PRT_TEST_TMP");
  const fs::path p = fs::path(root && *root ? root : PRT_TEST_TMP_DIR) / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

std::string ShellQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

doctest::skip NeedsSharedData() { return doctest::skip(!SharedData().has_value()); }

std::optional<std::string> Ffmpeg() {
  const auto ffmpeg = FindProgram("ffmpeg");
  if (!ffmpeg || !FindProgram("ffprobe")) return std::nullopt;
  return ffmpeg;
}

doctest::skip NeedsFfmpeg() { return doctest::skip(!Ffmpeg().has_value()); }

std::optional<std::string> CmarkGfm() { return FindProgram("cmark-gfm"); }

doctest::skip NeedsCmarkGfm() { return doctest::skip(!CmarkGfm().has_value()); }

std::optional<std::string> Chromium() {
  if (!FindProgram("python3")) return std::nullopt;
  return FindProgram("chromium");
}

doctest::skip NeedsChromium() { return doctest::skip(!Chromium().has_value()); }

std::map<std::string, std::string> FolderFiles(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    files[e.path().filename().string()] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  return files;
}

bool SlurmAvailable() {
  return ::geteuid() == 0 && FindProgram("slurmctld") && FindProgram("slurmd") && FindProgram("munged") &&
         FindProgram("sbatch") && FindProgram("sinfo");
}

doctest::skip NeedsSlurm() { return doctest::skip(!SlurmAvailable()); }

std::string ErrorMessage(const std::function<void()>& run) {
  try {
    run();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string QuickScene() {
  return "--mesh " + Q(Fixture("obj/tetra_no_normals.obj")) + " --env furnace --transport unshadowed";
}

namespace {
Mesh Floor() { return MakePlane(2.0f, 8); }
Mesh Wall() {
  return MakeBox(glm::vec3(-1.25f, 0.0f, -1.0f), glm::vec3(-1.05f, 1.5f, 1.0f), BoxFacing::kOutward, 4);
}
}  // namespace

std::string WriteFloorAndWall(const std::string& dir, const glm::vec3& floor_kd, const glm::vec3& wall_kd) {
  const std::vector<ObjPart> parts = {{"floor", Floor(), floor_kd}, {"wall", Wall(), wall_kd}};
  WriteFileAtomic(dir + "/scene.obj", FormatObj(parts, "scene.mtl"));
  WriteFileAtomic(dir + "/scene.mtl", FormatMtl(parts));
  return dir + "/scene.obj";
}

std::string WriteSmallScene(const std::string& dir, const glm::vec3& knot_kd) {
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, 32, 6);
  StandUpright(knot, 3.4f);
  const std::vector<ObjPart> parts = {{"ground", MakePlane(12.0f, 6), glm::vec3(0.7f)}, {"knot", knot, knot_kd}};
  WriteFileAtomic(dir + "/small_scene.obj", FormatObj(parts, "small_scene.mtl"));
  WriteFileAtomic(dir + "/small_scene.mtl", FormatMtl(parts));
  return dir + "/small_scene.obj";
}

std::string SmallSceneOption(const std::string& name) { return " --mesh " + Q(WriteSmallScene(ScratchDir(name))); }

std::size_t FloorTriangles() { return Floor().triangle_count(); }
std::size_t WallTriangles() { return Wall().triangle_count(); }

std::vector<std::string> CsvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) fields.emplace_back();
    else fields.back() += c;
  }
  return fields;
}

glm::ivec3 PixelAt(const Image8& image, int x, int y) {
  const std::size_t p = 3 * (static_cast<std::size_t>(y) * image.width + x);
  return {image.rgb[p], image.rgb[p + 1], image.rgb[p + 2]};
}

std::string FramePath(const std::string& dir, int i, int count) { return dir + "/" + FrameName(i, count); }

}  // namespace prt::test
