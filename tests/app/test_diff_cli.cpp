// `prt diff` through the built binary: output line, limits and the exit codes of CLI.md.
#include <doctest/doctest.h>

#include <string>

#include "io/png_io.h"
#include "tests/test_process.h"

namespace {

using prt::test::Q;

prt::Image8 Flat(int w, int h, std::uint8_t value) {
  prt::Image8 image(w, h);
  for (auto& v : image.rgb) v = value;
  return image;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("prt diff: identical, slightly different and differently sized images") {
    const std::string dir = prt::test::ScratchDir("diff_cli");
    const std::string a = dir + "/a.png", b = dir + "/b.png", c = dir + "/c.png";
    prt::WritePng(a, Flat(8, 4, 100));
    prt::Image8 slightly = Flat(8, 4, 100);
    slightly.rgb[0] = 102;  // one channel of one pixel, off by 2
    prt::WritePng(b, slightly);
    prt::WritePng(c, Flat(4, 8, 100));

    const auto same = prt::test::RunPrt("diff " + Q(a) + " " + Q(a));
    CHECK(same.exit_code == 0);
    CHECK(same.out == "max_abs=0 mean_abs=0 rmse=0 psnr=inf differing_pixels=0\n");
    CHECK(same.err.empty());

    const auto differ = prt::test::RunPrt("diff " + Q(a) + " " + Q(b));
    CHECK(differ.exit_code == 1);  // no limits given: must be identical
    CHECK(differ.out.rfind("max_abs=2 mean_abs=0.0208333 rmse=0.204124 psnr=", 0) == 0);
    CHECK(differ.out.find("differing_pixels=1\n") != std::string::npos);

    CHECK(prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --max-abs 2").exit_code == 0);
    CHECK(prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --max-abs 1").exit_code == 1);
    CHECK(prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --mean-abs 0.01").exit_code == 1);
    CHECK(prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --min-psnr 40").exit_code == 0);
    CHECK(prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --min-psnr 70").exit_code == 1);
    // Outside the limits, stderr says which limit failed, with the value and the limit; the
    // metric line is on stdout as always.
    const auto which = prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --max-abs 2 --mean-abs 0.01 --min-psnr 40");
    CHECK(which.exit_code == 1);
    CHECK(which.out.rfind("max_abs=2 ", 0) == 0);
    CHECK(which.err.find("mean_abs 0.0208333 > 0.01 (--mean-abs)") != std::string::npos);
    CHECK(which.err.find("--max-abs") == std::string::npos);
    CHECK(which.err.find("--min-psnr") == std::string::npos);
    const auto psnr = prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --min-psnr 70");
    CHECK(psnr.err.find("(--min-psnr)") != std::string::npos);
    const auto identical = prt::test::RunPrt("diff " + Q(a) + " " + Q(b));
    CHECK(identical.err.find("not identical") != std::string::npos);

    const auto with_out = prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --max-abs 5 --out " + Q(dir + "/d.png"));
    CHECK(with_out.exit_code == 0);
    const prt::Image8 d = prt::ReadPng(dir + "/d.png");
    CHECK(d.rgb[0] == 255);
    CHECK(d.rgb[1] == 0);

    const auto sizes = prt::test::RunPrt("diff " + Q(a) + " " + Q(c));
    CHECK(sizes.exit_code == 2);
    CHECK(sizes.out.empty());
    CHECK(sizes.err.rfind("prt: error: ", 0) == 0);
    CHECK(sizes.err.find("c.png") != std::string::npos);

    const auto missing = prt::test::RunPrt("diff " + Q(a) + " " + Q(dir + "/nope.png"));
    CHECK(missing.exit_code == 2);
    CHECK(missing.err.find("nope.png: no such file") != std::string::npos);

    const auto bad_option = prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --max-abs 300");
    CHECK(bad_option.exit_code == 2);
    CHECK(bad_option.err.find("--max-abs") != std::string::npos);
    CHECK(bad_option.err.find("prt help diff") != std::string::npos);
    CHECK(prt::test::RunPrt("diff " + Q(a)).exit_code == 2);
    CHECK(prt::test::RunPrt("diff " + Q(a) + " " + Q(b) + " --bogus 1").exit_code == 2);
  }
}
