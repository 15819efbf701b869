#include "app/view_scene.h"

#include <chrono>
#include <cmath>
#include <set>

#include "basis/cache_plan.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/text.h"
#include "precompute/reference.h"
#include "raster/exposure.h"
#include "render/render_frames.h"

namespace prt {
namespace {

/// The transport modes the page offers.
const std::vector<std::string> kModes = {"unshadowed", "shadowed", "interreflection"};

/// A word the shell passes through as it is, else the word in single quotes.
std::string ShellWord(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                              "0123456789_-+=.,/:@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += char(c);
    else if (c < 0x20) out += Formatted("\\u%04x", c);
    else out += char(c);
  }
  return out + "\"";
}

std::string JsonList(const std::vector<std::string>& words) {
  std::string out = "[";
  for (const std::string& w : words) out += (out.size() > 1 ? "," : "") + JsonString(w);
  return out + "]";
}

std::string Vec(const glm::dvec3& v) { return Formatted("%.9g,%.9g,%.9g", v.x, v.y, v.z); }

std::string Key(const std::string& basis, const std::string& mode) { return basis + " " + mode; }

}  // namespace

/// A reference the page asked for: measuring (not done), measured, or failed (`error`).
struct ViewScene::Measured {
  std::mutex mutex;
  bool done = false;
  std::string error;
  Reference reference;
};

/// One transport the page asked for: computing (prepared empty), ready, or failed (`error`).
struct ViewScene::Prepared {
  std::mutex mutex;
  bool done = false;
  std::string error;
  std::unique_ptr<PreparedBasis> basis;
  SceneOptions scene;
};

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
  limits_.modes = kModes;
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

  auto first = std::make_shared<Prepared>();
  prepared_[Key(defaults_.basis, defaults_.mode)] = first;
  Prepare(first, defaults_.basis, defaults_.mode);
  if (!first->error.empty()) throw Error(first->error);
  if (!defaults_.draw.exposure) {
    // As render measures it: on the first frame's mesh pixels.
    FrameRequest probe = defaults_;
    probe.draw.exposure = 0.0;
    double ms = 0.0;
    Frame(probe, &ms);
    std::lock_guard<std::mutex> lock(draw_mutex_);
    defaults_.draw.exposure = AutoExposureEv(
        RasterizeFrame(rasterizer_, mesh_, *light_, *envs_[0], ChooseCamera(mesh_, probe.draw), probe.draw,
                       probe.draw.start_degrees * kPi / 180.0, 0.0),
        defaults_.draw.tonemap);
    ReportAutoExposure(*defaults_.draw.exposure, "the first frame's mesh pixels");
  }
}

ViewScene::~ViewScene() {
  for (std::thread& t : workers_) t.join();
}

SceneOptions ViewScene::SceneOf(const std::string& basis, const std::string& mode) const {
  SceneOptions s = setup_.scene;
  s.basis = FindBasis(basis);
  s.transport = mode;
  if (s.basis != setup_.scene.basis && s.basis->Lmax() >= 0) s.lmax = s.basis->Lmax();
  return s;
}

void ViewScene::Prepare(const std::shared_ptr<Prepared>& slot, const std::string& basis, const std::string& mode) {
  const SceneOptions scene = SceneOf(basis, mode);
  const bool first = basis == defaults_.basis && mode == defaults_.mode;
  try {
    const CachePlan cache = first ? PlanCache(setup_.cache, nullptr, "", Bases()) : CachePlan{"", false, {}};
    ComputeLight(*envs_[0], scene);  // said on the run summary, as render says it; each frame makes its own
    const TransportOptions transport = TransportOptionsOf(scene);  // every vertex seen: the camera moves
    const CpcaOptions cpca{};
    const glm::dvec3 axis = defaults_.draw.axis;
    const BasisInputs inputs{mesh_, transport, scene.samples_from_rule, scene.lmax_why, scene.own(), axis,
                             cpca,  *envs_[0], &camera_,                 cache,          false};
    std::unique_ptr<PreparedBasis> prepared = scene.basis->Prepare(inputs);
    std::lock_guard<std::mutex> lock(slot->mutex);
    slot->basis = std::move(prepared);
    slot->scene = scene;
    slot->done = true;
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(slot->mutex);
    slot->error = basis + " " + mode + ": " + e.what();
    slot->done = true;
  }
}

std::shared_ptr<ViewScene::Prepared> ViewScene::Find(const std::string& basis, const std::string& mode) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = prepared_.find(Key(basis, mode));
  return it == prepared_.end() ? nullptr : it->second;
}

void ViewScene::Compute(const std::string& basis, const std::string& mode) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto& slot = prepared_[Key(basis, mode)];
  if (slot) return;
  slot = std::make_shared<Prepared>();
  Summary("view: computing the " + basis + " transport, " + mode + ", as the page asked");
  workers_.emplace_back([this, s = slot, basis, mode] { Prepare(s, basis, mode); });
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

Image8 ViewScene::Frame(const FrameRequest& request, double* draw_ms) {
  const std::shared_ptr<Prepared> slot = Find(request.basis, request.mode);
  if (!slot) throw NotReady(Key(request.basis, request.mode) + ": not computed (POST /compute starts it)");
  {
    std::lock_guard<std::mutex> lock(slot->mutex);
    if (!slot->done) throw NotReady(Key(request.basis, request.mode) + ": still computing");
    if (!slot->error.empty()) throw Error(slot->error);
  }
  if (request.draw.view == View::kTransport && !slot->scene.basis->Traits().coefficient_view)
    throw Error("view=transport: the " + request.basis + " basis keeps no SH transfer coefficients (expected basis=" +
                DefaultBasis()->Name() + ")");
  const auto start = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> lock(draw_mutex_);
  const bool bands = slot->scene.basis->Traits().light_bands;
  const int computed = slot->scene.lmax;
  const int lmax = bands ? std::min(request.lmax, computed) : computed;
  const std::string key = Key(request.basis, request.mode) + " " + std::to_string(request.env) + " " +
                          std::to_string(lmax) + " " + ViewName(request.draw.view) + " " + Vec(request.draw.axis) +
                          " " + std::to_string(request.light_terms);
  if (key != light_key_ || !light_) {
    // Bands above lmax zeroed: the frame of a transport computed at lmax.
    ShRgb light = Light(request.env, lmax, request.draw.view, slot->scene);
    light.resize(CoeffCount(computed), glm::dvec3(0.0));
    light_ = slot->basis->Light(*envs_[request.env], light, request.draw.axis, request.light_terms);
    light_key_ = key;
  }
  const Camera camera = ChooseCamera(mesh_, request.draw);
  ToneMapped toned = DrawFrame(rasterizer_, mesh_, *light_, *envs_[request.env], camera, request.draw,
                               request.draw.start_degrees * kPi / 180.0, request.draw.exposure.value_or(0.0));
  *draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return std::move(toned.image);
}

void ViewScene::MeasureReference(const FrameRequest& r) {
  const std::string key = r.mode + " " + std::to_string(r.env);
  std::lock_guard<std::mutex> lock(mutex_);
  auto& slot = references_[key];
  if (slot) return;
  slot = std::make_shared<Measured>();
  Summary("view: measuring prt reference for " + r.mode + " under " + setup_.envs[r.env] + " (" +
          std::to_string(setup_.reference_samples) + " directions a vertex), as the page asked");
  ReferenceOptions ro;
  ro.mode = TransportModeFromName(r.mode);
  ro.samples = setup_.reference_samples;
  ro.bounces = setup_.scene.bounces;
  ro.seed = setup_.scene.seed;
  ro.material = setup_.scene.material;
  ro.eye = glm::dvec3(camera_.eye);
  workers_.emplace_back([this, s = slot, ro, env = r.env] {
    try {
      Reference reference = ComputeReference(mesh_, *envs_[env], ro);
      std::lock_guard<std::mutex> l(s->mutex);
      s->reference = std::move(reference);
      s->done = true;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> l(s->mutex);
      s->error = e.what();
      s->done = true;
    }
  });
}

std::string ViewScene::ErrorJson(const FrameRequest& r) {
  std::shared_ptr<Measured> measured;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = references_.find(r.mode + " " + std::to_string(r.env));
    if (it != references_.end()) measured = it->second;
  }
  if (!measured) throw NotReady("the reference of " + r.mode + " under environment " + std::to_string(r.env) +
                                " is not measured (POST /reference starts it)");
  {
    std::lock_guard<std::mutex> lock(measured->mutex);
    if (!measured->done) throw NotReady("the reference is still being measured");
    if (!measured->error.empty()) throw Error("reference: " + measured->error);
  }
  const std::shared_ptr<Prepared> slot = Find(r.basis, r.mode);
  if (!slot) throw NotReady(Key(r.basis, r.mode) + ": not computed (POST /compute starts it)");
  {
    std::lock_guard<std::mutex> lock(slot->mutex);
    if (!slot->done) throw NotReady(Key(r.basis, r.mode) + ": still computing");
    if (!slot->error.empty()) throw Error(slot->error);
  }
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
  const std::unique_ptr<FrameLight> frame_light = slot->basis->Light(*envs_[r.env], light, defaults_.draw.axis, r.light_terms);
  frame_light->Turn(0.0);
  const glm::dvec3 eye(camera_.eye);
  const std::vector<glm::vec3> shaded = frame_light->Shade(mesh_, true, &eye);
  const Reference& ref = measured->reference;
  double diff = 0.0, norm = 0.0;
  for (std::size_t v = 0; v < shaded.size(); ++v) {
    const glm::dvec3 d = glm::dvec3(shaded[v]) - ref.radiance[v];
    diff += glm::dot(d, d);
    norm += glm::dot(ref.radiance[v], ref.radiance[v]);
  }
  const double error = norm > 0 ? std::sqrt(diff / norm) : 0.0;
  const double own = ref.rms_radiance > 0 ? ref.rms_error / ref.rms_radiance : 0.0;
  const std::string json = Formatted("{\"error\":%.6g,\"reference_error\":%.6g,\"vertices\":%zu,\"samples\":%d,"
                                     "\"lmax\":%d}", error, own, shaded.size(), setup_.reference_samples, lmax);
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
  std::string transports = "[", references = "[";
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [key, slot] : prepared_) {
      std::lock_guard<std::mutex> slot_lock(slot->mutex);
      const std::string state = !slot->done ? "computing" : slot->error.empty() ? "ready" : "failed";
      transports += std::string(transports.size() > 1 ? "," : "") + "{\"key\":" + JsonString(key) +
                    ",\"state\":\"" + state + "\",\"error\":" + JsonString(slot->error) + "}";
    }
    for (const auto& [key, measured] : references_) {
      std::lock_guard<std::mutex> measured_lock(measured->mutex);
      const std::string state = !measured->done ? "measuring" : measured->error.empty() ? "ready" : "failed";
      references += std::string(references.size() > 1 ? "," : "") + "{\"key\":" + JsonString(key) +
                    ",\"state\":\"" + state + "\",\"error\":" + JsonString(measured->error) + "}";
    }
  }
  transports += "]";
  references += "]";
  const ProgressReading progress = LatestProgress();
  const RenderOptions& d = defaults_.draw;
  std::vector<std::string> env_names = setup_.envs;
  return "{\"limits\":{\"lmax\":" + std::to_string(limits_.lmax) + ",\"bases\":" + JsonList(limits_.bases) +
         ",\"modes\":" + JsonList(limits_.modes) + ",\"environments\":" + JsonList(env_names) +
         ",\"coefficients\":" + std::to_string(limits_.coefficients) +
         ",\"light_terms\":" + std::to_string(limits_.light_terms) +
         ",\"camera_moves\":" + (limits_.camera_moves ? "true" : "false") + "},\"defaults\":{\"query\":" +
         JsonString(FrameQuery(defaults_)) + ",\"eye\":[" + Vec(*d.eye) + "],\"target\":[" + Vec(*d.target) +
         "],\"up\":[" + Vec(*d.up) + "],\"fov\":" + Formatted("%.9g", *d.fov) +
         ",\"exposure\":" + Formatted("%.9g", d.exposure.value_or(0.0)) + ",\"axis\":[" + Vec(d.axis) +
         "],\"width\":" + std::to_string(d.width) + ",\"height\":" + std::to_string(d.height) +
         "},\"transports\":" + transports + ",\"references\":" + references + ",\"progress\":{\"label\":" + JsonString(progress.label) +
         ",\"fraction\":" + Formatted("%.4f", progress.fraction) + ",\"active\":" + (progress.active ? "true" : "false") +
         "}}";
}

}  // namespace prt
