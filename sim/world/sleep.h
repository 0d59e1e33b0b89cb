// Sleeping (sim: {sleep: true}): islands of touching bodies that have been at rest for a while stop
// being integrated and solved until an awake body touches them, a force acts on them or an event
// strikes them (Box2D 2.4's b2Island and sleep timers, b2Island::Solve; Box2D v3's solver sets,
// b2TrySleepIsland and b2WakeSolverSet). Islands are built anew after every step from the step's
// contacts and the springs, by union–find; static bodies join none, so a floor does not tie every
// pile on it into one island. A sleeping body keeps its pose exactly, its velocity is zero, and the
// contacts of its island are kept as they were, to warm start the solve when it wakes.
#pragma once

#include <vector>

#include "sim/core/body.h"
#include "sim/core/forces.h"
#include "sim/world/contact.h"

namespace sim::world {

class Sleep {
 public:
  bool asleep(int body) const { return body < static_cast<int>(island_.size()) && island_[body] >= 0; }
  int sleepingBodies() const { return sleeping_; }
  // the contacts the sleeping islands kept, one list per island (empty once it woke)
  const std::vector<std::vector<Contact>>& keptContacts() const { return kept_; }

  // after a step of length h: each body's time at rest, and the islands (joined by `contacts` and
  // the springs) whose every body has been at rest for kTimeToSleep fall asleep; a body pushed by a
  // point force that is on at `t` is never at rest
  void afterStep(std::vector<sim::core::Body>& bodies, const std::vector<Contact>& contacts, const sim::core::ForceSet& forces,
                 double t, double h);

  // the island of `body` wakes; the contacts it kept are put back into `contacts` (sorted by pair)
  void wake(int body, std::vector<Contact>& contacts);

  // the islands that a point force on at `t` pushes wake
  void wakeForced(const sim::core::ForceSet& forces, double t, std::vector<Contact>& contacts);

  // the islands that a `found` contact joins to an awake body wake; true when any did
  bool wakeTouched(const std::vector<Contact>& found, std::vector<Contact>& contacts);

 private:
  int root(int body);
  void join(int a, int b);

  std::vector<double> atRest_;              // s: how long each body has been at rest
  std::vector<int> island_;                 // each body's sleeping island, −1 when awake
  std::vector<std::vector<int>> members_;   // each sleeping island's bodies (empty once woken)
  std::vector<std::vector<Contact>> kept_;  // each sleeping island's contacts, as they were
  std::vector<int> parent_;                 // union–find over the bodies, scratch of afterStep
  std::vector<double> islandRest_;          // scratch: the shortest time at rest of each root
  int sleeping_ = 0;
};

}  // namespace sim::world
