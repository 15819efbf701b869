// An environment's fingerprint (env/environment_hash.h) changes with any texel's direction, solid
// angle or radiance, with its analytic disks, and with the order of its rows, and not with its
// description (the path as the command line spelled it).
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "env/environment_hash.h"

namespace prt {
namespace {

/// Two rows of two texels, and what a test changes of them.
class TinyEnvironment : public Environment {
 public:
  std::vector<std::vector<Texel>> rows = {{{{0, 0, 1}, 0.5, {1, 2, 3}}, {{0, 1, 0}, 0.5, {4, 5, 6}}},
                                          {{{1, 0, 0}, 0.25, {7, 8, 9}}, {{0, 0, -1}, 0.25, {1, 1, 1}}}};
  std::vector<LightDisk> disks;
  std::string name = "tiny";

  glm::dvec3 Radiance(const glm::dvec3&) const override { return glm::dvec3(1.0); }
  std::size_t RowCount() const override { return rows.size(); }
  void Row(std::size_t i, std::vector<Texel>& out) const override { out = rows[i]; }
  std::vector<LightDisk> Disks() const override { return disks; }
  std::string Describe() const override { return name; }
};

}  // namespace

TEST_SUITE("env") {
TEST_CASE("environment hash: any texel, disk or row order changes it; the description does not") {
  const TinyEnvironment base;
  const std::uint64_t h = EnvironmentHash(base);
  CHECK(EnvironmentHash(TinyEnvironment{}) == h);  // a function of the numbers alone
  TinyEnvironment named;
  named.name = "./tiny";
  CHECK(EnvironmentHash(named) == h);
  TinyEnvironment radiance;
  radiance.rows[1][1].radiance.z = std::nextafter(1.0, 2.0);  // the last texel, one bit
  CHECK(EnvironmentHash(radiance) != h);
  TinyEnvironment angle;
  angle.rows[0][0].solid_angle = 0.5000001;
  CHECK(EnvironmentHash(angle) != h);
  TinyEnvironment swapped;
  std::swap(swapped.rows[0], swapped.rows[1]);
  CHECK(EnvironmentHash(swapped) != h);
  TinyEnvironment sun;
  sun.disks.push_back({{0, 1, 0}, 0.9999, {1000, 1000, 1000}});
  CHECK(EnvironmentHash(sun) != h);
  TinyEnvironment brighter = sun;
  brighter.disks[0].radiance.x = 2000;
  CHECK(EnvironmentHash(brighter) != EnvironmentHash(sun));
}
}  // TEST_SUITE

}  // namespace prt
