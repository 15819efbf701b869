// The threads tier of src/render (tests/README.md, "Tiers"): the frame pipeline. RenderFrames
// draws each frame with the pool (rasterizer, shading, fused tone map) while FrameWriter's
// encoder threads write the frames before it and the video takes them in order; on one thread
// and on more threads than cores every frame file and the video are the same bytes.
// ThreadSanitizer watches the many-thread run. (FrameWriter's own threads: test_frame_writer.cpp.)
#include <doctest/doctest.h>

#include <string>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "env/procedural.h"
#include "precompute/light.h"
#include "precompute/transport.h"
#include "render/render_frames.h"
#include "sh_basis/frame_light.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/threads_util.h"
#include "video/video_writer.h"

namespace prt {

TEST_SUITE("render") {
  TEST_CASE("threads: the frame pipeline writes the same frames and video on 1 and many threads") {
    const Mesh mesh = test::SphereOverPlane();
    TransportOptions o;
    o.samples = 64;
    const Transport transport = ComputeTransport(mesh, o, nullptr);
    const auto sky = MakeSky(SkyParams{});
    const ShRgb light = ProjectLight(*sky, 2);
    RenderOptions options;
    options.frames = 6;
    options.width = 96, options.height = 72;
    const Camera camera = ChooseCamera(mesh, options);
    const std::string dir = test::ScratchDir("threads_frames");
    const auto run = [&](const std::string& name) {
      const std::string out = dir + "/" + name;
      std::vector<std::string> names;
      for (int i = 0; i < options.frames; ++i) names.push_back(FrameName(i, options.frames));
      names.push_back("turn.png");
      OutputFolder folder(out, OutputPlan{"render", names});
      VideoSpec spec;
      spec.format = VideoFormat::kApng, spec.width = options.width, spec.height = options.height;
      spec.frames = options.frames, spec.fps = 10;
      VideoWriter video(spec, folder.Output("turn.png"), "turn.png");
      const auto frame_light = MakeShFrameLight(transport, light, glm::dvec3(0, 1, 0));
      RenderFrames(mesh, *frame_light, *sky, camera, options, folder, &video);
      video.Finish();
      folder.Finish();
      std::string bytes;
      for (const std::string& file : names) bytes += ReadFile(out + "/" + file);
      return bytes;
    };
    const auto [one, many] = test::OneAndMany([&, n = 0]() mutable { return run("run" + std::to_string(n++)); });
    CHECK(one == many);
  }
}

}  // namespace prt
