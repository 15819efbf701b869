// The README runs verbatim: every command of its ```sh blocks is run, in order, with bash from a
// scratch folder laid out like a fresh clone after the quick start (build/prt, scripts/), and
// must exit 0. Commands that need the course's files (they name $GAMES202) run against the
// course data in ../shared/data, laid out as the course's framework has it, in a test case of
// their own that the runner skips when the data is absent. The other commands run in groups that
// share no files (GroupOf), a test case each, so that they run side by side. Two kinds are run
// elsewhere, not again here: the quick start's own commands (they are what runs these tests), and
// `prt report --stability`, which the stability test (tests/report/test_report.cpp) runs as the
// README writes it and then holds every case's figure to its own limits.
#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>

#include <sys/wait.h>
#include <string>

#include "core/atomic_file.h"
#include "tests/readme_commands.h"
#include "tests/test_process.h"
#include "tests/view/view_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

/// Which test case runs a command of the README: groups of commands that read only what their
/// own group wrote, so that they run side by side (the README took 125 s in one test case).
enum class Group {
  kCourse,     ///< names $GAMES202: the course's framework
  kSamples,    ///< reads or writes out/samples, the sample files
  kReport,     ///< prt report (not --stability)
  kView,       ///< prt view: serves until Ctrl-C
  kOther,      ///< everything else
};

Group GroupOf(const std::string& command) {
  if (command.find("$GAMES202") != std::string::npos) return Group::kCourse;
  if (command.find("out/samples") != std::string::npos) return Group::kSamples;
  if (command.find("prt report") != std::string::npos) return Group::kReport;
  if (command.find("prt view") != std::string::npos) return Group::kView;
  return Group::kOther;
}

/// The README commands run elsewhere: the quick start's own (they run these tests) and the
/// stability command (the stability test runs it, test_report.cpp).
bool RunElsewhere(const std::string& command) {
  return command.rfind("bash scripts/quickstart.sh", 0) == 0 || command.find("prt report --stability") != std::string::npos;
}

/// Runs, in order, the README's commands of `group` in `clone`; each must exit 0. Returns how
/// many ran.
int RunReadmeCommands(const std::string& clone, Group group) {
  int ran = 0;
  for (const std::string& command : test::ReadmeCommands()) {
    if (RunElsewhere(command) || GroupOf(command) != group) continue;
    test::RunInClone(clone, command);
    ++ran;
  }
  return ran;
}

}  // namespace

TEST_SUITE("readme") {
  TEST_CASE("readme: the commands on the sample files run as written") {
    const std::string clone = test::MakeReadmeClone("readme_samples");
    CHECK(RunReadmeCommands(clone, Group::kSamples) >= 5);
    // What the commands say they make is there.
    CHECK(fs::exists(clone + "/out/samples/scene.obj"));
    CHECK(fs::exists(clone + "/out/frames_split/frame_0059.png"));
  }

  TEST_CASE("readme: the report commands run as written") {
    const std::string clone = test::MakeReadmeClone("readme_report");
    CHECK(RunReadmeCommands(clone, Group::kReport) >= 1);
    CHECK(fs::exists(clone + "/out/report/report.md"));
  }

  TEST_CASE("readme: every other command runs as written") {
    const std::string clone = test::MakeReadmeClone("readme_other");
    CHECK(RunReadmeCommands(clone, Group::kOther) >= 5);
    CHECK(fs::exists(clone + "/out/diff.png"));
  }

  TEST_CASE("readme: prt view runs as written, serves its page and a frame, and ends on Ctrl-C") {
    const std::string clone = test::MakeReadmeClone("readme_view");
    int ran = 0;
    for (const std::string& command : test::ReadmeCommands()) {
      if (GroupOf(command) != Group::kView) continue;
      INFO(command);
      test::ViewProcess view = test::ViewProcess::Shell(command, clone, clone + "/view_stderr.txt");
      CHECK(test::Request(view.port(), "/").status == 200);
      // Its defaults as docs/CLI.md gives them: lmax 4, SH, shadowed.
      const std::string state = test::Request(view.port(), "/state").body;
      CHECK(state.find("\"limits\":{\"lmax\":4,\"bases\":[\"sh\",\"wavelet\"]") != std::string::npos);
      CHECK(state.find("mode=shadowed&") != std::string::npos);
      // Its render command line gives every vertex the directions the page's vertices took
      // (without --samples, the sample rule's: the hidden vertices' rule would take fewer).
      const std::string line = test::Request(view.port(), "/command").body;
      const std::size_t samples = line.find(" --samples "), hidden = line.find(" --hidden-samples ");
      REQUIRE(samples != std::string::npos);
      REQUIRE(hidden != std::string::npos);
      CHECK(std::stoi(line.substr(samples + 11)) == std::stoi(line.substr(hidden + 18)));
      const test::HttpReply frame = test::Request(view.port(), "/frame");
      CHECK(frame.status == 200);
      CHECK(frame.body.size() == 640u * 480u * 3u);
      const int status = view.Stop(SIGINT);
      CHECK(WIFSIGNALED(status));
      CHECK(WTERMSIG(status) == SIGINT);
      ++ran;
    }
    CHECK(ran >= 1);
  }

  TEST_CASE("readme: the course commands run against the course's framework" * test::NeedsSharedData()) {
    const std::string clone = test::MakeReadmeClone("readme_course");
    CHECK(RunReadmeCommands(clone, Group::kCourse) >= 2);
    const std::string grace = clone + "/games202/assets/cubemap/GraceCathedral";
    CHECK(fs::exists(grace + "/transport.txt"));
    CHECK(ReadFile(grace + "/transport.txt") != test::ShippedFile("transport.txt"));
    // The README says the framework's own files are kept as *.orig.
    CHECK(ReadFile(grace + "/light.txt.orig") == test::ShippedFile("light.txt"));
    CHECK(ReadFile(grace + "/transport.txt.orig") == test::ShippedFile("transport.txt"));
  }
}

}  // namespace prt
