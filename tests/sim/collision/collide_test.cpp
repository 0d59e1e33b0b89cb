#include "sim/collision/collide.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sim/core/settings.h"

using sim::core::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMargin = sim::core::settings::kContactMargin;

sim::core::Pose pose(double x, double y, double angle = 0.0) { return {Vec2(x, y), sim::core::Rot::fromAngle(angle)}; }

// ---------------------------------------------------------------------------------------------
// An independent reference, written from the notes' definitions with plain loops. It uses only
// the shape's body vertices and Pose::toWorld; the edge normals are recomputed from the world
// edges rather than taken from Shape::normals.

std::vector<Vec2> worldVertices(const sim::core::Shape& s, const sim::core::Pose& p) {
  std::vector<Vec2> w;
  for (const Vec2& v : s.vertices) w.push_back(p.toWorld(v));
  return w;
}

// outward unit normal of edge i (vertex i to i + 1) of a counter-clockwise polygon
Vec2 edgeNormal(const std::vector<Vec2>& P, size_t i) {
  const Vec2 e = P[(i + 1) % P.size()] - P[i];
  return Vec2(e.y(), -e.x()) / std::hypot(e.x(), e.y());
}

// distance(e → x) = normal(e)·(x − point_on(e)), with point_on(e) the edge's first vertex
double edgeDistance(const std::vector<Vec2>& P, size_t e, const Vec2& x) { return edgeNormal(P, e).dot(x - P[e]); }

// separation(e → Q) = min over vertices v of Q of distance(e → v)
double edgeSeparation(const std::vector<Vec2>& P, size_t e, const std::vector<Vec2>& Q) {
  double s = kInf;
  for (const Vec2& v : Q) s = std::min(s, edgeDistance(P, e, v));
  return s;
}

// separation(P → Q) = max over edges e of P of separation(e → Q)
double directedSeparation(const std::vector<Vec2>& P, const std::vector<Vec2>& Q) {
  double s = -kInf;
  for (size_t e = 0; e < P.size(); ++e) s = std::max(s, edgeSeparation(P, e, Q));
  return s;
}

// separation(P, Q) = max(separation(P → Q), separation(Q → P))
double referenceSeparation(const std::vector<Vec2>& P, const std::vector<Vec2>& Q) {
  return std::max(directedSeparation(P, Q), directedSeparation(Q, P));
}

// the Euclidean distance from x to the segment [a, b], and where along it the closest point lies
double pointSegmentDistance(const Vec2& x, const Vec2& a, const Vec2& b, double* along = nullptr) {
  const Vec2 d = b - a;
  const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  if (along) *along = t;
  return (x - (a + t * d)).norm();
}

// the closest pair found among vertex–edge pairs, both ways: the true distance of two disjoint
// convex polygons (for overlapping ones it is the distance between the boundaries)
struct Closest {
  double distance = kInf;
  Vec2 onP, onQ;              // the closest points
  bool edgeInterior = false;  // a vertex against the interior of an edge
};

Closest boundaryDistance(const std::vector<Vec2>& P, const std::vector<Vec2>& Q) {
  Closest c;
  auto scan = [&c](const std::vector<Vec2>& X, const std::vector<Vec2>& E, bool xIsP) {
    for (const Vec2& x : X)
      for (size_t i = 0; i < E.size(); ++i) {
        const Vec2 &a = E[i], &b = E[(i + 1) % E.size()];
        double t = 0.0;
        const double d = pointSegmentDistance(x, a, b, &t);
        if (d < c.distance) {
          const Vec2 on = a + t * (b - a);
          c.distance = d;
          c.onP = xIsP ? x : on;
          c.onQ = xIsP ? on : x;
          c.edgeInterior = t > 1e-6 && t < 1.0 - 1e-6;
        }
      }
  };
  scan(P, Q, true);
  scan(Q, P, false);
  return c;
}

// orientation of c relative to the directed line a → b
double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return sim::core::cross(b - a, c - a); }

// closed segments [a, b] and [c, d] share a point
bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  auto onSegment = [](const Vec2& p, const Vec2& q, const Vec2& r) {  // r on [p, q], given collinear
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
           r.y() <= std::max(p.y(), q.y());
  };
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) || (o3 == 0 && onSegment(c, d, a)) ||
         (o4 == 0 && onSegment(c, d, b));
}

// x inside or on a counter-clockwise convex polygon, up to an absolute tolerance
bool insideConvex(const std::vector<Vec2>& P, const Vec2& x, double tolerance = 0.0) {
  for (size_t i = 0; i < P.size(); ++i) {
    const Vec2 e = P[(i + 1) % P.size()] - P[i];
    if (sim::core::cross(e, x - P[i]) < -tolerance * e.norm()) return false;
  }
  return true;
}

// the overlap verdict by a different method than separating axes: two convex polygons overlap
// when some edges cross, or else when one lies inside the other
bool overlapByEdges(const std::vector<Vec2>& P, const std::vector<Vec2>& Q) {
  for (size_t i = 0; i < P.size(); ++i)
    for (size_t j = 0; j < Q.size(); ++j)
      if (segmentsIntersect(P[i], P[(i + 1) % P.size()], Q[j], Q[(j + 1) % Q.size()])) return true;
  return insideConvex(P, Q[0]) || insideConvex(Q, P[0]);
}

// the signed distance from x to a convex polygon's boundary: negative inside
double signedDistance(const std::vector<Vec2>& P, const Vec2& x) {
  double d = kInf;
  for (size_t i = 0; i < P.size(); ++i) d = std::min(d, pointSegmentDistance(x, P[i], P[(i + 1) % P.size()]));
  return insideConvex(P, x) ? -d : d;
}

// ---------------------------------------------------------------------------------------------
// random convex polygons: 3–8 random angles on an ellipse of random size, around a random body
// origin; sometimes a box, so that parallel edges (ties) appear too

struct RandomPolygon {
  sim::core::Shape shape;
  double radius = 0.0;  // largest vertex distance from the body origin
};

RandomPolygon randomPolygon(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (;;) {
    if (u(rng) < 0.1) {
      const double w = 0.2 + 2.0 * u(rng), h = 0.2 + 2.0 * u(rng);
      return {sim::core::makeBox(w, h), 0.5 * std::hypot(w, h)};
    }
    const int n = 3 + static_cast<int>(rng() % 6);
    std::vector<double> angles(n);
    for (double& a : angles) a = 2 * kPi * u(rng);
    std::sort(angles.begin(), angles.end());
    bool spread = true;
    for (int i = 0; i < n; ++i) {
      const double gap = i + 1 < n ? angles[i + 1] - angles[i] : angles[0] + 2 * kPi - angles[i];
      spread = spread && gap > 0.05;
    }
    if (!spread) continue;
    const double a = 0.2 + 1.8 * u(rng), b = a * (0.3 + 0.7 * u(rng));
    const Vec2 center(a * (u(rng) - 0.5) * 0.6, b * (u(rng) - 0.5) * 0.6);
    std::vector<Vec2> v;
    double radius = 0.0;
    for (double t : angles) {
      v.push_back(center + Vec2(a * std::cos(t), b * std::sin(t)));
      radius = std::max(radius, v.back().norm());
    }
    try {
      return {sim::core::makePolygon(v), radius};
    } catch (const std::invalid_argument&) {
      continue;  // a sliver the shape module rejects: draw again
    }
  }
}

// every point of the manifold is midway between the two surfaces: with n from B to A and the
// separation s, the point on A is point + s/2 n and the point on B is point − s/2 n
void checkPointsOnSurfaces(const sim::collision::Manifold& m, const std::vector<Vec2>& A, const std::vector<Vec2>& B,
                           double tolerance) {
  for (int k = 0; k < m.count; ++k) {
    const sim::collision::ManifoldPoint& p = m.points[k];
    const Vec2 onA = p.point + 0.5 * p.separation * m.normal, onB = p.point - 0.5 * p.separation * m.normal;
    CHECK(insideConvex(A, onA, tolerance));
    CHECK(insideConvex(B, onB, tolerance));
  }
}

}  // namespace

// =============================================================================================
// 1. the separating-axis test against an independent reference

TEST_CASE("sat: 12,000 random convex polygon pairs against a brute-force reference") {
  std::mt19937 rng(20240611u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int overlapping = 0, separated = 0, touching = 0, equalToDistance = 0, missedContacts = 0;
  const int pairs = 12000;
  for (int i = 0; i < pairs; ++i) {
    const RandomPolygon ra = randomPolygon(rng), rb = randomPolygon(rng);
    const sim::core::Shape &a = ra.shape, &b = rb.shape;
    const sim::core::Pose pa = pose(4 * u(rng) - 2, 4 * u(rng) - 2, 2 * kPi * u(rng));
    sim::core::Pose pb;
    // an axis-aligned pose now and then, so that boxes meet with exactly parallel edges
    pb.q = (i % 10 == 0) ? sim::core::Rot::fromAngle(0.5 * kPi * (rng() % 4)) : sim::core::Rot::fromAngle(2 * kPi * u(rng));
    const double reach = ra.radius + rb.radius, heading = 2 * kPi * u(rng);
    const Vec2 direction(std::cos(heading), std::sin(heading));
    const int kind = i % 4;
    // 0, 1: anywhere from concentric to just out of reach; 2: deep; 3: touching-ish (below)
    const double offset = kind == 2 ? 0.3 * reach * u(rng) : kind == 3 ? reach + 0.1 : 1.2 * reach * u(rng);
    pb.x = pa.x + offset * direction;

    std::vector<Vec2> A = worldVertices(a, pa), B = worldVertices(b, pb);
    double gap = 0.0;           // the intended gap of a touching-ish pair
    bool vertexOnEdge = false;  // ... met a vertex against an edge's interior
    if (kind == 3) {
      // move B toward A along the line of the closest points until the gap is a small ε (or an
      // overlap of −ε, or exact contact): for convex sets the distance drops by the move exactly
      const Closest c = boundaryDistance(A, B);
      const double gaps[] = {0.0, 1e-9, -1e-9, 1e-7, -1e-7, 1e-5, -1e-5, 1e-3};
      gap = gaps[(i / 4) % 8];
      pb.x -= (c.distance - gap) * (c.onQ - c.onP) / c.distance;
      vertexOnEdge = c.edgeInterior;
      B = worldVertices(b, pb);
      if (gap >= 0.0) CHECK(std::abs(boundaryDistance(A, B).distance - gap) <= 1e-12);
    }
    const double scale = std::max({1.0, ra.radius, rb.radius, (pb.x - pa.x).norm()});
    const double tol = 1e-12 * scale;
    CAPTURE(i);

    const sim::collision::SatFeatures f = sim::collision::sat(a, pa, b, pb);
    REQUIRE(f.valid);
    const double expected = referenceSeparation(A, B);
    // (b) the separation recomputed from the notes' definitions
    CHECK(std::abs(f.separation - expected) <= tol);

    // the reference edge and incident vertex attain the separation
    const std::vector<Vec2>& ref = f.referenceOnA ? A : B;
    const std::vector<Vec2>& other = f.referenceOnA ? B : A;
    REQUIRE(f.referenceEdge >= 0);
    REQUIRE(f.referenceEdge < static_cast<int>(ref.size()));
    REQUIRE(f.incidentVertex >= 0);
    REQUIRE(f.incidentVertex < static_cast<int>(other.size()));
    CHECK(std::abs(edgeDistance(ref, f.referenceEdge, other[f.incidentVertex]) - f.separation) <= tol);
    // ... and no vertex of the other polygon is deeper below that edge
    CHECK(edgeSeparation(ref, f.referenceEdge, other) >= f.separation - tol);
    // no edge of either polygon separates more
    for (size_t e = 0; e < A.size(); ++e) CHECK(edgeSeparation(A, e, B) <= f.separation + tol);
    for (size_t e = 0; e < B.size(); ++e) CHECK(edgeSeparation(B, e, A) <= f.separation + tol);

    // (a) the overlap verdict by edge crossings and containment, against the sign of the
    // separation. The notes' slide prints "overlap(P, Q): separation(P, Q) > 0", but with its own
    // distance(e → x) = normal(e)·(x − point_on(e)) and outward normals a positive separation is
    // a gap between the polygons: they overlap exactly when the separation is NEGATIVE.
    const Closest closest = boundaryDistance(A, B);
    const bool overlap = overlapByEdges(A, B);
    if (std::abs(f.separation) <= 1e-11 * scale) {
      // touching: the verdict is up to round-off, but then the polygons are in contact
      ++touching;
      CHECK(closest.distance <= 1e-11 * scale);
    } else if (overlap) {
      ++overlapping;
      CHECK(f.separation < 0.0);
    } else {
      ++separated;
      CHECK(f.separation > 0.0);
      // a separating axis gives a lower bound of the true distance ...
      CHECK(f.separation <= closest.distance + tol);
      // ... which is the distance itself when the closest features are a vertex and an edge
      if (closest.edgeInterior) {
        ++equalToDistance;
        CHECK(std::abs(f.separation - closest.distance) <= tol);
      }
    }
    // a vertex pushed through an edge by ε overlaps by ε (pushed past another vertex by ε, two sharp
    // corners may still miss each other, so only this case has a sure verdict)
    if (kind == 3 && vertexOnEdge && gap != 0.0) {
      // pushed in: that edge's axis gives exactly −ε, others may give less overlap
      if (gap < 0) CHECK(f.separation < 0.0);
      if (gap < 0) CHECK(f.separation >= gap - tol);
      // short of touching: the edge's axis gives the distance itself
      if (gap > 0) CHECK(std::abs(f.separation - gap) <= tol);
    }

    // the manifold carries the same SAT bookkeeping, and a consistent set of points
    const sim::collision::Manifold m = sim::collision::collide(a, pa, b, pb, kMargin);
    CHECK(m.sat.valid);
    CHECK(m.sat.separation == f.separation);
    CHECK(m.sat.referenceOnA == f.referenceOnA);
    CHECK(m.sat.referenceEdge == f.referenceEdge);
    CHECK(m.sat.incidentVertex == f.incidentVertex);
    CHECK(std::abs(m.normal.norm() - 1.0) <= 1e-12);
    CHECK(m.count >= 0);
    CHECK(m.count <= 2);
    if (f.separation > kMargin) {
      CHECK(m.count == 0);
      CHECK(m.separation == f.separation);
    }
    if (m.count == 0) {
      CHECK(m.separation == f.separation);
    } else {
      double smallest = kInf;
      for (int k = 0; k < m.count; ++k) {
        CHECK(m.points[k].separation <= kMargin);
        // measured against a reference edge within the manifold's hysteresis of the best one
        CHECK(m.points[k].separation >= f.separation - sim::core::settings::kReferenceEdgeHysteresis - tol);
        smallest = std::min(smallest, m.points[k].separation);
      }
      CHECK(m.separation == smallest);
      if (m.count == 2) CHECK(m.points[0].id != m.points[1].id);
      checkPointsOnSurfaces(m, A, B, 1e-9 * scale);
    }
    // overlapping polygons must get at least one contact point, or nothing pushes them apart
    if (f.separation < -1e-9 * scale && m.count == 0) {
      ++missedContacts;
      FAIL_CHECK("overlapping polygons (separation " << f.separation << ") gave no contact point");
    }
  }
  MESSAGE("overlapping " << overlapping << ", separated " << separated << " (" << equalToDistance
                         << " with separation = distance), touching " << touching << ", missed contacts " << missedContacts);
  CHECK(overlapping > pairs / 4);
  CHECK(separated > pairs / 4);
  CHECK(touching > 100);
  CHECK(equalToDistance > pairs / 10);
}

TEST_CASE("sat is only for two polygons") {
  const sim::core::Shape box = sim::core::makeBox(1, 1), circle = sim::core::makeCircle(0.5),
                         plane = sim::core::makePlane({0, 1});
  CHECK_FALSE(sim::collision::sat(box, pose(0, 0), circle, pose(0, 0)).valid);
  CHECK_FALSE(sim::collision::sat(circle, pose(0, 0), box, pose(0, 0)).valid);
  CHECK_FALSE(sim::collision::sat(box, pose(0, 0), plane, pose(0, 0)).valid);
  CHECK(sim::collision::sat(box, pose(0, 0), box, pose(0.5, 0)).valid);
}

TEST_CASE("sat on two unit squares: the sign of the separation is a gap, not an overlap") {
  const sim::core::Shape box = sim::core::makeBox(1, 1);
  // 0.25 apart side by side: separation +0.25 (the slide would call this an overlap)
  const sim::collision::SatFeatures apart = sim::collision::sat(box, pose(0, 0), box, pose(1.25, 0));
  CHECK(apart.separation == doctest::Approx(0.25).epsilon(1e-15));
  // half overlapping: separation −0.5
  const sim::collision::SatFeatures over = sim::collision::sat(box, pose(0, 0), box, pose(0.5, 0));
  CHECK(over.separation == doctest::Approx(-0.5).epsilon(1e-15));
  // diagonal, corner to corner 0.1·√2 apart: the best axis gives 0.1, below the distance
  const sim::collision::SatFeatures diagonal = sim::collision::sat(box, pose(0, 0), box, pose(1.1, 1.1));
  CHECK(diagonal.separation == doctest::Approx(0.1).epsilon(1e-14));
}

// =============================================================================================
// 2. contact manifolds

namespace {

// the point of a two-point manifold further along x
const sim::collision::ManifoldPoint& rightmost(const sim::collision::Manifold& m) {
  return m.points[0].point.x() >= m.points[1].point.x() ? m.points[0] : m.points[1];
}
const sim::collision::ManifoldPoint& leftmost(const sim::collision::Manifold& m) {
  return m.points[0].point.x() < m.points[1].point.x() ? m.points[0] : m.points[1];
}

}  // namespace

TEST_CASE("a box lying flat on a bigger box: two points, normal from B up to A, stable ids") {
  const sim::core::Shape top = sim::core::makeBox(1.0, 0.5), floor = sim::core::makeBox(4.0, 1.0);
  const sim::core::Pose pFloor = pose(0, 0);  // its top face at y = 0.5
  const double depth = 0.01;
  const sim::core::Pose pTop = pose(0.3, 0.5 + 0.25 - depth);

  const sim::collision::Manifold m = sim::collision::collide(top, pTop, floor, pFloor, kMargin);
  REQUIRE(m.count == 2);
  CHECK(std::abs(m.normal.x()) < 1e-15);
  CHECK(m.normal.y() == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(m.separation == doctest::Approx(-depth).epsilon(1e-12));
  for (int k = 0; k < 2; ++k) {
    CHECK(m.points[k].separation == doctest::Approx(-depth).epsilon(1e-12));
    // midway between the floor's top (0.5) and the box's bottom (0.49)
    CHECK(m.points[k].point.y() == doctest::Approx(0.5 - 0.5 * depth).epsilon(1e-12));
  }
  CHECK(leftmost(m).point.x() == doctest::Approx(-0.2).epsilon(1e-12));
  CHECK(rightmost(m).point.x() == doctest::Approx(0.8).epsilon(1e-12));
  CHECK(m.points[0].id != m.points[1].id);
  CHECK(m.sat.valid);
  CHECK(m.sat.separation == doctest::Approx(-depth).epsilon(1e-12));

  // the next step: moved 1e-4 sideways and turned by 1e-4 rad; the same features make the points
  const sim::core::Pose moved = pose(0.3 + 1e-4, 0.5 + 0.25 - depth, 1e-4);
  const sim::collision::Manifold next = sim::collision::collide(top, moved, floor, pFloor, kMargin);
  REQUIRE(next.count == 2);
  CHECK(leftmost(next).id == leftmost(m).id);
  CHECK(rightmost(next).id == rightmost(m).id);
  CHECK(next.normal.y() > 0.99);
  // turned counter-clockwise by 1e-4 about its center: its left corner dips by 0.5·1e-4
  CHECK(leftmost(next).separation == doctest::Approx(-depth - 0.5e-4).epsilon(1e-6));
  CHECK(rightmost(next).separation == doctest::Approx(-depth + 0.5e-4).epsilon(1e-6));
  // and turned the other way
  const sim::collision::Manifold other =
      sim::collision::collide(top, pose(0.3 - 1e-4, 0.5 + 0.25 - depth, -1e-4), floor, pFloor, kMargin);
  REQUIRE(other.count == 2);
  CHECK(leftmost(other).id == leftmost(m).id);
  CHECK(rightmost(other).id == rightmost(m).id);

  // swapping A and B flips the normal and keeps the separations and the points
  const sim::collision::Manifold swapped = sim::collision::collide(floor, pFloor, top, pTop, kMargin);
  REQUIRE(swapped.count == 2);
  CHECK(swapped.normal.y() == doctest::Approx(-1.0).epsilon(1e-15));
  CHECK(swapped.separation == doctest::Approx(m.separation).epsilon(1e-12));
  CHECK((leftmost(swapped).point - leftmost(m).point).norm() < 1e-12);
  CHECK((rightmost(swapped).point - rightmost(m).point).norm() < 1e-12);
  CHECK(leftmost(swapped).separation == doctest::Approx(-depth).epsilon(1e-12));
  CHECK(rightmost(swapped).separation == doctest::Approx(-depth).epsilon(1e-12));
}

TEST_CASE("two equal boxes as in a pyramid: the ids stay when the reference edge passes from one box to the other") {
  // A rests on B half a box to the right, 5 mm deep. Turned a little clockwise, A's bottom edge is
  // the reference; turned counter-clockwise, the line of A's bottom edge cuts deep under B's far
  // corner, and B's top edge is the reference. Either way the same two features make the points:
  // A's bottom-left corner on B's top edge (left) and B's top-right corner on A's bottom edge
  // (right). Equal boxes face to face pass between the two cases from step to step; a changed id
  // would lose the point's warm start.
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0);
  const double depth = 0.005, turn = 0.004;
  const sim::collision::Manifold onB = sim::collision::collide(box, pose(0.5625, 1.0 - depth, turn), box, pose(0, 0), kMargin);
  const sim::collision::Manifold onA = sim::collision::collide(box, pose(0.5625, 1.0 - depth, -turn), box, pose(0, 0), kMargin);
  REQUIRE(onB.count == 2);
  REQUIRE(onA.count == 2);
  // the normal is the reference edge's: B's top edge (not turned), or A's bottom edge (turned)
  CHECK(onB.normal.x() == 0.0);
  CHECK(onA.normal.x() == doctest::Approx(std::sin(turn)).epsilon(1e-9));
  CHECK(leftmost(onB).point.x() == doctest::Approx(0.0625).epsilon(0.05));
  CHECK(rightmost(onB).point.x() == doctest::Approx(0.5).epsilon(0.01));
  CHECK(leftmost(onA).id == leftmost(onB).id);
  CHECK(rightmost(onA).id == rightmost(onB).id);
  CHECK(leftmost(onB).id != rightmost(onB).id);
}

TEST_CASE("a box on one as wide, turned by a hair: with the side slack both points keep their ids") {
  // A rests on B, 5 mm deep, turned by round-off. A's bottom edge is the reference (the two edges'
  // separations tie), and its side planes turn with it: one of B's top corners falls a hair outside
  // them. Clipped at the edge's end, that point becomes A's corner on B's edge, a new id, and starts
  // cold in the stack solver on one side only; with the side planes moved out by the slack (Box2D
  // 2.4's skin) B's corner stays the point it was, a hair past the reference edge's end
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0);
  const double depth = 0.005, slack = sim::core::settings::kClipSideSlack;
  auto ids = [&](double turn, double sideSlack) {
    const sim::collision::Manifold m =
        sim::collision::collide(box, pose(0, 1.0 - depth, turn), box, pose(0, 0), kMargin, sideSlack);
    REQUIRE(m.count == 2);
    return std::make_pair(leftmost(m).id, rightmost(m).id);
  };
  const auto level = ids(0.0, 0.0);
  CHECK(ids(0.0, slack) == level);
  for (double turn : {1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3}) {
    CAPTURE(turn);
    CHECK(ids(turn, slack) == level);
    CHECK(ids(turn, 0.0) != level);
  }
  // a point past the reference edge's end is where B's corner is (A's is 0.5 mm in)
  const sim::collision::Manifold m = sim::collision::collide(box, pose(0, 1.0 - depth, 1e-3), box, pose(0, 0), kMargin, slack);
  CHECK(leftmost(m).point.x() == doctest::Approx(-0.5).epsilon(1e-4));
  CHECK(rightmost(m).point.x() == doctest::Approx(0.5).epsilon(1e-4));
}

TEST_CASE("a wide box on a narrow one: the points are at the narrow box's corners") {
  const sim::core::Shape wide = sim::core::makeBox(3.0, 0.5), narrow = sim::core::makeBox(1.0, 1.0);
  const sim::collision::Manifold m = sim::collision::collide(wide, pose(0.2, 0.5 + 0.25 - 0.004), narrow, pose(0, 0), kMargin);
  REQUIRE(m.count == 2);
  CHECK(m.normal.y() == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(leftmost(m).point.x() == doctest::Approx(-0.5).epsilon(1e-12));
  CHECK(rightmost(m).point.x() == doctest::Approx(0.5).epsilon(1e-12));
  for (int k = 0; k < 2; ++k) {
    CHECK(m.points[k].separation == doctest::Approx(-0.004).epsilon(1e-12));
    CHECK(m.points[k].point.y() == doctest::Approx(0.498).epsilon(1e-12));
  }
}

TEST_CASE("a box within the margin above another: two speculative points with positive separation") {
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0);
  const double gap = 0.5 * kMargin;
  const sim::collision::Manifold m = sim::collision::collide(box, pose(0.1, 1.0 + gap), box, pose(0, 0), kMargin);
  REQUIRE(m.count == 2);
  CHECK(m.normal.y() == doctest::Approx(1.0).epsilon(1e-15));
  for (int k = 0; k < 2; ++k) {
    CHECK(m.points[k].separation == doctest::Approx(gap).epsilon(1e-9));
    CHECK(m.points[k].point.y() == doctest::Approx(0.5 + 0.5 * gap).epsilon(1e-12));
  }
}

TEST_CASE("a tilted box resting on a corner: one point") {
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0), floor = sim::core::makeBox(4.0, 1.0);
  const double angle = kPi / 6, depth = 0.01;
  sim::core::Pose p = pose(0, 0, angle);
  // put its lowest corner at (0.2, 0.5 − depth)
  Vec2 lowest = p.toWorld(box.vertices[0]);
  for (const Vec2& v : box.vertices)
    if (p.toWorld(v).y() < lowest.y()) lowest = p.toWorld(v);
  p.x = Vec2(0.2, 0.5 - depth) - lowest;

  const sim::collision::Manifold m = sim::collision::collide(box, p, floor, pose(0, 0), kMargin);
  REQUIRE(m.count == 1);
  CHECK(std::abs(m.normal.x()) < 1e-15);
  CHECK(m.normal.y() == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(m.points[0].separation == doctest::Approx(-depth).epsilon(1e-12));
  CHECK(m.separation == doctest::Approx(-depth).epsilon(1e-12));
  CHECK((m.points[0].point - Vec2(0.2, 0.5 - 0.5 * depth)).norm() < 1e-12);
  // the SAT features: the floor's top edge (edge 2 of a box) and the corner
  CHECK_FALSE(m.sat.referenceOnA);
  CHECK(m.sat.referenceEdge == 2);
  CHECK((p.toWorld(box.vertices[m.sat.incidentVertex]) - Vec2(0.2, 0.5 - depth)).norm() < 1e-12);

  const sim::collision::Manifold swapped = sim::collision::collide(floor, pose(0, 0), box, p, kMargin);
  REQUIRE(swapped.count == 1);
  CHECK(swapped.normal.y() == doctest::Approx(-1.0).epsilon(1e-15));
  CHECK(swapped.points[0].separation == doctest::Approx(-depth).epsilon(1e-12));
  CHECK((swapped.points[0].point - m.points[0].point).norm() < 1e-12);

  // a small turn keeps the feature id
  const sim::collision::Manifold turned =
      sim::collision::collide(box, pose(p.x.x() + 1e-4, p.x.y(), angle + 1e-4), floor, pose(0, 0), kMargin);
  REQUIRE(turned.count == 1);
  CHECK(turned.points[0].id == m.points[0].id);
}

// BUG (collide.cpp, polygons()): to keep the reference face from flipping on near ties, the
// manifold keeps A's best edge unless B's is better by more than 0.05·kContactMargin (5e-4). When
// B's edge is better by less than that, B's incident edge (the one most anti-parallel to A's
// face) can lie wholly outside A's face's side planes; clipping then leaves fewer than two points
// and polygons() returns NO contact points although the polygons overlap. Corners meeting near a
// corner do this. Nothing then pushes the bodies apart, and the answer depends on the argument
// order: collide(B, A) finds the contact.
TEST_CASE("overlapping polygons get a contact point: a corner just past another box's corner") {
  // A: the unit square at the origin. B: a unit square turned by 30° whose lowest corner is at
  // (0.5 + 1e-4, 0.5 − 3e-4): just right of A's top right corner and 3e-4 below A's top, so that
  // B's left edge cuts off A's corner. The best separating edge is B's left edge (−6.34e-5); A's
  // top edge gives −3e-4, within the hysteresis, so A's top is kept as the reference face and
  // B's bottom edge, which starts at x = 0.5001, is clipped away entirely.
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0);
  const sim::core::Pose pa = pose(0, 0);
  sim::core::Pose pb = pose(0, 0, kPi / 6);
  pb.x = Vec2(0.5 + 1e-4, 0.5 - 3e-4) - pb.q.apply(Vec2(-0.5, -0.5));
  const std::vector<Vec2> A = worldVertices(box, pa), B = worldVertices(box, pb);
  // they overlap: A's corner is inside B, B's left edge crosses A's right edge below the corner
  REQUIRE(overlapByEdges(A, B));
  REQUIRE(insideConvex(B, Vec2(0.5, 0.5)));
  const double expected = 1e-4 * std::cos(kPi / 6) - 3e-4 * std::sin(kPi / 6);  // −6.34e-5
  const sim::collision::Manifold m = sim::collision::collide(box, pa, box, pb, kMargin);
  CHECK(m.sat.separation == doctest::Approx(expected).epsilon(1e-9));
  CHECK(m.separation < 0.0);
  // the other argument order finds the contact: 2 points, the deepest at the SAT separation
  const sim::collision::Manifold swapped = sim::collision::collide(box, pb, box, pa, kMargin);
  REQUIRE(swapped.count >= 1);
  CHECK(std::min(swapped.points[0].separation, swapped.points[swapped.count - 1].separation) ==
        doctest::Approx(expected).epsilon(1e-9));
  // FAILS: collide(A, B) returns count 0 (with normal (0, −1) from A's top face)
  CHECK(m.count >= 1);
  CHECK(m.count == swapped.count);
  CHECK(m.separation == doctest::Approx(swapped.separation).epsilon(1e-9));
}

TEST_CASE("overlapping polygons get a contact point: random corners pushed slightly into corners") {
  // random pairs put corner to corner (B's corner facing A's, turned by up to ±0.6 rad) and
  // moved by up to 5e-4 in a random direction, below the manifold's hysteresis: each
  // overlapping pair must get at least one point, in either argument order
  std::mt19937 rng(515u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // the outward direction at vertex k: between the normals of its two edges
  auto outward = [](const sim::core::Shape& s, size_t k) {
    const size_t n = s.vertices.size();
    return Vec2(s.normals[k] + s.normals[(k + n - 1) % n]).normalized();
  };
  int overlapping = 0, missed = 0, missedSwapped = 0;
  for (int i = 0; i < 20000; ++i) {
    const RandomPolygon ra = randomPolygon(rng), rb = randomPolygon(rng);
    const size_t ka = rng() % ra.shape.vertices.size(), kb = rng() % rb.shape.vertices.size();
    const sim::core::Pose pa = pose(0, 0, 2 * kPi * u(rng));
    // turn B so that its corner's outward direction faces A's, give or take 0.6 rad
    const Vec2 da = pa.q.apply(outward(ra.shape, ka)), db = outward(rb.shape, kb);
    const double facing = std::atan2(-da.y(), -da.x()) - std::atan2(db.y(), db.x()) + 1.2 * (u(rng) - 0.5);
    sim::core::Pose pb = pose(0, 0, facing);
    const double heading = 2 * kPi * u(rng), nudge = 5e-4 * u(rng);
    const Vec2 cornerA = pa.toWorld(ra.shape.vertices[ka]);
    pb.x = cornerA + nudge * Vec2(std::cos(heading), std::sin(heading)) - pb.q.apply(rb.shape.vertices[kb]);

    const sim::collision::Manifold m = sim::collision::collide(ra.shape, pa, rb.shape, pb, kMargin);
    if (!(m.sat.separation < -1e-9)) continue;
    ++overlapping;
    const sim::collision::Manifold swapped = sim::collision::collide(rb.shape, pb, ra.shape, pa, kMargin);
    if (m.count == 0 && missed++ == 0) {
      std::ostringstream what;
      what.precision(17);
      what << "first miss, pair " << i << ": A vertices";
      for (const Vec2& v : worldVertices(ra.shape, pa)) what << " (" << v.x() << ", " << v.y() << ")";
      what << "; B vertices";
      for (const Vec2& v : worldVertices(rb.shape, pb)) what << " (" << v.x() << ", " << v.y() << ")";
      what << "; SAT separation " << m.sat.separation << ", swapped count " << swapped.count;
      MESSAGE(what.str());
    }
    if (swapped.count == 0) ++missedSwapped;
  }
  MESSAGE(overlapping << " overlapping pairs; no contact point for " << missed << " as (A, B) and " << missedSwapped
                      << " as (B, A)");
  CHECK(overlapping > 5000);
  // FAILS: some overlapping pairs get no contact point (see the test above)
  CHECK(missed == 0);
  CHECK(missedSwapped == 0);
}

// BUG (collide.cpp, polygons(), lesser): a corner hovering next to another polygon's corner,
// closer than the margin (or touching it), gets no contact point in either argument order: the
// incident edge chosen against either candidate reference face lies wholly outside that face's
// side planes, so clipping leaves fewer than two points. The header promises points "kept while
// their separation is at most margin", and World::findContacts drops count-0 manifolds, so such a
// resting corner contact flickers, and a corner-on-corner impact found by the event method has no
// point to take the impulse.
TEST_CASE("corner next to a corner within the margin: a contact point") {
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0);
  struct Case {
    double degrees, right, up;  // B turned by this, its lowest corner at (0.5 + right, 0.5 + up)
  };
  // 0.002 up and right of A's top right corner (2.8e-3 apart, SAT 2.7e-3); exactly on it
  for (const Case c : {Case{30, 2e-3, 2e-3}, Case{20, 0.0, 0.0}, Case{10, 1e-3, 1e-3}}) {
    CAPTURE(c.degrees);
    CAPTURE(c.right);
    CAPTURE(c.up);
    sim::core::Pose pb = pose(0, 0, c.degrees * kPi / 180);
    pb.x = Vec2(0.5 + c.right, 0.5 + c.up) - pb.q.apply(Vec2(-0.5, -0.5));
    const double distance = std::hypot(c.right, c.up);
    const sim::collision::Manifold m = sim::collision::collide(box, pose(0, 0), box, pb, kMargin);
    const sim::collision::Manifold swapped = sim::collision::collide(box, pb, box, pose(0, 0), kMargin);
    CHECK(m.sat.separation >= -1e-15);
    CHECK(m.sat.separation <= distance + 1e-15);
    // FAILS: count 0 in both orders
    CHECK(m.count >= 1);
    CHECK(swapped.count >= 1);
  }
}

TEST_CASE("circle against circle: separation = distance − r1 − r2, normal from B to A, point midway") {
  const sim::core::Shape a = sim::core::makeCircle(0.5), b = sim::core::makeCircle(0.3);
  const Vec2 dir(0.6, 0.8);
  const Vec2 cb(0.4, 1.2);
  const sim::core::Pose pb = pose(cb.x(), cb.y(), 1.0);  // the circles' rotations do not matter

  SUBCASE("overlapping") {
    const Vec2 ca = cb + 0.7 * dir;
    const sim::collision::Manifold m = sim::collision::collide(a, pose(ca.x(), ca.y(), -2.0), b, pb, kMargin);
    REQUIRE(m.count == 1);
    CHECK_FALSE(m.sat.valid);
    CHECK((m.normal - dir).norm() < 1e-15);
    CHECK(m.points[0].separation == doctest::Approx(0.7 - 0.8).epsilon(1e-12));
    CHECK(m.separation == m.points[0].separation);
    // B's surface at cb + 0.3 dir, A's at ca − 0.5 dir = cb + 0.2 dir: midway at cb + 0.25 dir
    CHECK((m.points[0].point - (cb + 0.25 * dir)).norm() < 1e-12);

    const sim::collision::Manifold swapped = sim::collision::collide(b, pb, a, pose(ca.x(), ca.y()), kMargin);
    REQUIRE(swapped.count == 1);
    CHECK((swapped.normal + dir).norm() < 1e-15);
    CHECK(swapped.points[0].separation == doctest::Approx(m.points[0].separation).epsilon(1e-12));
    CHECK((swapped.points[0].point - m.points[0].point).norm() < 1e-12);
  }
  SUBCASE("farther apart than the margin") {
    const Vec2 ca = cb + 1.0 * dir;
    const sim::collision::Manifold m = sim::collision::collide(a, pose(ca.x(), ca.y()), b, pb, kMargin);
    CHECK(m.count == 0);
    CHECK(m.separation == doctest::Approx(0.2).epsilon(1e-12));
    CHECK((m.normal - dir).norm() < 1e-15);
  }
  SUBCASE("within the margin: a speculative point") {
    const Vec2 ca = cb + (0.8 + 0.5 * kMargin) * dir;
    const sim::collision::Manifold m = sim::collision::collide(a, pose(ca.x(), ca.y()), b, pb, kMargin);
    REQUIRE(m.count == 1);
    CHECK(m.points[0].separation == doctest::Approx(0.5 * kMargin).epsilon(1e-9));
  }
}

TEST_CASE("circle against polygon: face region, vertex region, center inside") {
  const sim::core::Shape box = sim::core::makeBox(2.0, 1.0);
  const double angle = 0.4;
  const sim::core::Pose pBox = pose(1.0, -0.5, angle);
  const sim::core::Rot q = pBox.q;
  auto world = [&](const Vec2& body) { return pBox.toWorld(body); };

  SUBCASE("face region: the top face") {
    const sim::core::Shape c = sim::core::makeCircle(0.25);
    const Vec2 center = world({0.3, 0.5 + 0.25 - 0.02});
    const sim::collision::Manifold m = sim::collision::collide(c, pose(center.x(), center.y()), box, pBox, kMargin);
    REQUIRE(m.count == 1);
    CHECK((m.normal - q.apply({0, 1})).norm() < 1e-15);
    CHECK(m.points[0].separation == doctest::Approx(-0.02).epsilon(1e-12));
    CHECK((m.points[0].point - world({0.3, 0.5 - 0.01})).norm() < 1e-12);

    // the polygon as A: the normal flips, the point and separation stay
    const sim::collision::Manifold swapped = sim::collision::collide(box, pBox, c, pose(center.x(), center.y()), kMargin);
    REQUIRE(swapped.count == 1);
    CHECK((swapped.normal + q.apply({0, 1})).norm() < 1e-15);
    CHECK(swapped.points[0].separation == doctest::Approx(-0.02).epsilon(1e-12));
    CHECK((swapped.points[0].point - m.points[0].point).norm() < 1e-12);
  }
  SUBCASE("vertex region: beyond the top right corner") {
    const sim::core::Shape c = sim::core::makeCircle(0.31);
    const Vec2 dirBody(0.6, 0.8);
    const Vec2 center = world(Vec2(1.0, 0.5) + 0.3 * dirBody);
    const sim::collision::Manifold m = sim::collision::collide(c, pose(center.x(), center.y()), box, pBox, kMargin);
    REQUIRE(m.count == 1);
    CHECK((m.normal - q.apply(dirBody)).norm() < 1e-12);
    CHECK(m.points[0].separation == doctest::Approx(-0.01).epsilon(1e-12));
    // the circle's surface is 0.01 inside the corner: midway, 0.005 inside
    CHECK((m.points[0].point - world(Vec2(1.0, 0.5) - 0.005 * dirBody)).norm() < 1e-12);

    const sim::collision::Manifold swapped = sim::collision::collide(box, pBox, c, pose(center.x(), center.y()), kMargin);
    REQUIRE(swapped.count == 1);
    CHECK((swapped.normal + q.apply(dirBody)).norm() < 1e-12);
    CHECK(swapped.points[0].separation == doctest::Approx(-0.01).epsilon(1e-12));
  }
  SUBCASE("the center inside, nearest the right face") {
    const sim::core::Shape c = sim::core::makeCircle(0.1);
    const Vec2 center = world({0.8, 0.1});
    const sim::collision::Manifold m = sim::collision::collide(c, pose(center.x(), center.y()), box, pBox, kMargin);
    REQUIRE(m.count == 1);
    CHECK((m.normal - q.apply({1, 0})).norm() < 1e-15);
    CHECK(m.points[0].separation == doctest::Approx(-0.2 - 0.1).epsilon(1e-12));
  }
  SUBCASE("farther than the margin, off a corner: count 0 and the exact gap") {
    const sim::core::Shape c = sim::core::makeCircle(0.2);
    const Vec2 center = world(Vec2(-1.0, -0.5) + 0.5 * Vec2(-0.8, -0.6));
    const sim::collision::Manifold m = sim::collision::collide(c, pose(center.x(), center.y()), box, pBox, kMargin);
    CHECK(m.count == 0);
    CHECK(m.separation == doctest::Approx(0.3).epsilon(1e-12));
    CHECK((m.normal - q.apply({-0.8, -0.6})).norm() < 1e-12);
  }
}

TEST_CASE("circle against random polygons: the separation is the signed distance minus the radius") {
  std::mt19937 rng(7u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int inside = 0, outside = 0;
  for (int i = 0; i < 3000; ++i) {
    const RandomPolygon rp = randomPolygon(rng);
    const sim::core::Pose pp = pose(2 * u(rng) - 1, 2 * u(rng) - 1, 2 * kPi * u(rng));
    const double r = 0.05 + 0.5 * u(rng), heading = 2 * kPi * u(rng);
    const Vec2 center = pp.x + (rp.radius + r) * 1.2 * u(rng) * Vec2(std::cos(heading), std::sin(heading));
    const sim::core::Shape circle = sim::core::makeCircle(r);
    const sim::core::Pose pc = pose(center.x(), center.y(), u(rng));
    const std::vector<Vec2> P = worldVertices(rp.shape, pp);
    const double sd = signedDistance(P, center);
    (sd < 0 ? inside : outside)++;
    CAPTURE(i);

    const sim::collision::Manifold m = sim::collision::collide(circle, pc, rp.shape, pp, kMargin);
    CHECK_FALSE(m.sat.valid);
    CHECK(std::abs(m.separation - (sd - r)) <= 1e-12);
    CHECK(std::abs(m.normal.norm() - 1.0) <= 1e-12);
    CHECK(m.count == (sd - r <= kMargin ? 1 : 0));
    if (m.count == 1) {
      CHECK(m.points[0].separation == m.separation);
      // the circle's surface point is center − r n; the polygon's is on its boundary
      const Vec2 onA = m.points[0].point + 0.5 * m.separation * m.normal;
      const Vec2 onB = m.points[0].point - 0.5 * m.separation * m.normal;
      CHECK((onA - (center - r * m.normal)).norm() <= 1e-12);
      CHECK(std::abs(signedDistance(P, onB)) <= 1e-12);
    }
    if (sd > 1e-6) {
      // outside: the normal points from the polygon's closest point to the center
      const Vec2 onB = center - (sd)*m.normal;
      CHECK(std::abs(signedDistance(P, onB)) <= 1e-12);
    }
    const sim::collision::Manifold swapped = sim::collision::collide(rp.shape, pp, circle, pc, kMargin);
    CHECK(swapped.count == m.count);
    CHECK(swapped.separation == m.separation);
    CHECK((swapped.normal + m.normal).norm() == 0.0);
    if (m.count == 1) CHECK((swapped.points[0].point - m.points[0].point).norm() == 0.0);
  }
  CHECK(inside > 300);
  CHECK(outside > 300);
}

TEST_CASE("half-planes: a floor with normal (0, 1) through its pose's x") {
  const sim::core::Shape floor = sim::core::makePlane({0, 1});
  const sim::core::Pose pFloor = pose(5.0, -1.0);  // the line y = −1 (x of the pose is any point on it)

  SUBCASE("a circle sinking into it") {
    const sim::core::Shape c = sim::core::makeCircle(0.5);
    const sim::collision::Manifold m = sim::collision::collide(c, pose(3.0, -0.6), floor, pFloor, kMargin);
    REQUIRE(m.count == 1);
    CHECK((m.normal - Vec2(0, 1)).norm() < 1e-15);
    CHECK(m.points[0].separation == doctest::Approx(-0.1).epsilon(1e-12));
    CHECK((m.points[0].point - Vec2(3.0, -1.05)).norm() < 1e-12);
    CHECK_FALSE(m.sat.valid);

    const sim::collision::Manifold swapped = sim::collision::collide(floor, pFloor, c, pose(3.0, -0.6), kMargin);
    REQUIRE(swapped.count == 1);
    CHECK((swapped.normal - Vec2(0, -1)).norm() < 1e-15);
    CHECK(swapped.points[0].separation == doctest::Approx(-0.1).epsilon(1e-12));
    CHECK((swapped.points[0].point - m.points[0].point).norm() < 1e-12);
  }
  SUBCASE("a circle above it, beyond the margin") {
    const sim::collision::Manifold m =
        sim::collision::collide(sim::core::makeCircle(0.5), pose(-7.0, 0.0), floor, pFloor, kMargin);
    CHECK(m.count == 0);
    CHECK(m.separation == doctest::Approx(0.5).epsilon(1e-12));
  }
  SUBCASE("a box lying on it: two points, stable ids") {
    const sim::core::Shape box = sim::core::makeBox(1.0, 0.5);
    const sim::collision::Manifold m = sim::collision::collide(box, pose(2.0, -1.0 + 0.25 - 0.01), floor, pFloor, kMargin);
    REQUIRE(m.count == 2);
    CHECK((m.normal - Vec2(0, 1)).norm() < 1e-15);
    CHECK(m.separation == doctest::Approx(-0.01).epsilon(1e-12));
    CHECK(leftmost(m).point.x() == doctest::Approx(1.5).epsilon(1e-12));
    CHECK(rightmost(m).point.x() == doctest::Approx(2.5).epsilon(1e-12));
    for (int k = 0; k < 2; ++k) {
      CHECK(m.points[k].separation == doctest::Approx(-0.01).epsilon(1e-12));
      CHECK(m.points[k].point.y() == doctest::Approx(-1.005).epsilon(1e-12));
    }
    CHECK(m.points[0].id != m.points[1].id);
    const sim::collision::Manifold next =
        sim::collision::collide(box, pose(2.0 + 1e-4, -1.0 + 0.25 - 0.01, 1e-4), floor, pFloor, kMargin);
    REQUIRE(next.count == 2);
    CHECK(leftmost(next).id == leftmost(m).id);
    CHECK(rightmost(next).id == rightmost(m).id);

    const sim::collision::Manifold swapped = sim::collision::collide(floor, pFloor, box, pose(2.0, -1.0 + 0.25 - 0.01), kMargin);
    REQUIRE(swapped.count == 2);
    CHECK((swapped.normal - Vec2(0, -1)).norm() < 1e-15);
    CHECK((leftmost(swapped).point - leftmost(m).point).norm() < 1e-12);
    CHECK(leftmost(swapped).separation == doctest::Approx(-0.01).epsilon(1e-12));
  }
  SUBCASE("a tilted box on a corner: one point") {
    const sim::core::Shape box = sim::core::makeBox(1.0, 1.0);
    sim::core::Pose p = pose(0, 0, 0.5);
    double lowest = kInf;
    for (const Vec2& v : box.vertices) lowest = std::min(lowest, p.toWorld(v).y());
    p.x = Vec2(0.7, -1.0 - 0.02 - lowest);
    const sim::collision::Manifold m = sim::collision::collide(box, p, floor, pFloor, kMargin);
    REQUIRE(m.count == 1);
    CHECK(m.points[0].separation == doctest::Approx(-0.02).epsilon(1e-12));
    CHECK(m.points[0].point.y() == doctest::Approx(-1.01).epsilon(1e-12));
  }
  SUBCASE("a box above it, beyond the margin") {
    const sim::collision::Manifold m =
        sim::collision::collide(sim::core::makeBox(1.0, 0.5), pose(0.0, 0.0, 0.3), floor, pFloor, kMargin);
    CHECK(m.count == 0);
    // the lowest corner of a box turned by 0.3 is 0.5 sin 0.3 + 0.25 cos 0.3 below its center
    CHECK(m.separation == doctest::Approx(1.0 - 0.5 * std::sin(0.3) - 0.25 * std::cos(0.3)).epsilon(1e-12));
  }
}

TEST_CASE("half-planes: a turned plane and random polygons against the vertex distances") {
  std::mt19937 rng(99u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double a = 2 * kPi * u(rng), turn = 2 * kPi * u(rng);
    const sim::core::Shape plane = sim::core::makePlane({std::cos(a) * (0.5 + u(rng)), std::sin(a) * (0.5 + u(rng))});
    const sim::core::Pose pp = pose(4 * u(rng) - 2, 4 * u(rng) - 2, turn);
    const Vec2 n = pp.q.apply(plane.planeNormal);
    const RandomPolygon rp = randomPolygon(rng);
    const sim::core::Pose po = pose(pp.x.x() + 4 * u(rng) - 2, pp.x.y() + 4 * u(rng) - 2, 2 * kPi * u(rng));
    CAPTURE(i);

    std::vector<double> s;
    for (const Vec2& v : worldVertices(rp.shape, po)) s.push_back(n.dot(v - pp.x));
    std::vector<double> sorted = s;
    std::sort(sorted.begin(), sorted.end());
    int within = 0;
    for (double d : sorted) within += d <= kMargin;

    const sim::collision::Manifold m = sim::collision::collide(rp.shape, po, plane, pp, kMargin);
    CHECK((m.normal - n).norm() < 1e-15);
    CHECK(std::abs(m.separation - sorted[0]) <= 1e-12);
    CHECK(m.count == std::min(within, 2));
    for (int k = 0; k < m.count; ++k) {
      CHECK(std::abs(m.points[k].separation - sorted[k]) <= 1e-12);
      // midway: the vertex is at point + s/2 n, its foot on the plane at point − s/2 n
      CHECK(std::abs(n.dot(m.points[k].point - 0.5 * m.points[k].separation * n - pp.x)) <= 1e-12);
    }
    const sim::collision::Manifold swapped = sim::collision::collide(plane, pp, rp.shape, po, kMargin);
    CHECK((swapped.normal + n).norm() < 1e-15);
    CHECK(swapped.count == m.count);
    CHECK(swapped.separation == m.separation);
  }
}

TEST_CASE("two half-planes never collide") {
  const sim::core::Shape floor = sim::core::makePlane({0, 1}), wall = sim::core::makePlane({1, 0});
  const sim::collision::Manifold m = sim::collision::collide(floor, pose(0, 0), wall, pose(0, 0), kMargin);
  CHECK(m.count == 0);
}

TEST_CASE("farther apart than the margin: no points, and a positive lower bound of the distance") {
  const sim::core::Shape box = sim::core::makeBox(1.0, 1.0), tri = sim::core::makePolygon({{0, 0}, {1, 0}, {0.2, 0.8}});
  const sim::core::Shape circle = sim::core::makeCircle(0.4), floor = sim::core::makePlane({0, 1});
  struct Case {
    const sim::core::Shape *a, *b;
    sim::core::Pose pa, pb;
    double distance;
  };
  // corner to corner the distance is 0.5·√2 ≈ 0.707 while the best axis gives 0.5
  // the top corner of a box turned by 0.7, with a circle straight above it
  const double c7 = std::cos(0.7), s7 = std::sin(0.7);
  const Vec2 corner(0.5 * c7 - 0.5 * s7, 0.5 * s7 + 0.5 * c7);
  const Case cases[] = {
      {&box, &box, pose(1.5, 1.5), pose(0, 0), std::hypot(0.5, 0.5)},
      {&box, &box, pose(0, 1.3, 0.0), pose(0, 0), 0.3},
      {&tri, &box, pose(0.7, 0.1, 0.0), pose(0, 0), 0.2},
      {&circle, &box, pose(0.5 + 0.3, 0.5 + 0.4), pose(0, 0), 0.1},
      {&box, &circle, pose(0, 0, 0.7), pose(corner.x(), 2.0), 2.0 - 0.4 - corner.y()},
      {&circle, &circle, pose(1, 1), pose(0, 0), std::sqrt(2.0) - 0.8},
      {&circle, &floor, pose(0, 1), pose(0, 0), 0.6},
      {&floor, &box, pose(0, 0), pose(3, 0.75, 0.0), 0.25},
  };
  for (const Case& c : cases) {
    CAPTURE(c.distance);
    const sim::collision::Manifold m = sim::collision::collide(*c.a, c.pa, *c.b, c.pb, kMargin);
    CHECK(m.count == 0);
    CHECK(m.separation > kMargin);
    CHECK(m.separation <= c.distance + 1e-12);
  }
}

// =============================================================================================
// 3. bounds

TEST_CASE("bounds: rotated polygons contain every vertex, tightly") {
  std::mt19937 rng(3u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const RandomPolygon rp = randomPolygon(rng);
    const sim::core::Pose p = pose(10 * u(rng) - 5, 10 * u(rng) - 5, 2 * kPi * u(rng));
    const sim::collision::Aabb box = sim::collision::bounds(rp.shape, p);
    Vec2 lo = Vec2::Constant(kInf), hi = Vec2::Constant(-kInf);
    for (const Vec2& v : worldVertices(rp.shape, p)) {
      CHECK(box.lower.x() <= v.x());
      CHECK(box.lower.y() <= v.y());
      CHECK(v.x() <= box.upper.x());
      CHECK(v.y() <= box.upper.y());
      lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    }
    CHECK((box.lower - lo).norm() == 0.0);
    CHECK((box.upper - hi).norm() == 0.0);
  }
  // a unit square turned by 45°: half a diagonal each way
  const sim::collision::Aabb diamond = sim::collision::bounds(sim::core::makeBox(1, 1), pose(1, 2, kPi / 4));
  CHECK(diamond.lower.x() == doctest::Approx(1 - std::sqrt(0.5)).epsilon(1e-15));
  CHECK(diamond.upper.y() == doctest::Approx(2 + std::sqrt(0.5)).epsilon(1e-15));
}

TEST_CASE("bounds: circles, whatever their rotation") {
  const sim::collision::Aabb box = sim::collision::bounds(sim::core::makeCircle(0.5), pose(1, -2, 1.3));
  CHECK((box.lower - Vec2(0.5, -2.5)).norm() == 0.0);
  CHECK((box.upper - Vec2(1.5, -1.5)).norm() == 0.0);
}

TEST_CASE("bounds: planes are unbounded on the free side and along themselves") {
  const sim::collision::Aabb floor = sim::collision::bounds(sim::core::makePlane({0, 1}), pose(3, -1));
  CHECK(floor.upper.y() == -1.0);
  CHECK(floor.lower.y() == -kInf);
  CHECK(floor.lower.x() == -kInf);
  CHECK(floor.upper.x() == kInf);

  const sim::collision::Aabb ceiling = sim::collision::bounds(sim::core::makePlane({0, -1}), pose(3, 4));
  CHECK(ceiling.lower.y() == 4.0);
  CHECK(ceiling.upper.y() == kInf);
  CHECK(ceiling.lower.x() == -kInf);
  CHECK(ceiling.upper.x() == kInf);

  const sim::collision::Aabb wall = sim::collision::bounds(sim::core::makePlane({1, 0}), pose(-2, 7));
  CHECK(wall.upper.x() == -2.0);
  CHECK(wall.lower.x() == -kInf);
  CHECK(wall.lower.y() == -kInf);
  CHECK(wall.upper.y() == kInf);

  const sim::collision::Aabb right = sim::collision::bounds(sim::core::makePlane({-2, 0}), pose(6, 7));
  CHECK(right.lower.x() == 6.0);
  CHECK(right.upper.x() == kInf);

  // a slanted plane is unbounded every way
  const sim::collision::Aabb slanted = sim::collision::bounds(sim::core::makePlane({1, 1}), pose(0, 0));
  CHECK(slanted.lower.x() == -kInf);
  CHECK(slanted.lower.y() == -kInf);
  CHECK(slanted.upper.x() == kInf);
  CHECK(slanted.upper.y() == kInf);

  // bounded boxes meet the floor's box only when they reach below its line
  const sim::collision::Aabb above = sim::collision::bounds(sim::core::makeBox(1, 1), pose(100, 0));
  const sim::collision::Aabb touching = sim::collision::bounds(sim::core::makeBox(1, 1), pose(-100, -0.6));
  CHECK_FALSE(floor.overlaps(above));
  CHECK(floor.overlaps(touching));
  CHECK(touching.overlaps(floor));
}

TEST_CASE("bounds of overlapping polygons overlap") {
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int overlapping = 0;
  for (int i = 0; i < 1000; ++i) {
    const RandomPolygon ra = randomPolygon(rng), rb = randomPolygon(rng);
    const sim::core::Pose pa = pose(0, 0, 2 * kPi * u(rng));
    const double heading = 2 * kPi * u(rng), offset = (ra.radius + rb.radius) * u(rng);
    const sim::core::Pose pb = pose(offset * std::cos(heading), offset * std::sin(heading), 2 * kPi * u(rng));
    if (sim::collision::sat(ra.shape, pa, rb.shape, pb).separation >= 0.0) continue;
    ++overlapping;
    CHECK(sim::collision::bounds(ra.shape, pa).overlaps(sim::collision::bounds(rb.shape, pb)));
  }
  // the check speaks only for the pairs that overlap: about half do (offsets up to the sum of the
  // bounding radii), so a change of the draws that left few would not pass unnoticed
  MESSAGE(overlapping << " of 1000 random pairs overlap");
  CHECK(overlapping > 400);
}
