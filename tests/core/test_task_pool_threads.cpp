// The threads tier of core/task_pool.h (tests/README.md, "Tiers"): tasks submitted from several
// threads at once run each exactly once, on the pool's workers only and never more at a time
// than it has; a pool that goes while tasks are queued leaves every future answered, with a
// value or a broken promise. Watched by ThreadSanitizer.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "core/task_pool.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("core") {
  TEST_CASE("threads: tasks submitted from several threads each run once, on the pool's workers, at most that many at a time") {
    constexpr int kWorkers = 2, kPerThread = 50;
    std::atomic<int> running{0}, most{0};
    std::mutex ids_mutex;
    std::set<std::thread::id> ids, submitters;
    std::vector<std::vector<int>> results(std::size_t(test::kManyThreads));
    {
      TaskPool pool(kWorkers);
      test::OnThreads(test::kManyThreads, [&](int t) {
        {
          std::lock_guard<std::mutex> lock(ids_mutex);
          submitters.insert(std::this_thread::get_id());
        }
        std::vector<std::future<int>> futures;
        for (int i = 0; i < kPerThread; ++i)
          futures.push_back(pool.Submit([&, t, i] {
            const int now = ++running;
            int seen = most.load();
            while (now > seen && !most.compare_exchange_weak(seen, now)) {
            }
            {
              std::lock_guard<std::mutex> lock(ids_mutex);
              ids.insert(std::this_thread::get_id());
            }
            std::this_thread::yield();  // let another task start meanwhile, if the pool would
            --running;
            return t * kPerThread + i;
          }));
        for (auto& f : futures) results[std::size_t(t)].push_back(f.get());
      });
    }
    for (int t = 0; t < test::kManyThreads; ++t)
      for (int i = 0; i < kPerThread; ++i) CHECK(results[std::size_t(t)][std::size_t(i)] == t * kPerThread + i);
    CHECK(most.load() >= 1);
    CHECK(most.load() <= kWorkers);
    CHECK(ids.size() <= std::size_t(kWorkers));
    for (const std::thread::id id : ids) CHECK(submitters.count(id) == 0);
  }

  TEST_CASE("threads: a pool that goes while threads fill its queue answers every future, with its value or a broken promise") {
    constexpr int kPerThread = 40;
    std::atomic<int> ran{0};
    std::vector<std::vector<std::future<int>>> futures(std::size_t(test::kManyThreads));
    {
      TaskPool pool(2);
      test::OnThreads(test::kManyThreads, [&](int t) {
        for (int i = 0; i < kPerThread; ++i) futures[std::size_t(t)].push_back(pool.Submit([&ran, i] {
          ++ran;
          return i;
        }));
      });
    }
    int values = 0, broken = 0;
    for (auto& list : futures)
      for (std::size_t i = 0; i < list.size(); ++i) {
        REQUIRE(list[i].wait_for(std::chrono::seconds(0)) == std::future_status::ready);
        try {
          const int value = list[i].get();  // outside CHECK, which would catch what it throws
          CHECK(value == int(i));
          ++values;
        } catch (const std::future_error& e) {
          broken += e.code() == std::make_error_code(std::future_errc::broken_promise);
        }
      }
    CHECK(values == ran.load());
    CHECK(values + broken == test::kManyThreads * kPerThread);
  }
}

}  // namespace prt
