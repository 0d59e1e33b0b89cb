// A long `check` or `simulate` on a terminal says how far it is: "FILE: t = 12.5 of 100 s, 2.1e+06
// steps/s" on standard error, redrawn in place after the first second, at most four times a second,
// and cleared when the run ends. On a pipe or a file nothing is drawn and no clock is read. On any
// output it stops the run between two steps on Ctrl-C (render/jobs/interrupt.h).
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "render/jobs/interrupt.h"
#include "render/jobs/status_line.h"
#include "sim/world/world.h"
#include "sim/world3d/world.h"

namespace render::cli {

// a StepObserver of the 2D or the 3D world (World, Observer: sim::world's or sim::world3d's) that
// passes every call on to `next` (a trace writer, or none)
template <class World, class Observer, class Event>
class RunProgressOf : public Observer {
 public:
  // (`shown` false: never drawn, as for --quiet)
  RunProgressOf(std::string what, double until, Observer* next = nullptr, bool shown = true)
      : what_(std::move(what)),
        until_(until),
        next_(next),
        line_(shown, std::chrono::seconds(1), std::chrono::milliseconds(250)) {}

  // the observer to pass to advanceTo: this one, which also stops the run on Ctrl-C between steps
  Observer* observer() { return this; }

  void afterStep(const World& w) override {
    render::jobs::checkInterrupted();
    if (next_) next_->afterStep(w);
    if (!line_.enabled()) return;
    // the clock read every `stride_` steps, about every 10 ms: a step of one body takes less time
    // than reading the clock
    if (++sinceCheck_ < stride_) return;
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - lastCheck_).count();
    stride_ = seconds < 0.005 ? stride_ * 2 : seconds > 0.02 && stride_ > 1 ? stride_ / 2 : stride_;
    sinceCheck_ = 0;
    lastCheck_ = now;
    if (!line_.due()) return;
    char text[160];
    std::snprintf(text, sizeof text, ": t = %.4g of %.4g s, %.3g steps/s", w.time, until_,
                  static_cast<double>(w.steps) / line_.elapsed());
    line_.draw(what_ + text);
  }
  void afterEvent(const World& w, const Event& e) override {
    if (next_) next_->afterEvent(w, e);
  }
  // the line cleared, before the run's results are printed
  void finish() { line_.erase(); }

 private:
  std::string what_;
  double until_;
  Observer* next_;
  render::jobs::StatusLine line_;
  long stride_ = 1, sinceCheck_ = 0;
  std::chrono::steady_clock::time_point lastCheck_ = std::chrono::steady_clock::now();
};

using RunProgress = RunProgressOf<sim::world::World, sim::world::StepObserver, sim::world::ImpulseEvent>;
using RunProgress3d = RunProgressOf<sim::world3d::World, sim::world3d::StepObserver, sim::world3d::ImpulseEvent>;

}  // namespace render::cli
