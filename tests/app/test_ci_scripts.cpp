// CI's own scripts: scripts/phase.sh (each step of .ci/run timed, the table at its end),
// scripts/sanitize.sh (which tests run under which sanitizer, built how), run with stand-ins for
// cmake and ctest that record how they were called, so nothing is built here, and .ci/run itself
// over stand-ins for the two scripts it calls.
#include <doctest/doctest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include <unistd.h>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;
using test::Q;

/// The modules of src/ with code that runs on more than one thread, read from their sources
/// independently of sanitize.sh's list: a thread, a parallel loop, an atomic, a mutex, a future,
/// or the HTTP library, whose server runs prt's handlers on its own pool.
std::set<std::string> ThreadedModules() {
  const std::regex threaded(
      R"(std::thread|std::jthread|Parallel[A-Z][a-z]*\(|std::atomic|std::mutex|condition_variable|std::async|std::future|httplib::)");
  std::set<std::string> modules;
  for (const auto& file : fs::recursive_directory_iterator(test::SourceDir() + "/src")) {
    if (!file.is_regular_file()) continue;
    const std::string module = fs::relative(file.path(), test::SourceDir() + "/src").begin()->string();
    if (std::regex_search(ReadFile(file.path().string()), threaded)) modules.insert(module);
  }
  return modules;
}

/// The labels sanitize.sh's `variable` (TSAN_LEFT_OUT, ASAN_LEFT_OUT) names.
std::set<std::string> LeftOut(const std::string& variable) {
  std::smatch m;
  const std::string script = ReadFile(test::SourceDir() + "/scripts/sanitize.sh");
  std::set<std::string> modules;
  if (!std::regex_search(script, m, std::regex("\n" + variable + "=\"([^\"]*)\""))) return modules;
  std::istringstream words(m[1].str());
  for (std::string w; words >> w;) modules.insert(w);
  return modules;
}

/// The modules (suites) of the tests of `tier` that the build beside these tests registered
/// (its prt_TIER_tests_cases.cmake: labels SUITE;TIER).
std::set<std::string> TierModules(const std::string& tier) {
  const std::string cases =
      ReadFile(fs::path(PRT_TEST_TMP_DIR).parent_path().string() + "/prt_" + tier + "_tests_cases.cmake");
  std::set<std::string> modules;
  const std::regex label(R"(LABELS \[==\[([^;\]]*);)" + tier + R"(\]==\])");
  for (auto it = std::sregex_iterator(cases.begin(), cases.end(), label); it != std::sregex_iterator(); ++it)
    modules.insert((*it)[1]);
  return modules;
}

/// The line of `log` that starts with `prefix` and contains `part` ("" if none).
std::string CallWith(const std::string& log, const std::string& prefix, const std::string& part) {
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(prefix, 0) == 0 && line.find(part) != std::string::npos) return line;
  return "";
}

/// Runs `bash scripts/sanitize.sh all` with stand-ins for cmake and ctest that record their
/// arguments (ctest its sanitizer options too) in a log, then run `cmake_tail` and `ctest_tail`.
/// Returns the exit status and the log.
std::pair<int, std::string> RunSanitize(const std::string& dir, const std::string& ctest_tail,
                                        const std::string& cmake_tail = "") {
  const std::string log = dir + "/calls.log", bin = dir + "/bin";
  fs::create_directories(bin);
  std::ofstream(bin + "/cmake") << "#!/bin/sh\necho \"cmake $*\" >> " << Q(log) << "\n" << cmake_tail;
  std::ofstream(bin + "/ctest") << "#!/bin/sh\necho \"ctest $* ASAN_OPTIONS=$ASAN_OPTIONS UBSAN_OPTIONS=$UBSAN_OPTIONS "
                                   "TSAN_OPTIONS=$TSAN_OPTIONS\" >> "
                                << Q(log) << "\n" << ctest_tail;
  for (const char* tool : {"/cmake", "/ctest"}) fs::permissions(bin + tool, fs::perms::owner_all);
  // PRT_PHASE_LOG emptied: under .ci/run these steps are not CI's phases.
  // PRT_BUILD_DIR: a Release folder of the test's own, so that the smoke set's program is looked
  // for there and not in the checkout's build/.
  const std::string release = dir.substr(dir.rfind('/') + 1) + "_release";
  const auto r = test::RunCommand("cd " + Q(test::SourceDir()) + " && PATH=" + Q(bin) + ":\"$PATH\" PRT_BUILD_DIR=" +
                                  Q(release) + " PRT_PHASE_LOG= bash scripts/sanitize.sh all");
  return {r.exit_code, fs::exists(log) ? ReadFile(log) : ""};
}

/// The value the stand-in ctest recorded for the environment variable `name` in `call`.
std::string Value(const std::string& call, const std::string& name) {
  const auto at = call.find(" " + name + "=");
  if (at == std::string::npos) return "";
  const auto begin = at + name.size() + 2;
  return call.substr(begin, call.find(' ', begin) - begin);
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("ci phases: each step timed with its status, the table totals them, a failed step keeps its exit status") {
    // scripts/phase.sh, as .ci/run, quickstart.sh and sanitize.sh use it, on a stand-in clock:
    // `date` prints the time held in a file and each step moves it on, so a phase is timed
    // exactly (7 s and 2 s) and only if the clock is read before and after its command.
    const std::string dir = test::ScratchDir("ci_phases");
    const std::string log = dir + "/phases.tsv", clock = dir + "/clock", bin = dir + "/bin";
    fs::create_directories(bin);
    std::ofstream(clock) << "1000\n";
    std::ofstream(bin + "/date") << "#!/bin/sh\ncat " << Q(clock) << "\n";
    fs::permissions(bin + "/date", fs::perms::owner_all);
    std::ofstream(dir + "/steps.sh") << "source scripts/phase.sh\n"
                                     << "phase 'first step' sh -c 'echo 1007 > \"$1\"' - " << Q(clock) << "\n"
                                     << "phase second sh -c 'echo 1009 > \"$1\"; exit 3' - " << Q(clock) << "\n"
                                     << "echo \"status $?\"\n"
                                     << "phase_table \"$PRT_PHASE_LOG\"\n";
    const auto r = test::RunCommand("cd " + Q(test::SourceDir()) + " && PATH=" + Q(bin) + ":\"$PATH\" PRT_PHASE_LOG=" +
                                    Q(log) + " bash " + Q(dir + "/steps.sh"));
    CAPTURE(r.out);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("status 3\n") != std::string::npos);  // the step's own status, not 1
    CHECK(ReadFile(log) == "first step\t7\tok\nsecond\t2\tfailed\n");
    // The table: a row per step, the failed one marked, and their total.
    CHECK(r.out.find("first step") != std::string::npos);
    CHECK(r.out.find("(failed)") != std::string::npos);
    const auto total = r.out.find("total");
    REQUIRE(total != std::string::npos);
    CHECK(std::stoi(r.out.substr(r.out.find_first_of("0123456789", total))) == 9);
  }


  TEST_CASE("sanitize.sh: ASan + UBSan builds and runs the unit and threads tiers, TSan the threads tier, both -O1 -g1, each with its smoke set") {
    const std::string dir = test::ScratchDir("ci_sanitize");
    const auto [exit_code, calls] = RunSanitize(dir, "");
    REQUIRE(exit_code == 0);
    CAPTURE(calls);

    // Both builds: -O1 -g1, each with its own sanitizer and only its tiers' programs (the whole
    // folder is built: prt and those programs), the smoke set's program the Release build's.
    const std::string asan_build = CallWith(calls, "cmake -S", "-DPRT_SANITIZE=ON");
    const std::string tsan_build = CallWith(calls, "cmake -S", "-DPRT_TSAN=ON");
    for (const std::string& call : {asan_build, tsan_build}) {
      CAPTURE(call);
      CHECK(call.find("-O1 -g1") != std::string::npos);
      CHECK(call.find("-DPRT_SMOKE_DRIVER=" + test::SourceDir() + "/" + dir.substr(dir.rfind('/') + 1) +
                      "_release/prt_e2e_tests") != std::string::npos);
    }
    // A new folder: Ninja, which logs each compile; one configured before keeps its generator.
    for (const auto& [call, folder] : {std::pair<std::string, std::string>{asan_build, "build-asan"}, {tsan_build, "build-tsan"}}) {
      CAPTURE(folder);
      const bool fresh = !fs::exists(test::SourceDir() + "/" + folder + "/CMakeCache.txt");
      CHECK((call.find(" -G Ninja ") != std::string::npos) == fresh);
    }
    CHECK(asan_build.find("-DPRT_TEST_TIERS=unit;threads ") != std::string::npos);
    CHECK(tsan_build.find("-DPRT_TEST_TIERS=threads ") != std::string::npos);
    CHECK(CallWith(calls, "cmake --build build-asan", "") != "");
    CHECK(CallWith(calls, "cmake --build build-tsan", "") != "");
    // The smoke set's program built (nothing to do when CI's Release build has it).
    CHECK(CallWith(calls, "cmake --build ", "--target prt_e2e_tests") != "");

    // Each suite: every test its folder registers (its tiers and its smoke set); reports fatal,
    // no second of sleep at every exit under TSan.
    const std::string asan = CallWith(calls, "ctest --test-dir build-asan", "");
    REQUIRE(asan != "");
    CHECK(asan.find("--label") == std::string::npos);
    CHECK(Value(asan, "ASAN_OPTIONS").find("abort_on_error=1") != std::string::npos);
    CHECK(Value(asan, "ASAN_OPTIONS").find("detect_leaks=1") != std::string::npos);
    CHECK(Value(asan, "UBSAN_OPTIONS").find("halt_on_error=1") != std::string::npos);
    const std::string tsan = CallWith(calls, "ctest --test-dir build-tsan", "");
    REQUIRE(tsan != "");
    CHECK(tsan.find("--label") == std::string::npos);
    CHECK(Value(tsan, "TSAN_OPTIONS").find("halt_on_error=1") != std::string::npos);
    CHECK(Value(tsan, "TSAN_OPTIONS").find("atexit_sleep_ms=0") != std::string::npos);
  }

  TEST_CASE("sanitize.sh: every module with threaded code, whoever starts its threads, has tests in the threads tier that TSan runs, or a reason") {
    const std::set<std::string> threads_tier = TierModules("threads");
    REQUIRE(threads_tier.count("core") == 1);
    const std::string script = ReadFile(test::SourceDir() + "/scripts/sanitize.sh");
    const std::set<std::string> left_out = LeftOut("TSAN_LEFT_OUT"), threaded = ThreadedModules();
    // The HTTP library's pool runs prt view's handlers: its module counts though it starts no
    // thread of its own.
    CHECK(threaded.count("view") == 1);
    CHECK(threaded.count("app") == 1);  // view_scene's workers
    for (const std::string& module : threaded) {
      CAPTURE(module);
      if (left_out.count(module)) {
        CHECK(script.find("# - " + module + ": ") != std::string::npos);  // its reason
      } else {
        CHECK(threads_tier.count(module) == 1);
      }
    }
    CHECK(left_out.size() <= 2);  // the two measured and explained; a third needs its reason here too
  }

  TEST_CASE("sanitize.sh: a failing sanitized suite fails the run, and ThreadSanitizer does not start after it") {
    const std::string dir = test::ScratchDir("ci_sanitize_fails");
    // ctest fails (a test found a report) in the ASan + UBSan build.
    const auto [exit_code, calls] = RunSanitize(dir, "case \"$*\" in *build-asan*) exit 8 ;; esac\n");
    CAPTURE(calls);
    CHECK(exit_code != 0);
    CHECK(calls.find("ctest --test-dir build-asan") != std::string::npos);
    CHECK(calls.find("build-tsan") == std::string::npos);
  }

  TEST_CASE("sanitize.sh: a failed sanitized build fails the run before its suite, and nothing after it starts") {
    const std::string dir = test::ScratchDir("ci_sanitize_build_fails");
    // The compiler fails building the ASan + UBSan objects.
    const auto [exit_code, calls] =
        RunSanitize(dir, "", "case \"$*\" in *--build\\ build-asan*) exit 2 ;; esac\n");
    CAPTURE(calls);
    CHECK(exit_code != 0);
    CHECK(calls.find("cmake --build build-asan") != std::string::npos);
    CHECK(calls.find("ctest") == std::string::npos);
    CHECK(calls.find("build-tsan") == std::string::npos);
  }

  TEST_CASE("quickstart.sh test: its last line counts the skipped tests and says what they lack") {
    // quickstart.sh and the scripts it runs, copied into a tree whose package installer is a
    // stand-in, with stand-ins for cmake and ctest: ctest prints what CTest prints of `skipped`
    // tests that did not run, then exits with $STAND_IN.
    const std::string tree = test::ScratchDir("quickstart_skipped"), bin = tree + "/bin";
    fs::create_directories(tree + "/scripts");
    fs::create_directories(bin);
    fs::create_directories(tree + "/build");  // what cmake's configure step would make
    for (const char* script : {"quickstart.sh", "phase.sh", "configure.sh", "skipped-tests.sh", "slowest-tests.sh", "slowest-files.sh"})
      fs::copy_file(test::SourceDir() + "/scripts/" + script, tree + "/scripts/" + script);
    std::ofstream(tree + "/scripts/install-deps.sh") << "true\n";
    std::ofstream(bin + "/cmake") << "#!/bin/sh\ntrue\n";
    // The default suite's run skips two; the readme tier's run (--label-regex) skips none.
    std::ofstream(bin + "/ctest") << "#!/bin/sh\n"
                                     "case \"$*\" in *--label-regex*) echo '100% tests passed, 0 tests failed out of 1'; "
                                     "exit ${STAND_IN_README:-$STAND_IN} ;; esac\n"
                                     "echo '1/5 Test #12: obj: mary from the course data .......***Skipped   0.01 sec'\n"
                                     "echo '2/5 Test #40: readme: the course commands ..........***Skipped   0.01 sec'\n"
                                     "echo '100% tests passed, 0 tests failed out of 5'\n"
                                     "echo 'The following tests did not run:'\n"
                                     "echo '\t 12 - obj: mary from the course data (Skipped)'\n"
                                     "echo '\t 40 - readme: the course commands (Skipped)'\n"
                                     "exit $STAND_IN\n";
    for (const char* tool : {"/cmake", "/ctest"}) fs::permissions(bin + tool, fs::perms::owner_all);
    for (const int status : {0, 8}) {
      CAPTURE(status);
      const auto r = test::RunCommand("cd " + Q(tree) + " && STAND_IN=" + std::to_string(status) + " PATH=" + Q(bin) +
                                      ":\"$PATH\" PRT_SHARED_DATA=none PRT_PHASE_LOG= bash scripts/quickstart.sh test");
      CAPTURE(r.out);
      CHECK(r.exit_code == status);  // the suite's status, the line printed all the same
      std::string out = r.out;
      while (!out.empty() && out.back() == '\n') out.pop_back();
      const std::string last = out.substr(out.rfind('\n') + 1);
      CHECK(last.rfind("tests: 2 skipped, not passed, for want of the course's files (../shared/data", 0) == 0);
    }
    // The readme tier's run alone fails: so does the command.
    const auto readme = test::RunCommand("cd " + Q(tree) + " && STAND_IN=0 STAND_IN_README=7 PATH=" + Q(bin) +
                                         ":\"$PATH\" PRT_SHARED_DATA=none PRT_PHASE_LOG= bash scripts/quickstart.sh test");
    CHECK(readme.exit_code == 7);
    // Nothing skipped: said as well.
    std::ofstream(tree + "/none.log") << "100% tests passed, 0 tests failed out of 5\n";
    const auto none = test::RunCommand("bash " + Q(tree + "/scripts/skipped-tests.sh") + " " + Q(tree + "/none.log"));
    CHECK(none.exit_code == 0);
    CHECK(none.out == "tests: none skipped\n");
    // What is lacking, each by its own check, on a PATH that holds only what the script needs
    // (and, the second time, stand-ins for ffmpeg, cmark-gfm, chromium, python3 and Slurm's
    // daemons and clients).
    const std::string log = tree + "/build/suite.log", tools = tree + "/tools";
    fs::create_directories(tools);
    for (const char* tool : {"grep", "dirname"}) {
      const auto where = test::RunCommand(std::string("command -v ") + tool);
      REQUIRE(where.exit_code == 0);
      fs::create_symlink(where.out.substr(0, where.out.find('\n')), tools + "/" + tool);
    }
    const auto lacking = [&](const std::string& data) {
      const auto r = test::RunCommand("PATH=" + Q(tools) + " PRT_SHARED_DATA=" + Q(data) + " /bin/bash " +
                                      Q(tree + "/scripts/skipped-tests.sh") + " " + Q(log));
      CHECK(r.exit_code == 0);
      return r.out;
    };
    const std::string missing = tree + "/no-such-data";
    CHECK(lacking(missing) == "tests: 2 skipped, not passed, for want of the course's files (../shared/data, beside the "
                              "clone; a fresh clone does not have them), ffmpeg, cmark-gfm, chromium, python3" +
                              std::string(::geteuid() == 0 ? ", " : ", root with ") + "Slurm (slurm-wlm, munge); "
                              "tests/README.md says what each needs\n");
    for (const char* tool : {"ffmpeg", "cmark-gfm", "chromium", "python3", "slurmctld", "slurmd", "munged", "sbatch", "sinfo"}) {
      std::ofstream(tools + "/" + tool) << "#!/bin/sh\n";
      fs::permissions(tools + "/" + tool, fs::perms::owner_all);
    }
    if (::geteuid() == 0)  // the slurm tier needs root as well
      CHECK(lacking(tree) == "tests: 2 skipped, not passed, for want of what they compare with; tests/README.md says what "
                             "each needs\n");
  }

  TEST_CASE("slowest-tests.sh: each tier's seconds against its budget in the column of the folder's pass, OVER when beyond it") {
    // A folder of the ASan + UBSan pass (its CMakeCache says so): two unit cases, a smoke case of
    // the e2e tier (labels suite;e2e;smoke) and a readme case, which that pass has no budget for.
    const std::string dir = test::ScratchDir("ci_slowest_tests"), build = dir + "/build";
    fs::create_directories(build + "/Testing/Temporary");
    std::ofstream(build + "/CMakeCache.txt") << "PRT_SANITIZE:BOOL=ON\nPRT_TSAN:BOOL=OFF\n";
    std::ofstream(build + "/Testing/Temporary/LastTest.log") << "1/4 Test: a\nTest time =  30.00 sec\n"
                                                                "2/4 Test: b\nTest time =  15.00 sec\n"
                                                                "3/4 Test: c\nTest time =   8.00 sec\n"
                                                                "4/4 Test: d\nTest time =   2.00 sec\n";
    std::ofstream(build + "/prt_unit_tests_cases.cmake")
        << "set_tests_properties([==[a]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[core;unit]==] TIMEOUT 60)\n"
           "set_tests_properties([==[b]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[sh;unit]==] TIMEOUT 60)\n";
    std::ofstream(build + "/prt_smoke_cases.cmake")
        << "set_tests_properties([==[c]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[app;e2e;smoke]==] TIMEOUT 60 "
           "ENVIRONMENT [==[PRT_BINARY=/x]==])\n";
    std::ofstream(build + "/prt_readme_tests_cases.cmake")
        << "set_tests_properties([==[d]==] PROPERTIES WORKING_DIRECTORY [==[x]==] LABELS [==[readme;readme]==] TIMEOUT 60)\n";
    // Each pass's column its own number: the unit tier (45 s) is within ASan's 50 but over
    // Release's 40 and TSan's 44; the e2e tier (8 s) is over ASan's 7.
    std::ofstream(dir + "/budgets.md") << "### Budgets\n\n| tier | program | Release | ASan + UBSan | TSan |\n|---|---|---|---|---|\n"
                                          "| `unit` | prt_unit_tests | 40 | 50 | 44 |\n| `e2e` | prt_e2e_tests | 300 | 7 | 6 |\n"
                                          "| `readme` | prt_readme_tests | 350 | – | – |\n";
    const auto r = test::RunCommand("PRT_BUDGET_TABLE=" + Q(dir + "/budgets.md") + " bash " +
                                    Q(test::SourceDir() + "/scripts/slowest-tests.sh") + " " + Q(build) + " 2");
    CAPTURE(r.out);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("The slowest 2 of 4 test cases") != std::string::npos);
    CHECK(r.out.find("(ASan + UBSan pass;") != std::string::npos);
    CHECK(r.out.find("\n  unit          2         45         50\n") != std::string::npos);
    CHECK(r.out.find("\n  e2e           1          8          7  OVER\n") != std::string::npos);
    CHECK(r.out.find("\n  readme        1          2       none  (no budget for this pass)\n") != std::string::npos);
    // The same folder as TSan's: its column.
    std::ofstream(build + "/CMakeCache.txt") << "PRT_SANITIZE:BOOL=OFF\nPRT_TSAN:BOOL=ON\n";
    const auto tsan = test::RunCommand("PRT_BUDGET_TABLE=" + Q(dir + "/budgets.md") + " bash " +
                                       Q(test::SourceDir() + "/scripts/slowest-tests.sh") + " " + Q(build));
    CAPTURE(tsan.out);
    CHECK(tsan.out.find("(TSan pass;") != std::string::npos);
    CHECK(tsan.out.find("\n  unit          2         45         44  OVER\n") != std::string::npos);
    // tests/README.md's own table: every tier with a budget in the Release column.
    const std::string readme = ReadFile(test::SourceDir() + "/tests/README.md");
    for (const char* tier : {"unit", "threads", "e2e", "readme"}) {
      CAPTURE(tier);
      const auto row = readme.find(std::string("\n| `") + tier + "` | `prt_" + tier + "_tests` | ", readme.find("### Budgets"));
      REQUIRE(row != std::string::npos);
      CHECK(std::isdigit(static_cast<unsigned char>(readme[readme.find("_tests` | ", row) + 10])));
    }
  }

  TEST_CASE("mutants.py: a mutant is caught by whichever tier's program fails, the readme's too, or by a crash; one that no program notices survives") {
    // A project of its own: four programs named as the tiers' are, each failing when the header
    // it reads holds another number (the e2e program crashes instead), and four mutants.
    const std::string tree = test::ScratchDir("ci_mutants");
    fs::create_directories(tree + "/scripts");
    fs::create_directories(tree + "/src");
    fs::create_directories(tree + "/tests");
    fs::copy_file(test::SourceDir() + "/scripts/mutants.py", tree + "/scripts/mutants.py");
    std::ofstream(tree + "/CMakeLists.txt")
        << "cmake_minimum_required(VERSION 3.20)\nproject(fake C)\n"
           "foreach(tier unit threads e2e readme)\n"
           "  add_executable(prt_${tier}_tests src/${tier}.c)\n"
           "  target_include_directories(prt_${tier}_tests PRIVATE src)\n"
           "endforeach()\n";
    for (const char* tier : {"unit", "threads", "readme"})
      std::ofstream(tree + "/src/" + tier + ".c") << "#include \"" << tier << ".h\"\nint main(void) { return VALUE == 1 ? 0 : 1; }\n";
    std::ofstream(tree + "/src/e2e.c") << "#include <stdlib.h>\n#include \"e2e.h\"\nint main(void) { if (VALUE != 1) abort(); return 0; }\n";
    for (const char* tier : {"unit", "threads", "e2e", "readme"}) std::ofstream(tree + "/src/" + tier + ".h") << "#define VALUE 1\n";
    std::ofstream(tree + "/src/unused.h") << "#define UNUSED 1\n";
    std::ofstream(tree + "/tests/mutants.txt")
        << "=== seen by unit\nsrc/unit.h\n<<<\n#define VALUE 1\n>>>\n#define VALUE 2\n===\n\n"
           "=== seen by readme alone\nsrc/readme.h\n<<<\n#define VALUE 1\n>>>\n#define VALUE 2\n===\n\n"
           "=== a crash in e2e\nsrc/e2e.h\n<<<\n#define VALUE 1\n>>>\n#define VALUE 3\n===\n\n"
           "=== seen by nobody\nsrc/unused.h\n<<<\n#define UNUSED 1\n>>>\n#define UNUSED 2\n===\n";
    const auto r = test::RunCommand("python3 " + Q(tree + "/scripts/mutants.py"));
    CAPTURE(r.out);
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);  // one survived
    CHECK(r.out.find("CAUGHT    seen by unit") != std::string::npos);
    CHECK(r.out.find("CAUGHT    seen by readme alone") != std::string::npos);
    CHECK(r.out.find("CAUGHT    a crash in e2e") != std::string::npos);
    CHECK(r.out.find("SURVIVED  seen by nobody") != std::string::npos);
    CHECK(r.out.find("3 of 4 mutants caught") != std::string::npos);
    // The project itself is never touched: the mutants were applied to a copy.
    CHECK(ReadFile(tree + "/src/unit.h") == "#define VALUE 1\n");
  }

  TEST_CASE("slowest-files.sh: each target's compiler seconds and the slowest files of the last build, from Ninja's log") {
    const std::string dir = test::ScratchDir("ci_slowest_files");
    // Ninja's log (start and end in ms, mtime, output, hash); a file compiled twice counts once,
    // at its latest time; links and other steps are not compiles.
    std::ofstream(dir + "/.ninja_log") << "# ninja log v5\n"
                                          "0\t9000\t1\tCMakeFiles/prtcore.dir/src/a.cpp.o\tx\n"
                                          "0\t2500\t1\tCMakeFiles/prtcore.dir/src/b.cpp.o\tx\n"
                                          "0\t5000\t1\ttests/CMakeFiles/prt_unit_tests.dir/core/t.cpp.o\tx\n"
                                          "0\t30000\t1\tprt_unit_tests\tx\n"
                                          "0\t1500\t2\tCMakeFiles/prtcore.dir/src/a.cpp.o\tx\n";
    const auto r = test::RunCommand("bash " + Q(test::SourceDir() + "/scripts/slowest-files.sh") + " " + Q(dir) + " 2");
    CAPTURE(r.out);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find(": 9 s over 3 files (prt_unit_tests 5 s, prtcore 4 s)") != std::string::npos);
    CHECK(r.out.find("The 2 slowest to compile:\n     5.0 s  core/t.cpp\n     2.5 s  src/b.cpp\n") != std::string::npos);
    // A folder of another generator: said, not an error.
    const std::string other = test::ScratchDir("ci_slowest_files_make");
    const auto none = test::RunCommand("bash " + Q(test::SourceDir() + "/scripts/slowest-files.sh") + " " + Q(other));
    CHECK(none.exit_code == 0);
    CHECK(none.out.find("no compile times") != std::string::npos);
  }

  TEST_CASE("install-deps: what it installs to build, and to test (ffmpeg, cmark-gfm, chromium, python3)") {
    // As a user who is not root on a machine that has none of them: the script names what is
    // missing and stops, which shows its lists without installing anything.
    const std::string tree = test::ScratchDir("install_deps"), bin = tree + "/bin";
    fs::create_directories(bin);
    std::ofstream(bin + "/dpkg-query") << "#!/bin/sh\nexit 1\n";
    std::ofstream(bin + "/id") << "#!/bin/sh\necho 1000\n";
    for (const char* tool : {"/dpkg-query", "/id"}) fs::permissions(bin + tool, fs::perms::owner_all);
    const auto missing = [&](const std::string& argument) {
      const auto r = test::RunCommand("PATH=" + Q(bin) + ":\"$PATH\" bash " + Q(test::SourceDir() + "/scripts/install-deps.sh") +
                                      " " + argument);
      CHECK(r.exit_code == 1);
      return r.err.substr(0, r.err.find('\n'));
    };
    const std::string build = missing(""), test_set = missing("test");
    for (const char* package : {"g++", "cmake", "ninja-build", "libglm-dev", "libopenexr-dev", "libcpp-httplib-dev"}) {
      CHECK(build.find(std::string(" ") + package) != std::string::npos);
      CHECK(test_set.find(std::string(" ") + package) != std::string::npos);
    }
    for (const char* package : {"ffmpeg", "cmark-gfm", "chromium", "python3"}) {
      CAPTURE(package);
      CHECK(build.find(std::string(" ") + package) == std::string::npos);
      CHECK(test_set.find(std::string(" ") + package) != std::string::npos);
    }
  }

  TEST_CASE("ci run: its phase table holds the steps of the scripts it calls, and its last line says how it ended") {
    // .ci/run, copied into a tree whose quickstart.sh and sanitize.sh are stand-ins: each times
    // one step through the real scripts/phase.sh; the sanitizers' step exits with $STAND_IN.
    const std::string tree = test::ScratchDir("ci_run");
    fs::create_directories(tree + "/.ci");
    fs::create_directories(tree + "/scripts");
    fs::copy_file(test::SourceDir() + "/.ci/run", tree + "/.ci/run");
    fs::copy_file(test::SourceDir() + "/scripts/phase.sh", tree + "/scripts/phase.sh");
    std::ofstream(tree + "/scripts/quickstart.sh") << "source scripts/phase.sh\nphase \"stand-in build\" true\n";
    std::ofstream(tree + "/scripts/sanitize.sh")
        << "source scripts/phase.sh\nphase \"stand-in sanitizers\" bash -c \"exit $STAND_IN\"\n";
    for (const int status : {0, 5}) {
      CAPTURE(status);
      // A run of under a second: within a budget of a minute, over one of -1 s.
      const int budget = status == 0 ? 60 : -1;
      const auto r = test::RunCommand("STAND_IN=" + std::to_string(status) + " PRT_CI_BUDGET=" + std::to_string(budget) +
                                      " bash " + Q(tree + "/.ci/run"));
      CAPTURE(r.out);
      CHECK((r.exit_code == 0) == (status == 0));
      CHECK(r.out.find("stand-in build") != std::string::npos);
      CHECK(r.out.find("stand-in sanitizers") != std::string::npos);
      CHECK(r.out.find("\ntotal") != std::string::npos);
      const auto last = r.out.rfind("CI: ");
      REQUIRE(last != std::string::npos);
      const std::string line = r.out.substr(last, r.out.find('\n', last) - last);
      CHECK(line.find(status == 0 ? " s in all (budget 60 s), passed" : " s in all (budget -1 s, OVER), FAILED (exit 5)") !=
            std::string::npos);
    }
  }
}

}  // namespace prt
