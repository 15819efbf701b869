// `prt bench raster`: frames per second of the rasterizer at 1920x1080 on a procedural mesh of
// about 100k triangles with per-vertex colours; tone mapping against drawing (fused into the
// bands, and as a pass of its own); PNG encoding at several zlib levels; the whole render loop
// (draw and tone map, encode) at 1920x1080 and 640x480, with its page faults per frame. Built with
// -DPRT_BENCH_LLVMPIPE=ON it also draws the same triangles through Mesa's llvmpipe (OSMesa,
// legacy OpenGL), side by side in the same run, and compares the two images.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "core/memory.h"
#include "core/error.h"
#include "core/parallel.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "io/png_io.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"
#include "render/frame_writer.h"

#ifdef PRT_BENCH_LLVMPIPE
#include <GL/osmesa.h>
#include <glm/gtc/type_ptr.hpp>
#endif

namespace prt::bench {
namespace {

struct Scene {
  Mesh mesh;
  std::vector<glm::vec3> colors;  // linear RGB in [0, 1], from the normals
  Camera camera;
};

Scene MakeScene(float aspect) {
  Scene s;
  // A (2, 3) torus knot: 2 * 1024 * 50 = 102,400 triangles with deep self-occlusion.
  s.mesh = MakeTorusKnot(2, 3, 0.16f, 1024, 50);
  for (const glm::vec3& n : s.mesh.normals) s.colors.push_back(0.5f * n + 0.5f);
  const Bounds3 b = MeshBounds(s.mesh);
  s.camera = FrameBounds(b.lo, b.hi, aspect);
  return s;
}

// "WxH" -> (W, H), or a UsageError.
void ParseSize(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  const auto w = ParseNumber(text.substr(0, x)), h = ParseNumber(text.substr(x + 1));
  if (x == std::string::npos || !w || !h || *w < 1 || *h < 1 || *w > 8192 || *h > 8192 ||
      *w != int(*w) || *h != int(*h))
    throw UsageError("--size: '" + text + "' (expected WxH, each 1 to 8192)", "bench");
  width = int(*w);
  height = int(*h);
}

// 8-bit linear quantisation, as an RGBA8 OpenGL framebuffer stores colours.
Image8 Quantize(const ImageF& image) {
  Image8 out(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = std::min(std::max(image.pixels[i][c], 0.f), 1.f);
      out.rgb[3 * i + c] = static_cast<std::uint8_t>(v * 255.f + 0.5f);
    }
  return out;
}

#ifdef PRT_BENCH_LLVMPIPE
// The scene drawn by llvmpipe: same camera matrices, colours, depth test (GL_LESS, first drawn
// keeps ties, like ours) and black background. Draw() draws one frame; Image() reads it back
// (row 0 at the top).
class Llvmpipe {
 public:
  Llvmpipe(const Scene& s, int width, int height)
      : width_(width), height_(height), rgba_(4 * static_cast<std::size_t>(width) * height) {
    context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!context_) throw Error("llvmpipe: OSMesaCreateContextExt failed (expected OSMesa)");
    if (!OSMesaMakeCurrent(context_, rgba_.data(), GL_UNSIGNED_BYTE, width, height))
      throw Error("llvmpipe: OSMesaMakeCurrent failed");
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 of the buffer is the top of the picture
    const float aspect = float(width) / float(height);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(glm::value_ptr(ProjectionMatrix(s.camera, aspect)));
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(glm::value_ptr(ViewMatrix(s.camera)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, s.mesh.positions.data());
    glColorPointer(3, GL_FLOAT, 0, s.colors.data());
    const auto* indices = s.mesh.triangles.data()->data();
    const auto count = static_cast<GLsizei>(3 * s.mesh.triangles.size());
    // Geometry in a display list, so that each frame only draws.
    list_ = glGenLists(1);
    glNewList(list_, GL_COMPILE);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, indices);
    glEndList();
  }
  ~Llvmpipe() {
    glDeleteLists(list_, 1);
    OSMesaDestroyContext(context_);
  }
  void Draw() const {
    glClearColor(0.f, 0.f, 0.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glCallList(list_);
    glFinish();
  }
  Image8 Image() const {
    Image8 image(width_, height_);
    for (std::size_t i = 0; i < image.rgb.size() / 3; ++i)
      for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = rgba_[4 * i + c];
    return image;
  }

 private:
  int width_, height_;
  std::vector<unsigned char> rgba_;
  OSMesaContext context_ = nullptr;
  GLuint list_ = 0;
};

// Share of pixels whose channels all agree within 1/255.
double Agreement(const Image8& a, const Image8& b) {
  std::size_t agree = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    bool ok = true;
    for (int c = 0; c < 3; ++c) ok = ok && std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])) <= 1;
    agree += ok;
  }
  return double(agree) / double(a.rgb.size() / 3);
}
#endif

// The render loop as `prt render` runs it (render/render_frames.cpp): each frame drawn and tone
// mapped band by band into an image of the frame writer's, which encodes it on its own threads
// (to memory here; render also writes the file), one frame in flight per thread. Frames per
// second are a median over `runs` loops of kLoopFrames frames after a warm-up loop; page faults
// are counted over the timed loops' frames, so that 0 means no frame touches fresh memory once
// the loop's buffers exist (the warm-up loop makes them: the first frame of a size, and the
// frame writer's slots).
constexpr int kLoopFrames = 12;
struct LoopResult {
  double fps = 0.0;
  double faults_per_frame = 0.0;
};
LoopResult RenderLoop(const Scene& scene, int width, int height, int runs) {
  Rasterizer rasterizer;
  FrameWriter writer(ThreadCount(), nullptr);
  const ToneMapOptions tone;
  std::uint64_t faults = 0, frames = 0;
  int next = 0;
  bool warm = false;  // MedianSeconds's first call is its warm-up
  const double seconds = MedianSeconds(runs, [&] {
    const std::uint64_t before = MinorPageFaults();
    for (int f = 0; f < kLoopFrames; ++f) {
      RasterOptions options;
      options.tone_map = &tone;
      options.tone_mapped = &writer.Next(next);
      options.keep_linear = false;
      rasterizer.Draw(scene.camera, width, height, scene.mesh.positions, scene.mesh.triangles, scene.colors, options);
      writer.Submit("");
      ++next;
    }
    writer.Finish();
    if (warm) {
      faults += MinorPageFaults() - before;
      frames += kLoopFrames;
    }
    warm = true;
  });
  return {kLoopFrames / seconds, double(faults) / double(frames)};
}

}  // namespace

int BenchRaster(Args& args) {
  const int runs = args.Int("--runs", 5, 1, 1000);
  const int threads = args.Int("--threads", 0, 0, 1024);
  int width = 1920, height = 1080;
  ParseSize(args.String("--size", "1920x1080"), width, height);
  SetThreadCount(threads);

  const Scene scene = MakeScene(float(width) / float(height));
  Print("raster_triangles", double(scene.mesh.triangles.size()));
  Print("raster_size", std::to_string(width) + "x" + std::to_string(height));
  Print("raster_threads", double(ThreadCount()));

  // Frames as a render loop draws them: one Rasterizer reusing its buffers.
  Rasterizer rasterizer;
  const RasterImage* frame = nullptr;
  const auto draw = [&] {
    frame = &rasterizer.Draw(scene.camera, width, height, scene.mesh.positions,
                             scene.mesh.triangles, scene.colors);
  };
  const double t_draw = MedianSeconds(runs, draw);
  double covered = 0.0;
  for (float c : frame->coverage) covered += c;
  Print("raster_covered_share", covered / double(frame->coverage.size()));
  Print("raster_ms", 1e3 * t_draw);
  Print("raster_fps", 1.0 / t_draw);

  // Tone mapping against drawing, side by side: fused into the drawing's bands (the added time),
  // and as a pass of its own over the finished frame.
  Image8 image;
  const ToneMapOptions tone;
  RasterOptions fused;
  fused.tone_map = &tone;
  fused.tone_mapped = &image;
  const auto draw_with = [&](const RasterOptions& options) {
    rasterizer.Draw(scene.camera, width, height, scene.mesh.positions, scene.mesh.triangles, scene.colors, options);
  };
  const SideBySide with_tone = TimeSideBySide(runs, draw, [&] { draw_with(fused); });
  Print("tonemap_ms", 1e3 * (with_tone.theirs - with_tone.ours));
  Print("tonemap_share_of_draw", with_tone.ratio - 1.0);  // median over pairs of (fused - draw) / draw
  draw();
  const SideBySide separate = TimeSideBySide(runs, draw, [&] { ToneMapInto(frame->image, tone, image); });
  Print("tonemap_separate_ms", 1e3 * separate.theirs);
  Print("tonemap_separate_share_of_draw", separate.ratio);
  // The render loop's frame: the 8-bit image straight from the bands, no linear frame kept.
  RasterOptions render_frame = fused;
  render_frame.keep_linear = false;
  const SideBySide loop_frame = TimeSideBySide(runs, draw, [&] { draw_with(render_frame); });
  Print("render_frame_ms", 1e3 * loop_frame.theirs);
  Print("ratio_render_frame_vs_raster", loop_frame.ratio);  // < 1: faster than the linear frame alone
  draw();

  // zlib levels on this frame: time (one thread) and size; frames use kPngLevel.
  PngEncoder encoder;  // as the render loop keeps one per thread
  for (int level : {1, 2, 3, 4, 6}) {
    std::size_t bytes = 0;
    const double t = MedianSeconds(runs, [&] { bytes = encoder.Encode(image, level).size(); });
    const std::string key = "png_level_" + std::to_string(level);
    Print(key + "_ms", 1e3 * t);
    Print(key + "_bytes", double(bytes));
  }
  Print("png_level_used", double(kPngLevel));

  // The whole render loop, at this size and at 640x480.
  const LoopResult loop = RenderLoop(scene, width, height, runs);
  Print("render_loop_fps", loop.fps);
  Print("render_loop_page_faults_per_frame", loop.faults_per_frame);
  const Scene small = MakeScene(640.f / 480.f);
  const LoopResult small_loop = RenderLoop(small, 640, 480, runs);
  Print("render_loop_640x480_fps", small_loop.fps);
  Print("render_loop_640x480_page_faults_per_frame", small_loop.faults_per_frame);

#ifdef PRT_BENCH_LLVMPIPE
  // Ours and llvmpipe alternating, frame for frame (OpenGL calls stay on this thread).
  const Llvmpipe gl(scene, width, height);
  const SideBySide vs = TimeSideBySide(runs, draw, [&] { gl.Draw(); });
  const SideBySide vs_loop = TimeSideBySide(runs, [&] { draw_with(render_frame); }, [&] { gl.Draw(); });
  draw();  // the linear frame again, for the comparison of the images
  const Image8 gl_image = gl.Image();
  Print("llvmpipe_ms", 1e3 * vs.theirs);
  Print("llvmpipe_fps", 1.0 / vs.theirs);
  std::size_t lit = 0;  // pixels llvmpipe drew (the background is black, the colours are not)
  for (std::size_t i = 0; i < gl_image.rgb.size(); i += 3)
    lit += (gl_image.rgb[i] | gl_image.rgb[i + 1] | gl_image.rgb[i + 2]) != 0;
  Print("llvmpipe_covered_share", double(lit) / double(gl_image.rgb.size() / 3));
  Print("agreement_within_1_255", Agreement(Quantize(frame->image), gl_image));
  Print("ratio_fps_vs_llvmpipe", vs.ratio);
  // Both ending in an 8-bit frame: the render loop's (sRGB, tone mapped) against llvmpipe's.
  Print("ratio_render_frame_fps_vs_llvmpipe", vs_loop.ratio);
#else
  (void)Quantize;
  Print("llvmpipe", "not built (configure with -DPRT_BENCH_LLVMPIPE=ON)");
#endif
  return 0;
}

}  // namespace prt::bench
