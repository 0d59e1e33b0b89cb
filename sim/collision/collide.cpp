#include "sim/collision/collide.h"

#include <algorithm>
#include <limits>

#include "sim/collision/compound.h"
#include "sim/core/settings.h"

namespace sim::collision {
using namespace sim::core;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// a polygon in world coordinates: a placed shape's vertices and outward edge normals
struct WorldPolygon {
  const Vec2* v;
  const Vec2* n;
  size_t count;
  explicit WorldPolygon(const PlacedShape& s) : v(s.vertices.data()), n(s.normals.data()), count(s.vertices.size()) {}
  size_t size() const { return count; }
};

// shapes placed for one call of the shape-and-pose functions: the callers keep one pair per
// thread, so that their pairs allocate nothing
thread_local PlacedShape scratchA, scratchB;

// separation(P → Q) of the notes, with the edge of P and the vertex of Q that attain it
struct EdgeSeparation {
  double separation = -kInf;
  int edge = -1;
  int vertex = -1;
};

// (kSize > 0: both polygons have that many vertices, so that the loops unroll; 0: any)
template <size_t kSize>
EdgeSeparation maxSeparationOf(const WorldPolygon& p, const WorldPolygon& q) {
  const size_t np = kSize ? kSize : p.size(), nq = kSize ? kSize : q.size();
  EdgeSeparation best;
  for (size_t e = 0; e < np; ++e) {
    // separation(e → Q): the deepest vertex of Q below the edge's line
    double deepest = kInf;
    int vertex = -1;
    for (size_t k = 0; k < nq; ++k) {
      const double d = p.n[e].dot(q.v[k] - p.v[e]);
      if (d < deepest) deepest = d, vertex = static_cast<int>(k);
    }
    if (deepest > best.separation) best = {deepest, static_cast<int>(e), vertex};
  }
  return best;
}

// A point's id names the two features that make it, one of A and one of B: a vertex of one
// polygon against an edge of the other (Box2D's b2ContactFeature). Which polygon holds the
// reference edge does not enter it, so the id survives the reference passing from one polygon to
// the other between steps, as it does all the time for two equal boxes face to face (their two
// separations tie within round-off), and the sequential solver keeps warm starting the point.
enum class FeatureKind : std::uint32_t { Vertex = 0, Edge = 1 };
struct Feature {
  FeatureKind kind;
  int index;  // vertex i, or edge i from vertex i to i + 1
};

// one feature in 32 bits: its kind, then its index (a non-negative int, so it fits in 31)
FeatureId featureBits(Feature f) {
  return static_cast<FeatureId>(f.kind) | static_cast<FeatureId>(static_cast<std::uint32_t>(f.index)) << 1;
}

FeatureId featureId(bool referenceOnA, Feature reference, Feature incident) {
  return referenceOnA ? featureBits(reference) | featureBits(incident) << 32
                      : featureBits(incident) | featureBits(reference) << 32;
}

struct ClipPoint {
  Vec2 p;
  int incidentVertex;   // the incident edge's end it is, or -1
  int referenceVertex;  // the reference vertex whose side plane cut the incident edge here, or -1
};

// keep the part of segment (in[0], in[1]) where normal·x ≤ offset (Box2D-Lite's ClipSegmentToLine);
// the side plane is that of reference vertex `sideVertex`
[[gnu::always_inline]] inline int clipSegment(const ClipPoint in[2], ClipPoint out[2], const Vec2& normal, double offset,
                                              int sideVertex) {
  int count = 0;
  const double d0 = normal.dot(in[0].p) - offset, d1 = normal.dot(in[1].p) - offset;
  if (d0 <= 0.0) out[count++] = in[0];
  if (d1 <= 0.0) out[count++] = in[1];
  if (d0 * d1 < 0.0) out[count++] = {in[0].p + (d0 / (d0 - d1)) * (in[1].p - in[0].p), -1, sideVertex};
  return count;
}

// the points of a polygon pair with the reference edge on A (refA) or on B: the incident edge
// (the one most anti-parallel to the reference normal) clipped to the reference edge's side
// planes (Box2D-Lite's clipping) moved out by the side slack (Box2D 2.4's b2CollidePolygons moves
// them by the skin), keeping the points within the margin of the reference face
// (kSize > 0: both polygons have that many vertices, so that the loop unrolls and the next vertex
// is found without a division)
template <size_t kSize>
void clipToReference(const WorldPolygon& A, const WorldPolygon& B, const EdgeSeparation& ea, const EdgeSeparation& eb, bool refA,
                     double margin, double sideSlack, Manifold& m) {
  const WorldPolygon& ref = refA ? A : B;
  const WorldPolygon& inc = refA ? B : A;
  const int edge = refA ? ea.edge : eb.edge;
  const Vec2 nRef = ref.n[edge];
  m.normal = refA ? Vec2(-nRef) : nRef;
  m.count = 0;

  int incEdge = 0;
  double most = kInf;
  const size_t incCount = kSize ? kSize : inc.size(), refCount = kSize ? kSize : ref.size();
  for (size_t i = 0; i < incCount; ++i) {
    const double d = inc.n[i].dot(nRef);
    if (d < most) most = d, incEdge = static_cast<int>(i);
  }
  const int incNext = static_cast<int>((incEdge + 1) % incCount), refNext = static_cast<int>((edge + 1) % refCount);
  const ClipPoint incident[2] = {{inc.v[incEdge], incEdge, -1}, {inc.v[incNext], incNext, -1}};
  const Vec2 v1 = ref.v[edge], v2 = ref.v[refNext];
  const Vec2 t = (v2 - v1).normalized();
  ClipPoint once[3], twice[3];
  if (clipSegment(incident, once, -t, -t.dot(v1) + sideSlack, edge) < 2) return;
  if (clipSegment(once, twice, t, t.dot(v2) + sideSlack, refNext) < 2) return;
  for (int k = 0; k < 2; ++k) {
    const double sep = nRef.dot(twice[k].p - v1);
    if (sep > margin) continue;
    // an incident vertex against the reference edge, or a reference vertex against the incident edge
    const FeatureId id = twice[k].referenceVertex >= 0
                             ? featureId(refA, {FeatureKind::Vertex, twice[k].referenceVertex}, {FeatureKind::Edge, incEdge})
                             : featureId(refA, {FeatureKind::Edge, edge}, {FeatureKind::Vertex, twice[k].incidentVertex});
    m.points[m.count++] = {twice[k].p - 0.5 * sep * nRef, sep, id};
  }
}

// polygon against polygon: SAT picks the reference edge, the incident edge is clipped to its sides
// (kSize as clipToReference's: 4 for two boxes, the common case, whose loops unroll)
template <size_t kSize>
Manifold polygonsOf(const WorldPolygon& A, const WorldPolygon& B, double margin, double sideSlack) {
  const EdgeSeparation ea = maxSeparationOf<kSize>(A, B), eb = maxSeparationOf<kSize>(B, A);
  Manifold m;
  // the notes' separation(P, Q) and its features, exactly as on the slide
  const bool bestA = ea.separation >= eb.separation;
  m.sat = {true, std::max(ea.separation, eb.separation), bestA, bestA ? ea.edge : eb.edge, bestA ? ea.vertex : eb.vertex};
  m.separation = m.sat.separation;
  // for the manifold, keep A's edge unless B's is clearly better, so the choice does not flip
  // from step to step on near ties (Box2D's b2CollidePolygons does the same)
  const bool refA = !(eb.separation > ea.separation + settings::kReferenceEdgeHysteresis);
  clipToReference<kSize>(A, B, ea, eb, refA, margin, sideSlack, m);
  if (m.separation > margin) return m;
  // the kept edge's sides can miss the incident edge near a corner: then use the best edge
  if (m.count == 0 && refA != bestA) clipToReference<kSize>(A, B, ea, eb, bestA, margin, sideSlack, m);
  // corner against corner: no edge's sides hold the other's edge; the incident vertex touches
  // the reference edge's end, so the contact runs between the closest points of the two
  if (m.count == 0) {
    const WorldPolygon& ref = bestA ? A : B;
    const WorldPolygon& inc = bestA ? B : A;
    const int e = m.sat.referenceEdge;
    const Vec2 v1 = ref.v[e], v2 = ref.v[(e + 1) % ref.size()], w = inc.v[m.sat.incidentVertex];
    const double along = std::clamp((w - v1).dot(v2 - v1) / (v2 - v1).squaredNorm(), 0.0, 1.0);
    const Vec2 closest = v1 + along * (v2 - v1), d = w - closest;
    Vec2 n = ref.n[e];
    double sep = m.sat.separation;
    if (d.dot(n) > 0.0 && d.norm() > 0.0) n = d / d.norm(), sep = d.norm();
    if (sep > margin) return m;
    m.normal = bestA ? Vec2(-n) : n;
    m.count = 1;
    m.points[0] = {w - 0.5 * sep * n, sep, featureId(bestA, {FeatureKind::Edge, e}, {FeatureKind::Vertex, m.sat.incidentVertex})};
  }
  m.separation = kInf;
  for (int k = 0; k < m.count; ++k) m.separation = std::min(m.separation, m.points[k].separation);
  return m;
}

Manifold polygons(const PlacedShape& a, const PlacedShape& b, double margin, double sideSlack) {
  const WorldPolygon A(a), B(b);
  return A.size() == 4 && B.size() == 4 ? polygonsOf<4>(A, B, margin, sideSlack) : polygonsOf<0>(A, B, margin, sideSlack);
}

// a contact whose normal points out of the first shape toward the second
Manifold single(const Vec2& normal, const Vec2& point, double separation, FeatureId id, double margin) {
  Manifold m;
  m.normal = normal;
  m.separation = separation;
  if (separation <= margin) {
    m.count = 1;
    m.points[0] = {point, separation, id};
  }
  return m;
}

// out of circle b toward circle a
Manifold circles(const PlacedShape& a, const PlacedShape& b, double margin) {
  const Vec2 d = a.pose.x - b.pose.x;
  const double distance = d.norm();
  const Vec2 n = distance > 0.0 ? Vec2(d / distance) : Vec2(Vec2::UnitY());
  const double s = distance - a.shape->radius - b.shape->radius;
  return single(n, b.pose.x + (b.shape->radius + 0.5 * s) * n, s, 0, margin);
}

// out of polygon p toward circle c (Box2D's b2CollidePolygonAndCircle: face or vertex region)
Manifold polygonCircle(const PlacedShape& p, const PlacedShape& c, double margin) {
  const WorldPolygon P(p);
  const Vec2 center = c.pose.x;
  const double r = c.shape->radius;
  int edge = 0;
  double face = -kInf;
  for (size_t i = 0; i < P.size(); ++i) {
    const double s = P.n[i].dot(center - P.v[i]);
    if (s > face) face = s, edge = static_cast<int>(i);
  }
  const Vec2 v1 = P.v[edge], v2 = P.v[(edge + 1) % P.size()];
  Vec2 n = P.n[edge];
  double s = face - r;
  FeatureId id = featureBits({FeatureKind::Edge, edge});
  if (face > 0.0) {
    // outside: the closest feature is the edge or one of its end vertices
    const bool nearV1 = (center - v1).dot(v2 - v1) <= 0.0, nearV2 = (center - v2).dot(v1 - v2) <= 0.0;
    if (nearV1 || nearV2) {
      const Vec2 v = nearV1 ? v1 : v2;
      const double distance = (center - v).norm();
      n = (center - v) / distance;
      s = distance - r;
      id = featureBits({FeatureKind::Vertex, nearV1 ? edge : static_cast<int>((edge + 1) % P.size())});
    }
  }
  return single(n, center - (r + 0.5 * s) * n, s, id, margin);
}

// out of the plane toward the other shape: the vertices (at most two) deepest below the margin
Manifold planeShape(const PlacedShape& placedPlane, const PlacedShape& placed, double margin) {
  const Shape &plane = *placedPlane.shape, &o = *placed.shape;
  const Pose &pp = placedPlane.pose, &po = placed.pose;
  const Vec2 n = pp.q.apply(plane.planeNormal);
  if (o.kind == ShapeKind::Circle) {
    const double s = n.dot(po.x - pp.x) - o.radius;
    return single(n, po.x - (o.radius + 0.5 * s) * n, s, 0, margin);
  }
  Manifold m;
  m.normal = n;
  m.separation = kInf;
  if (o.kind != ShapeKind::Polygon) return m;
  int first = -1, second = -1;
  const std::vector<Vec2>& v = placed.vertices;
  thread_local std::vector<double> s;  // (kept per thread: a pile on a half-plane floor allocates nothing per pair)
  s.resize(v.size());
  for (size_t k = 0; k < v.size(); ++k) {
    s[k] = n.dot(v[k] - pp.x);
    if (first < 0 || s[k] < s[first]) second = first, first = static_cast<int>(k);
    else if (second < 0 || s[k] < s[second]) second = static_cast<int>(k);
  }
  m.separation = s[first];
  for (int k : {first, second})
    if (k >= 0 && s[k] <= margin) m.points[m.count++] = {v[k] - 0.5 * s[k] * n, s[k], static_cast<FeatureId>(k)};
  return m;
}

Manifold flipped(Manifold m) {
  m.normal = -m.normal;
  return m;
}

}  // namespace

void place(const Shape& shape, const Pose& pose, PlacedShape& out) {
  out.shape = &shape;
  out.pose = pose;
  out.vertices.clear();
  out.normals.clear();
  if (shape.kind != ShapeKind::Polygon) return;
  for (const Vec2& v : shape.vertices) out.vertices.push_back(pose.toWorld(v));
  for (const Vec2& n : shape.normals) out.normals.push_back(pose.q.apply(n));
}

SatFeatures sat(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  if (a.kind != ShapeKind::Polygon || b.kind != ShapeKind::Polygon) return {};
  place(a, pa, scratchA);
  place(b, pb, scratchB);
  const WorldPolygon A(scratchA), B(scratchB);
  const EdgeSeparation ea = maxSeparationOf<0>(A, B), eb = maxSeparationOf<0>(B, A);
  const bool onA = ea.separation >= eb.separation;
  return {true, onA ? ea.separation : eb.separation, onA, onA ? ea.edge : eb.edge, onA ? ea.vertex : eb.vertex};
}

Manifold collide(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb, double margin, double sideSlack) {
  if (a.kind == ShapeKind::Compound || b.kind == ShapeKind::Compound) return closestParts(a, pa, b, pb, margin, sideSlack);
  place(a, pa, scratchA);
  place(b, pb, scratchB);
  return collide(scratchA, scratchB, margin, sideSlack);
}

Manifold collide(const PlacedShape& pa, const PlacedShape& pb, double margin, double sideSlack) {
  using K = ShapeKind;
  const Shape &a = *pa.shape, &b = *pb.shape;
  if (a.kind == K::Compound || b.kind == K::Compound) return closestParts(a, pa.pose, b, pb.pose, margin, sideSlack);
  // each pair function's normal points out of its first shape; ours points out of B
  if (a.kind == K::Polygon && b.kind == K::Polygon) return polygons(pa, pb, margin, sideSlack);
  if (a.kind == K::Circle && b.kind == K::Circle) return circles(pa, pb, margin);
  if (b.kind == K::Plane && a.kind != K::Plane) return planeShape(pb, pa, margin);
  if (a.kind == K::Plane && b.kind != K::Plane) return flipped(planeShape(pa, pb, margin));
  if (b.kind == K::Polygon && a.kind == K::Circle) return polygonCircle(pb, pa, margin);
  if (a.kind == K::Polygon && b.kind == K::Circle) return flipped(polygonCircle(pa, pb, margin));
  Manifold none;  // two planes never touch: both are static
  none.separation = kInf;
  return none;
}

Aabb bounds(const Shape& shape, const Pose& pose) {
  if (shape.kind == ShapeKind::Compound) return compoundBounds(shape, pose);
  place(shape, pose, scratchA);
  return bounds(scratchA);
}

Aabb bounds(const PlacedShape& placed) {
  const Shape& shape = *placed.shape;
  const Pose& pose = placed.pose;
  switch (shape.kind) {
    case ShapeKind::Circle: return {pose.x - Vec2::Constant(shape.radius), pose.x + Vec2::Constant(shape.radius)};
    case ShapeKind::Polygon: {
      Aabb box{Vec2::Constant(kInf), Vec2::Constant(-kInf)};
      for (const Vec2& w : placed.vertices) {
        box.lower = box.lower.cwiseMin(w);
        box.upper = box.upper.cwiseMax(w);
      }
      return box;
    }
    case ShapeKind::Compound: return compoundBounds(shape, pose);
    case ShapeKind::Plane: {
      // unbounded, but an axis-aligned floor or wall is bounded on one side
      const Vec2 n = pose.q.apply(shape.planeNormal);
      Aabb box{Vec2::Constant(-kInf), Vec2::Constant(kInf)};
      if (n.x() == 0.0) (n.y() > 0.0 ? box.upper.y() : box.lower.y()) = pose.x.y();
      if (n.y() == 0.0) (n.x() > 0.0 ? box.upper.x() : box.lower.x()) = pose.x.x();
      return box;
    }
  }
  return {};
}

}  // namespace sim::collision
