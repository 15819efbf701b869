// prt view in a real browser: tests/view/browser_check.py and browser_controls_check.py drive
// Debian's chromium, headless, over the DevTools Protocol (scripts/cdp.py); these cases run them
// on the small scene.
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

TEST_CASE("prt view's controls in chromium: the slider follows a touch drag, the orbit stops at the pole and the ground, "
          "the command follows every setting, controls that change nothing say why, each environment's error its own" *
          NeedsChromium()) {
  const std::string dir = ScratchDir("view_browser_controls");
  const std::string script = SourceDir() + "/tests/view/browser_controls_check.py";
  const RunResult r = RunCommand("python3 " + Q(script) + " " + Q(PrtBinary()) + " " + Q(WriteSmallScene(dir)) + " " +
                                 Q(dir));
  INFO(r.err);
  CHECK(r.exit_code == 0);
  for (const char* said : {"the turn slider follows a touch drag", "an orbit past the pole stops", "an orbit down stops at the ground",
                           "reset camera draws the first camera", "the command line follows exposure",
                           "the command line follows tonemap", "the command line follows lmax",
                           "the command line follows an orbit", "are disabled and say why",
                           "a basis and a mode chosen at once", "under wavelets lmax and the transport view are disabled",
                           "names the wavelet light's terms", "at the reference's own noise says so",
                           "a computation the server refuses is said", "listed by its file name",
                           "explained in their titles", "ssaa 4 is over the frame's samples",
                           "160 x 120 at ssaa 3 is drawn as prt render draws it",
                           "after switching the environment, the error is not the other one's",
                           "each environment's error is its own", "an error answer for the environment left behind is dropped",
                           "every request of the page carries the run's token", "no console error over the whole session"})
    CHECK(r.err.find(said) != std::string::npos);
  CHECK(r.err.find("FAILED") == std::string::npos);
}

}  // TEST_SUITE

}  // namespace prt::test
