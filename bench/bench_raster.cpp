// `prt bench raster`: frames per second of the rasterizer at 1920x1080 on a procedural mesh of
// about 100k triangles with per-vertex colours, without and with PNG encoding. Built with
// -DPRT_BENCH_LLVMPIPE=ON it also draws the same triangles through Mesa's llvmpipe (OSMesa,
// legacy OpenGL), side by side in the same run, and compares the two images.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "core/error.h"
#include "core/parallel.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "io/png_io.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"

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
// Draws the scene with llvmpipe: same camera matrices, colours, depth test (GL_LESS, first
// drawn keeps ties, like ours) and black background. Returns the median seconds per frame and
// the image (row 0 at the top).
double DrawLlvmpipe(const Scene& s, int width, int height, int runs, Image8& image) {
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context) throw Error("llvmpipe: OSMesaCreateContextExt failed (expected OSMesa)");
  std::vector<unsigned char> rgba(4 * static_cast<std::size_t>(width) * height);
  if (!OSMesaMakeCurrent(context, rgba.data(), GL_UNSIGNED_BYTE, width, height))
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
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, indices);
  glEndList();
  const auto frame = [&] {
    glClearColor(0.f, 0.f, 0.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glCallList(list);
    glFinish();
  };
  const double seconds = MedianSeconds(runs, frame);
  image = Image8(width, height);
  for (std::size_t i = 0; i < image.rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = rgba[4 * i + c];
  glDeleteLists(list, 1);
  OSMesaDestroyContext(context);
  return seconds;
}

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

  // The parts of writing a frame, then the whole: draw, tone map, encode.
  Image8 image;
  const double t_tonemap = MedianSeconds(runs, [&] { image = ToneMap(frame->image).image; });
  std::size_t png_bytes = 0;
  const double t_encode = MedianSeconds(runs, [&] { png_bytes = EncodePng(image).size(); });
  const double t_png = MedianSeconds(runs, [&] {
    draw();
    png_bytes = EncodePng(ToneMap(frame->image).image).size();
  });
  Print("tonemap_ms", 1e3 * t_tonemap);
  Print("png_encode_ms", 1e3 * t_encode);
  Print("png_bytes", double(png_bytes));
  Print("raster_png_ms", 1e3 * t_png);
  Print("raster_png_fps", 1.0 / t_png);

  // A render loop that encodes on other threads while the next frame draws (up to two frames
  // in flight): frames per second over a run of frames, not a median.
  const int frames = std::max(8, 2 * runs);
  const auto start = std::chrono::steady_clock::now();
  std::deque<std::future<std::size_t>> in_flight;
  for (int f = 0; f < frames; ++f) {
    draw();
    auto tone_mapped = std::make_shared<Image8>(ToneMap(frame->image).image);
    if (in_flight.size() >= 2) in_flight.front().get(), in_flight.pop_front();
    in_flight.push_back(std::async(std::launch::async, [tone_mapped] { return EncodePng(*tone_mapped).size(); }));
  }
  for (auto& f : in_flight) f.get();
  const double t_loop = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Print("raster_png_pipelined_fps", frames / t_loop);

#ifdef PRT_BENCH_LLVMPIPE
  Image8 gl;
  const double t_gl = DrawLlvmpipe(scene, width, height, runs, gl);
  Print("llvmpipe_ms", 1e3 * t_gl);
  Print("llvmpipe_fps", 1.0 / t_gl);
  std::size_t lit = 0;  // pixels llvmpipe drew (the background is black, the colours are not)
  for (std::size_t i = 0; i < gl.rgb.size(); i += 3) lit += (gl.rgb[i] | gl.rgb[i + 1] | gl.rgb[i + 2]) != 0;
  Print("llvmpipe_covered_share", double(lit) / double(gl.rgb.size() / 3));
  Print("agreement_within_1_255", Agreement(Quantize(frame->image), gl));
  Print("ratio_fps_vs_llvmpipe", t_gl / t_draw);
#else
  (void)Quantize;
  Print("llvmpipe", "not built (configure with -DPRT_BENCH_LLVMPIPE=ON)");
#endif
  return 0;
}

}  // namespace prt::bench
