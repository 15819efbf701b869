// A frame's options have one set of limits on every road (render/frame_limits.h): what render's
// command line accepts at each edge, prt view's page accepts, and what one refuses the other
// refuses. Catches a limit written again on one road and changed there alone.
#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "app/commands.h"
#include "app/render_args.h"
#include "tests/test_support.h"
#include "view/frame_request.h"

namespace prt {
namespace {

/// True when `prt render OPTION VALUE --ssaa 1` is accepted (read, not run; one sample a pixel,
/// as the page's default, so that the size alone is at stake).
bool RenderAccepts(const std::string& option, const std::string& value) {
  std::vector<std::string> tokens = {option, value};
  if (option != "--ssaa") tokens.insert(tokens.end(), {"--ssaa", "1"});
  return test::ErrorMessage([&] {
           Args args("render", tokens, RenderSpec());
           ReadRenderOptions(args, RenderJobOptions{});
         }).empty();
}

/// True when the page's query `name=value` is accepted.
bool PageAccepts(const std::string& name, const std::string& value) {
  FrameRequest defaults;
  defaults.draw.width = 16, defaults.draw.height = 16, defaults.draw.ssaa = 1;
  ViewLimits limits;
  return test::ErrorMessage([&] { ParseFrameRequest({{name, value}}, defaults, limits); }).empty();
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("frame limits: render's command line and prt view's page accept and refuse the same edges") {
    struct Edge {
      const char* option;
      const char* query;
      std::vector<const char*> values;
    };
    const std::vector<Edge> edges = {
        {"--size", "size", {"1x1", "0x1", "16384x1", "16385x1", "1x16384", "1x16385"}},
        {"--ssaa", "ssaa", {"0", "1", "8", "9"}},
        {"--fov", "fov", {"0.0009", "0.001", "179", "179.01"}},
        {"--exposure", "exposure", {"-20.01", "-20", "20", "20.01"}},
        {"--start-angle", "angle", {"-1000001", "-1000000", "1000000", "1000001"}},
    };
    int accepted = 0, refused = 0;
    for (const Edge& e : edges)
      for (const char* v : e.values) {
        const std::string what = std::string(e.option) + " " + v;
        INFO(what);
        const bool render = RenderAccepts(e.option, v);
        CHECK(render == PageAccepts(e.query, v));
        (render ? accepted : refused) += 1;
      }
    CHECK(accepted == 11);  // each edge value inside on both roads, each outside refused on both
    CHECK(refused == 11);
  }
}

}  // namespace prt
