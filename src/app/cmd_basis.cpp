#include "app/commands.h"
#include "core/log.h"
#include "core/output_folder.h"
#include "io/png_io.h"
#include "raster/basis_chart.h"

namespace prt {

CommandSpec BasisSpec() {
  return {"prt basis [--lmax L] [--cell PIXELS] --out FILE.png",
          "Draws the real SH basis functions of bands 0..L as a labelled grid of spheres (row l, column m = -l..l), "
          "positive lobes red and negative ones blue.\n\nThe SH polar axis (the axis of the m = 0 functions) is world "
          "+Z, while scenes are Y-up: on an up-facing floor T_6 (l = 2, m = 0) is negative, because the floor's "
          "normal lies on the SH equator.",
          {{"options",
            {{"--lmax", "L", "highest band, 0..8", "3"},
             {"--cell", "PIXELS", "size of each sphere's cell, 32..512", "96"},
             {"--out", "FILE.png", "output image, a .png (its folder is created if missing)", "required"},
             QuietOption()}}}};
}

int RunBasis(const std::vector<std::string>& tokens) {
  Args args("basis", tokens, BasisSpec());
  const int lmax = args.Int("--lmax", 3, 0, 8);
  const int cell = args.Int("--cell", 96, 32, 512);
  const auto out = args.String("--out");
  SetQuiet(args.Flag("--quiet"));
  args.Finish();
  if (!out) args.Fail("--out FILE.png is required");
  args.RequirePngName("--out", *out);
  SingleFileOutput file(*out);
  file.Write(EncodePng(DrawBasisChart(lmax, cell)));
  file.Commit();
  Summary("wrote " + *out);
  return 0;
}

}  // namespace prt
