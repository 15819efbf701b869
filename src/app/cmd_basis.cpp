#include "app/commands.h"
#include "core/error.h"
#include "core/log.h"
#include "io/png_io.h"
#include "raster/basis_chart.h"

namespace prt {

const char* const kBasisHelp =
    "usage: prt basis [--lmax L] [--cell PIXELS] --out FILE.png\n"
    "  Draws the real SH basis functions of bands 0..L as a labelled grid of spheres (row l,\n"
    "  column m), positive lobes red and negative ones blue.\n"
    "  --lmax L        highest band, 0..8 (default 3)\n"
    "  --cell PIXELS   size of each sphere's cell, 32..512 (default 96)\n"
    "  --out FILE.png  output image (required)\n";

int RunBasis(const std::vector<std::string>& tokens) {
  Args args("basis", tokens);
  const int lmax = args.Int("--lmax", 3, 0, 8);
  const int cell = args.Int("--cell", 96, 32, 512);
  const auto out = args.String("--out");
  SetQuiet(args.Flag("--quiet"));
  args.Finish();
  if (!out) throw UsageError("--out FILE.png is required", "basis");
  WritePng(*out, DrawBasisChart(lmax, cell));
  Summary("wrote " + *out);
  return 0;
}

}  // namespace prt
