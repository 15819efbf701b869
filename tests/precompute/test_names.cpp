// The names of precompute's choices (core/name_table.h): the samplers (`--sampler`) and the
// transport modes (`--transport`), each against its words written out here, and an unknown
// name refused with the names expected (once, both fell back to a default: any other word was
// fibonacci, or shadowed).
#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "precompute/samplers.h"
#include "precompute/transport.h"
#include "tests/name_checks.h"

namespace prt {

TEST_SUITE("precompute") {
  TEST_CASE("names: --sampler's words each name their own sampler, and no other word is one") {
    const std::vector<std::pair<Sampler, std::string>> words = {
        {Sampler::kFibonacci, "fibonacci"}, {Sampler::kStratified, "stratified"}, {Sampler::kUniform, "uniform"}};
    CHECK(test::NameProblems<Sampler>(words, SamplerName, test::Refusing<Sampler>(SamplerFromName), SamplerNames()) ==
          "");
    CHECK_THROWS_WITH_AS(SamplerFromName("halton"), "sampler 'halton': expected one of fibonacci, stratified, uniform",
                         Error);
  }

  TEST_CASE("names: --transport's words each name their own mode, and no other word is one") {
    const std::vector<std::pair<TransportMode, std::string>> words = {{TransportMode::kUnshadowed, "unshadowed"},
                                                                      {TransportMode::kShadowed, "shadowed"},
                                                                      {TransportMode::kInterreflection, "interreflection"}};
    CHECK(test::NameProblems<TransportMode>(words, TransportModeName,
                                            test::Refusing<TransportMode>(TransportModeFromName),
                                            TransportModeNames()) == "");
    CHECK_THROWS_WITH_AS(TransportModeFromName("glossy"),
                         "transport mode 'glossy': expected one of unshadowed, shadowed, interreflection", Error);
  }
}

}  // namespace prt
