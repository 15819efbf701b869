#include "view/frame_request.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/text.h"
#include "raster/tonemap.h"
#include "render/frame_limits.h"

namespace prt {
namespace {

[[noreturn]] void Refuse(const std::string& name, const std::string& value, const std::string& expected) {
  throw Error(name + "=" + value + ": refused (expected " + expected + ")");
}

double Number(const std::string& name, const std::string& value, double lo, double hi) {
  const std::optional<double> x = ParseNumber(value);
  if (!x || *x < lo || *x > hi) Refuse(name, value, "a number in " + Formatted("%g..%g", lo, hi));
  return *x;
}

int Integer(const std::string& name, const std::string& value, int lo, int hi) {
  const double x = Number(name, value, lo, hi);
  if (x != std::floor(x)) Refuse(name, value, "an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<int>(x);
}

glm::dvec3 Vector(const std::string& name, const std::string& value, bool nonzero) {
  std::vector<double> xs;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = value.find(',', start);
    const std::optional<double> x = ParseNumber(value.substr(start, comma - start));
    if (!x || std::abs(*x) > 1e6) Refuse(name, value, "X,Y,Z, three numbers within 1e6");
    xs.push_back(*x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (xs.size() != 3) Refuse(name, value, "X,Y,Z, three numbers within 1e6");
  const glm::dvec3 v(xs[0], xs[1], xs[2]);
  if (nonzero && glm::length(v) < 1e-9) Refuse(name, value, "a non-zero direction");
  return v;
}

std::string Joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : " | ") + w;
  return text;
}

std::string OneOf(const std::string& name, const std::string& value, const std::vector<std::string>& choices) {
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) Refuse(name, value, Joined(choices));
  return value;
}

void ReadView(const std::string& value, const ViewLimits& limits, RenderOptions& draw) {
  const std::string expected = "radiance | irradiance | albedo | light | glossy | transport:K with K < " +
                               std::to_string(limits.coefficients);
  const std::string prefix = "transport:";
  if (value.compare(0, prefix.size(), prefix) == 0) {
    const std::optional<double> k = ParseNumber(value.substr(prefix.size()));
    if (!k || *k != std::floor(*k) || *k < 0 || *k >= limits.coefficients) Refuse("view", value, expected);
    draw.view = View::kTransport;
    draw.transport_index = static_cast<int>(*k);
    return;
  }
  const std::optional<View> view = ViewFromName(value);
  if (!view || *view == View::kTransport) Refuse("view", value, expected);
  draw.view = *view;
}

void ReadSize(const std::string& value, RenderOptions& draw) {
  const std::size_t x = value.find('x');
  const std::string expected = "WxH, each " + std::to_string(kMinFrameSide) + ".." + std::to_string(kMaxFrameSide);
  if (x == std::string::npos) Refuse("size", value, expected);
  const std::optional<double> w = ParseNumber(value.substr(0, x)), h = ParseNumber(value.substr(x + 1));
  if (!w || !h || *w != std::floor(*w) || *h != std::floor(*h) || *w < kMinFrameSide || *h < kMinFrameSide ||
      *w > kMaxFrameSide || *h > kMaxFrameSide)
    Refuse("size", value, expected);
  draw.width = static_cast<int>(*w);
  draw.height = static_cast<int>(*h);
}

std::string Vec(const glm::dvec3& v) { return Formatted("%.17g,%.17g,%.17g", v.x, v.y, v.z); }

}  // namespace

FrameRequest ParseFrameRequest(const std::vector<std::pair<std::string, std::string>>& query,
                               const FrameRequest& defaults, const ViewLimits& limits) {
  FrameRequest r = defaults;
  RenderOptions& d = r.draw;
  std::map<std::string, int> seen;
  for (const auto& [name, value] : query) {
    if (++seen[name] > 1) throw Error(name + ": given twice (expected each parameter once)");
    if (name == "axis") d.axis = Vector(name, value, true);
    else if (name == "angle") d.start_degrees = Number(name, value, -kMaxAngle, kMaxAngle);
    else if (name == "lmax") r.lmax = Integer(name, value, 0, limits.lmax);
    else if (name == "basis") r.basis = OneOf(name, value, limits.bases);
    else if (name == "mode") r.mode = OneOf(name, value, limits.modes);
    else if (name == "env") r.env = Integer(name, value, 0, limits.environments - 1);
    else if (name == "view") ReadView(value, limits, d);
    else if (name == "exposure") d.exposure = Number(name, value, -kMaxExposure, kMaxExposure);
    else if (name == "tonemap") d.tonemap = *ParseToneCurve(OneOf(name, value, ToneCurveNames()));
    else if (name == "eye") d.eye = Vector(name, value, false);
    else if (name == "target") d.target = Vector(name, value, false);
    else if (name == "up") d.up = Vector(name, value, true);
    else if (name == "fov") d.fov = Number(name, value, kMinFov, kMaxFov);
    else if (name == "size") ReadSize(value, d);
    else if (name == "ssaa") d.ssaa = Integer(name, value, 1, kMaxSsaa);
    else if (name == "terms") r.light_terms = Integer(name, value, 0, limits.light_terms);
    else if (name == "quality") r.interactive = OneOf(name, value, {"still", "interactive"}) == "interactive";
    else throw Error(name + ": unknown parameter (expected axis, angle, lmax, basis, mode, env, view, exposure, "
                            "tonemap, eye, target, up, fov, size, ssaa, terms, quality)");
  }
  if (double(d.width) * d.height * d.ssaa * d.ssaa > kMaxViewSamples)
    throw Error("size=" + std::to_string(d.width) + "x" + std::to_string(d.height) + "&ssaa=" + std::to_string(d.ssaa) +
                ": refused (expected width x height x ssaa^2 at most 4096^2 samples)");
  if (d.eye && d.target && glm::length(*d.eye - *d.target) < 1e-9) throw Error("eye: the same point as target");
  if (!limits.camera_moves && (seen.count("eye") || seen.count("target") || seen.count("up") || seen.count("fov")) &&
      (d.eye != defaults.draw.eye || d.target != defaults.draw.target || d.up != defaults.draw.up ||
       d.fov != defaults.draw.fov))
    throw Error("eye: the camera cannot move (the glossy transfer was computed for the camera's eye)");
  return r;
}

std::string FrameQuery(const FrameRequest& r) {
  const RenderOptions& d = r.draw;
  std::string q = "axis=" + Vec(d.axis) + Formatted("&angle=%.17g", d.start_degrees) + "&lmax=" + std::to_string(r.lmax) +
                  "&basis=" + r.basis + "&mode=" + r.mode + "&env=" + std::to_string(r.env) + "&view=" +
                  (d.view == View::kTransport ? "transport:" + std::to_string(d.transport_index) : ViewName(d.view));
  if (d.exposure) q += Formatted("&exposure=%.17g", *d.exposure);
  q += std::string("&tonemap=") + ToneCurveName(d.tonemap);
  if (d.eye) q += "&eye=" + Vec(*d.eye);
  if (d.target) q += "&target=" + Vec(*d.target);
  if (d.up) q += "&up=" + Vec(*d.up);
  if (d.fov) q += Formatted("&fov=%.17g", *d.fov);
  q += "&size=" + std::to_string(d.width) + "x" + std::to_string(d.height) + "&ssaa=" + std::to_string(d.ssaa) +
       "&terms=" + std::to_string(r.light_terms) + "&quality=" + (r.interactive ? "interactive" : "still");
  return q;
}

}  // namespace prt
