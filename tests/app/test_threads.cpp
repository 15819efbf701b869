// The threads tier of src/app (tests/README.md, "Tiers"): prt view's scene (app/view_scene.h) in
// this process. Its background computations (another transport mode, the reference's error
// figures) run on the scene's kViewWorkers threads (core/task_pool.h) while the server's threads
// draw frames of the mode that is ready; a frame of the mode being computed is refused (NotReady)
// until it is ready, then drawn; more jobs than workers wait their turn and finish; and a scene
// that goes while a computation runs waits for it. ThreadSanitizer watches the workers, the
// drawing threads and the pool meet.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "app/view_scene.h"
#include "tests/app/small_view_setup.h"
#include "tests/threads_util.h"

namespace prt {
namespace {

ViewSetup SmallSetup(const std::string& name) { return test::SmallViewSetup(name, 2, 16); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("threads: prt view's scene computes a mode and a reference in the background while threads draw the mode that is ready") {
    const test::ThreadCountScope pool(test::kManyThreads);
    ViewScene scene(SmallSetup("threads_view_scene"));
    scene.ComputeFirst();
    const FrameRequest shadowed = scene.Defaults();
    REQUIRE(shadowed.mode == "shadowed");
    FrameRequest bounced = shadowed;
    bounced.mode = "interreflection";
    double ms = 0;
    const Image8 first = scene.Frame(shadowed, &ms);

    scene.Compute("sh", "interreflection");
    scene.MeasureReference(shadowed);
    constexpr int kDrawers = 3, kFrames = 6;
    std::atomic<int> differing{0};
    test::OnThreads(kDrawers, [&](int) {
      for (int i = 0; i < kFrames; ++i) {
        double draw_ms = 0;
        if (scene.Frame(shadowed, &draw_ms).rgb != first.rgb) ++differing;
        scene.StateJson();
      }
    });
    CHECK(differing == 0);  // the same request draws the same bytes, whoever draws it

    // The mode computed in the background: refused until ready, then drawn.
    const bool ready = test::WaitFor([&] {
      try {
        scene.Frame(bounced, &ms);
        return true;
      } catch (const NotReady&) {
        return false;
      }
    });
    CHECK(ready);
    const bool measured = test::WaitFor([&] {
      try {
        return scene.ErrorJson(shadowed).find("\"error\":") != std::string::npos;
      } catch (const NotReady&) {
        return false;
      }
    });
    CHECK(measured);
  }

  TEST_CASE("threads: prt view's scene queues more background jobs than it has workers, and finishes each") {
    const test::ThreadCountScope pool(test::kManyThreads);
    ViewScene scene(SmallSetup("threads_view_scene_queue"));
    scene.ComputeFirst();
    // Two transports and three references on kViewWorkers (2) threads, asked for from threads
    // of their own as the server's would.
    std::vector<FrameRequest> requests;
    for (const char* mode : {"unshadowed", "shadowed", "interreflection"}) {
      FrameRequest r = scene.Defaults();
      r.mode = mode;
      requests.push_back(r);
    }
    test::OnThreads(static_cast<int>(requests.size()), [&](int t) {
      scene.Compute("sh", requests[std::size_t(t)].mode);
      scene.MeasureReference(requests[std::size_t(t)]);
    });
    for (const FrameRequest& r : requests) {
      CAPTURE(r.mode);
      const bool finished = test::WaitFor([&] {
        try {
          return scene.ErrorJson(r).find("\"error\":") != std::string::npos;  // the transport's and the reference's
        } catch (const NotReady&) {
          return false;
        }
      });
      CHECK(finished);
    }
    const std::string state = scene.StateJson();
    for (const char* unfinished : {"computing", "measuring", "failed"})
      CHECK(state.find(std::string("\"state\":\"") + unfinished + "\"") == std::string::npos);
  }

  TEST_CASE("threads: a view scene that goes while a background computation runs waits for it") {
    const test::ThreadCountScope pool(test::kManyThreads);
    ViewSetup setup = SmallSetup("threads_view_scene_gone");
    setup.scene.samples = 256;  // a computation that is still running when the scene goes
    ViewScene scene(setup);
    scene.ComputeFirst();
    scene.Compute("sh", "interreflection");
    scene.MeasureReference(scene.Defaults());
  }
}

}  // namespace prt
