// A few threads that run one task side by side and meet at barriers: soft_step's sets of
// contacts, each set split between the threads (the contacts of a set touch disjoint bodies, so
// the split never changes the result). The workers sleep between tasks (C++20 atomic wait, a
// futex) once no task came for most of a millisecond, and spin at the barriers, which are short:
// one set's contacts.
#pragma once

#include <atomic>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

namespace sim::world {

// one thread's part of a range: the t-th of n nearly equal pieces (the split never changes a
// result, only who computes it)
struct Share {
  int t = 0, n = 1;
  std::pair<int, int> of(int begin, int end) const {
    const long len = end - begin;
    return {begin + static_cast<int>(len * t / n), begin + static_cast<int>(len * (t + 1) / n)};
  }
};

class WorkerPool {
 public:
  // `threads` in all, the caller's included: threads − 1 workers are started
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int size() const { return threads_; }
  // task(i) on every thread i (0 on the caller's), back when all have returned
  void run(const std::function<void(int)>& task);
  // inside a task: wait until every thread has reached this point
  void sync();

 private:
  void work(int index);

  int threads_;
  std::vector<std::thread> workers_;
  const std::function<void(int)>* task_ = nullptr;
  std::atomic<unsigned> epoch_{0};  // bumped for each task (and to stop)
  std::atomic<int> arrived_{0};
  std::atomic<unsigned> phase_{0};  // bumped when every thread reached a barrier
  std::atomic<bool> stop_{false};
};

}  // namespace sim::world
