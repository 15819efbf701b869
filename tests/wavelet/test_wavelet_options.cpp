// The wavelet basis's own options as the basis reads them (wavelet/wavelet_basis.h), at every
// edge its help states: --cube-size a power of two 8..64, --wavelet-terms 6..6 F^2,
// --light-terms 0..6 F^2, the defaults where none is given, and the command line written back.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "tests/test_support.h"
#include "wavelet/wavelet_basis.h"

namespace prt {
namespace {

/// The wavelet options read from `tokens` (a command whose table is the basis's own options),
/// or the refusal's message in `problem`.
WaveletOptions Read(const std::vector<std::string>& tokens, std::string* problem = nullptr) {
  const CommandSpec spec{"prt test", "", {OptionGroup{"wavelet options", WaveletBasis().OwnOptions()}}};
  WaveletOptions read;
  const std::string message = test::ErrorMessage([&] {
    Args args("test", tokens, spec);
    read = WaveletOptionsOf(*WaveletBasis().ReadOptions(args));
  });
  if (problem) *problem = message;
  return read;
}

bool Refused(const std::vector<std::string>& tokens) {
  std::string problem;
  Read(tokens, &problem);
  return !problem.empty();
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("wavelet options: each edge of the help accepted, one past it refused") {
    const WaveletOptions defaults = Read({});
    CHECK(defaults.face_size == WaveletOptions{}.face_size);
    CHECK(defaults.budget == WaveletOptions{}.budget);
    CHECK(defaults.light_terms == 0);
    CHECK(WaveletOptionsOf(*WaveletBasis().DefaultSettings()).budget == defaults.budget);

    for (const int f : {8, 16, 32, 64}) CHECK(Read({"--cube-size", std::to_string(f)}).face_size == f);
    for (const char* f : {"4", "7", "12", "128"}) CHECK(Refused({"--cube-size", f}));

    // 6 F^2 at F = 8 is 384: every coefficient kept is allowed, one more is not.
    CHECK(Read({"--cube-size", "8", "--wavelet-terms", "384"}).budget == 384);
    CHECK(Read({"--cube-size", "8", "--wavelet-terms", "6"}).budget == 6);
    CHECK(Refused({"--cube-size", "8", "--wavelet-terms", "385"}));
    CHECK(Refused({"--cube-size", "8", "--wavelet-terms", "5"}));
    // The default budget (512) is cut to a small cube's texels.
    CHECK(Read({"--cube-size", "8"}).budget == 384);

    CHECK(Read({"--cube-size", "8", "--light-terms", "384"}).light_terms == 384);
    CHECK(Read({"--light-terms", "0"}).light_terms == 0);
    CHECK(Refused({"--cube-size", "8", "--light-terms", "385"}));
    CHECK(Refused({"--light-terms", "-1"}));
  }

  TEST_CASE("wavelet options: the light terms the basis keeps, their most and the command line written back") {
    const auto settings = [](const std::vector<std::string>& tokens) {
      const CommandSpec spec{"prt test", "", {OptionGroup{"wavelet options", WaveletBasis().OwnOptions()}}};
      Args args("test", tokens, spec);
      return WaveletBasis().ReadOptions(args);
    };
    const auto small = settings({"--cube-size", "16", "--light-terms", "40"});
    CHECK(WaveletBasis().MaxLightTerms(*small) == 6 * 16 * 16);
    CHECK(WaveletBasis().LightTerms(*small) == 40);
    CHECK(WaveletBasis().CommandLine(*small, 40) == " --light-terms 40");
    CHECK(WaveletBasis().Lmax() == 4);  // the bounces' lmax, measured (wavelet_basis.cpp)
    CHECK(WaveletBasis().LmaxWhy().find("lmax 4") == 0);
  }
}

}  // namespace prt
