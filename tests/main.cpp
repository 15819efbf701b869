// The runner of every test program (one per tier, tests/CMakeLists.txt): doctest's, one
// TEST_SUITE per module of src/, with two rules
// about the tests that need ../shared/data (those decorated with test::NeedsSharedData()):
//
// - Skipped, never passed. Without the data they carry doctest's skip decorator, so a whole run
//   counts them as skipped. CTest runs each test case as its own process (the top-level CMakeLists.txt);
//   a run whose filter selects only such skipped cases exits with kSkipExit, which CTest reports
//   as "Skipped". Listing always names every case, so CTest knows them whether or not the data
//   is there.
// - Required where it must be there: with PRT_REQUIRE_SHARED_DATA=1 (CI sets it) a missing data
//   folder fails the run at once instead of skipping anything.
// A run whose filters select no test case at all fails: every CTest test names one case.
// The tests that need Debian's ffmpeg (test::NeedsFfmpeg()) follow the same two rules, with
// PRT_REQUIRE_FFMPEG=1, and so do those that need Debian's cmark-gfm (test::NeedsCmarkGfm()),
// with PRT_REQUIRE_CMARK_GFM=1, and those that need Debian's chromium (test::NeedsChromium()),
// with PRT_REQUIRE_CHROMIUM=1, and the slurm tier's (test::NeedsSlurm()), with PRT_REQUIRE_SLURM=1.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "tests/test_support.h"

namespace {

/// Whether the environment variable `name` is set to something other than "" or "0".
bool Required(const char* name) {
  const char* value = std::getenv(name);
  return value && *value && std::strcmp(value, "0") != 0;
}

/// The exit status CTest takes for "skipped" (SKIP_RETURN_CODE in the top-level CMakeLists.txt).
constexpr int kSkipExit = 77;

/// Counts the test cases that start, and the ones a count query selects.
struct Counter : doctest::IReporter {
  static inline bool run = false;  ///< false for queries (--list-test-cases, --count...)
  static inline int started = 0;
  static inline unsigned selected = 0;
  explicit Counter(const doctest::ContextOptions&) {}
  void report_query(const doctest::QueryData& q) override {
    if (q.run_stats) selected = q.run_stats->numTestCasesPassingFilters;
  }
  void test_run_start() override { run = true; }
  void test_run_end(const doctest::TestRunStats&) override {}
  void test_case_start(const doctest::TestCaseData&) override { ++started; }
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
  void test_case_skipped(const doctest::TestCaseData&) override {}
};
REGISTER_LISTENER("prt_counter", 1, Counter);

bool IsListing(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    for (const char* flag : {"--list-test-cases", "-ltc", "--dt-list-test-cases", "--dt-ltc"}) {
      if (std::strncmp(argv[i], flag, std::strlen(flag)) == 0) return true;
    }
  }
  return false;
}

/// How many test cases the command line's filters select when nothing is skipped.
unsigned SelectedWithoutSkipping(int argc, char** argv) {
  std::vector<const char*> args(argv, argv + argc);
  args.push_back("--no-skip");
  args.push_back("--count");  // a flag only: setOption would write --count=true, which is ignored
  std::ostringstream quiet;
  doctest::Context count(static_cast<int>(args.size()), args.data());
  count.setCout(&quiet);
  Counter::selected = 0;
  count.run();
  return Counter::selected;
}

}  // namespace

int main(int argc, char** argv) {
  // The program's name in its messages: one program per tier (prt_unit_tests, ...).
  const char* slash = std::strrchr(argv[0], '/');
  const char* self = slash ? slash + 1 : argv[0];
  if (Required("PRT_REQUIRE_SHARED_DATA") && !prt::test::SharedData()) {
    std::fprintf(stderr, "%s: PRT_REQUIRE_SHARED_DATA is set, but the course data (%s) is missing\n", self,
                 PRT_SHARED_DATA_DIR);
    return 1;
  }
  if (Required("PRT_REQUIRE_FFMPEG") && !prt::test::Ffmpeg()) {
    std::fprintf(stderr, "%s: PRT_REQUIRE_FFMPEG is set, but ffmpeg and ffprobe are not on PATH\n", self);
    return 1;
  }
  if (Required("PRT_REQUIRE_CMARK_GFM") && !prt::test::CmarkGfm()) {
    std::fprintf(stderr, "%s: PRT_REQUIRE_CMARK_GFM is set, but cmark-gfm is not on PATH\n", self);
    return 1;
  }
  if (Required("PRT_REQUIRE_SLURM") && !prt::test::SlurmAvailable()) {
    std::fprintf(stderr, "%s: PRT_REQUIRE_SLURM is set, but this is not root with slurmctld, slurmd, munged and sbatch on PATH\n", self);
    return 1;
  }
  if (Required("PRT_REQUIRE_CHROMIUM") && !prt::test::Chromium()) {
    std::fprintf(stderr, "%s: PRT_REQUIRE_CHROMIUM is set, but chromium or python3 is not on PATH\n", self);
    return 1;
  }
  int result = 0;
  {
    doctest::Context context(argc, argv);
    if (IsListing(argc, argv)) context.setOption("no-skip", true);
    result = context.run();
  }
  if (result == 0 && Counter::run && Counter::started == 0) {
    if (SelectedWithoutSkipping(argc, argv) == 0) {
      // A filter that matches nothing is an error, not a pass: a test registered under a name
      // that no longer selects its case (CTest's registration is stale, or a name was cut at a
      // character the registration mishandled) would otherwise pass without running.
      std::fprintf(stderr, "%s: no test case matches the filters\n", self);
      return 1;
    }
    std::printf("[%s] skipped: the selected test cases need the course data (%s), ffmpeg, cmark-gfm or chromium\n", self,
                PRT_SHARED_DATA_DIR);
    return kSkipExit;
  }
  return result;
}
