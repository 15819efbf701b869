#pragma once
/// \file
/// The small scene as prt view's scene (app/view_scene.h) for the tests in this process: under
/// the sky, SH to `lmax` with 32 directions a vertex (a transport in milliseconds), 48 x 36
/// frames, the mesh repeated in the render command line as a user would type it; and a wait for
/// what it computes in the background.

#include <chrono>
#include <string>
#include <thread>

#include "app/view_scene.h"
#include "tests/test_support.h"

namespace prt::test {

inline ViewSetup SmallViewSetup(const std::string& name, int lmax, int reference_samples) {
  ViewSetup setup;
  setup.scene.mesh = WriteSmallScene(ScratchDir(name));
  setup.scene.lmax = lmax;
  setup.scene.samples = 32;
  setup.scene.hidden_samples = 32;
  setup.draw.width = 48;
  setup.draw.height = 36;
  setup.draw.ssaa = 1;
  setup.envs = {setup.scene.env};
  setup.cache = "none";
  setup.reference_samples = reference_samples;
  setup.kept_tokens = {"--mesh", setup.scene.mesh};
  return setup;
}

/// Waits for the scene's background work (at most a minute: a broken build must not hang the suite) until `ready()` is true.
template <class F>
bool WaitFor(F&& ready) {
  for (int i = 0; i < 6000; ++i) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

}  // namespace prt::test
