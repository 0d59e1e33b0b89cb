// Four quad pairs in four lanes (quad_lanes.h): collide.cpp's polygonsOf<4> and clipToReference<4>
// written again over GCC's vector extensions, compiled with -mavx2 where the compiler targets
// x86-64 (sim/CMakeLists.txt), elsewhere for the target's own vectors. Every number is computed by
// the same operations in the same order as there (Eigen's dot is x·x' + y·y', normalized() divides
// by the square root of x² + y²; no fused multiply-add), and every choice by the same strict
// comparison in the same order, blended where the scalar code branches; so each lane is collide()'s
// result to the bit.
#include "sim/collision/quad_lanes.h"
#include "sim/core/avx2_transpose.h"

namespace sim::collision::quad {
namespace {

typedef double V __attribute__((vector_size(32)));
typedef long long I __attribute__((vector_size(32)));

constexpr double kInf = __builtin_inf();

V splat(double x) { return V{x, x, x, x}; }
I splatI(long long x) { return I{x, x, x, x}; }
// a where m, else b, bit by bit
V select(I m, V a, V b) { return reinterpret_cast<V>((reinterpret_cast<I>(a) & m) | (reinterpret_cast<I>(b) & ~m)); }
I selectI(I m, I a, I b) { return (a & m) | (b & ~m); }
// x[index] in each lane (index 0 to 3)
V pick(const V x[4], I index) { return select(index == 0, x[0], select(index == 1, x[1], select(index == 2, x[2], x[3]))); }

// one polygon of each lane: vertex k and the normal of edge k (from vertex k to k + 1)
struct Polygon {
  V vx[4], vy[4], nx[4], ny[4];
};

#if defined(__AVX2__)
// points x0 y0 x1 y1 x2 y2 x3 y3 of each lane into x[k], y[k]
[[gnu::always_inline]] inline void loadPoints(const double* const p[kLanes], V x[4], V y[4]) {
  for (int half = 0; half < 2; ++half) {
    __m256d r0 = _mm256_loadu_pd(p[0] + 4 * half), r1 = _mm256_loadu_pd(p[1] + 4 * half);
    __m256d r2 = _mm256_loadu_pd(p[2] + 4 * half), r3 = _mm256_loadu_pd(p[3] + 4 * half);
    sim::core::transpose4(r0, r1, r2, r3);
    x[2 * half] = V(r0), y[2 * half] = V(r1), x[2 * half + 1] = V(r2), y[2 * half + 1] = V(r3);
  }
}
#else
void loadPoints(const double* const p[kLanes], V x[4], V y[4]) {
  for (int k = 0; k < 4; ++k)
    for (int lane = 0; lane < kLanes; ++lane) x[k][lane] = p[lane][2 * k], y[k][lane] = p[lane][2 * k + 1];
}
#endif

// separation(P → Q) of each lane, with its edge of P and vertex of Q (collide.cpp's maxSeparationOf)
struct EdgeSeparation {
  V separation;
  I edge, vertex;
};

[[gnu::always_inline]] inline EdgeSeparation maxSeparation(const Polygon& p, const Polygon& q) {
  EdgeSeparation best{splat(-kInf), splatI(-1), splatI(-1)};
  for (int e = 0; e < 4; ++e) {
    V deepest = splat(kInf);
    I vertex = splatI(-1);
    for (int k = 0; k < 4; ++k) {
      const V d = p.nx[e] * (q.vx[k] - p.vx[e]) + p.ny[e] * (q.vy[k] - p.vy[e]);
      const I deeper = d < deepest;
      deepest = select(deeper, d, deepest);
      vertex = selectI(deeper, splatI(k), vertex);
    }
    const I better = deepest > best.separation;
    best.separation = select(better, deepest, best.separation);
    best.edge = selectI(better, splatI(e), best.edge);
    best.vertex = selectI(better, vertex, best.vertex);
  }
  return best;
}

// a register's lanes stored side by side
void store(double* to, V v) { *reinterpret_cast<V*>(to) = v; }
void store(long long* to, I v) { *reinterpret_cast<I*>(to) = v; }

// a point of the incident edge as the clipping carries it (collide.cpp's ClipPoint)
struct ClipPoint {
  V x, y;
  I incidentVertex, referenceVertex;
};

ClipPoint selectPoint(I m, const ClipPoint& a, const ClipPoint& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), selectI(m, a.incidentVertex, b.incidentVertex),
          selectI(m, a.referenceVertex, b.referenceVertex)};
}

// clipSegment: the part of (in[0], in[1]) where n·x ≤ offset, in the lanes where it keeps two
// points (`kept`); the others stop there in the scalar code
[[gnu::always_inline]] inline void clipSegment(const ClipPoint in[2], ClipPoint out[2], V nx, V ny, V offset, I side, I& kept) {
  const V d0 = (nx * in[0].x + ny * in[0].y) - offset, d1 = (nx * in[1].x + ny * in[1].y) - offset;
  const I keep0 = d0 <= 0.0, keep1 = d1 <= 0.0, cross = d0 * d1 < 0.0;
  const V s = d0 / (d0 - d1);
  const ClipPoint cut{in[0].x + s * (in[1].x - in[0].x), in[0].y + s * (in[1].y - in[0].y), splatI(-1), side};
  // two kept: both ends, or one end and the cut (the first end found first)
  const I count = (keep0 & 1) + (keep1 & 1) + (cross & 1);
  kept &= count >= 2;
  out[0] = selectPoint(keep0, in[0], in[1]);
  out[1] = selectPoint(keep0 & keep1, in[1], cut);
}

// featureBits and featureId of collide.cpp: 1 for an edge, 0 for a vertex, then the index (as 32
// bits: the lanes that do not use it may hold -1)
I featureBits(long long kind, I index) { return splatI(kind) | (index & 0xffffffffLL) << 1; }
I featureId(I referenceOnA, I reference, I incident) {
  return selectI(referenceOnA, reference | incident << 32, incident | reference << 32);
}

// the notes' separation(P, Q) of each lane, the better of A's and B's edges, with its features,
// and which polygon holds the reference edge (A's unless B's is clearly better)
struct Sat {
  EdgeSeparation a, b;
  I bestA, refA;
  V separation;
  I edge, vertex;
};

[[gnu::always_inline]] inline Sat separatingAxis(const Polygon& A, const Polygon& B, double hysteresis) {
  Sat sat{maxSeparation(A, B), maxSeparation(B, A), {}, {}, {}, {}, {}};
  sat.bestA = sat.a.separation >= sat.b.separation;
  sat.separation = select(sat.a.separation < sat.b.separation, sat.b.separation, sat.a.separation);
  sat.edge = selectI(sat.bestA, sat.a.edge, sat.b.edge), sat.vertex = selectI(sat.bestA, sat.a.vertex, sat.b.vertex);
  sat.refA = ~(sat.b.separation > sat.a.separation + splat(hysteresis));
  return sat;
}

// clipToReference<4> with the reference edge on A where refA, else on B: the two polygons by role
[[gnu::always_inline]] inline void byRole(const Polygon& A, const Polygon& B, I refA, Polygon& ref, Polygon& inc) {
  for (int k = 0; k < 4; ++k) {
    ref.vx[k] = select(refA, A.vx[k], B.vx[k]), ref.vy[k] = select(refA, A.vy[k], B.vy[k]);
    ref.nx[k] = select(refA, A.nx[k], B.nx[k]), ref.ny[k] = select(refA, A.ny[k], B.ny[k]);
    inc.vx[k] = select(refA, B.vx[k], A.vx[k]), inc.vy[k] = select(refA, B.vy[k], A.vy[k]);
    inc.nx[k] = select(refA, B.nx[k], A.nx[k]), inc.ny[k] = select(refA, B.ny[k], A.ny[k]);
  }
}

// the incident edge: the one whose normal is most against the reference normal (the first least)
[[gnu::always_inline]] inline I incidentEdge(const Polygon& inc, V nRefX, V nRefY) {
  I incEdge = splatI(0);
  V most = splat(kInf);
  for (int i = 0; i < 4; ++i) {
    const V d = inc.nx[i] * nRefX + inc.ny[i] * nRefY;
    const I less = d < most;
    most = select(less, d, most);
    incEdge = selectI(less, splatI(i), incEdge);
  }
  return incEdge;
}

// the reference edge's unit direction (normalized(): unchanged where it has no length)
[[gnu::always_inline]] inline void edgeDirection(V dx, V dy, V& tx, V& ty) {
  const V z = dx * dx + dy * dy;
  const I positive = z > 0.0;
#if defined(__AVX2__)
  const V root = V(_mm256_sqrt_pd(__m256d(z)));
#else
  V root = z;
  for (int lane = 0; lane < kLanes; ++lane) root[lane] = __builtin_sqrt(z[lane]);
#endif
  tx = select(positive, dx / root, dx), ty = select(positive, dy / root, dy);
}

// the clipped points as the manifold has them: separation from the reference edge, kept within
// the margin, feature ids, and each point halfway between the two surfaces
struct ClippedPoints {
  V sep[2], px[2], py[2];
  I keep[2], id[2];
};

[[gnu::always_inline]] inline ClippedPoints manifoldPoints(const ClipPoint twice[2], I kept, I refA, I edge, I incEdge, V nRefX,
                                                           V nRefY, V v1x, V v1y, double margin) {
  ClippedPoints p;
  for (int k = 0; k < 2; ++k) {
    p.sep[k] = nRefX * (twice[k].x - v1x) + nRefY * (twice[k].y - v1y);
    p.keep[k] = kept & ~(p.sep[k] > margin);
    const I vertexOnEdge = featureId(refA, featureBits(0, twice[k].referenceVertex), featureBits(1, incEdge));
    const I edgeOnVertex = featureId(refA, featureBits(1, edge), featureBits(0, twice[k].incidentVertex));
    p.id[k] = selectI(twice[k].referenceVertex >= 0, vertexOnEdge, edgeOnVertex);
    const V half = 0.5 * p.sep[k];
    p.px[k] = twice[k].x - half * nRefX, p.py[k] = twice[k].y - half * nRefY;
  }
  return p;
}

// the kept points first, in order, and zeros past them (as a Manifold's points start); apart by
// more than the margin: the first clipping's points as they are, with the notes' separation; else
// the least of the points' (std::min from infinity, as collide() takes it)
[[gnu::always_inline]] inline void storeManifold(const Sat& sat, const ClippedPoints& p, V normalX, V normalY, double margin,
                                                 Output& out) {
  const I count = (p.keep[0] & 1) + (p.keep[1] & 1), first = p.keep[0], second = p.keep[0] & p.keep[1];
  const V zero = splat(0.0);
  store(out.normalX, normalX), store(out.normalY, normalY), store(out.count, count);
  store(out.pointX[0], select(count > 0, select(first, p.px[0], p.px[1]), zero));
  store(out.pointY[0], select(count > 0, select(first, p.py[0], p.py[1]), zero));
  const V firstSeparation = select(count > 0, select(first, p.sep[0], p.sep[1]), zero);
  store(out.pointSeparation[0], firstSeparation);
  store(out.id[0], selectI(count > 0, selectI(first, p.id[0], p.id[1]), splatI(0)));
  store(out.pointX[1], select(second, p.px[1], zero)), store(out.pointY[1], select(second, p.py[1], zero));
  store(out.pointSeparation[1], select(second, p.sep[1], zero)), store(out.id[1], selectI(second, p.id[1], splatI(0)));
  store(out.satSeparation, sat.separation), store(out.satReferenceOnA, sat.bestA);
  store(out.satReferenceEdge, sat.edge), store(out.satIncidentVertex, sat.vertex);
  const I apart = sat.separation > margin;
  const V least = select(firstSeparation < kInf, firstSeparation, splat(kInf));
  const V both = select(p.sep[1] < least, p.sep[1], least);
  store(out.separation, select(apart, sat.separation, select(second, both, least)));
  store(out.again, (sat.a.edge < 0) | (sat.b.edge < 0) | (~apart & (count == 0)));
}

}  // namespace

void collideLanes(const Input& in, double margin, double hysteresis, double sideSlack, Output& out) {
  Polygon A, B;
  loadPoints(in.av, A.vx, A.vy);
  loadPoints(in.an, A.nx, A.ny);
  loadPoints(in.bv, B.vx, B.vy);
  loadPoints(in.bn, B.nx, B.ny);
  // the axis of least penetration and the edge to clip against (collide.cpp's polygonsOf<4>)
  const Sat sat = separatingAxis(A, B, hysteresis);
  Polygon ref, inc;
  byRole(A, B, sat.refA, ref, inc);
  // the reference edge's normal, the manifold's (collide()'s sign), and the incident edge
  const I edge = selectI(sat.refA, sat.a.edge, sat.b.edge);
  const V nRefX = pick(ref.nx, edge), nRefY = pick(ref.ny, edge);
  const V normalX = select(sat.refA, -nRefX, nRefX), normalY = select(sat.refA, -nRefY, nRefY);
  const I incEdge = incidentEdge(inc, nRefX, nRefY);
  const I incNext = (incEdge + 1) & 3, refNext = (edge + 1) & 3;
  const ClipPoint incident[2] = {{pick(inc.vx, incEdge), pick(inc.vy, incEdge), incEdge, splatI(-1)},
                                 {pick(inc.vx, incNext), pick(inc.vy, incNext), incNext, splatI(-1)}};
  const V v1x = pick(ref.vx, edge), v1y = pick(ref.vy, edge), v2x = pick(ref.vx, refNext), v2y = pick(ref.vy, refNext);
  V tx, ty;
  edgeDirection(v2x - v1x, v2y - v1y, tx, ty);
  // the incident edge clipped to the reference edge's side planes moved out by the side slack
  // (collide.cpp's clipToReference, after Box2D-Lite's ClipSegmentToLine)
  ClipPoint once[2], twice[2];
  I kept = splatI(-1);
  clipSegment(incident, once, -tx, -ty, -(tx * v1x + ty * v1y) + splat(sideSlack), edge, kept);
  clipSegment(once, twice, tx, ty, tx * v2x + ty * v2y + splat(sideSlack), refNext, kept);
  const ClippedPoints points = manifoldPoints(twice, kept, sat.refA, edge, incEdge, nRefX, nRefY, v1x, v1y, margin);
  storeManifold(sat, points, normalX, normalY, margin, out);
}

}  // namespace sim::collision::quad
