#include "render/cli/energy_report.h"

#include <cmath>
#include <cstdio>

namespace render::cli {
namespace {

// a billionth of the run's largest energy: what the sums of a run's round-off stay below
constexpr double kRoundOffShare = 1e-9;

double shown(const LedgerAccounts& l, double joules) { return std::abs(joules) <= kRoundOffShare * l.scale ? 0.0 : joules; }

// three significant digits, as a lecturer reads an amount of energy: "2.45 J"
std::string joules(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g J", x);
  return text;
}

std::string place(const NameOf& nameOf, const sim::core::EnergyRise& r) {
  char time[32];
  std::snprintf(time, sizeof time, "t = %.6g s", r.time);
  if (r.a < 0) return std::string(time) + ", in free motion (the integrator's)";
  return std::string(time) + ", at the contact of '" + nameOf(r.a) + "' and '" + nameOf(r.b) + "'";
}

}  // namespace

std::string describeLedger(const LedgerAccounts& l, const NameOf& nameOf) {
  std::string s = "energy: " + joules(shown(l, l.start)) + " at the start, " + joules(shown(l, l.end)) + " at the end; lost " +
                  joules(shown(l, l.lostAtImpacts)) + " at impacts, " + joules(shown(l, l.lostInContacts)) +
                  " in contacts (friction, settling), " + joules(shown(l, l.lostToDamping)) + " to damping, " +
                  joules(shown(l, l.lostByIntegrator)) + " by the integrator; applied forces did " +
                  joules(shown(l, l.appliedWork)) + ", impulse events " + joules(shown(l, l.eventWork)) + "; ";
  if (shown(l, l.gained) == 0.0) return s + "gained nothing beyond round-off";
  return s + "gained " + joules(l.gained) + " (the most in one step " + joules(l.largestGain.amount) + ", " +
         place(nameOf, l.largestGain) + ")";
}

void writeLedger(render::jobs::JsonWriter& j, const LedgerAccounts& l, const NameOf& nameOf) {
  j.key("energy_ledger").beginObject();
  j.field("start", l.start).field("end", l.end);
  j.field("lost_at_impacts", shown(l, l.lostAtImpacts)).field("lost_in_contacts", shown(l, l.lostInContacts));
  j.field("lost_to_damping", shown(l, l.lostToDamping)).field("lost_by_integrator", shown(l, l.lostByIntegrator));
  j.field("applied_work", shown(l, l.appliedWork)).field("event_work", shown(l, l.eventWork));
  j.field("gained", shown(l, l.gained));
  // where the most was gained in one step, when anything was
  if (shown(l, l.gained) != 0.0) {
    j.key("largest_gain").beginObject().field("t", l.largestGain.time).field("amount", l.largestGain.amount);
    if (l.largestGain.a >= 0) j.field("a", nameOf(l.largestGain.a)).field("b", nameOf(l.largestGain.b));
    j.endObject();
  }
  j.endObject();
}

}  // namespace render::cli
