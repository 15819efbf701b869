#pragma once
/// \file
/// A stand-in for prt view's scene (view/view_server.h's ViewBackend), for the server's tests in
/// this process: one colour per frame (its width, so a reply that answered another request
/// shows), each frame taking `draw_ms`; it counts its frames and the most drawn at once.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>

#include "view/view_server.h"

namespace prt::test {

/// A scene whose frames take `draw_ms` each, one colour per frame (its width): counts its draws
/// and the most it was asked to draw at once.
class StandInBackend : public ViewBackend {
 public:
  explicit StandInBackend(int draw_ms = 0) : draw_ms_(draw_ms) {
    limits_.bases = {"sh"};
    limits_.modes = {"shadowed"};
    defaults_.basis = "sh";
    defaults_.mode = "shadowed";
    defaults_.draw.width = 16;
    defaults_.draw.height = 8;
    defaults_.draw.ssaa = 1;
  }
  const ViewLimits& Limits() const override { return limits_; }
  const FrameRequest& Defaults() const override { return defaults_; }
  std::string StateJson() const override { return "{\"frames\":" + std::to_string(frames_.load()) + "}"; }
  Image8 Frame(const FrameRequest& request, double* draw_ms) override {
    const int now = ++drawing_;
    for (int most = most_.load(); now > most && !most_.compare_exchange_weak(most, now);) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(draw_ms_));
    Image8 image;
    image.width = request.draw.width;
    image.height = request.draw.height;
    image.rgb.assign(std::size_t(3) * image.width * image.height, std::uint8_t(request.draw.width));
    *draw_ms = draw_ms_;
    --drawing_;
    ++frames_;
    return image;
  }
  void Compute(const std::string&, const std::string&) override {}
  void MeasureReference(const FrameRequest&) override {}
  std::string ErrorJson(const FrameRequest&) override { throw NotReady("not measured"); }
  std::string Command(const FrameRequest&) const override { return "prt render\n"; }

  int most_at_once() const { return most_; }
  int frames() const { return frames_; }

 private:
  const int draw_ms_;
  ViewLimits limits_;
  FrameRequest defaults_;
  std::atomic<int> drawing_{0}, most_{0}, frames_{0};
};

}  // namespace prt::test
