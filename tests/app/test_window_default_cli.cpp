// The default window of render and demo (app/seen_ringing.h), through the program: the auto
// window where the frames would show the light's ringing, said on the light's summary line; an
// explicit --window honoured; precompute and light keep the raw light; and the ringing note's
// advice true for the window the run used. The scenes are the embedded knot and ground under the
// built-in sky with closed-form transport: a fraction of a second each. Under this sky the light
// itself rings at lmax 2 and 4 (the sun), its irradiance does not, and a phong:50 lobe shows
// about -9% of its peak at lmax 4.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "core/atomic_file.h"
#include "tests/test_process.h"

using namespace prt;
using namespace prt::test;

namespace {

/// A render of the embedded scene, closed-form transport, 2 frames of `size` at a fixed exposure
/// (so frames of two runs compare byte for byte), into the folder `out`.
RunResult Render(const std::string& out, const std::string& options, const std::string& command = "render",
                 const std::string& size = "32x24") {
  return RunPrt(command + " --cache none --transport unshadowed --frames 2 --size " + size + " --exposure 0 --out " +
                Q(out) + " " + options);
}

/// Frame 0 of the run into `out`.
std::string Frame0(const std::string& out) { return ReadFile(FramePath(out, 0, 2)); }

/// The line of the run summary that starts with `prefix` ("" if none).
std::string SummaryLine(const std::string& err, const std::string& prefix) {
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) return line;
  return "";
}

bool Has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kGlossy = "--lmax 4 --material phong:50,0.3 --albedo 0.6,0.6,0.6";

/// The glossy renders' scene: the small scene (the rule reads the light and the lobe, not the
/// mesh).
std::string GlossyScene() { return SmallSceneOption("window_default_small_scene"); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("default window: a glossy coat that would show the light's ringing gets the auto window") {
    const std::string dir = ScratchDir("window_default_glossy");
    const RunResult chosen = Render(dir + "/default", kGlossy + GlossyScene());
    REQUIRE_MESSAGE(chosen.exit_code == 0, chosen.err);
    const std::string line = SummaryLine(chosen.err, "light: ");
    CAPTURE(line);
    // Said with what went negative and how to keep the raw light. The irradiance of this light
    // does not ring (the next case): catches a rule that leaves the lobe out.
    CHECK(Has(line, "; window auto (default: the light seen through the glossy lobe goes down to -"));
    CHECK(Has(line, "--window none keeps the raw light): lowest radiance"));
    // --window none keeps the raw light: catches a default that overrides an explicit value.
    const RunResult raw = Render(dir + "/none", kGlossy + GlossyScene() + " --window none");
    REQUIRE(raw.exit_code == 0);
    CHECK_FALSE(Has(SummaryLine(raw.err, "light: "), "window"));
    // The window is applied, not only said (the frames differ from the raw light's), and it is
    // the auto window (the frames equal --window auto's).
    const RunResult asked = Render(dir + "/auto", kGlossy + GlossyScene() + " --window auto");
    REQUIRE(asked.exit_code == 0);
    CHECK(Frame0(dir + "/default") != Frame0(dir + "/none"));
    CHECK(Frame0(dir + "/default") == Frame0(dir + "/auto"));
    // demo has the same default. Catches a default given to render alone.
    const RunResult demo = Render(dir + "/demo", kGlossy, "demo");
    REQUIRE(demo.exit_code == 0);
    CHECK(Has(SummaryLine(demo.err, "light: "), "; window auto (default: the light seen through the glossy lobe"));
  }

  TEST_CASE("default window: a diffuse scene whose irradiance does not ring keeps the raw light") {
    const std::string dir = ScratchDir("window_default_diffuse");
    // The light itself rings here (--window auto has work to do on it)...
    const RunResult light = RunPrt("light --lmax 2 --window auto");
    REQUIRE(light.exit_code == 0);
    CHECK(Has(light.err, " with one: strength "));
    // ...but a diffuse surface shows its irradiance, which stays non-negative: no window, the same
    // frames as --window none. Catches a rule that checks the light rather than what is shown.
    const RunResult chosen = Render(dir + "/default", "--lmax 2");
    REQUIRE_MESSAGE(chosen.exit_code == 0, chosen.err);
    const std::string line = SummaryLine(chosen.err, "light: ");
    CAPTURE(line);
    CHECK(Has(line, "; no window needed (the irradiance stays non-negative)"));
    CHECK_FALSE(Has(line, "window auto"));
    REQUIRE(Render(dir + "/none", "--lmax 2 --window none").exit_code == 0);
    CHECK(Frame0(dir + "/default") == Frame0(dir + "/none"));
    // --view light shows the light itself, which rings: there the default windows it, and no
    // pixel comes out negative. Catches a rule blind to the view.
    const RunResult seen = Render(dir + "/view_light", "--lmax 2 --view light");
    REQUIRE(seen.exit_code == 0);
    CHECK(Has(SummaryLine(seen.err, "light: "), "; window auto (default: the light goes down to -"));
    CHECK(SummaryLine(seen.err, "ringing: ").empty());
  }

  TEST_CASE("default window: precompute and light keep the raw light (the course's files)") {
    // Under a sun of 1000 even the irradiance rings at lmax 2, so render's default would window
    // this light (checked first): precompute and light must not.
    const std::string sun = " --env sky:sun=1000 --lmax 2";
    const std::string dir = ScratchDir("window_default_precompute");
    const RunResult render = Render(dir + "/render", sun);
    REQUIRE(render.exit_code == 0);
    CHECK(Has(SummaryLine(render.err, "light: "), "; window auto (default: the irradiance goes down to -"));
    const std::string precompute = "precompute --quiet --transport unshadowed --mesh " +
                                   Q(Fixture("obj/tetra_no_normals.obj")) + sun + " --out ";
    for (const char* name : {"default", "none", "auto"}) {
      const std::string window = std::string(name) == "default" ? "" : std::string(" --window ") + name;
      REQUIRE(RunPrt(precompute + Q(dir + "/" + name) + window).exit_code == 0);
    }
    // light.txt as with --window none, not as with auto (the two differ for this light).
    // Catches render's default given to precompute.
    const std::string plain = ReadFile(dir + "/default/light.txt");
    CHECK(plain == ReadFile(dir + "/none/light.txt"));
    CHECK(plain != ReadFile(dir + "/auto/light.txt"));
    // The same for prt light. Catches it given to light.
    const RunResult light = RunPrt("light --quiet" + sun);
    const RunResult light_none = RunPrt("light --quiet --window none" + sun);
    REQUIRE(light.exit_code == 0);
    CHECK(light.out == light_none.out);
    CHECK(light.out == plain);
  }

  TEST_CASE("ringing note: its advice fits the window the run used") {
    const std::string dir = ScratchDir("ringing_note");
    // The raw light seen as itself rings: the auto window is the advice.
    const RunResult raw = Render(dir + "/raw", "--lmax 4 --view light --window none");
    REQUIRE(raw.exit_code == 0);
    const std::string raw_note = SummaryLine(raw.err, "ringing: ");
    CAPTURE(raw_note);
    CHECK(Has(raw_note, "clamped to 0; --window auto reduces it"));
    // With the auto window the light is non-negative; a sharp coat seen from an orbiting camera
    // still has negative pixels, made by the transfer matrices' truncation. The note must not
    // advise the window the run already used (the old note did).
    const RunResult windowed = Render(dir + "/auto", "--lmax 4 --material phong:1000,0.9 --albedo 0.1,0.1,0.1 "
                                                           "--env sky:sun=1000 --orbit 60 --window auto" + SmallSceneOption("ringing_note_scene"),
                                      "render", "64x48");
    REQUIRE(windowed.exit_code == 0);
    const std::string note = SummaryLine(windowed.err, "ringing: ");
    CAPTURE(note);
    CHECK(Has(note, "the light is already windowed: --window auto"));
    CHECK(Has(note, "transfer matrices of --orbit truncate"));
    CHECK(Has(note, "without --orbit"));
    CHECK_FALSE(Has(note, "--window auto reduces it"));
  }
}
