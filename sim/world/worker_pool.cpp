#include "sim/world/worker_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace sim::world {

namespace {

// at a barrier: this many pauses (a few microseconds, about one set's solve), then the core
// offered to others (the machine is shared: a spinning thread must not hold a core its partner
// waits for)
constexpr int kSpinsBeforeYield = 64;
// between tasks: this many pauses (0.7 ms on a Zen 4) before the worker sleeps on the futex.
// A step runs four tasks back to back (three finding contacts, one solving); waking a sleeping
// worker for each cost more than the spinning (the 5,050-box pyramid on two threads: 4.9-6.6 ms a step without it, 3.8-5.0 with)
constexpr int kSpinsBeforeSleep = 20000;

void pauseOnce() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

void pause(int& spins) {
  if (++spins < kSpinsBeforeYield) {
    pauseOnce();
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
  // (alone, nobody to meet: the atomics were 3 % of a 210-box pyramid's step)
  if (threads_ == 1) return;
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
    // the next task of a step comes soon: spin a while before sleeping on the futex
    for (int spins = 0; epoch_.load() == seen && spins < kSpinsBeforeSleep; ++spins) pauseOnce();
    epoch_.wait(seen);
    seen = epoch_.load();
    if (stop_) return;
    (*task_)(index);
    sync();
  }
}

}  // namespace sim::world
