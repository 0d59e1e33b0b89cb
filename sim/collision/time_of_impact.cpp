#include "sim/collision/time_of_impact.h"

#include <algorithm>
#include <cmath>

#include "sim/collision/collide.h"
#include "sim/core/settings.h"

namespace sim::collision {
using sim::core::BodyState;
using sim::core::Shape;
using namespace sim::core;

namespace {

// a point of the search: the time and the gap there
struct Probe {
  double tau = 0.0;
  double gap = 0.0;
};

// one search: its input and the gap s(τ) it measures
class Search {
 public:
  explicit Search(const ToiInput& in) : in_(in) {}

  double gap(double tau) const {
    const PosePair p = in_.motion(tau);
    return collide(*in_.a, p.a, *in_.b, p.b, 0.0).separation;
  }

  // regula falsi (Illinois) between lo (gap ≥ 0) and hi (overlap), ending on the gap side
  double refine(double lo, double slo, double hi, double shi) const {
    const double tol = in_.tolerance;
    for (int k = 0; k < settings::kMaxRefineIterations && slo > tol && hi - lo > settings::kImpactBracket * in_.span; ++k) {
      const double mid = std::clamp(lo + (hi - lo) * slo / (slo - shi), lo, hi);
      const double s = gap(mid);
      if (s >= 0.0) lo = mid, slo = s, shi *= 0.5;
      else hi = mid, shi = s, slo *= 0.5;
      if (s >= 0.0 && s <= tol) return mid;
    }
    return lo;
  }

  // touching at τ = 0 and not approaching (impacts at this instant are already answered): look
  // ahead, doubling, for where the pair is clear of the touching band (`clear`), or an impact
  // where it came back in on the way there; neither when it stays in the band to the horizon
  struct LookAhead {
    std::optional<double> impact;
    std::optional<Probe> clear;
  };
  LookAhead leaveTouching(double s0) const {
    const double tol = in_.tolerance, touch = in_.touching, horizon = in_.horizon;
    double ahead = settings::kLookAheadStart * in_.span, last = 0.0, sLast = std::max(s0, 0.0);
    while (true) {
      ahead = std::min(ahead, horizon);
      const double sa = gap(ahead);
      // it came back in: an impact inside (last, ahead)
      if (sa < -tol) return {refine(last, sLast, ahead, sa), std::nullopt};
      if (sa > touch || ahead >= horizon) {
        if (ahead >= horizon) return {};
        return {std::nullopt, Probe{ahead, sa}};
      }
      last = ahead, sLast = std::max(sa, 0.0);
      ahead *= 2.0;
    }
  }

  // conservative advancement from `at`, with a secant probe to bracket the root early
  std::optional<double> advance(Probe at) const {
    const double tol = in_.tolerance, bound = in_.approachBound, horizon = in_.horizon;
    double tau = at.tau, s = at.gap;
    double prevTau = -1.0, prevS = 0.0;
    for (int k = 0; k < settings::kMaxAdvancementIterations; ++k) {
      if (s <= tol) return tau;
      const double advance = s / bound;
      // the secant through the last two gaps: if its root is farther than the safe advance and
      // the gap there is an overlap, the root is bracketed
      if (prevTau >= 0.0 && prevS > s) {
        const double probe = tau + s * (tau - prevTau) / (prevS - s);
        if (probe > tau + advance && probe < horizon) {
          const double sp = gap(probe);
          if (sp < 0.0) return refine(tau, s, probe, sp);
        }
      }
      prevTau = tau, prevS = s;
      tau += advance;
      if (tau > horizon) return std::nullopt;
      s = gap(tau);
    }
    return std::nullopt;
  }

 private:
  const ToiInput& in_;
};

}  // namespace

std::optional<double> timeOfImpact(const ToiInput& input) {
  // nothing approaches: no impact
  if (input.approachBound == 0.0) return std::nullopt;
  const Search search(input);
  Probe start{0.0, search.gap(0.0)};
  // touching now: start from where the pair gets clear, unless it comes back in before
  if (start.gap <= input.touching) {
    const Search::LookAhead ahead = search.leaveTouching(start.gap);
    if (ahead.impact) return ahead.impact;
    if (!ahead.clear) return std::nullopt;
    start = *ahead.clear;
  }
  return search.advance(start);
}

double approachBound(const Shape& a, const BodyState& sa, const Shape& b, const BodyState& sb) {
  double bound = (sa.v - sb.v).norm();
  // a plane's radius is infinite: only a turning shape adds its rim speed
  if (sa.omega != 0.0) bound += std::abs(sa.omega) * boundingRadius(a);
  if (sb.omega != 0.0) bound += std::abs(sb.omega) * boundingRadius(b);
  return bound;
}

}  // namespace sim::collision
