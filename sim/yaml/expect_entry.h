// What the 2D and the 3D reader read alike of an `expect` entry (sim/core/expect_def_of.h): its place,
// its time or `energy_never_rises`, its body, its energies and momenta, and its tolerance. Each reader reads the entry's other
// keys around these, every key in the order it always has, so that a fault is found first as before.
#pragma once

#include <initializer_list>
#include <string>

#include "sim/core/expect_def_of.h"
#include "sim/yaml/yaml_reader.h"

namespace sim::yaml {

struct ExpectTime {
  double time = 0.0;
  bool energyNeverRises = false;
};

// `energy_never_rises` holds at every step (up to the entry's `time`, the duration unless given)
// and stands alone, since it is checked over the run where the others are checked at one time
inline ExpectTime readExpectTime(const Reader& r, const YAML::Node& entry, double duration) {
  ExpectTime out;
  if (const YAML::Node rises = entry["energy_never_rises"]) {
    if (!r.boolean(rises, "energy_never_rises"))
      r.fail(rises, "'energy_never_rises: false' checks nothing; remove the entry, or write 'energy_never_rises: true'");
    for (const auto& kv : entry) {
      const std::string key = kv.first.Scalar();
      if (key != "energy_never_rises" && key != "time" && key != "tolerance" && key != "source")
        r.fail(kv.second,
               "'" + key + "' is checked at one time, and 'energy_never_rises' at every step: give each an entry of its own");
    }
    out.energyNeverRises = true;
    out.time = duration;
  }
  if (!out.energyNeverRises || entry["time"]) {
    const YAML::Node t = r.required(entry, "time", "an expect entry");
    out.time = r.finite(t, "time");
    r.checkTime(t, out.time, duration, "expect");
  }
  return out;
}

// an entry's place, its time (or `energy_never_rises`) and its body, which each of `bodyKeys` the
// entry has needs
template <class Scene, class Vec>
void readExpectHead(const Reader& r, const YAML::Node& n, const Scene& s, std::initializer_list<const char*> bodyKeys,
                    sim::core::ExpectDefOf<Vec>& e) {
  e.loc = {n.Mark().line + 1, n.Mark().column + 1};
  const ExpectTime when = readExpectTime(r, n, s.duration);
  e.time = when.time;
  e.energyNeverRises = when.energyNeverRises;
  if (n["body"]) e.body = r.bodyRef(n, "body", s, "an expect entry");
  for (const char* key : bodyKeys)
    if (n[key] && e.body.empty()) r.fail(n[key], std::string("'") + key + "' is a body's: add 'body:'");
}

// an entry's kinetic, potential and total energies
template <class Vec>
void readExpectEnergies(const Reader& r, const YAML::Node& n, sim::core::ExpectDefOf<Vec>& e) {
  r.optional(n, "kinetic_energy", e.kineticEnergy, &Reader::finite);
  r.optional(n, "potential_energy", e.potentialEnergy, &Reader::finite);
  r.optional(n, "total_energy", e.totalEnergy, &Reader::finite);
}

// an entry's energies, momentum and angular momentum (a number in 2D, a vector in 3D: read by
// `angular`), on the dimension's reader `r`
template <class DimReader, class Expect, class ReadAngular>
void readExpectMomenta(const DimReader& r, const YAML::Node& n, Expect& e, ReadAngular angular) {
  readExpectEnergies(r, n, e);
  r.optional(n, "momentum", e.momentum, DimReader::kVector);
  r.optional(n, "angular_momentum", e.angularMomentum, angular);
}

// an entry's tolerance, and whether its answer is an earlier run's (`source: earlier_run`)
template <class Vec>
void readExpectTolerance(const Reader& r, const YAML::Node& n, sim::core::ExpectDefOf<Vec>& e) {
  r.optional(n, "tolerance", e.tolerance, &Reader::positive);
  e.earlierRun = r.expectSource(n);
}

}  // namespace sim::yaml
