// The README runs verbatim: every command of its ```sh blocks is run, in order, with bash from a
// scratch folder laid out like a fresh clone after the quick start (build/prt, scripts/), and
// must exit 0. Commands that need the course's files (they name $GAMES202) run against the
// course data in ../shared/data, laid out as the course's framework has it, in a test case of
// their own that the runner skips when the data is absent. The other commands run in groups that
// share no files (GroupOf), a test case each, so that they run side by side. The quick start's
// own commands are what runs these tests, so they are not run again.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "tests/test_support.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

/// The commands of the README's ```sh blocks: comment lines dropped, continuations joined.
std::vector<std::string> ReadmeCommands(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> commands;
  bool in_block = false;
  std::string pending;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      in_block = !in_block && line == "```sh";
      continue;
    }
    if (!in_block) continue;
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    if (!line.empty() && line.back() == '\\') {
      pending += line.substr(0, line.size() - 1);
      continue;
    }
    commands.push_back(pending + line);
    pending.clear();
  }
  return commands;
}

/// What the course's framework ships as each cubemap's light.txt and transport.txt (stand-ins:
/// the README's course command must keep them as *.orig).
std::string ShippedFile(const std::string& name) { return "the framework's own " + name + "\n"; }

/// The course's framework layout (assets/mary, assets/cubemap/<Name>/faces, with the framework's
/// own light.txt and transport.txt) over the shared data: real folders holding links to the
/// files, so outputs written there stay in `root`.
void LayOutCourseFramework(const std::string& data, const std::string& root) {
  fs::create_directories(root + "/assets");
  fs::create_directory_symlink(data + "/games202/mary", root + "/assets/mary");
  for (const auto& cubemap : fs::directory_iterator(data + "/games202/cubemap")) {
    const std::string folder = root + "/assets/cubemap/" + cubemap.path().filename().string();
    fs::create_directories(folder);
    for (const auto& face : fs::directory_iterator(cubemap.path()))
      fs::create_symlink(face.path(), folder + "/" + face.path().filename().string());
    for (const char* name : {"light.txt", "transport.txt"}) std::ofstream(folder + "/" + name) << ShippedFile(name);
  }
}

/// A scratch folder laid out like a fresh clone after the quick start: build/prt and scripts/,
/// with the course's framework under games202/ when the course data is there.
std::string MakeClone(const std::string& name) {
  const std::string clone = test::ScratchDir(name);
  fs::create_directories(clone + "/build");
  fs::create_symlink(test::PrtBinary(), clone + "/build/prt");
  fs::create_directory_symlink(test::SourceDir() + "/scripts", clone + "/scripts");
  if (const auto data = test::SharedData()) LayOutCourseFramework(*data, clone + "/games202");
  return clone;
}

/// Which test case runs a command of the README: groups of commands that read only what their
/// own group wrote, so that they run side by side (the README took 125 s in one test case).
enum class Group {
  kCourse,     ///< names $GAMES202: the course's framework
  kSamples,    ///< reads or writes out/samples, the sample files
  kReport,     ///< prt report (not --stability)
  kStability,  ///< prt report --stability
  kOther,      ///< everything else
};

Group GroupOf(const std::string& command) {
  if (command.find("$GAMES202") != std::string::npos) return Group::kCourse;
  if (command.find("out/samples") != std::string::npos) return Group::kSamples;
  if (command.find("prt report --stability") != std::string::npos) return Group::kStability;
  if (command.find("prt report") != std::string::npos) return Group::kReport;
  return Group::kOther;
}

/// Runs, in order, the README's commands of `group` in `clone`; each must exit 0. Returns how
/// many ran. The quick start's own commands are what runs these tests: they are left out.
int RunReadmeCommands(const std::string& clone, Group group) {
  int ran = 0;
  for (const std::string& command : ReadmeCommands(test::SourceDir() + "/README.md")) {
    CAPTURE(command);
    if (command.rfind("bash scripts/quickstart.sh", 0) == 0) continue;
    if (GroupOf(command) != group) continue;
    const auto r = test::RunCommand("cd " + test::Q(clone) + " && GAMES202=" + test::Q(clone + "/games202") +
                                    " bash -c " + test::Q(command));
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    ++ran;
  }
  return ran;
}

}  // namespace

TEST_SUITE("readme") {
  TEST_CASE("readme: the commands on the sample files run as written") {
    const std::string clone = MakeClone("readme_samples");
    CHECK(RunReadmeCommands(clone, Group::kSamples) >= 5);
    // What the commands say they make is there.
    CHECK(fs::exists(clone + "/out/samples/scene.obj"));
    CHECK(fs::exists(clone + "/out/frames_split/frame_0059.png"));
  }

  TEST_CASE("readme: the report commands run as written") {
    const std::string clone = MakeClone("readme_report");
    CHECK(RunReadmeCommands(clone, Group::kReport) >= 1);
    CHECK(fs::exists(clone + "/out/report/report.md"));
  }

  TEST_CASE("readme: the stability command runs as written") {
    const std::string clone = MakeClone("readme_stability");
    CHECK(RunReadmeCommands(clone, Group::kStability) == 1);
    CHECK(fs::exists(clone + "/out/stability/stability.csv"));
  }

  TEST_CASE("readme: every other command runs as written") {
    const std::string clone = MakeClone("readme_other");
    CHECK(RunReadmeCommands(clone, Group::kOther) >= 5);
    CHECK(fs::exists(clone + "/out/diff.png"));
  }

  TEST_CASE("readme: the course commands run against the course's framework" * test::NeedsSharedData()) {
    const std::string clone = MakeClone("readme_course");
    CHECK(RunReadmeCommands(clone, Group::kCourse) >= 2);
    const std::string grace = clone + "/games202/assets/cubemap/GraceCathedral";
    CHECK(fs::exists(grace + "/transport.txt"));
    CHECK(ReadFile(grace + "/transport.txt") != ShippedFile("transport.txt"));
    // The README says the framework's own files are kept as *.orig.
    CHECK(ReadFile(grace + "/light.txt.orig") == ShippedFile("light.txt"));
    CHECK(ReadFile(grace + "/transport.txt.orig") == ShippedFile("transport.txt"));
  }
}

}  // namespace prt
