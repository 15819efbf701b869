// prt sample-files: inputs made by prt itself, so every command of the README runs in a fresh
// clone: an HDR sky as an equirectangular .hdr and as a cubemap folder, and a textureless OBJ
// scene with two materials whose ground is one large quad (the case --max-edge is for).
#include <cmath>

#include <glm/geometric.hpp>

#include "app/commands.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "env/cube_faces.h"
#include "env/procedural.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "io/hdr_writer.h"
#include "io/obj_writer.h"

namespace prt {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The equirect layout of env/equirect.h: row 0 looks straight up, the centre column along -Z.
ImageF SkyEquirect(const Environment& sky, int width, int height) {
  ImageF image(width, height);
  for (int row = 0; row < height; ++row) {
    const double theta = kPi * (row + 0.5) / height;
    for (int col = 0; col < width; ++col) {
      const double phi = 2.0 * kPi * (col + 0.5) / width - kPi;
      const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      image.at(col, row) = glm::vec3(sky.Radiance(d));
    }
  }
  return image;
}

/// One face of the standard cube layout (env/cube_faces.h).
ImageF SkyFace(const Environment& sky, const FaceFrame& f, int size) {
  ImageF image(size, size);
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const double s = 2.0 * (col + 0.5) / size - 1.0, t = 2.0 * (row + 0.5) / size - 1.0;
      image.at(col, row) = glm::vec3(sky.Radiance(glm::normalize(f.n + s * f.u + t * f.v)));
    }
  return image;
}

std::vector<ObjPart> SampleScene() {
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, 192, 20);
  const Bounds3 b = MeshBounds(knot);
  const float scale = 2.0f / (b.hi.y - b.lo.y);
  TransformMesh(knot, scale, glm::vec3(0.0f, 0.05f - scale * b.lo.y, 0.0f));
  return {{"knot", knot, glm::vec3(0.80f, 0.30f, 0.20f)}, {"ground", MakePlane(8.0f, 1), glm::vec3(0.75f)}};
}

}  // namespace

CommandSpec SampleFilesSpec() {
  return {"prt sample-files [--out DIR]",
          "Writes inputs to try the commands on, made by prt itself: DIR/sky.hdr (the built-in sky as a 1024x512 "
          "equirectangular Radiance HDR), DIR/sky_cubemap/ (the same sky as six 128x128 .hdr faces posx ... negz, "
          "standard layout) and DIR/scene.obj with DIR/scene.mtl (a red torus knot, 7,680 triangles, standing on a "
          "grey ground that is one 8 x 8 quad).",
          {{"options", {{"--out", "DIR", "output folder, created if missing", "out/samples"}, QuietOption()}}}};
}

int RunSampleFiles(const std::vector<std::string>& tokens) {
  Args args("sample-files", tokens, SampleFilesSpec());
  const std::string out = args.String("--out", "out/samples");
  SetQuiet(args.Flag("--quiet"));
  args.Finish();
  OutputFolder folder(out);
  const auto sky = MakeSky(SkyParams{});
  WriteFileAtomic(folder.Output("sky.hdr"), EncodeHdr(SkyEquirect(*sky, 1024, 512)));
  {
    OutputFolder cube(out + "/sky_cubemap");
    for (int f = 0; f < 6; ++f)
      WriteFileAtomic(cube.Output(std::string(kFaceNames[f]) + ".hdr"),
                      EncodeHdr(SkyFace(*sky, FaceFrames(CubeLayout::kStandard)[f], 128)));
    cube.Finish();
  }
  const auto parts = SampleScene();
  WriteFileAtomic(folder.Output("scene.obj"), FormatObj(parts, "scene.mtl"));
  WriteFileAtomic(folder.Output("scene.mtl"), FormatMtl(parts));
  folder.Finish();
  Summary("wrote " + out + "/sky.hdr, " + out + "/sky_cubemap/ (posx ... negz .hdr) and " + out +
          "/scene.obj with scene.mtl");
  return 0;
}

}  // namespace prt
