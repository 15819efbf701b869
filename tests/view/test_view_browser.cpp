// prt view in a real browser: tests/view/browser_check.py drives Debian's chromium, headless,
// over the DevTools Protocol (scripts/cdp.py); this case runs it on the small scene.
#include "tests/test_process.h"

namespace prt::test {

TEST_SUITE("view") {

TEST_CASE("prt view in chromium: no console error, a drag turns the light as render does, lmax switches, frame rate shown" *
          NeedsChromium()) {
  const std::string dir = ScratchDir("view_browser");
  const std::string script = SourceDir() + "/tests/view/browser_check.py";
  const RunResult r = RunCommand("python3 " + Q(script) + " " + Q(PrtBinary()) + " " + Q(WriteSmallScene(dir)) + " " +
                                 Q(dir));
  INFO(r.err);
  CHECK(r.exit_code == 0);
  // Each check the script makes is named; none may be missing from its report.
  for (const char* said : {"no console error", "turned the light by 45 degrees", "prt render's of the same light",
                           "still render's picture", "the drags composed", "--start-angle 10", "the measured exposure", "the transport view on the page", "from the oldest input", "prt render --lmax 1", "changed the picture",
                           "shows its frame rate", "the page shows the error", "more bands, less error",
                           "interactive quality while it moved", "in order, on one stream", "the stream's reason",
                           "reopened one stream",
                           "draws the mode it shows and says which", "not posted again and again",
                           "sent again with the next message",
                           "an end said twice opens one stream", "overtaken by a later one gives way"})
    CHECK(r.err.find(said) != std::string::npos);
  CHECK(r.err.find("FAILED") == std::string::npos);
}

}  // TEST_SUITE

}  // namespace prt::test
