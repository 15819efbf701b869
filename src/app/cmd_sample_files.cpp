// prt sample-files: inputs made by prt itself, so every command of the README runs in a fresh
// clone: an HDR sky as an equirectangular .hdr and as a cubemap folder, and a textureless OBJ
// scene with two materials whose ground is one large quad (the case --max-edge is for).
#include <cmath>

#include <glm/geometric.hpp>

#include "app/commands.h"
#include "app/pipeline.h"
#include "core/atomic_file.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "env/cube_faces.h"
#include "env/cubemap.h"
#include "env/equirect.h"
#include "env/procedural.h"
#include "geometry/procedural.h"
#include "io/hdr_writer.h"
#include "io/obj_writer.h"

namespace prt {
namespace {

std::vector<ObjPart> SampleScene() {
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, 192, 20);
  StandUpright(knot, 2.0f, 0.05f);
  return {{"knot", knot, glm::vec3(0.80f, 0.30f, 0.20f)}, {"ground", MakePlane(8.0f, 1), glm::vec3(0.75f)}};
}

}  // namespace

CommandSpec SampleFilesSpec() {
  return {"prt sample-files [--out DIR]",
          "Writes inputs to try the commands on, made by prt itself: DIR/sky.hdr (the built-in sky as a 1024x512 "
          "equirectangular Radiance HDR), DIR/sky_cubemap/ (the same sky as six 128x128 .hdr faces posx ... negz, "
          "standard layout) and DIR/scene.obj with DIR/scene.mtl (a red torus knot, 7,680 triangles, standing on a "
          "grey ground that is one 8 x 8 quad).",
          {{"options", {{"--out", "DIR", "output folder, created if missing", "out/samples"}, ReplaceOption(), QuietOption()}}}};
}

int RunSampleFiles(const std::vector<std::string>& tokens) {
  Args args("sample-files", tokens, SampleFilesSpec());
  const std::string out = args.String("--out", "out/samples");
  const bool replace = args.Flag("--replace");
  SetQuiet(args.Flag("--quiet"));
  args.Finish();
  // Both folders and all their names are checked before any work; both are finished once all
  // is written.
  OutputFolder folder(out, {"sample-files", {"sky.hdr", "scene.obj", "scene.mtl"}, replace});
  std::vector<std::string> faces_names;
  for (const char* face : kFaceNames) faces_names.push_back(std::string(face) + ".hdr");
  OutputFolder cube(out + "/sky_cubemap", {"sample-files", faces_names, replace});
  const auto sky = MakeSky(SkyParams{});
  const auto radiance = [&sky](const glm::dvec3& d) { return sky->Radiance(d); };
  WriteFileAtomic(folder.Output("sky.hdr"), EncodeHdr(EquirectImage(radiance, 1024, 512)));
  const auto faces = CubemapFaceImages(radiance, 128);
  for (int f = 0; f < 6; ++f) WriteFileAtomic(cube.Output(faces_names[f]), EncodeHdr(faces[f]));
  const auto parts = SampleScene();
  WriteFileAtomic(folder.Output("scene.obj"), FormatObj(parts, "scene.mtl"));
  WriteFileAtomic(folder.Output("scene.mtl"), FormatMtl(parts));
  FinishOutputs(cube);
  FinishOutputs(folder);
  Summary("wrote " + out + "/sky.hdr, " + out + "/sky_cubemap/ (posx ... negz .hdr) and " + out +
          "/scene.obj with scene.mtl");
  return 0;
}

}  // namespace prt
