#include "sim/world/contact.h"

#include <array>
#include <cmath>

namespace sim::world {
using namespace sim::core;
using namespace sim::collision;


double combinedRestitution(double a, double b) { return std::max(a, b); }
double combinedFriction(double a, double b) { return std::sqrt(a * b); }

}  // namespace sim::world
