#include "render/render_options.h"

#include <utility>

namespace prt {
namespace {

constexpr std::pair<View, const char*> kViews[] = {
    {View::kRadiance, "radiance"}, {View::kIrradiance, "irradiance"}, {View::kAlbedo, "albedo"},
    {View::kTransport, "transport"}, {View::kLight, "light"}, {View::kGlossy, "glossy"},
};

}  // namespace

const char* ViewName(View view) {
  for (const auto& [v, name] : kViews)
    if (v == view) return name;
  return "radiance";
}

std::optional<View> ViewFromName(const std::string& name) {
  for (const auto& [v, word] : kViews)
    if (name == word) return v;
  return std::nullopt;
}

std::vector<std::string> ViewNames() {
  std::vector<std::string> names;
  for (const auto& view : kViews) names.emplace_back(view.second);
  return names;
}

RenderOptions WithDemoCamera(RenderOptions o) {
  o.eye = glm::dvec3(6.0, 3.2, 9.0);
  o.target = glm::dvec3(0.0, 1.5, 0.0);
  o.fov = 36.0;
  return o;
}

}  // namespace prt
