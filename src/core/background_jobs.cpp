#include "core/background_jobs.h"

#include <algorithm>
#include <chrono>
#include <utility>

namespace prt {
namespace {

// Collects the oldest job (rethrowing its exception); returns the seconds spent waiting.
double CollectOldest(std::deque<std::future<void>>& in_flight) {
  const auto t0 = std::chrono::steady_clock::now();
  std::future<void> oldest = std::move(in_flight.front());
  in_flight.pop_front();
  oldest.get();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

BackgroundJobs::BackgroundJobs(int limit) : limit_(static_cast<std::size_t>(std::max(1, limit))) {}

BackgroundJobs::~BackgroundJobs() {
  for (auto& job : in_flight_)
    if (job.valid()) job.wait();
}

double BackgroundJobs::Submit(std::function<void()> job) {
  double waited = 0.0;
  while (in_flight_.size() >= limit_) waited += CollectOldest(in_flight_);
  in_flight_.push_back(std::async(std::launch::async, std::move(job)));
  return waited;
}

double BackgroundJobs::Wait() {
  double waited = 0.0;
  while (!in_flight_.empty()) waited += CollectOldest(in_flight_);
  return waited;
}

}  // namespace prt
