#include "render/render_options.h"

#include "core/name_table.h"

namespace prt {
namespace {

constexpr auto kViews = MakeNameTable<View>({
    {View::kRadiance, "radiance"}, {View::kIrradiance, "irradiance"}, {View::kAlbedo, "albedo"},
    {View::kTransport, "transport"}, {View::kLight, "light"}, {View::kGlossy, "glossy"},
});
static_assert(kViews.Distinct());

}  // namespace

const char* ViewName(View view) { return kViews.Name(view); }

std::optional<View> ViewFromName(const std::string& name) { return kViews.Find(name); }

std::vector<std::string> ViewNames() { return kViews.Names(); }

RenderOptions WithDemoCamera(RenderOptions o) {
  o.eye = glm::dvec3(6.0, 3.2, 9.0);
  o.target = glm::dvec3(0.0, 1.5, 0.0);
  o.fov = 36.0;
  return o;
}

}  // namespace prt
