// The pool of background jobs (core/task_pool.h) on one worker, where the order is certain: a
// task's result or exception through its future, tasks started in the order submitted, and a
// pool that goes finishing the task it runs and dropping those queued, whose futures throw
// broken_promise rather than hang. Many threads at once: test_task_pool_threads.cpp.
#include <doctest/doctest.h>

#include <chrono>
#include <future>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/task_pool.h"

namespace prt {
namespace {

/// How long a task waits for what the test does next before it gives up: far beyond the
/// microseconds it takes, so only a pool that never lets the test go on reaches it, and fails
/// instead of hanging the suite.
constexpr auto kPatience = std::chrono::seconds(20);

/// Whether `future` (ready) holds the broken promise of a task dropped unrun.
template <class T>
bool Broken(std::future<T>& future) {
  try {
    future.get();
    return false;
  } catch (const std::future_error& e) {
    return e.code() == std::make_error_code(std::future_errc::broken_promise);
  }
}

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("TaskPool: a task's result, or what it throws, comes back through its future") {
    TaskPool pool(1);
    CHECK(pool.Workers() == 1);
    std::future<int> answer = pool.Submit([] { return 42; });
    std::future<std::string> text = pool.Submit([] { return std::string("sky.hdr"); });
    std::future<int> failed = pool.Submit([]() -> int { throw Error("sky.hdr: not an image"); });
    std::future<void> nothing = pool.Submit([] {});
    CHECK(answer.get() == 42);
    CHECK(text.get() == "sky.hdr");
    CHECK_THROWS_WITH_AS(failed.get(), "sky.hdr: not an image", Error);
    nothing.get();
    CHECK(pool.Submit([] { return 7; }).get() == 7);  // the worker goes on after a task threw
  }

  TEST_CASE("TaskPool: a pool of one worker starts its tasks in the order submitted, on a thread of its own") {
    TaskPool pool(1);
    std::vector<int> order;  // only the worker writes it; each future's get() orders the reads
    std::vector<std::future<std::thread::id>> done;
    for (int i = 0; i < 20; ++i)
      done.push_back(pool.Submit([&order, i] {
        order.push_back(i);
        return std::this_thread::get_id();
      }));
    std::set<std::thread::id> ids;
    for (auto& f : done) ids.insert(f.get());
    std::vector<int> expected(20);
    for (int i = 0; i < 20; ++i) expected[std::size_t(i)] = i;
    CHECK(order == expected);
    CHECK(ids.size() == 1);
    CHECK(ids.count(std::this_thread::get_id()) == 0);
  }

  TEST_CASE("TaskPool: at least one worker, whatever it is asked for") {
    TaskPool pool(0);
    CHECK(pool.Workers() == 1);
    CHECK(pool.Submit([] { return 1; }).get() == 1);
  }

  TEST_CASE("TaskPool: a pool that goes finishes the task it runs and drops the queued ones, whose futures throw") {
    std::promise<void> go, started;
    std::future<bool> running, queued_second;
    std::future<int> queued_first;
    {
      TaskPool pool(1);
      // The running task waits for the first queued one to be dropped, which only the pool's
      // going does: so the pool drops its queue before it waits for its workers.
      running = pool.Submit([&go, &started, &queued_first] {
        go.get_future().wait();  // queued_first is set
        started.set_value();
        return queued_first.wait_for(kPatience) == std::future_status::ready;
      });
      queued_first = pool.Submit([] { return 1; });
      queued_second = pool.Submit([] { return true; });
      go.set_value();
      started.get_future().wait();  // the pool goes with one task running, two queued
    }
    CHECK(running.get());  // it ran to its end, and saw the queued task dropped meanwhile
    REQUIRE(queued_first.wait_for(std::chrono::seconds(0)) == std::future_status::ready);
    REQUIRE(queued_second.wait_for(std::chrono::seconds(0)) == std::future_status::ready);
    CHECK(Broken(queued_first));
    CHECK(Broken(queued_second));
  }
}

}  // namespace prt
