// Every option is checked before any work. Proof of the order: each bad option is given with a
// --mesh that cannot be loaded (a file without faces); had the mesh been loaded first, its error
// would be the one reported. Also: what is repaired rather than refused (a camera looking along
// world up, an unusable cache) and output paths that are created like render's folder.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "core/error.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

using test::Q;

/// A mesh whose loading fails: any error about it means it was loaded before the options.
std::string Unloadable() { return Q(test::Fixture("obj/no_faces.obj")); }

/// A quick scene: closed-form transport of a small mesh under the furnace, one tiny frame.
std::string Quick(const std::string& out) {
  return test::QuickScene() + " --frames 1 --size 32x24 --out " + Q(out);
}

void ExpectUsage(const std::string& arguments, const std::string& message) {
  const auto r = test::RunPrt(arguments);
  CAPTURE(arguments);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find(message) != std::string::npos);
  CHECK(r.err.find("no_faces.obj") == std::string::npos);  // the mesh was never loaded
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("fail fast: bad options are refused before the mesh is loaded") {
    const std::string out = test::ScratchDir("fail_fast") + "/out";
    const std::string render = "render --mesh " + Unloadable() + " --out " + Q(out);
    ExpectUsage(render + " --lmax 1 --view transport:4", "--view: transport:4 is out of range (expected 0 to 3 for lmax 1)");
    ExpectUsage(render + " --up 0,0,0", "--up: '0,0,0' is zero");
    ExpectUsage(render + " --eye 1,2,3 --target 1,2,3", "--eye: equals --target");
    ExpectUsage(render + " --eye 0,0,0 --target 0,1,0 --up 0,2,0", "--up: parallel to the view direction");
    ExpectUsage(render + " --fov 0", "--fov: '0' is out of range");
    ExpectUsage(render + " --size 10x0", "--size: '10x0' is out of range");
    ExpectUsage(render + " --size 10y4", "--size: '10y4' is not a size");
    ExpectUsage(render + " --frames 0x10", "--frames: '0x10' is not a number");
    ExpectUsage(render + " --exposure AUTO", "(expected a number from -20 to 20, or auto)");
    ExpectUsage(render + " --tonemap ACES", "did you mean aces?");
    ExpectUsage(render + " --albedo 1,2,3", "--albedo: '1,2,3' is out of range (expected R,G,B, each from 0 to 1)");
    ExpectUsage(render + " -frames 3", "'-frames': unknown option (options start with --; did you mean --frames?)");
    ExpectUsage(render + " --samples lots", "--samples: 'lots' is not a number");
    ExpectUsage(render + " --max-edge 0", "--max-edge: '0' is out of range");
    ExpectUsage(render + " --max-edge 200%", "--max-edge: '200%' is out of range");
    ExpectUsage(render + " --max-edge 2x%", "--max-edge: '2x%' is not a number");
    ExpectUsage(render + " --exposure bright", "--exposure: 'bright' is not a number");
    ExpectUsage("precompute --mesh " + Unloadable() + " --max-edge 2% --out " + Q(out), "--max-edge: not with precompute");
    // Built-in environments: parameters checked as values, names with the nearest one.
    ExpectUsage(render + " --env sky:sun=abc", "--env: sky:sun=abc: sun 'abc' is not a number");
    ExpectUsage(render + " --env sky:sun=5e9", "--env: sky:sun=5e9: sun '5e9' is out of range");
    ExpectUsage(render + " --env sky:sun", "--env: sky:sun: sun has no value");
    ExpectUsage(render + " --env sky:sun=1,sun=2", "sun is given twice");
    ExpectUsage(render + " --env furnace:0x10", "value '0x10' is not a number");
    ExpectUsage(render + " --env skyy", "(did you mean sky?)");
    // A cubemap folder is checked face by face (headers only) before the mesh is loaded.
    const auto faces = test::RunPrt(render + " --env " + Q(test::Fixture("cubemaps/missing_face")));
    CHECK(faces.exit_code == 1);
    CHECK(faces.err.find("missing face") != std::string::npos);
    CHECK(faces.err.find("no_faces.obj") == std::string::npos);
    ExpectUsage("reference --mesh " + Unloadable(), "--out DIR is required");
    // Input paths are checked before anything is loaded too.
    const auto missing = test::RunPrt("render --mesh /nonexistent/m.obj --out " + Q(out));
    CHECK(missing.exit_code == 1);
    CHECK(missing.err == "prt: error: /nonexistent/m.obj: no such file (expected an OBJ mesh for --mesh)\n");
    const auto env = test::RunPrt("render --env /nonexistent/sky.hdr --mesh " + Unloadable() + " --out " + Q(out));
    CHECK(env.exit_code == 1);
    CHECK(env.err.find("/nonexistent/sky.hdr: no such file") != std::string::npos);
    CHECK_FALSE(fs::exists(out));  // nothing was created for a refused run
    // A split too fine for the mesh is known once the mesh is loaded; the count is legible.
    const auto fine = test::RunPrt("render --mesh " + Q(test::Fixture("obj/tetra_no_normals.obj")) +
                                   " --max-edge 0.001% --out " + Q(out));
    CHECK(fine.exit_code == 1);
    CHECK(fine.err.find("would split the mesh into about ") != std::string::npos);
    CHECK(fine.err.find("18446744073709551615") == std::string::npos);
    const auto finer = test::RunPrt("render --max-edge 0.0000001% --out " + Q(out));
    CHECK(finer.err.find("is finer than float coordinates resolve on this mesh (expected more than ") !=
          std::string::npos);
  }

  TEST_CASE("fail fast: a camera looking along world up gets a perpendicular up, printed") {
    const std::string out = test::ScratchDir("camera_up") + "/out";
    const auto r = test::RunPrt("render " + Quick(out) + " --eye 0,10,0 --target 0,0,0");
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("--up 0,0,-1") != std::string::npos);
    CHECK(r.err.find("up 0,1,0 is parallel to the view, so up 0,0,-1 is used") != std::string::npos);
    // From below, the other way.
    const auto below = test::RunPrt("render " + Quick(out) + " --eye 0,-10,0 --target 0,0,0");
    CHECK(below.exit_code == 0);
    CHECK(below.err.find("--up 0,0,1") != std::string::npos);
  }

  TEST_CASE("fail fast: an unusable --cache is a warning naming the cause, and the run goes on") {
    const std::string dir = test::ScratchDir("cache_warn");
    const auto missing = test::RunPrt("render " + Quick(dir + "/a") + " --cache " + Q(dir + "/no/such/dir/t.cache"));
    CAPTURE(missing.err);
    CHECK(missing.exit_code == 0);
    CHECK(missing.err.find("prt: warning: --cache: " + dir + "/no/such/dir/t.cache: folder '" + dir +
                            "/no/such/dir' does not exist; going on without the cache") != std::string::npos);
    CHECK(fs::exists(dir + "/a/frame_0000.png"));
    const auto folder = test::RunPrt("render " + Quick(dir + "/b") + " --cache " + Q(dir));
    CHECK(folder.exit_code == 0);
    CHECK(folder.err.find("is a folder (expected a file name)") != std::string::npos);
    std::ofstream(dir + "/file") << "x";
    const auto under_file = test::RunPrt("render " + Quick(dir + "/c") + " --cache " + Q(dir + "/file/t.cache"));
    CHECK(under_file.exit_code == 0);
    CHECK(under_file.err.find("is a file, not a folder") != std::string::npos);
    // What exists at an explicit --cache and is not a prt cache is never replaced: a file the
    // user meant to keep, a pipe, a link (read if it is a matching cache, never replaced).
    std::ofstream(dir + "/notes.txt") << "my notes";
    const auto notes = test::RunPrt("render " + Quick(dir + "/e") + " --cache " + Q(dir + "/notes.txt"));
    CHECK(notes.exit_code == 0);
    CHECK(notes.err.find("notes.txt: exists and is not a prt transport cache: left as it is; going on without the "
                          "cache") != std::string::npos);
    CHECK(ReadFile(dir + "/notes.txt") == "my notes");
    REQUIRE(::mkfifo((dir + "/pipe").c_str(), 0644) == 0);
    const auto pipe = test::RunPrt("render " + Quick(dir + "/f") + " --cache " + Q(dir + "/pipe"));
    CHECK(pipe.exit_code == 0);
    CHECK(pipe.err.find("pipe: is not a regular file: left alone") != std::string::npos);
    CHECK(fs::is_fifo(dir + "/pipe"));
    // A usable explicit cache is written and reused.
    const auto write = test::RunPrt("render " + Quick(dir + "/d") + " --cache " + Q(dir + "/t.cache"));
    CHECK(write.exit_code == 0);
    CHECK(fs::exists(dir + "/t.cache"));
    const auto reuse = test::RunPrt("render " + Quick(dir + "/d") + " --cache " + Q(dir + "/t.cache"));
    CHECK(reuse.err.find("taken from the cache") != std::string::npos);
    fs::create_symlink(dir + "/t.cache", dir + "/link.cache");
    const auto link = test::RunPrt("render " + Quick(dir + "/g") + " --cache " + Q(dir + "/link.cache"));
    CHECK(link.err.find("is a symbolic link: the cache is read if it matches, but never replaced") != std::string::npos);
    CHECK(link.err.find("taken from the cache") != std::string::npos);
    CHECK(fs::is_symlink(dir + "/link.cache"));
  }

  TEST_CASE("fail fast: prt demo takes render's options (--cache none among them)") {
    const std::string out = test::ScratchDir("demo_options") + "/out";
    const auto r = test::RunPrt("demo --transport unshadowed --frames 1 --size 32x24 --cache none --out " + Q(out));
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    CHECK(fs::exists(out + "/frame_0000.png"));
    CHECK_FALSE(fs::exists(out + "/transport.cache"));
    CHECK(r.err.find("--target 0,1.5,0 --up 0,1,0 --fov 36") != std::string::npos);  // the demo's camera
  }

  TEST_CASE("fail fast: --out of basis and diff creates missing folders, other formats are refused") {
    const std::string dir = test::ScratchDir("out_folders");
    const auto basis = test::RunPrt("basis --lmax 1 --cell 32 --out " + Q(dir + "/new/deeper/basis.png"));
    CHECK(basis.exit_code == 0);
    CHECK(fs::exists(dir + "/new/deeper/basis.png"));
    const auto jpg = test::RunPrt("basis --out " + Q(dir + "/basis.jpg"));
    CHECK(jpg.exit_code == 2);
    CHECK(jpg.err.find("does not end in .png") != std::string::npos);
    CHECK_FALSE(fs::exists(dir + "/basis.jpg"));

    const std::string a = dir + "/new/deeper/basis.png";
    const auto diff = test::RunPrt("diff " + Q(a) + " " + Q(a) + " --out " + Q(dir + "/d/e/diff.png"));
    CHECK(diff.exit_code == 0);
    CHECK(fs::exists(dir + "/d/e/diff.png"));
    // A folder that cannot be made names the real cause, and the result line is printed anyway.
    std::ofstream(dir + "/blocker") << "x";
    const auto blocked = test::RunPrt("diff " + Q(a) + " " + Q(a) + " --out " + Q(dir + "/blocker/diff.png"));
    CHECK(blocked.exit_code == 2);
    CHECK(blocked.out.rfind("max_abs=0 ", 0) == 0);
    CHECK(blocked.err.find("'" + dir + "/blocker' is a file, expected a folder") != std::string::npos);
  }

  TEST_CASE("fail fast: write errors name their cause") {
    CHECK(WriteProblem("/x/y/z.png", ENOENT) == "folder '/x/y' does not exist");
    CHECK(WriteProblem("/x/y/z.png", EACCES) == "folder '/x/y' is not writable: permission denied");
    CHECK(WriteProblem("/x/y/z.png", EROFS) == "folder '/x/y' is on a read-only file system");
    CHECK(WriteProblem("/x/y/z.png", ENOSPC) == "disk full: no space left on the device of '/x/y'");
    const std::string dir = test::ScratchDir("write_cause");
    const std::string missing = dir + "/missing/f.txt: cannot write (folder '" + dir + "/missing' does not exist)";
    CHECK_THROWS_WITH_AS(WriteFileAtomic(dir + "/missing/f.txt", "x"), missing.c_str(), Error);
    // A folder that cannot be made names the deepest existing folder, the one that refused
    // (/proc takes no new entries, even from root).
    CHECK_THROWS_WITH_AS(CreateFolder("/proc/prt-test/sub"),
                         "/proc/prt-test/sub: cannot create the folder (folder '/proc' does not accept new files)", Error);
    // ENOENT is also what a folder that takes no new files answers (/proc): the folder exists.
    CHECK(WriteProblem(dir + "/f.txt", ENOENT) == "folder '" + dir + "' does not accept new files");
    std::ofstream(dir + "/plain") << "x";
    CHECK(WriteProblem(dir + "/plain/f.txt", ENOTDIR) == "'" + dir + "/plain' is a file, not a folder");
  }
}

}  // namespace prt
