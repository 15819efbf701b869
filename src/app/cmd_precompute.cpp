#include <algorithm>

#include "app/commands.h"
#include "app/pipeline.h"
#include "app/precompute_shard.h"
#include "app/render_args.h"
#include "core/atomic_file.h"
#include "core/color.h"
#include "bases/list.h"
#include "basis/cache_plan.h"
#include "core/log.h"
#include "precompute_io/cpca_matrix_file.h"
#include "precompute_io/light_txt.h"
#include "precompute_io/transfer_matrix_file.h"
#include "precompute_io/transport_txt.h"
// The course's files are SH coefficients: precompute takes the SH transport itself.
#include "sh_basis/scene_transport.h"

namespace prt {
namespace {

/// The course's viewer reads exactly this many numbers per row of light.txt and transport.txt.
constexpr int kCourseLmax = 2;

/// The one transfer vector that best stands for three coloured ones in the course's
/// single-vector transport.txt: weighted as the eye weighs R, G and B (core/color.h).
Transport LuminanceMix(const Transport& t) {
  Transport mix;
  mix.lmax = t.lmax;
  mix.channels = 1;
  mix.vertices = t.vertices;
  const std::size_t n = CoeffCount(t.lmax);
  mix.coeffs.assign(t.vertices * n, 0.0f);
  for (std::size_t v = 0; v < t.vertices; ++v)
    for (int c = 0; c < 3; ++c)
      for (std::size_t k = 0; k < n; ++k) mix.coeffs[v * n + k] += static_cast<float>(kLuminanceWeights[c]) * t.at(v, c)[k];
  return mix;
}

/// precompute's --basis: the bases that write the course's files, and where the others go.
std::string CourseBasesHelp() {
  std::string course, others;
  for (const Basis* b : Bases()) {
    std::string& list = b->Traits().course_files ? course : others;
    list += (list.empty() ? "" : ", ") + b->Name();
  }
  return course + " only: the course's light.txt and transport.txt are SH coefficients (" + others +
         ": render, demo and report take it)";
}

}  // namespace

CommandSpec PrecomputeSpec() {
  RenderJobOptions no_out;
  no_out.out.clear();  // its help then says "required"
  no_out.cpca.clusters = 0;  // the compressed file only when asked for
  OptionGroup output = RenderOptionGroup(no_out, {"--out", "--replace", "--cache", "--cpca"}, "output options");
  for (auto& o : output.options)
    if (o.name == "--cpca")
      o.help = "with --material phong:N,KS, also write DIR/transfer_matrices_cpca.bin: the transfer matrices "
               "compressed by clustered PCA into C clusters of a mean and K principal matrices (layout in "
               "docs/CLI.md); off: only transfer_matrices.bin";
  for (const OptionSpec& o : ShardOptions("DIR/transport.cache.shard-IIIII-of-NNNNN", "writes what one run writes"))
    output.options.push_back(o);
  output.options.push_back(QuietOption());
  output.options[0].help = "output folder, created if missing; one run at a time; after a successful run it holds "
                           "this run's files, and what an earlier precompute wrote there and this one did not is "
                           "removed (other commands' outputs and files prt did not write are never touched)";
  // No camera here: every vertex takes --samples (the course's viewer turns the model freely).
  std::vector<std::string> names = AllSceneOptionNames();
  names.erase(std::find(names.begin(), names.end(), "--hidden-samples"));
  // The course's files are SH: --basis is taken only to refuse the other bases with a reason,
  // whose own options are not offered here.
  for (const Basis* basis : Bases())
    if (!basis->Traits().course_files)
      for (const OptionSpec& own : basis->OwnOptions()) names.erase(std::find(names.begin(), names.end(), own.name));
  OptionGroup scene = SceneOptionGroup(SceneOptions{}, names);
  for (auto& o : scene.options)
    if (o.name == "--max-edge")
      o.help = "refused here: the course's transport.txt has three rows per face of the OBJ file, and split "
               "triangles are other faces (render and reference take it)",
      o.default_text = "";
    else if (o.name == "--basis")
      o.help = CourseBasesHelp();
  return {"prt precompute [scene options] --out DIR",
          "Writes DIR/light.txt and DIR/transport.txt in the course's text format (GAMES202 homework 2: its WebGL "
          "framework loads them), and the binary cache DIR/transport.cache that render reuses.\n\n"
          "light.txt: (L+1)^2 lines `R G B`. transport.txt: the welded vertex count, then three rows per face of "
          "the OBJ in file order, each the corner's (L+1)^2 transfer coefficients, 1/pi included, albedo not "
          "(the course's viewer multiplies by no albedo, so it shows the mesh as white). The viewer reads exactly "
          "9 numbers per row: use --lmax 2 (the default) for it.\n\n"
          "With coloured albedo and interreflection the transport differs per colour channel: the exact "
          "DIR/transport_r.txt, transport_g.txt and transport_b.txt are written too, and transport.txt holds "
          "their luminance-weighted mix 0.2126 R + 0.7152 G + 0.0722 B, which the viewer loads.\n\n"
          "With --material phong:N,KS, transport.txt keeps the diffuse part (the course's format) and "
          "DIR/transfer_matrices.bin adds the glossy part for any view: per vertex its position, normal, albedo, "
          "diffuse transfer and (L+1)^2 x (L+1)^2 transfer matrix, with the lobe's zonal coefficients "
          "(layout in docs/CLI.md). With --cpca C,K, DIR/transfer_matrices_cpca.bin holds the same with the matrices "
          "compressed by clustered PCA.",
          {scene, output}};
}

int RunPrecompute(const std::vector<std::string>& tokens) { return Precompute(tokens, {}); }

int Precompute(const std::vector<std::string>& tokens, const ShardedTransport& sharded, bool check_only) {
  Args args("precompute", tokens, PrecomputeSpec());
  const SceneOptions options = ReadSceneOptions(args);
  const auto out = args.String("--out");
  const std::optional<ShardTask> task = ReadShardTask(args, options);
  const std::string cache_option = args.String("--cache", "");
  const bool replace = args.Flag("--replace");
  CpcaOptions cpca_option;
  cpca_option.clusters = 0;
  ReadCpca(args, cpca_option);
  CheckCpcaTerms(args, cpca_option, options.lmax);
  const bool cpca = cpca_option.clusters > 0;
  args.Finish();
  if (cpca && !options.material.glossy)
    args.Fail("--cpca: compresses a glossy material's transfer matrices (expected --material phong:N,KS, or no --cpca)");
  if (!out) args.Fail("--out DIR is required");
  if (!options.basis->Traits().course_files)
    args.Fail("--basis " + options.basis->Name() +
              ": precompute writes the course's SH files (light.txt, transport.txt) only; render, demo and report "
              "take --basis " + options.basis->Name());
  if (options.max_edge > 0.0)
    args.Fail("--max-edge: not with precompute (the course's transport.txt has three rows per face of the OBJ "
              "file, and split triangles are other faces; render and reference take it)");
  if (task) {
    if (check_only) return 0;
    return RunPrecomputeShard(options, task->shard, *out, ShardCommand("precompute", tokens), task->stage);
  }
  if (options.lmax != kCourseLmax)  // known from the options: said before any work
    Warn("lmax " + std::to_string(options.lmax) + ": these files will have " +
         std::to_string(CoeffCount(options.lmax)) +
         " numbers per row, but the course's WebGL viewer reads exactly 9 (lmax 2) and draws garbage, without an "
         "error, from any other count");
  // A glossy material is exported as transfer matrices (any view).
  const bool glossy = options.material.glossy;
  OutputPlan plan{"precompute", {"light.txt", "transport.txt"}, replace};
  if (glossy) plan.names.push_back("transfer_matrices.bin");
  if (cpca) plan.names.push_back("transfer_matrices_cpca.bin");
  OutputFolder folder(*out, plan);
  const CachePlan cache = PlanCache(cache_option, &folder, options.basis->CacheName(), Bases());

  const Mesh mesh = LoadSceneMesh(options, &folder);
  // Coloured interreflection writes one file per channel: known once the albedo is.
  if (TransportChannels(mesh, TransportModeFromName(options.transport)) == 3)
    folder.Plan({"transport_r.txt", "transport_g.txt", "transport_b.txt"});
  // The memory of the transfer matrices is checked before the light is loaded.
  if (glossy) CheckMatrixMemory(mesh, TransportModeFromName(options.transport), options.lmax);
  const auto env = LoadSceneEnvironment(options, &folder);
  const ShRgb light = ComputeLight(*env, options);
  Transport transport = ComputeSceneTransport(*options.basis, mesh, TransportOptionsOf(options), options.samples_from_rule,
                                              cache, nullptr, glossy, sharded);

  WriteFileAtomic(folder.Output("light.txt"), FormatLightTxt(light));
  std::string wrote;
  if (transport.channels == 1) {
    WriteFileAtomic(folder.Output("transport.txt"), FormatTransportTxt(mesh, transport, 0));
    wrote = "wrote " + *out + "/light.txt and " + *out + "/transport.txt";
  } else {
    const char* names[3] = {"r", "g", "b"};
    for (int c = 0; c < 3; ++c)
      WriteFileAtomic(folder.Output(std::string("transport_") + names[c] + ".txt"), FormatTransportTxt(mesh, transport, c));
    WriteFileAtomic(folder.Output("transport.txt"), FormatTransportTxt(mesh, LuminanceMix(transport), 0));
    wrote = "wrote " + *out + "/light.txt, transport_r.txt, transport_g.txt, transport_b.txt (coloured "
            "interreflection: the exact transport of each channel) and transport.txt (their luminance-weighted "
            "mix 0.2126 R + 0.7152 G + 0.0722 B, for the course's viewer, which reads one vector per row)";
  }
  if (glossy) {
    WriteTransferMatrixFile(folder.Output("transfer_matrices.bin"), mesh, transport);
    wrote += "; the glossy part (" + options.material.Name() + ") as transfer matrices for any view in " + *out +
             "/transfer_matrices.bin (layout in docs/CLI.md)";
  }
  if (cpca) {
    const CpcaTransfer compressed = CompressSceneMatrices(transport, cpca_option.clusters, cpca_option.terms);
    WriteCpcaMatrixFile(folder.Output("transfer_matrices_cpca.bin"), mesh, transport, compressed);
    wrote += "; the same compressed by clustered PCA in " + *out + "/transfer_matrices_cpca.bin (layout in docs/CLI.md)";
  }
  FinishOutputs(folder);  // the files are in place from here on
  Summary(wrote);
  return 0;
}

}  // namespace prt
