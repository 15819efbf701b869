#include <filesystem>

#include "app/commands.h"
#include "app/pipeline.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "io/light_txt.h"
#include "io/transport_txt.h"

namespace prt {

const char* const kPrecomputeHelp =
    "usage: prt precompute [scene options] --out DIR\n"
    "  Writes DIR/light.txt and DIR/transport.txt in the course's text format (GAMES202 hw2:\n"
    "  loadable by its WebGL framework), and the binary cache DIR/transport.cache that `render`\n"
    "  reuses. With coloured albedo and interreflection the transport differs per colour\n"
    "  channel: DIR/transport_r.txt, transport_g.txt and transport_b.txt are written instead.\n"
    "  --out DIR          output folder, created if missing (required)\n";

int RunPrecompute(const std::vector<std::string>& tokens) {
  Args args("precompute", tokens, SceneFlags());
  const SceneOptions options = ReadSceneOptions(args);
  const auto out = args.String("--out");
  args.Finish();
  if (!out) throw UsageError("--out DIR is required", "precompute");
  std::error_code ec;
  std::filesystem::create_directories(*out, ec);
  if (!std::filesystem::is_directory(*out)) throw Error(*out + ": cannot create the output folder");

  const auto env = LoadSceneEnvironment(options);
  const ShRgb light = ComputeLight(*env, options);
  const Mesh mesh = LoadSceneMesh(options);
  const Transport transport = ComputeSceneTransport(mesh, options, *out + "/transport.cache");

  WriteFileAtomic(*out + "/light.txt", FormatLightTxt(light));
  if (transport.channels == 1) {
    WriteFileAtomic(*out + "/transport.txt", FormatTransportTxt(mesh, transport, 0));
    Summary("wrote " + *out + "/light.txt and " + *out + "/transport.txt");
  } else {
    const char* names[3] = {"r", "g", "b"};
    for (int c = 0; c < 3; ++c)
      WriteFileAtomic(*out + "/transport_" + names[c] + ".txt", FormatTransportTxt(mesh, transport, c));
    Summary("wrote " + *out + "/light.txt and transport_{r,g,b}.txt (coloured interreflection: the "
            "course format holds one vector per row, so one file per channel)");
  }
  return 0;
}

}  // namespace prt
