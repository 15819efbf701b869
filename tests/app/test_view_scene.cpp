// prt view's scene (app/view_scene.h) in this process: the page may ask for every band the run
// computed (lmax up to --lmax, and transport:K of the last band), and what it draws there is
// prt render's frame of the command line the scene gives (render run in this process too); the
// error figures are each environment's own, as a scene that measured only the other
// environment's reference gives them.
#include <doctest/doctest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.h"
#include "app/view_scene.h"
#include "tests/app/small_view_setup.h"
#include "io/png_io.h"
#include "tests/test_support.h"
#include "view/frame_request.h"

namespace prt {
namespace {

ViewSetup SmallSetup(const std::string& name) { return test::SmallViewSetup(name, 3, 64); }

/// The words of a command line as a shell reads them (ShellWord's single quotes undone).
std::vector<std::string> Words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool quoted = false, any = false;
  for (char c : line) {
    if (c == '\'') {
      quoted = !quoted;
      any = true;
    } else if (c == ' ' && !quoted) {
      if (any) words.push_back(word);
      word.clear();
      any = false;
    } else {
      word += c;
      any = true;
    }
  }
  if (any) words.push_back(word);
  return words;
}

/// prt render's first frame of `command` (the scene's render command line), rendered in this
/// process into `dir`.
Image8 RenderedFrame(const std::string& command, const std::string& dir) {
  std::vector<std::string> words = Words(command);
  REQUIRE(words.size() > 2);
  REQUIRE(words[0] == "prt");
  REQUIRE(words[1] == "render");
  words.erase(words.begin(), words.begin() + 2);
  for (std::size_t i = 0; i + 1 < words.size(); ++i) {
    if (words[i] == "--out") words[i + 1] = dir;
    if (words[i] == "--frames") words[i + 1] = "1";
  }
  words.push_back("--quiet");
  REQUIRE(RunRender(words) == 0);
  return ReadPng(test::FramePath(dir, 0, 1));
}

/// The scene's error figure for `request`, once its reference is measured.
std::string MeasuredError(ViewScene& scene, const FrameRequest& request) {
  scene.MeasureReference(request);
  std::string json;
  const bool measured = test::WaitFor([&] {
    try {
      json = scene.ErrorJson(request);
      return true;
    } catch (const NotReady&) {
      return false;
    }
  });
  REQUIRE(measured);
  return json;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("prt view --lmax 3: the page may ask for lmax 3 and transport:15, and draws them as prt render --lmax 3 does") {
    ViewScene scene(SmallSetup("view_scene_bands"));
    scene.ComputeFirst();
    const ViewLimits& limits = scene.Limits();
    CHECK(limits.lmax == 3);
    CHECK(limits.coefficients == 16);  // (lmax + 1)^2: every coefficient of bands 0..3
    const auto request = [&](const std::vector<std::pair<std::string, std::string>>& query) {
      return ParseFrameRequest(query, scene.Defaults(), limits);  // throws when the limits refuse it
    };
    double ms = 0;
    const FrameRequest top = request({{"lmax", "3"}});
    const Image8 at3 = scene.Frame(top, &ms);
    const Image8 at2 = scene.Frame(request({{"lmax", "2"}}), &ms);
    CHECK(at3.rgb != at2.rgb);  // band 3 of the light is drawn
    CHECK(at3.rgb == RenderedFrame(scene.Command(top), test::ScratchDir("view_scene_bands_render")).rgb);

    // The last band's last coefficient: accepted, and drawn as render draws it.
    const FrameRequest last = request({{"view", "transport:15"}});
    const Image8 coefficient = scene.Frame(last, &ms);
    CHECK(coefficient.rgb == RenderedFrame(scene.Command(last), test::ScratchDir("view_scene_bands_render15")).rgb);
    CHECK(coefficient.rgb != scene.Frame(request({{"view", "transport:14"}}), &ms).rgb);
    CHECK_THROWS_AS(request({{"lmax", "4"}}), Error);
    CHECK_THROWS_AS(request({{"view", "transport:16"}}), Error);
  }

  TEST_CASE("prt view's error figures are each environment's own, whichever was measured first") {
    ViewSetup setup = SmallSetup("view_scene_envs");
    setup.envs = {"sky", "sky:sun=3,elevation=10,azimuth=200"};
    FrameRequest second;
    std::string first_figure, second_figure;
    {
      ViewScene scene(setup);
      scene.ComputeFirst();
      FrameRequest first = scene.Defaults();
      second = first;
      second.env = 1;
      first_figure = MeasuredError(scene, first);
      second_figure = MeasuredError(scene, second);
    }
    CHECK(first_figure != second_figure);
    // A scene that measured only environment 1's reference gives the same figure for it.
    ViewScene alone(setup);
    alone.ComputeFirst();
    CHECK(MeasuredError(alone, second) == second_figure);
  }
}

}  // namespace prt
