// `prt diff A.png B.png`: compares two images and exits like cmp (see CLI.md): 0 within the
// limits, 1 outside them, 2 on an error. Errors are caught here, not in main, because main
// maps a plain Error to exit code 1, which for diff means "the images differ".
#include <cstdio>
#include <exception>
#include <limits>

#include "app/commands.h"
#include "core/error.h"
#include "core/output_folder.h"
#include "io/png_io.h"
#include "raster/image_diff.h"

namespace prt {

CommandSpec DiffSpec() {
  return {"prt diff A.png B.png [--max-abs N] [--mean-abs X] [--min-psnr P] [--out DIFF.png]",
          "Compares two PNG images of the same size channel by channel (R, G and B, 0..255; grey images count as "
          "R = G = B, an alpha channel is not compared: prt's frames have none) and prints one line on stdout:\n"
          "max_abs=<0..255> mean_abs=<x> rmse=<x> psnr=<dB or inf> differing_pixels=<n>\n\n"
          "Exits like cmp: 0 within the limits, 1 outside them (stderr then says which limit failed), 2 on an error "
          "(missing or unreadable file, not a PNG, size mismatch, bad option). Without any limit option the images "
          "must be identical; with limits, only the limits given apply.",
          {{"options",
            {{"--max-abs", "N", "largest allowed channel difference, 0..255", "0 when no limit option is given, else none"},
             {"--mean-abs", "X", "largest allowed mean channel difference, 0..255", "none"},
             {"--min-psnr", "P", "smallest allowed PSNR in dB", "none"},
             {"--out", "DIFF.png",
              "also write an amplified difference image (identical pixels black, every difference at least 64/255 "
              "bright, the largest at 255), a .png, not A or B; its folder is created if missing; the result line is "
              "printed first, even if this write fails",
              "none"},
             QuietOption()}}}};
}

namespace {

struct DiffLimits {
  int max_abs = 255;
  double mean_abs = std::numeric_limits<double>::infinity();
  double min_psnr = -std::numeric_limits<double>::infinity();
};

/// The limits `m` exceeds, as "max_abs 12 > 2 (--max-abs)"; empty when within all of them.
std::string Exceeded(const DiffMetrics& m, const DiffLimits& limits) {
  std::string out;
  char buf[128];
  auto add = [&out](const char* text) { out += (out.empty() ? "" : ", ") + std::string(text); };
  if (m.max_abs > limits.max_abs) std::snprintf(buf, sizeof buf, "max_abs %d > %d (--max-abs)", m.max_abs, limits.max_abs), add(buf);
  if (m.mean_abs > limits.mean_abs)
    std::snprintf(buf, sizeof buf, "mean_abs %.6g > %.6g (--mean-abs)", m.mean_abs, limits.mean_abs), add(buf);
  if (m.psnr < limits.min_psnr) std::snprintf(buf, sizeof buf, "psnr %.6g < %.6g (--min-psnr)", m.psnr, limits.min_psnr), add(buf);
  return out;
}

int Diff(const std::vector<std::string>& tokens) {
  Args args("diff", tokens, DiffSpec());
  const bool quiet = args.Flag("--quiet");
  const bool any_limit = args.Has("--max-abs") || args.Has("--mean-abs") || args.Has("--min-psnr");
  DiffLimits limits;
  limits.max_abs = args.Int("--max-abs", any_limit ? 255 : 0, 0, 255);
  limits.mean_abs = args.Double("--mean-abs", limits.mean_abs, 0.0, 255.0);
  limits.min_psnr = args.Double("--min-psnr", limits.min_psnr, -1e9, 1e9);
  const auto out = args.String("--out");
  const auto files = args.TakePositionals();
  args.Finish();
  if (files.size() != 2) args.Fail("expected two images, A.png B.png (got " + std::to_string(files.size()) + ")");
  if (out) {
    args.RequirePngName("--out", *out);
    for (const std::string& input : files)
      if (SameFile(*out, input))
        args.Fail("--out: '" + *out + "' is one of the images compared (expected another name: the difference "
                  "image would replace " + input + ")");
  }

  const Image8 a = ReadPng(files[0]);
  const Image8 b = ReadPng(files[1]);
  if (a.width != b.width || a.height != b.height)
    throw Error(files[1] + ": size " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                " differs from " + files[0] + " (expected " + std::to_string(a.width) + "x" +
                std::to_string(a.height) + ")");
  const DiffMetrics metrics = CompareImages(a, b);
  std::printf("%s\n", FormatDiffMetrics(metrics).c_str());
  std::fflush(stdout);
  if (out) {
    SingleFileOutput file(*out);
    file.Write(EncodePng(AmplifiedDifference(a, b)));
    file.Commit();
  }
  const std::string exceeded = Exceeded(metrics, limits);
  if (!exceeded.empty() && !quiet) {
    if (any_limit) std::fprintf(stderr, "prt: diff: outside the limits: %s\n", exceeded.c_str());
    else
      std::fprintf(stderr, "prt: diff: not identical (%zu differing pixels; --max-abs, --mean-abs or --min-psnr "
                   "allow differences)\n", metrics.differing_pixels);
  }
  return exceeded.empty() ? 0 : 1;
}

}  // namespace

int RunDiff(const std::vector<std::string>& tokens) {
  try {
    return Diff(tokens);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "prt: error: %s (see prt help diff)\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt: error: %s\n", e.what());
  }
  return 2;
}

}  // namespace prt
