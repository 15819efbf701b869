// Files users keep (docs/CLI.md, "Outputs" and "Output folders"), through the binary: prt never
// replaces a file it did not write (refused before any work, or --replace keeps it as
// NAME.orig), one command never removes another's deliverables, `diff --out` never replaces an
// input, a failed run leaves no trace, SIGTERM and SIGINT leave no temporary file (and the
// next run sweeps what SIGKILL left), and the same run gives the same video bytes.
#include <doctest/doctest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "tests/env/env_test_util.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;
using test::Q;

/// Every file under `dir` (hidden ones and those in sub-folders too) with its bytes: the
/// folder's whole state, to check that a refused or failed run changed nothing.
std::map<std::string, std::string> Snapshot(const std::string& dir) {
  std::map<std::string, std::string> all;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    all[rel] = e.is_regular_file() ? ReadFile(e.path().string()) : std::string("<folder>");
  }
  return all;
}

/// Names of the files in `dir` that are temporary files of an AtomicFile.
std::set<std::string> Temporaries(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (AtomicFile::IsTemporaryName(e.path().filename().string())) names.insert(e.path().filename().string());
  return names;
}

/// A precompute of the quick scene (milliseconds) into `out`.
std::string Precompute(const std::string& out) { return "precompute " + test::QuickScene() + " --out " + Q(out); }


/// The pid of a process that has exited and been reaped: no process has it (until reused).
pid_t GonePid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

/// Sets an environment variable for the scope (the long renders inherit it).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
    else ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

/// Starts a long render into `dir/out` with `--video video`, stops it with `sig` once frame 20
/// is staged, and checks that it ended by that signal and left no temporary file: none in the
/// output folder (no staging folder, no lock, no list: it wrote nothing there but the cache),
/// none beside the video, no ffmpeg log in $TMPDIR.
void CheckSignalLeavesNoTemporaries(const std::string& dir, const std::string& video, int sig) {
  const std::string tmp = dir + "/tmp";
  fs::create_directories(tmp);
  const ScopedEnv tmpdir("TMPDIR", tmp);
  const std::string out = dir + "/out";
  const pid_t pid = test::StartLongRender(out, "32x24", {"--video", video});
  REQUIRE(pid > 0);
  const int status = test::SignalWhenFileAppears(pid, out + "/" + OutputFolder::kStagingName + "/frame_0020.png", sig);
  REQUIRE(status != -1);
  CHECK(WIFSIGNALED(status));  // ended by the signal itself, after the cleanup
  CHECK(WTERMSIG(status) == sig);
  CHECK(fs::is_empty(tmp));  // ffmpeg's log
  CHECK(Temporaries(fs::path(video).parent_path().string()).empty());
  CHECK_FALSE(fs::exists(video));
  std::set<std::string> left;
  for (const auto& e : fs::directory_iterator(out)) left.insert(e.path().filename().string());
  CHECK(left == std::set<std::string>{"transport.cache"});  // valid on its own, written in place
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("files kept: an output over a file prt did not write is refused before any work, or kept as .orig") {
    // The course's framework ships light.txt and transport.txt in each cubemap folder.
    const std::string dir = test::ScratchDir("kept_course");
    std::ofstream(dir + "/light.txt") << "the course's light\n";
    std::ofstream(dir + "/transport.txt") << "the course's transport\n";
    std::ofstream(dir + "/posx.jpg") << "a face";
    const auto before = Snapshot(dir);
    const auto refused = test::RunPrt(Precompute(dir));
    CHECK(refused.exit_code == 1);
    CHECK(refused.err == "prt: error: " + dir + "/light.txt: exists and prt did not write it: this run would "
                         "replace it (expected another --out, or --replace to replace it and keep the old file as "
                         "light.txt.orig)\n");
    CHECK(Snapshot(dir) == before);  // no cache, no list, no lock: nothing happened

    // --replace: the originals kept as NAME.orig, and said so.
    const auto replaced = test::RunPrt(Precompute(dir) + " --replace");
    CAPTURE(replaced.err);
    CHECK(replaced.exit_code == 0);
    CHECK(replaced.err.find("outputs: replaced 2 files prt did not write in " + dir +
                            " (--replace), kept as light.txt.orig, transport.txt.orig") != std::string::npos);
    CHECK(ReadFile(dir + "/light.txt.orig") == "the course's light\n");
    CHECK(ReadFile(dir + "/transport.txt.orig") == "the course's transport\n");
    CHECK(ReadFile(dir + "/light.txt").rfind("the course's", 0) == std::string::npos);
    CHECK(ReadFile(dir + "/posx.jpg") == "a face");
    // Now they are prt's: the next run replaces them without --replace, the .orig untouched.
    const auto again = test::RunPrt(Precompute(dir) + " --albedo 0.5,0.5,0.5");
    CHECK(again.exit_code == 0);
    CHECK(ReadFile(dir + "/light.txt.orig") == "the course's light\n");

    // A NAME.orig already there is never overwritten.
    const std::string other = test::ScratchDir("kept_orig_exists");
    std::ofstream(other + "/light.txt") << "mine\n";
    std::ofstream(other + "/light.txt.orig") << "older\n";
    const auto blocked = test::RunPrt(Precompute(other) + " --replace");
    CHECK(blocked.exit_code == 1);
    CHECK(blocked.err.find(other + "/light.txt: --replace would keep it as light.txt.orig, which exists already") !=
          std::string::npos);
    CHECK(ReadFile(other + "/light.txt") == "mine\n");
    CHECK(ReadFile(other + "/light.txt.orig") == "older\n");

    // A render's --vertex-radiance file inside its folder is one of its planned outputs: refused
    // at once too, before the transport is computed (the run summary has not begun).
    const std::string frames = test::ScratchDir("kept_radiance");
    std::ofstream(frames + "/radiance.txt") << "mine\n";
    const auto radiance = test::RunPrt(test::QuickRender(frames, 1) + " --vertex-radiance " + test::Q(frames + "/radiance.txt"));
    CHECK(radiance.exit_code == 1);
    CHECK(radiance.err == "prt: error: " + frames + "/radiance.txt: exists and prt did not write it: this run would "
                          "replace it (expected another --out, or --replace to replace it and keep the old file as "
                          "radiance.txt.orig)\n");
    CHECK(ReadFile(frames + "/radiance.txt") == "mine\n");
  }

  TEST_CASE("files kept: a render never removes what a precompute delivered, nor a precompute the frames") {
    const std::string dir = test::ScratchDir("kept_commands");
    REQUIRE(test::RunPrt(Precompute(dir) + " --quiet").exit_code == 0);
    const std::string light = ReadFile(dir + "/light.txt"), transport = ReadFile(dir + "/transport.txt");
    const auto render = test::RunPrt(test::QuickRender(dir, 3));
    CAPTURE(render.err);
    CHECK(render.exit_code == 0);
    CHECK(render.err.find("outputs: removed") == std::string::npos);
    CHECK(render.err.find("transport: taken from the cache") != std::string::npos);  // precompute's, reused
    CHECK(ReadFile(dir + "/light.txt") == light);
    CHECK(ReadFile(dir + "/transport.txt") == transport);
    // The cache the render reused as it was stays the precompute's: a render without a cache
    // does not remove it.
    CHECK(ReadFile(dir + "/" + OutputFolder::kListName).find("precompute\ttransport.cache\n") != std::string::npos);
    CHECK(test::RunPrt(test::QuickRender(dir, 3) + " --cache none --quiet").exit_code == 0);
    CHECK(fs::exists(dir + "/transport.cache"));
    // A precompute keeps the frames; a render of fewer frames removes only its own extra ones.
    REQUIRE(test::RunPrt(Precompute(dir) + " --albedo 0.5,0.5,0.5 --quiet").exit_code == 0);
    CHECK(fs::exists(dir + "/frame_0002.png"));
    const auto fewer = test::RunPrt(test::QuickRender(dir, 1));
    CHECK(fewer.err.find("outputs: removed 2 files an earlier run of this command wrote in " + dir +
                         " and this one did not (frame_0001.png ... frame_0002.png)") != std::string::npos);
    CHECK(fs::exists(dir + "/light.txt"));
    CHECK(fs::exists(dir + "/transport.txt"));
    CHECK_FALSE(fs::exists(dir + "/frame_0001.png"));
    // The list says which command wrote what (the cache: the render, whose other albedo rewrote it).
    const std::string list = ReadFile(dir + "/" + OutputFolder::kListName);
    CHECK(list.find("precompute\tlight.txt\n") != std::string::npos);
    CHECK(list.find("render\tframe_0000.png\n") != std::string::npos);
    CHECK(list.find("render\ttransport.cache\n") != std::string::npos);
  }

  TEST_CASE("files kept: a NAME.orig that appears during the run is never overwritten, nor NAME lost") {
    const std::string dir = test::ScratchDir("kept_orig_late");
    std::ofstream(dir + "/a.txt") << "the user's a\n";
    {
      OutputFolder folder(dir, {"test", {"a.txt"}, true});
      WriteFileAtomic(folder.Output("a.txt"), "prt's a\n");
      std::ofstream(dir + "/a.txt.orig") << "the user's own backup\n";  // made while the run went on
      CHECK_THROWS_WITH_AS(folder.Finish(), doctest::Contains("which exists already"), Error);
    }
    CHECK(ReadFile(dir + "/a.txt") == "the user's a\n");
    CHECK(ReadFile(dir + "/a.txt.orig") == "the user's own backup\n");
  }

  TEST_CASE("files kept: output names with control characters or naming the folder's own files are refused") {
    const std::string dir = test::ScratchDir("kept_names");
    for (const std::string& option : {"--video " + Q(dir + "/a\nb.png"), "--vertex-radiance " + Q(dir + "/out/a\nlight.txt"),
                                      "--vertex-radiance " + Q(dir + "/out/frame_0000.png"),
                                      // A frame's name in any case: one file on a file system that ignores case.
                                      "--vertex-radiance " + Q(dir + "/out/FRAME_0001.PNG"),
                                      "--vertex-radiance " + Q(dir + "/out/.prt-lock")}) {
      CAPTURE(option);
      const auto r = test::RunPrt(test::QuickRender(dir + "/out", 1) + " " + option);
      CHECK(r.exit_code == 2);
      CHECK_FALSE(fs::exists(dir + "/out"));
    }
  }

  TEST_CASE("files kept: prt diff refuses an --out that is one of its inputs (exit 2)") {
    const std::string dir = test::ScratchDir("kept_diff");
    REQUIRE(test::RunPrt(test::QuickRender(dir, 2) + " --quiet").exit_code == 0);
    const std::string a = test::FramePath(dir, 0, 2), b = test::FramePath(dir, 1, 2);
    const std::string golden = ReadFile(a), other = ReadFile(b);
    for (const std::string& out : {a, b, dir + "/./" + fs::path(a).filename().string()}) {
      CAPTURE(out);
      const auto r = test::RunPrt("diff " + Q(a) + " " + Q(b) + " --out " + Q(out));
      CHECK(r.exit_code == 2);
      CHECK(r.err.find("--out: '" + out + "' is one of the images compared") != std::string::npos);
      CHECK(r.out.empty());  // refused before comparing
    }
    CHECK(ReadFile(a) == golden);
    CHECK(ReadFile(b) == other);
    // A link to an input is the input.
    fs::create_symlink(a, dir + "/link.png");
    CHECK(test::RunPrt("diff " + Q(a) + " " + Q(b) + " --out " + Q(dir + "/link.png")).exit_code == 2);
    CHECK(ReadFile(a) == golden);
  }

  TEST_CASE("files kept: a render's --video or --vertex-radiance may not be one of its inputs") {
    const std::string dir = test::ScratchDir("kept_render_inputs");
    const std::string mesh = dir + "/scene.obj";
    fs::copy_file(test::Fixture("obj/quad.obj"), mesh);
    const std::string mesh_bytes = ReadFile(mesh);
    const auto r = test::RunPrt("render --env furnace --mesh " + Q(mesh) + " --out " + Q(dir + "/out") +
                                " --vertex-radiance " + Q(mesh));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--vertex-radiance: '" + mesh + "' is an input of this run") != std::string::npos);
    CHECK(ReadFile(mesh) == mesh_bytes);
  }

  TEST_CASE("files kept: a run that fails leaves no trace, an existing folder exactly as it was") {
    const std::string dir = test::ScratchDir("kept_failed");
    const std::string bad = test::Fixture("obj/no_faces.obj");  // exists, fails when loaded
    // A folder that did not exist, two levels deep: neither level is left.
    for (const char* command : {"precompute", "render", "reference"}) {
      CAPTURE(command);
      const auto r = test::RunPrt(std::string(command) + " --env furnace --mesh " + Q(bad) + " --out " + Q(dir + "/new/p1"));
      CHECK(r.exit_code == 1);
      CHECK_FALSE(fs::exists(dir + "/new"));
    }
    // An empty folder stays empty; a folder with earlier outputs keeps them byte for byte (its
    // list included).
    fs::create_directories(dir + "/empty");
    CHECK(test::RunPrt("precompute --env furnace --mesh " + Q(bad) + " --out " + Q(dir + "/empty")).exit_code == 1);
    CHECK(fs::is_empty(dir + "/empty"));
    const std::string used = dir + "/used";
    REQUIRE(test::RunPrt(test::QuickRender(used, 2) + " --quiet").exit_code == 0);
    const auto before = Snapshot(used);
    CHECK(test::RunPrt("render --env furnace --mesh " + Q(bad) + " --out " + Q(used)).exit_code == 1);
    CHECK(Snapshot(used) == before);
    // A video's folders made for a run whose encoder then fails (a stand-in for ffmpeg that
    // lists the encoder and reads nothing) are removed again.
    fs::create_directories(dir + "/bin");
    std::ofstream(dir + "/bin/ffmpeg") << "#!/bin/sh\n"
                                          "case \"$*\" in *-encoders*) echo ' V....D libx264  H.264'; exit 0;; esac\n"
                                          "exit 3\n";
    fs::permissions(dir + "/bin/ffmpeg", fs::perms::owner_all);
    // The --vertex-radiance file outside the folder, written early, is renamed into place only
    // when the run succeeds.
    const auto video = test::RunCommand("PATH=" + Q(dir + "/bin") + ":\"$PATH\" " + Q(test::PrtBinary()) + " " +
                                        test::QuickRender(dir + "/v", 12, "64x48") + " --video " + Q(dir + "/videos/deep/turn.mp4") +
                                        " --vertex-radiance " + Q(dir + "/radiance.txt"));
    CHECK(video.exit_code == 1);
    CHECK_FALSE(fs::exists(dir + "/videos"));
    CHECK_FALSE(fs::exists(dir + "/radiance.txt"));
    CHECK(Temporaries(dir).empty());
  }

  TEST_CASE("files kept: --replace whose final move fails puts the user's file back under its own name") {
    // The move of the new transport.txt from staging into place fails (a preloaded rename()
    // that refuses it, tests/rename_fails.cpp), after the user's transport.txt was kept as
    // transport.txt.orig: the run fails, and the user's file is back as transport.txt.
    const std::string dir = test::ScratchDir("kept_replace_fails");
    std::ofstream(dir + "/transport.txt") << "the course's transport\n";
    // ASan checks that its runtime is the first library loaded; the stand-in is loaded before it.
    const auto r = test::RunCommand("LD_PRELOAD=" + Q(PRT_RENAME_FAILS_PATH) + " PRT_FAIL_RENAME_TO=/transport.txt "
                                    "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0\" " +
                                    Q(test::PrtBinary()) + " " + Precompute(dir) + " --replace");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find(dir + "/transport.txt: cannot write (") != std::string::npos);
    CHECK(ReadFile(dir + "/transport.txt") == "the course's transport\n");
    CHECK_FALSE(fs::exists(dir + "/transport.txt.orig"));
    CHECK(Temporaries(dir).empty());
    // The same run without the failing rename replaces it, keeping the user's as .orig.
    const auto good = test::RunPrt(Precompute(dir) + " --replace");
    CHECK(good.exit_code == 0);
    CHECK(ReadFile(dir + "/transport.txt.orig") == "the course's transport\n");
  }

  TEST_CASE("files kept: SIGTERM and SIGINT leave no temporary file, staging folder or lock (animated PNG)") {
    for (int sig : {SIGTERM, SIGINT}) {
      CAPTURE(sig);
      const std::string dir = test::ScratchDir(sig == SIGTERM ? "kept_sigterm" : "kept_sigint");
      CheckSignalLeavesNoTemporaries(dir, dir + "/k.png", sig);
    }
  }

  TEST_CASE("files kept: SIGTERM into a new nested --out with --cache none leaves none of the folders it made") {
    // The run makes new/a/b (three folders), its lock and its staging folder inside, and writes
    // nothing in place (no cache). Its cleanup must take the staging folder and the lock first,
    // then the folders innermost first: an outer folder removed before its content would stay.
    for (int sig : {SIGTERM, SIGINT}) {
      CAPTURE(sig);
      const std::string dir = test::ScratchDir(sig == SIGTERM ? "kept_nested_sigterm" : "kept_nested_sigint");
      std::ofstream(dir + "/mine.txt") << "the user's";
      const std::string out = dir + "/new/a/b";
      const pid_t pid = test::StartLongRender(out, "32x24", {"--cache", "none"});
      REQUIRE(pid > 0);
      const int status = test::SignalWhenFileAppears(pid, out + "/" + OutputFolder::kStagingName + "/frame_0020.png", sig);
      REQUIRE(status != -1);
      CHECK(WIFSIGNALED(status));
      CHECK(WTERMSIG(status) == sig);
      CHECK_FALSE(fs::exists(dir + "/new"));
      std::set<std::string> left;
      for (const auto& e : fs::directory_iterator(dir)) left.insert(e.path().filename().string());
      CHECK(left == std::set<std::string>{"mine.txt"});
    }
  }

  TEST_CASE("files kept: SIGTERM stops ffmpeg and leaves no partial .mp4 or ffmpeg log" * test::NeedsFfmpeg()) {
    const std::string dir = test::ScratchDir("kept_sigterm_mp4");
    CheckSignalLeavesNoTemporaries(dir, dir + "/k.mp4", SIGTERM);
  }

  TEST_CASE("files kept: a later run sweeps the temporaries SIGKILL left beside its single-file outputs") {
    const std::string dir = test::ScratchDir("kept_sigkill_sweep");
    const std::string gone = std::to_string(GonePid());
    const std::string tag = AtomicFile::kTemporaryTag;
    const std::set<std::string> stale = {".turn.png" + tag + gone + "_0", ".radiance.txt" + tag + gone + "_3",
                                         ".diff.png" + tag + gone + "_1"};
    for (const std::string& name : stale) std::ofstream(dir + "/" + name) << "partial";
    // Someone else's temporary-looking files, and a live process's, are not prt's to remove.
    const std::string live = ".turn.png" + tag + std::to_string(::getpid()) + "_0";
    std::ofstream(dir + "/" + live) << "being written";
    std::ofstream(dir + "/.other.png" + tag + gone + "_0") << "not an output of this run";
    std::ofstream(dir + "/.turn.png.tmp" + gone + "_0") << "someone else's, named like an older prt's";
    const auto r = test::RunPrt(test::QuickRender(dir + "/out", 2) + " --quiet --video " + Q(dir + "/turn.png") +
                                " --vertex-radiance " + Q(dir + "/radiance.txt"));
    CHECK(r.exit_code == 0);
    REQUIRE(test::RunPrt("diff " + Q(test::FramePath(dir + "/out", 0, 2)) + " " + Q(test::FramePath(dir + "/out", 1, 2)) +
                         " --max-abs 255 --out " + Q(dir + "/diff.png")).exit_code == 0);
    CHECK(Temporaries(dir) == std::set<std::string>{live, ".other.png" + tag + gone + "_0"});
    CHECK(fs::exists(dir + "/.turn.png.tmp" + gone + "_0"));
  }

  TEST_CASE("files kept: the same run twice gives the same bytes: frames, .png, .mp4 and .webm videos" *
            test::NeedsFfmpeg()) {
    const std::string dir = test::ScratchDir("kept_same_bytes");
    for (const char* extension : {"png", "mp4", "webm"}) {
      CAPTURE(extension);
      std::string bytes[2];
      for (int run = 0; run < 2; ++run) {
        const std::string video = dir + "/v" + std::to_string(run) + "." + extension;
        const auto r = test::RunPrt("render --env sky --samples 16 --frames 4 --size 32x24 --quiet --out " +
                                    Q(dir + "/f" + std::to_string(run)) + " --video " + Q(video));
        REQUIRE(r.exit_code == 0);
        bytes[run] = ReadFile(video);
      }
      CHECK(bytes[0].size() > 100);
      CHECK(bytes[0] == bytes[1]);
    }
    for (int i = 0; i < 4; ++i) CHECK(ReadFile(test::FramePath(dir + "/f0", i, 4)) == ReadFile(test::FramePath(dir + "/f1", i, 4)));
  }

  TEST_CASE("files kept: --size takes a capital X, and a path typo gets a did-you-mean") {
    const std::string dir = test::ScratchDir("kept_small_things");
    const auto size = test::RunPrt(test::QuickRender(dir + "/out", 1, "20X10") + " --quiet");
    CHECK(size.exit_code == 0);
    CHECK(fs::exists(dir + "/out/frame_0000.png"));
    test::WriteHdrCube(dir + "/cubemap/GraceCathedral", 4, [](int, int, int) { return glm::vec3(1.0f); });
    fs::copy_file(test::Fixture("obj/quad.obj"), dir + "/Mary.obj");
    const auto env = test::RunPrt("light --lmax 1 --env " + Q(dir + "/cubemap/Gracecathedral"));
    CHECK(env.exit_code == 1);
    CHECK(env.err.find("(did you mean " + dir + "/cubemap/GraceCathedral? expected a cubemap folder") !=
          std::string::npos);
    const auto mesh = test::RunPrt("render --env furnace --mesh " + Q(dir + "/mary.obj") + " --out " + Q(dir + "/o"));
    CHECK(mesh.exit_code == 1);
    CHECK(mesh.err.find("(did you mean " + dir + "/Mary.obj? expected an OBJ mesh for --mesh)") != std::string::npos);
    // A folder typo on the way to a file too; nothing near: no suggestion.
    const auto deep = test::RunPrt("render --env furnace --mesh " + Q(dir + "/cubemap/Grace/x.obj") + " --out " + Q(dir + "/o"));
    CHECK(deep.exit_code == 1);
    CHECK(deep.err.find("did you mean") == std::string::npos);
  }
}

}  // namespace prt
