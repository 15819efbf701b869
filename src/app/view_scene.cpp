#include "app/view_scene.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "basis/cache_plan.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/shell_word.h"
#include "core/text.h"
#include "precompute/transport_types.h"
#include "raster/exposure.h"
#include "render/render_frames.h"

namespace prt {
namespace {

/// JSON objects keep their keys in the order written: the page's tests find "key" before "state".
using Json = nlohmann::ordered_json;

/// `v` rounded as printf's `format` rounds it, as a JSON number: the page reads the double that
/// printf's text reads as (nlohmann may spell it longer, 79.48923979999999 for 79.4892398: its
/// Grisu2 gives digits that read back, not always the fewest). A whole number is an integer,
/// written as %g writes it (2, not nlohmann's 2.0; -0 as 0).
Json Rounded(const char* format, double v) {
  const double read = std::strtod(Formatted(format, v).c_str(), nullptr);
  if (std::trunc(read) == read && std::fabs(read) < 9007199254740992.0)  // 2^53: whole doubles exactly
    return static_cast<std::int64_t>(read);
  return read;  // not finite: null
}

/// A point or direction as [x,y,z], 9 digits.
Json Point(const glm::dvec3& v) {
  return Json::array({Rounded("%.9g", v.x), Rounded("%.9g", v.y), Rounded("%.9g", v.z)});
}

/// Bytes that are not UTF-8 (a file name) become U+FFFD, as the page's JSON parser reads them.
std::string JsonText(const Json& json) { return json.dump(-1, ' ', false, Json::error_handler_t::replace); }

std::string Vec(const glm::dvec3& v) { return Formatted("%.9g,%.9g,%.9g", v.x, v.y, v.z); }

std::string Key(const std::string& basis, const std::string& mode) { return basis + " " + mode; }

/// What a request needs of a background job: its result, once the job has finished. Throws
/// NotReady `never` when nobody asked for it (`job` not valid()), NotReady `running` until it has
/// finished, and Error(`failed` + its message) when it threw.
template <class T>
const T& Finished(const std::shared_future<T>& job, const std::string& never, const std::string& running,
                  const std::string& failed) {
  if (!job.valid()) throw NotReady(never);
  if (job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) throw NotReady(running);
  try {
    return job.get();
  } catch (const std::exception& e) {
    throw Error(failed + e.what());
  }
}

/// A job as /state shows it: {"key", "state": `running` until finished, then "ready" or
/// "failed", "error": `failed` + its message, or ""}.
template <class T>
Json JobState(const std::string& key, const std::shared_future<T>& job, const char* running,
              const std::string& failed) {
  std::string state = running, error;
  if (job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    try {
      job.get();
      state = "ready";
    } catch (const std::exception& e) {
      state = "failed";
      error = failed + e.what();
    }
  }
  return Json{{"key", key}, {"state", state}, {"error", error}};
}

/// A finished job of `value`, for what is computed before the page asks.
template <class T>
std::shared_future<T> Done(T value) {
  std::promise<T> promise;
  promise.set_value(std::move(value));
  return promise.get_future().share();
}

}  // namespace

ViewScene::ViewScene(ViewSetup setup) : setup_(std::move(setup)) {
  mesh_ = LoadSceneMesh(setup_.scene);
  camera_ = SceneCamera(mesh_, setup_.draw);
  for (const std::string& name : setup_.envs) {
    SceneOptions s = setup_.scene;
    s.env = name;
    envs_.push_back(LoadSceneEnvironment(s));
  }
  limits_.lmax = setup_.scene.lmax;
  limits_.bases.push_back(setup_.scene.basis->Name());
  for (const Basis* b : Bases())
    if (b != setup_.scene.basis && (b->Traits().glossy || !setup_.scene.material.glossy)) limits_.bases.push_back(b->Name());
  limits_.modes = TransportModeNames();  // every mode the page offers
  limits_.environments = static_cast<int>(envs_.size());
  limits_.coefficients = CoeffCount(setup_.scene.lmax);
  for (const Basis* b : Bases())  // the light terms of the bases that keep fewer than all
    if (const int most = b->MaxLightTerms(setup_.scene.basis_options.Of(*b)); most > 0) {
      limits_.light_terms = std::max(limits_.light_terms, most);
      defaults_.light_terms = b->LightTerms(setup_.scene.basis_options.Of(*b));
    }
  limits_.camera_moves = !setup_.scene.material.glossy;

  defaults_.draw = setup_.draw;
  defaults_.draw.eye = glm::dvec3(camera_.eye);
  defaults_.draw.target = glm::dvec3(camera_.target);
  defaults_.draw.up = glm::dvec3(camera_.up);
  defaults_.draw.fov = camera_.fov_deg;
  defaults_.lmax = setup_.scene.lmax;
  defaults_.basis = setup_.scene.basis->Name();
  defaults_.mode = setup_.scene.transport;

}

void ViewScene::ComputeFirst() {
  // The first transport, here and now: the run fails with its error.
  try {
    prepared_[Key(defaults_.basis, defaults_.mode)] = Done(Prepare(defaults_.basis, defaults_.mode));
  } catch (const std::exception& e) {
    throw Error(Key(defaults_.basis, defaults_.mode) + ": " + e.what());
  }
  if (!defaults_.draw.exposure) {
    // As render measures it: on the first frame's mesh pixels.
    FrameRequest probe = defaults_;
    probe.draw.exposure = 0.0;
    std::lock_guard<std::mutex> lock(draw_mutex_);
    FrameLight& light = FrameLightOf(probe, Find(defaults_.basis, defaults_.mode).get());
    defaults_.draw.exposure = AutoExposureEv(RasterizeFrame(rasterizer_, mesh_, light, *envs_[0], ChooseCamera(mesh_, probe.draw),
                                                            probe.draw, probe.draw.start_degrees * kPi / 180.0, 0.0),
                                             defaults_.draw.tonemap);
    ReportAutoExposure(*defaults_.draw.exposure, "the first frame's mesh pixels");
  }
}

SceneOptions ViewScene::SceneOf(const std::string& basis, const std::string& mode) const {
  SceneOptions s = setup_.scene;
  s.basis = FindBasis(basis);
  s.transport = mode;
  if (s.basis != setup_.scene.basis && s.basis->Lmax() >= 0) s.lmax = s.basis->Lmax();
  return s;
}

ViewScene::Prepared ViewScene::Prepare(const std::string& basis, const std::string& mode) const {
  const SceneOptions scene = SceneOf(basis, mode);
  const bool first = basis == defaults_.basis && mode == defaults_.mode;
  const CachePlan cache = first ? PlanCache(setup_.cache, nullptr, "", Bases()) : CachePlan{"", false, {}};
  ComputeLight(*envs_[0], scene);  // said on the run summary, as render says it; each frame makes its own
  const TransportOptions transport = TransportOptionsOf(scene);  // every vertex seen: the camera moves
  const CpcaOptions cpca{};
  const glm::dvec3 axis = defaults_.draw.axis;
  const BasisInputs inputs{mesh_, transport, scene.samples_from_rule, scene.lmax_why, scene.own(), axis,
                           cpca,  *envs_[0], &camera_,                 cache,          false};
  return Prepared{scene.basis->Prepare(inputs), scene};
}

std::shared_future<ViewScene::Prepared> ViewScene::Find(const std::string& basis, const std::string& mode) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = prepared_.find(Key(basis, mode));
  return it == prepared_.end() ? std::shared_future<Prepared>() : it->second;
}

void ViewScene::Compute(const std::string& basis, const std::string& mode) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::shared_future<Prepared>& job = prepared_[Key(basis, mode)];
  if (job.valid()) return;
  Summary("view: computing the " + basis + " transport, " + mode + ", as the page asked");
  job = pool_.Submit([this, basis, mode] { return Prepare(basis, mode); }).share();
}

const ViewScene::Prepared& ViewScene::Transport(const std::string& basis, const std::string& mode) const {
  const std::string key = Key(basis, mode);
  return Finished(Find(basis, mode), key + ": not computed (POST /compute starts it)", key + ": still computing",
                  key + ": ");
}

const ShRgb& ViewScene::Light(int env, int lmax, View view, const SceneOptions& scene) {
  // The window the frames of `view` need, at lmax: as render computes it for --lmax lmax.
  const std::string key =
      scene.basis->Name() + " " + std::to_string(env) + " " + std::to_string(lmax) + " " + ViewName(view);
  auto it = lights_.find(key);
  if (it == lights_.end()) {
    SceneOptions s = scene;
    s.lmax = lmax;
    it = lights_.emplace(key, ComputeLight(*envs_[env], s, view)).first;
  }
  return it->second;
}

FrameLight& ViewScene::FrameLightOf(const FrameRequest& request, const Prepared& slot) {
  const bool bands = slot.scene.basis->Traits().light_bands;
  const int computed = slot.scene.lmax;
  const int lmax = bands ? std::min(request.lmax, computed) : computed;
  const std::string key = Key(request.basis, request.mode) + " " + std::to_string(request.env) + " " +
                          std::to_string(lmax) + " " + ViewName(request.draw.view) + " " +
                          std::to_string(request.light_terms) + (request.interactive ? " interactive" : " still");
  auto it = frame_lights_.find(key);
  if (it == frame_lights_.end()) {
    if (frame_lights_.size() >= kKeptLights) frame_lights_.clear();
    // Bands above lmax zeroed: the frame of a transport computed at lmax.
    ShRgb light = Light(request.env, lmax, request.draw.view, slot.scene);
    light.resize(CoeffCount(computed), glm::dvec3(0.0));
    const LightQuality quality = request.interactive ? LightQuality::kInteractive : LightQuality::kStill;
    it = frame_lights_
             .emplace(key, KeptLight{slot.basis->Light(*envs_[request.env], light, request.draw.axis,
                                                       request.light_terms, quality),
                                     request.draw.axis})
             .first;
  } else if (it->second.axis != request.draw.axis) {
    it->second.light->SetAxis(request.draw.axis);
    it->second.axis = request.draw.axis;
  }
  return *it->second.light;
}

Image8 ViewScene::Frame(const FrameRequest& request, double* draw_ms) {
  const Prepared* const slot = &Transport(request.basis, request.mode);
  if (request.draw.view == View::kTransport && !slot->scene.basis->Traits().coefficient_view)
    throw Error("view=transport: the " + request.basis + " basis keeps no SH transfer coefficients (expected basis=" +
                DefaultBasis()->Name() + ")");
  const auto start = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(draw_mutex_);
  FrameLight& light = FrameLightOf(request, *slot);
  RenderOptions draw = request.draw;
  if (request.interactive) draw.ssaa = 1;
  const Camera camera = ChooseCamera(mesh_, draw);
  ToneMapped toned = DrawFrame(rasterizer_, mesh_, light, *envs_[request.env], camera, draw,
                               draw.start_degrees * kPi / 180.0, draw.exposure.value_or(0.0));
  *draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return std::move(toned.image);
}

void ViewScene::MeasureReference(const FrameRequest& r) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::shared_future<Reference>& job = references_[r.mode + " " + std::to_string(r.env)];
  if (job.valid()) return;
  Summary("view: measuring prt reference for " + r.mode + " under " + setup_.envs[r.env] + " (" +
          std::to_string(setup_.reference_samples) + " directions a vertex), as the page asked");
  ReferenceOptions ro;
  ro.mode = TransportModeFromName(r.mode);
  ro.samples = setup_.reference_samples;
  ro.bounces = setup_.scene.bounces;
  ro.seed = setup_.scene.seed;
  ro.material = setup_.scene.material;
  ro.eye = glm::dvec3(camera_.eye);
  job = pool_.Submit([this, ro, env = r.env] { return ComputeReference(mesh_, *envs_[env], ro); }).share();
}

const Reference& ViewScene::MeasuredReference(const std::string& mode, int env) const {
  std::shared_future<Reference> job;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = references_.find(mode + " " + std::to_string(env));
    if (it != references_.end()) job = it->second;
  }
  return Finished(job,
                  "the reference of " + mode + " under environment " + std::to_string(env) +
                      " is not measured (POST /reference starts it)",
                  "the reference is still being measured", "reference: ");
}

std::string ViewScene::ErrorJson(const FrameRequest& r) {
  const Reference& ref = MeasuredReference(r.mode, r.env);
  const Prepared* const slot = &Transport(r.basis, r.mode);
  std::lock_guard<std::mutex> lock(draw_mutex_);
  const bool bands = slot->scene.basis->Traits().light_bands;
  const int computed = slot->scene.lmax;
  const int lmax = bands ? std::min(r.lmax, computed) : computed;
  const std::string key =
      Key(r.basis, r.mode) + " " + std::to_string(r.env) + " " + std::to_string(lmax) + " " + std::to_string(r.light_terms);
  if (const auto it = errors_.find(key); it != errors_.end()) return it->second;
  // This setting's radiance per vertex, the light unturned, against the reference's.
  ShRgb light = Light(r.env, lmax, View::kRadiance, slot->scene);
  light.resize(CoeffCount(computed), glm::dvec3(0.0));
  const std::unique_ptr<FrameLight> frame_light =
      slot->basis->Light(*envs_[r.env], light, defaults_.draw.axis, r.light_terms, LightQuality::kStill);
  frame_light->Turn(0.0);
  const glm::dvec3 eye(camera_.eye);
  const std::vector<glm::vec3> shaded = frame_light->Shade(mesh_, true, &eye);
  double diff = 0.0, norm = 0.0;
  for (std::size_t v = 0; v < shaded.size(); ++v) {
    const glm::dvec3 d = glm::dvec3(shaded[v]) - ref.radiance[v];
    diff += glm::dot(d, d);
    norm += glm::dot(ref.radiance[v], ref.radiance[v]);
  }
  const double error = norm > 0 ? std::sqrt(diff / norm) : 0.0;
  const double own = ref.rms_radiance > 0 ? ref.rms_error / ref.rms_radiance : 0.0;
  const std::string json = JsonText(Json{{"error", Rounded("%.6g", error)},
                                          {"reference_error", Rounded("%.6g", own)},
                                          {"vertices", shaded.size()},
                                          {"samples", setup_.reference_samples},
                                          {"lmax", lmax}});
  errors_[key] = json;
  return json;
}

std::string ViewScene::Command(const FrameRequest& r) const {
  std::string line = "prt render";
  for (const std::string& t : setup_.kept_tokens) line += " " + ShellWord(t);
  const SceneOptions scene = SceneOf(r.basis, r.mode);
  const RenderOptions& d = r.draw;
  // The transport view shows coefficient K whatever the light's lmax: render computes its band.
  int lmax = scene.basis->Traits().light_bands ? r.lmax : scene.lmax;
  if (d.view == View::kTransport) lmax = std::max(lmax, static_cast<int>(std::sqrt(double(d.transport_index))));
  line += " --basis " + r.basis + " --transport " + r.mode + " --lmax " + std::to_string(lmax) +
          " --env " + ShellWord(setup_.envs[r.env]);
  line += scene.basis->CommandLine(scene.own(), r.light_terms);
  if (scene.basis->Traits().takes_samples && r.mode != "unshadowed")
    line += " --samples " + std::to_string(scene.samples) + " --hidden-samples " + std::to_string(scene.samples);
  line += " --axis " + Vec(d.axis) + Formatted(" --start-angle %.9g", d.start_degrees) + " --view " +
          (d.view == View::kTransport ? "transport:" + std::to_string(d.transport_index) : std::string(ViewName(d.view)));
  line += Formatted(" --exposure %.9g", d.exposure.value_or(0.0)) + " --tonemap " + ToneCurveName(d.tonemap);
  if (d.eye) line += " --eye " + Vec(glm::dvec3(glm::vec3(*d.eye)));
  if (d.target) line += " --target " + Vec(glm::dvec3(glm::vec3(*d.target)));
  if (d.up) line += " --up " + Vec(glm::dvec3(glm::vec3(*d.up)));
  if (d.fov) line += Formatted(" --fov %.9g", double(float(*d.fov)));
  line += " --size " + std::to_string(d.width) + "x" + std::to_string(d.height) + " --ssaa " + std::to_string(d.ssaa);
  return line + " --out out/view --frames 120";
}

std::string ViewScene::StateJson() const {
  Json transports = Json::array(), references = Json::array();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [key, job] : prepared_) transports.push_back(JobState(key, job, "computing", key + ": "));
    for (const auto& [key, job] : references_) references.push_back(JobState(key, job, "measuring", ""));
  }
  const ProgressReading progress = LatestProgress();
  const RenderOptions& d = defaults_.draw;
  const Json limits{{"lmax", limits_.lmax},
                    {"bases", limits_.bases},
                    {"modes", limits_.modes},
                    {"environments", setup_.envs},
                    {"coefficients", limits_.coefficients},
                    {"light_terms", limits_.light_terms},
                    {"camera_moves", limits_.camera_moves}};
  const Json defaults{{"query", FrameQuery(defaults_)},
                      {"eye", Point(*d.eye)},
                      {"target", Point(*d.target)},
                      {"up", Point(*d.up)},
                      {"fov", Rounded("%.9g", *d.fov)},
                      {"exposure", Rounded("%.9g", d.exposure.value_or(0.0))},
                      {"axis", Point(d.axis)},
                      {"width", d.width},
                      {"height", d.height}};
  const Json progress_json{
      {"label", progress.label}, {"fraction", Rounded("%.4f", progress.fraction)}, {"active", progress.active}};
  return JsonText(Json{{"limits", limits},
                       {"defaults", defaults},
                       {"transports", transports},
                       {"references", references},
                       {"progress", progress_json}});
}

}  // namespace prt
