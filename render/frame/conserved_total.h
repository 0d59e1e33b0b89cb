// A total the run may conserve (E, p, L), shown with the digits of its first value wherever it
// stays within round-off of it: a value rounded once, not per frame, so that an elastic impact that
// keeps E to 1e-15 J never flips its last shown digit (3.51 J at the impact, 3.52 J after). Where
// the total really changes (an event's impulse, a plastic impact, an integrator's drift), its value
// now is shown.
#pragma once

namespace render::frame {

class ConservedTotal {
 public:
  // `initial`: the total at t = 0; `scale`: the run's largest magnitude of it (the survey's), which
  // sets the round-off: a relative 1e-9 of it
  ConservedTotal(double initial, double scale);
  // the value to show for the total `now`: `initial` while within round-off of it, else `now`
  double shown(double now) const;

 private:
  double initial_, tolerance_;
};

}  // namespace render::frame
