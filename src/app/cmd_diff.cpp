// `prt diff A.png B.png`: compares two images and exits like cmp (see CLI.md): 0 within the
// limits, 1 outside them, 2 on an error. Errors are caught here, not in main, because main
// maps a plain Error to exit code 1, which for diff means "the images differ".
#include <cstdio>
#include <exception>
#include <limits>

#include "app/commands.h"
#include "core/error.h"
#include "io/png_io.h"
#include "raster/image_diff.h"

namespace prt {

const char* const kDiffHelp =
    "usage: prt diff A.png B.png [--max-abs N] [--mean-abs X] [--min-psnr P] [--out DIFF.png]\n"
    "  Compares two PNG images of the same size channel by channel (0..255) and prints one line:\n"
    "    max_abs=<0..255> mean_abs=<x> rmse=<x> psnr=<dB or inf> differing_pixels=<n>\n"
    "  Exit code: 0 within the limits, 1 outside them, 2 on an error (missing or unreadable\n"
    "  file, not a PNG, size mismatch, bad option).\n"
    "  Without any limit option the images must be identical (like cmp); with limits, only the\n"
    "  limits given apply.\n"
    "  --max-abs N     largest allowed channel difference, 0..255 (default: 0 when no limit\n"
    "                  option is given, else no limit)\n"
    "  --mean-abs X    largest allowed mean channel difference (default: no limit)\n"
    "  --min-psnr P    smallest allowed PSNR in dB (default: no limit)\n"
    "  --out DIFF.png  also write an amplified difference image: identical pixels black, every\n"
    "                  difference at least 64/255 bright, the largest at 255 (default: none)\n";

namespace {

struct DiffLimits {
  int max_abs = 255;
  double mean_abs = std::numeric_limits<double>::infinity();
  double min_psnr = -std::numeric_limits<double>::infinity();
};

bool Within(const DiffMetrics& m, const DiffLimits& limits) {
  return m.max_abs <= limits.max_abs && m.mean_abs <= limits.mean_abs && m.psnr >= limits.min_psnr;
}

int Diff(const std::vector<std::string>& tokens) {
  Args args("diff", tokens);
  args.Flag("--quiet");  // accepted by every command; diff prints only its result line anyway
  const bool any_limit = args.Has("--max-abs") || args.Has("--mean-abs") || args.Has("--min-psnr");
  DiffLimits limits;
  limits.max_abs = args.Int("--max-abs", any_limit ? 255 : 0, 0, 255);
  limits.mean_abs = args.Double("--mean-abs", limits.mean_abs, 0.0, 255.0);
  limits.min_psnr = args.Double("--min-psnr", limits.min_psnr, -1e9, 1e9);
  const auto out = args.String("--out");
  const auto files = args.TakePositionals();
  args.Finish();
  if (files.size() != 2)
    throw UsageError("expected two images, A.png B.png (got " + std::to_string(files.size()) + ")",
                     "diff");

  const Image8 a = ReadPng(files[0]);
  const Image8 b = ReadPng(files[1]);
  if (a.width != b.width || a.height != b.height)
    throw Error(files[1] + ": size " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                " differs from " + files[0] + " (expected " + std::to_string(a.width) + "x" +
                std::to_string(a.height) + ")");
  const DiffMetrics metrics = CompareImages(a, b);
  if (out) WritePng(*out, AmplifiedDifference(a, b));
  std::printf("%s\n", FormatDiffMetrics(metrics).c_str());
  return Within(metrics, limits) ? 0 : 1;
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
