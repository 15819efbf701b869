// --lmax auto measures the environment while the options are read, and the command then takes
// that one environment instead of loading the file again (app/pipeline.h LoadSceneEnvironment).
// Catches a second load (the file is gone by then) and the loaded light handed out for another
// --env (prt view's extra environments).
#include <doctest/doctest.h>

#include <filesystem>

#include "app/commands.h"
#include "app/pipeline.h"
#include "core/atomic_file.h"
#include "env/equirect.h"
#include "io/hdr_writer.h"
#include "tests/test_support.h"

namespace prt {

TEST_SUITE("app") {
  TEST_CASE("lmax auto: the environment is loaded once, for the options naming it only") {
    const std::string dir = test::ScratchDir("lmax_auto_env");
    const std::string path = dir + "/sky.hdr";
    // A bright upper half: low bands suffice, any lmax auto picks is fine here.
    WriteFileAtomic(path, EncodeHdr(EquirectImage([](const glm::dvec3& d) { return glm::dvec3(d.y > 0 ? 2.0 : 0.1); }, 64, 32)));
    Args args("render", {"--env", path, "--lmax", "auto", "--quiet"}, RenderSpec());
    const SceneOptions options = ReadSceneOptions(args);
    REQUIRE(options.loaded_env != nullptr);
    std::filesystem::remove(path);  // a second load would fail now
    const auto env = LoadSceneEnvironment(options);
    CHECK(env.get() == options.loaded_env.get());
    // Other options naming another environment load that one.
    SceneOptions other = options;
    other.env = "furnace:3";
    const auto furnace = LoadSceneEnvironment(other);
    CHECK(furnace.get() != options.loaded_env.get());
    CHECK(furnace->Describe().find("furnace") != std::string::npos);
    other.env = path;
    other.layout = CubeLayout::kGames202;  // the same name read another way is another environment
    CHECK_FALSE(test::ErrorMessage([&] { LoadSceneEnvironment(other); }).empty());
  }
}

}  // namespace prt
