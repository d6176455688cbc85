// Bounded waits for tests that could otherwise fail only by hanging until the ctest timeout
// (a join, or a destructor that joins, that never returns): the step runs on its own thread
// and the test waits a few seconds for it, then fails naming what hung.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <future>
#include <string>

namespace sl::test {

/// Runs `step` on another thread and waits at most `limit` for it: true when it returned (an
/// exception it threw is rethrown here). Else a test failure naming `what`, then `unblock`
/// (e.g. open the gate or set the cancel flag the step waits on) and a second wait of `limit`.
/// A step still blocked after that cannot be left running (it holds references into the
/// test), so the binary says why on stderr and exits with status 1 instead of hanging.
inline bool finishesWithin(std::chrono::milliseconds limit, const std::string& what,
                           const std::function<void()>& step,
                           const std::function<void()>& unblock = {}) {
  std::future<void> done = std::async(std::launch::async, step);
  if (done.wait_for(limit) == std::future_status::ready) {
    done.get();
    return true;
  }
  ADD_FAILURE() << what << " did not return within " << limit.count() << " ms";
  if (unblock) {
    unblock();
    if (done.wait_for(limit) == std::future_status::ready) {
      done.get();
      return false;
    }
  }
  std::fflush(stdout);
  std::fprintf(stderr,
               "FATAL: %s still has not returned after %lld ms%s; exiting instead of hanging\n",
               what.c_str(), static_cast<long long>((unblock ? 2 : 1) * limit.count()),
               unblock ? " (also after unblocking it)" : "");
  std::fflush(stderr);
  std::_Exit(1);
}

}  // namespace sl::test
