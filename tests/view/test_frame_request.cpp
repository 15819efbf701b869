// view/frame_request.h: the page's query read and checked, and written back.
#include "view/frame_request.h"

#include "core/error.h"
#include "tests/test_support.h"

namespace prt {
namespace {

ViewLimits Limits() {
  ViewLimits l;
  l.lmax = 4;
  l.bases = {"sh", "wavelet"};
  l.modes = {"unshadowed", "shadowed", "interreflection"};
  l.environments = 2;
  l.coefficients = 25;
  l.light_terms = 6144;
  return l;
}

FrameRequest Defaults() {
  FrameRequest r;
  r.lmax = 4;
  r.basis = "sh";
  r.mode = "shadowed";
  r.draw.exposure = -1.5;
  r.draw.eye = glm::dvec3(6, 3, 9);
  r.draw.target = glm::dvec3(0, 1.5, 0);
  r.draw.up = glm::dvec3(0, 1, 0);
  r.draw.fov = 36;
  return r;
}

using Query = std::vector<std::pair<std::string, std::string>>;

}  // namespace

TEST_SUITE("view") {

TEST_CASE("ParseFrameRequest reads every parameter into the frame it names") {
  const FrameRequest r = ParseFrameRequest(
      {{"axis", "1,2,3"}, {"angle", "-37.5"}, {"lmax", "2"}, {"basis", "wavelet"}, {"mode", "interreflection"},
       {"env", "1"}, {"view", "transport:24"}, {"exposure", "2.5"}, {"tonemap", "reinhard"}, {"eye", "1,2,3.5"},
       {"target", "0,0,1"}, {"up", "0,0,1"}, {"fov", "50"}, {"size", "320x200"}, {"ssaa", "3"}, {"terms", "6144"}},
      Defaults(), Limits());
  CHECK(r.draw.axis == glm::dvec3(1, 2, 3));
  CHECK(r.draw.start_degrees == -37.5);
  CHECK(r.lmax == 2);
  CHECK(r.basis == "wavelet");
  CHECK(r.mode == "interreflection");
  CHECK(r.env == 1);
  CHECK(r.draw.view == View::kTransport);
  CHECK(r.draw.transport_index == 24);
  CHECK(*r.draw.exposure == 2.5);
  CHECK(r.draw.tonemap == ToneCurve::kReinhard);
  CHECK(*r.draw.eye == glm::dvec3(1, 2, 3.5));
  CHECK(*r.draw.target == glm::dvec3(0, 0, 1));
  CHECK(*r.draw.up == glm::dvec3(0, 0, 1));
  CHECK(*r.draw.fov == 50);
  CHECK(r.draw.width == 320);
  CHECK(r.draw.height == 200);
  CHECK(r.draw.ssaa == 3);
  CHECK(r.light_terms == 6144);
  // Nothing given: the defaults as they are.
  const FrameRequest d = ParseFrameRequest({}, Defaults(), Limits());
  CHECK(d.lmax == 4);
  CHECK(d.mode == "shadowed");
  CHECK(*d.draw.exposure == -1.5);
  CHECK(d.draw.view == View::kRadiance);
  for (const char* v : {"radiance", "irradiance", "albedo", "light", "glossy"})
    CHECK(ViewName(ParseFrameRequest({{"view", v}}, Defaults(), Limits()).draw.view) == std::string(v));
}

TEST_CASE("ParseFrameRequest refuses what the run cannot draw, naming the parameter and what it expected") {
  const auto refused = [](const Query& q) {
    return test::ErrorMessage([&q] { ParseFrameRequest(q, Defaults(), Limits()); });
  };
  CHECK(refused({{"lmax", "5"}}) == "lmax=5: refused (expected a number in 0..4)");
  CHECK(refused({{"lmax", "1.5"}}) == "lmax=1.5: refused (expected an integer in 0..4)");
  CHECK(refused({{"env", "2"}}) == "env=2: refused (expected a number in 0..1)");
  CHECK(refused({{"mode", "smooth"}}) == "mode=smooth: refused (expected unshadowed | shadowed | interreflection)");
  CHECK(refused({{"basis", "haar"}}) == "basis=haar: refused (expected sh | wavelet)");
  CHECK(refused({{"view", "transport:25"}}).find("view=transport:25: refused (expected") == 0);
  CHECK(refused({{"view", "transport:25"}}).find("K < 25") != std::string::npos);
  CHECK_FALSE(refused({{"view", "transport:-1"}}).empty());
  CHECK_FALSE(refused({{"view", "transport:"}}).empty());
  CHECK_FALSE(refused({{"view", "transport"}}).empty());
  CHECK_FALSE(refused({{"view", "RADIANCE"}}).empty());
  CHECK(refused({{"axis", "0,0,0"}}) == "axis=0,0,0: refused (expected a non-zero direction)");
  CHECK_FALSE(refused({{"axis", "1,2"}}).empty());
  CHECK_FALSE(refused({{"axis", "1,2,3,4"}}).empty());
  CHECK_FALSE(refused({{"axis", "1,inf,3"}}).empty());
  CHECK_FALSE(refused({{"eye", "1,2,1e7"}}).empty());
  CHECK_FALSE(refused({{"up", "0,0,0"}}).empty());
  CHECK_FALSE(refused({{"angle", "nan"}}).empty());
  CHECK_FALSE(refused({{"angle", "1e7"}}).empty());
  CHECK_FALSE(refused({{"exposure", "-20.5"}}).empty());
  CHECK_FALSE(refused({{"fov", "0.0005"}}).empty());
  CHECK(ParseFrameRequest({{"fov", "0.5"}}, Defaults(), Limits()).draw.fov == 0.5);  // render's limit: 0.001
  CHECK_FALSE(refused({{"fov", "179.5"}}).empty());
  CHECK_FALSE(refused({{"tonemap", "filmic"}}).empty());
  CHECK_FALSE(refused({{"ssaa", "0"}}).empty());
  CHECK_FALSE(refused({{"ssaa", "9"}}).empty());
  CHECK(ParseFrameRequest({{"size", "64x64"}, {"ssaa", "8"}}, Defaults(), Limits()).draw.ssaa == 8);  // as render's
  CHECK(refused({{"size", "16385x16"}}) == "size=16385x16: refused (expected WxH, each 1..16384)");
  CHECK(ParseFrameRequest({{"size", "8x16384"}}, Defaults(), Limits()).draw.width == 8);  // as render's
  for (const char* size : {"0x100", "100x0", "16385x16", "16x16385", "100", "x100", "100x", "100.5x100", "axb"})
    CHECK_FALSE(refused({{"size", size}}).empty());
  CHECK(ParseFrameRequest({{"size", "4096x16"}, {"ssaa", "4"}}, Defaults(), Limits()).draw.width == 4096);
  CHECK(ParseFrameRequest({{"size", "4096x4096"}, {"ssaa", "1"}}, Defaults(), Limits()).draw.width == 4096);
  // Supersampling counts: a frame of more than 4096^2 samples is refused whatever its size.
  CHECK(refused({{"size", "4096x4096"}, {"ssaa", "2"}}) ==
        "size=4096x4096&ssaa=2: refused (expected width x height x ssaa^2 at most 4096^2 samples)");
  CHECK_FALSE(refused({{"size", "2049x2048"}, {"ssaa", "2"}}).empty());
  CHECK(ParseFrameRequest({{"size", "2048x2048"}, {"ssaa", "2"}}, Defaults(), Limits()).draw.ssaa == 2);
  CHECK_FALSE(refused({{"terms", "6145"}}).empty());
  CHECK_FALSE(refused({{"terms", "-1"}}).empty());
  CHECK(refused({{"lmax", "1"}, {"lmax", "1"}}) == "lmax: given twice (expected each parameter once)");
  CHECK(refused({{"colour", "red"}}).find("colour: unknown parameter") == 0);
  CHECK(refused({{"eye", "0,1.5,0"}}) == "eye: the same point as target");
}

TEST_CASE("ParseFrameRequest keeps a glossy scene's camera where its transfer was computed") {
  ViewLimits fixed = Limits();
  fixed.camera_moves = false;
  CHECK(test::ErrorMessage([&] { ParseFrameRequest({{"eye", "1,2,3"}}, Defaults(), fixed); }).find("cannot move") !=
        std::string::npos);
  CHECK(test::ErrorMessage([&] { ParseFrameRequest({{"fov", "20"}}, Defaults(), fixed); }).find("cannot move") !=
        std::string::npos);
  // The camera it has, written back as the page does, is accepted.
  CHECK(ParseFrameRequest({{"eye", "6,3,9"}, {"fov", "36"}}, Defaults(), fixed).draw.fov == 36);
  CHECK(ParseFrameRequest({{"eye", "1,2,3"}}, Defaults(), Limits()).draw.eye == glm::dvec3(1, 2, 3));
}

TEST_CASE("FrameQuery writes what ParseFrameRequest reads back as the same frame") {
  FrameRequest r = Defaults();
  r.draw.axis = glm::dvec3(0.1, 0.7, -1.0 / 3.0);
  r.draw.start_degrees = 1.0 / 7.0;
  r.lmax = 3;
  r.basis = "wavelet";
  r.mode = "unshadowed";
  r.env = 1;
  r.draw.view = View::kTransport;
  r.draw.transport_index = 7;
  r.draw.tonemap = ToneCurve::kSrgb;
  r.draw.width = 300;
  r.draw.height = 17;
  r.draw.ssaa = 1;
  r.light_terms = 77;
  std::vector<std::pair<std::string, std::string>> query;
  const std::string text = FrameQuery(r);
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t amp = std::min(text.find('&', start), text.size());
    const std::string pair = text.substr(start, amp - start);
    query.emplace_back(pair.substr(0, pair.find('=')), pair.substr(pair.find('=') + 1));
    start = amp + 1;
  }
  const FrameRequest back = ParseFrameRequest(query, FrameRequest{}, Limits());
  CHECK(back.draw.axis == r.draw.axis);
  CHECK(back.draw.start_degrees == r.draw.start_degrees);
  CHECK(back.lmax == 3);
  CHECK(back.basis == "wavelet");
  CHECK(back.mode == "unshadowed");
  CHECK(back.env == 1);
  CHECK(back.draw.view == View::kTransport);
  CHECK(back.draw.transport_index == 7);
  CHECK(*back.draw.exposure == *r.draw.exposure);
  CHECK(back.draw.tonemap == ToneCurve::kSrgb);
  CHECK(*back.draw.eye == *r.draw.eye);
  CHECK(*back.draw.target == *r.draw.target);
  CHECK(*back.draw.up == *r.draw.up);
  CHECK(*back.draw.fov == *r.draw.fov);
  CHECK(back.draw.width == 300);
  CHECK(back.draw.height == 17);
  CHECK(back.draw.ssaa == 1);
  CHECK(back.light_terms == 77);
}

}  // TEST_SUITE

}  // namespace prt
