#include "sim/world/worker_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace sim::world {

namespace {

// a short wait on a busy core: the processor told it spins, then the core offered to others
// (the machine is shared: a spinning thread must not hold a core its partner waits for)
void pause(int& spins) {
  if (++spins < 64) {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
  } else {
    std::this_thread::yield();
  }
}

}  // namespace

WorkerPool::WorkerPool(int threads) : threads_(threads < 1 ? 1 : threads) {
  for (int i = 1; i < threads_; ++i) workers_.emplace_back([this, i] { work(i); });
}

WorkerPool::~WorkerPool() {
  stop_ = true;
  epoch_.fetch_add(1);
  epoch_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::run(const std::function<void(int)>& task) {
  if (threads_ == 1) return task(0);
  task_ = &task;
  epoch_.fetch_add(1);
  epoch_.notify_all();
  task(0);
  // every worker done before the caller reads what they wrote (or the task goes out of scope)
  sync();
}

void WorkerPool::sync() {
  const unsigned phase = phase_.load();
  if (arrived_.fetch_add(1) + 1 == threads_) {
    arrived_ = 0;
    phase_.fetch_add(1);
    return;
  }
  for (int spins = 0; phase_.load() == phase;) pause(spins);
}

void WorkerPool::work(int index) {
  unsigned seen = 0;
  for (;;) {
    epoch_.wait(seen);
    seen = epoch_.load();
    if (stop_) return;
    (*task_)(index);
    sync();
  }
}

}  // namespace sim::world
