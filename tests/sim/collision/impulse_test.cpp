#include "sim/collision/impulse.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

namespace {

// a free body with the given mass properties and state (the shape does not enter the impulse)
sim::core::Body body(double mass, double inertia, const sim::core::Vec2& x, const sim::core::Vec2& v, double omega) {
  sim::core::Body b;
  b.shape = sim::core::makeCircle(0.5);
  b.mass = mass, b.invMass = 1.0 / mass;
  b.inertia = inertia, b.invInertia = 1.0 / inertia;
  b.setState({x, 0.0, v, omega});
  return b;
}

sim::core::Body obstacle() {
  sim::core::Body b;
  b.shape = sim::core::makePlane({0, 1});
  b.makeStatic();
  return b;
}

double normalVelocity(const sim::core::Body& a, const sim::core::Body& b, const sim::core::Vec2& r, const sim::core::Vec2& n) {
  return n.dot(sim::collision::relativeVelocity(a, b, r));
}

// Σ m v and Σ (x × m v + I ω) about the world origin, of the free bodies
sim::core::Vec2 momentum(const sim::core::Body& a, const sim::core::Body& b) { return a.mass * a.v + b.mass * b.v; }
double angularMomentum(const sim::core::Body& a, const sim::core::Body& b) {
  return sim::core::cross(a.x, a.mass * a.v) + a.inertia * a.omega + sim::core::cross(b.x, b.mass * b.v) + b.inertia * b.omega;
}
double kinetic(const sim::core::Body& a) { return 0.5 * a.mass * a.v.squaredNorm() + 0.5 * a.inertia * a.omega * a.omega; }

// a random free-space body–body impact: bodies within a few meters of the origin, speeds of a few
// m/s, the contact point between them and a random unit normal, turned so that they approach
// clearly (|v_n⁻| at least 0.2 m/s, so that 1e-12 relative is far above round-off)
struct RandomImpact {
  sim::core::Body a, b;
  sim::core::Vec2 r, n;
};

RandomImpact randomImpact(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.2, 5.0), inertia(0.05, 2.0);
  while (true) {
    RandomImpact c;
    c.a = body(mass(rng), inertia(rng), {3 * u(rng), 3 * u(rng)}, {2 * u(rng), 2 * u(rng)}, 3 * u(rng));
    c.b = body(mass(rng), inertia(rng), {3 * u(rng), 3 * u(rng)}, {2 * u(rng), 2 * u(rng)}, 3 * u(rng));
    c.r = 0.5 * (c.a.x + c.b.x) + sim::core::Vec2(0.5 * u(rng), 0.5 * u(rng));
    const double angle = 3.14159265358979 * u(rng);
    c.n = {std::cos(angle), std::sin(angle)};
    double vn = normalVelocity(c.a, c.b, c.r, c.n);
    if (vn > 0.0) c.n = -c.n, vn = -vn;
    if (vn < -0.2) return c;
  }
}

}  // namespace

TEST_CASE("body–obstacle: a static body (m⁻¹ = I⁻¹ = 0) gives m_eff = (m⁻¹ + (r′ × n̂)²/I)⁻¹") {
  // m = 2, I = 0.5 at x = (0, 1), v = (1, −2), ω = 0.5; contact at r = (0.3, 0) on the floor, n̂ = (0, 1)
  //   r′ = (0.3, −1), v + ω × r′ = (1 + 0.5·1, −2 + 0.5·0.3) = (1.5, −1.85): v_n⁻ = −1.85
  //   r′ × n̂ = 0.3, m_eff⁻¹ = 1/2 + 0.3²/0.5 = 0.68
  //   c_r = 0.5: γ = 1.5 · 1.85 / 0.68 = 555/136
  sim::core::Body ball = body(2.0, 0.5, {0, 1}, {1, -2}, 0.5);
  sim::core::Body floor = obstacle();
  const sim::core::Vec2 r(0.3, 0.0), n(0.0, 1.0);
  CHECK(sim::collision::inverseEffectiveMass(ball, floor, r, n) == doctest::Approx(0.68).epsilon(1e-15));
  CHECK(normalVelocity(ball, floor, r, n) == doctest::Approx(-1.85).epsilon(1e-15));

  const sim::collision::ImpulseResult j = sim::collision::resolveImpact(ball, floor, r, n, 0.5, 0.0);
  CHECK(j.gamma == doctest::Approx(555.0 / 136.0).epsilon(1e-15));
  CHECK(j.tangent == 0.0);
  // Δv = γ n̂ / m, Δω = (r′ × n̂) γ / I
  CHECK(ball.v.x() == 1.0);
  CHECK(ball.v.y() == doctest::Approx(11.0 / 272.0).epsilon(1e-14));
  CHECK(ball.omega == doctest::Approx(401.0 / 136.0).epsilon(1e-15));
  // v_n⁺ = −c_r v_n⁻ = 0.925
  CHECK(normalVelocity(ball, floor, r, n) == doctest::Approx(0.925).epsilon(1e-14));
  // the obstacle takes −j and does not move
  CHECK(floor.v == sim::core::Vec2::Zero());
  CHECK(floor.omega == 0.0);
}

TEST_CASE("body–body off-center: γ = −(1 + c_r) v_n⁻ / (m_a⁻¹ + m_b⁻¹ + (r_a × n̂)²/I_a + (r_b × n̂)²/I_b)") {
  // A: m = 2, I = 0.3 at (0, 0), v = (1, 0.2), ω = 0.4; B: m = 3, I = 0.7 at (1.2, 0.3), v = (−0.5, 0),
  // ω = −0.2; contact at r = (0.6, 0.25), n̂ = (−1, 0) from B to A, c_r = 0.5. By hand:
  //   r_a = (0.6, 0.25), r_b = (−0.6, −0.05)
  //   v_a + ω_a × r_a = (1 − 0.4·0.25, 0.2 + 0.4·0.6) = (0.9, 0.44)
  //   v_b + ω_b × r_b = (−0.5 − 0.2·0.05, −0.2·(−0.6)) = (−0.51, 0.12)
  //   v_n⁻ = n̂·((0.9, 0.44) − (−0.51, 0.12)) = −1.41
  //   r_a × n̂ = 0.6·0 − 0.25·(−1) = 0.25, r_b × n̂ = −0.6·0 − (−0.05)(−1) = −0.05
  //   m_eff⁻¹ = 1/2 + 1/3 + 0.0625/0.3 + 0.0025/0.7 = 439/420
  //   γ = 1.5 · 1.41 · 420/439 = 8883/4390
  sim::core::Body a = body(2.0, 0.3, {0, 0}, {1, 0.2}, 0.4);
  sim::core::Body b = body(3.0, 0.7, {1.2, 0.3}, {-0.5, 0}, -0.2);
  const sim::core::Vec2 r(0.6, 0.25), n(-1.0, 0.0);
  CHECK(normalVelocity(a, b, r, n) == doctest::Approx(-1.41).epsilon(1e-15));
  CHECK(sim::collision::inverseEffectiveMass(a, b, r, n) == doctest::Approx(439.0 / 420.0).epsilon(1e-15));
  const sim::collision::ImpulseResult j = sim::collision::resolveImpact(a, b, r, n, 0.5, 0.0);
  const double gamma = 8883.0 / 4390.0;
  CHECK(j.gamma == doctest::Approx(gamma).epsilon(1e-14));
  // j = γ n̂ to A, −j to B
  CHECK(a.v.x() == doctest::Approx(1.0 - gamma / 2.0).epsilon(1e-14));
  CHECK(a.v.y() == 0.2);
  CHECK(a.omega == doctest::Approx(0.4 + 0.25 * gamma / 0.3).epsilon(1e-14));
  CHECK(b.v.x() == doctest::Approx(-0.5 + gamma / 3.0).epsilon(1e-14));
  CHECK(b.v.y() == 0.0);
  CHECK(b.omega == doctest::Approx(-0.2 + 0.05 * gamma / 0.7).epsilon(1e-14));
  CHECK(normalVelocity(a, b, r, n) == doctest::Approx(0.705).epsilon(1e-14));
}

TEST_CASE("a separating contact gets no impulse") {
  sim::core::Body a = body(1.0, 1.0, {0, 1}, {0, 1}, 0.0);
  sim::core::Body floor = obstacle();
  const sim::collision::ImpulseResult j = sim::collision::resolveImpact(a, floor, {0, 0.5}, {0, 1}, 1.0, 0.5);
  CHECK(j.gamma == 0.0);
  CHECK(j.tangent == 0.0);
  CHECK(a.v == sim::core::Vec2(0, 1));
}

TEST_CASE("random impacts: v_n⁺ = −c_r v_n⁻ to 1e-12 relative, for c_r = 0, 0.3, 1") {
  std::mt19937_64 rng(20240601);
  int cases = 0;
  for (double cr : {0.0, 0.3, 1.0})
    for (int k = 0; k < 200; ++k) {
      RandomImpact c = randomImpact(rng);
      const bool withObstacle = k % 4 == 0;
      if (withObstacle) c.b = obstacle();
      double vn = normalVelocity(c.a, c.b, c.r, c.n);
      if (vn >= -0.2) continue;  // the obstacle changed the approach: not a clear impact
      ++cases;
      sim::collision::resolveImpact(c.a, c.b, c.r, c.n, cr, 0.0);
      const double after = normalVelocity(c.a, c.b, c.r, c.n);
      CAPTURE(cr);
      CAPTURE(k);
      CHECK(std::abs(after + cr * vn) <= 1e-12 * std::abs(vn));
    }
  CHECK(cases > 500);
}

TEST_CASE("body–body impulses conserve momentum and angular momentum about the origin, with and without friction") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> restitution(0.0, 1.0), mu(0.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    RandomImpact c = randomImpact(rng);
    const double cr = restitution(rng), friction = k % 2 ? mu(rng) : 0.0;
    const sim::core::Vec2 p0 = momentum(c.a, c.b);
    const double l0 = angularMomentum(c.a, c.b);
    const sim::collision::ImpulseResult j = sim::collision::resolveImpact(c.a, c.b, c.r, c.n, cr, friction);
    REQUIRE(j.gamma > 0.0);
    // the scale the round-off is relative to: the momenta and the impulse's
    const double pScale = c.a.mass * c.a.v.norm() + c.b.mass * c.b.v.norm() + j.gamma + std::abs(j.tangent);
    const double lScale = pScale * (c.a.x.norm() + c.b.x.norm() + c.r.norm()) + c.a.inertia * std::abs(c.a.omega) +
                          c.b.inertia * std::abs(c.b.omega);
    CAPTURE(k);
    CHECK((momentum(c.a, c.b) - p0).norm() <= 1e-12 * pScale);
    CHECK(std::abs(angularMomentum(c.a, c.b) - l0) <= 1e-12 * lScale);
  }
}

TEST_CASE("c_r = 1 without friction keeps the kinetic energy; c_r < 1 or friction only takes it away") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> restitution(0.0, 1.0), mu(0.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    RandomImpact c = randomImpact(rng);
    if (k % 3 == 0) c.b = obstacle();
    if (normalVelocity(c.a, c.b, c.r, c.n) >= 0.0) continue;
    const double e0 = kinetic(c.a) + (c.b.isStatic ? 0.0 : kinetic(c.b));
    CAPTURE(k);
    if (k % 2 == 0) {
      sim::collision::resolveImpact(c.a, c.b, c.r, c.n, 1.0, 0.0);
      const double e1 = kinetic(c.a) + (c.b.isStatic ? 0.0 : kinetic(c.b));
      CHECK(std::abs(e1 - e0) <= 1e-12 * e0);
    } else {
      // ΔE = −(1 − c_r²) (v_n⁻)² m_eff / 2 from the normal impulse; a tangential impulse
      // λ (−v_t/k_t), λ ∈ [0, 1], changes it by −(λ − λ²/2) v_t²/k_t ≤ 0
      sim::collision::resolveImpact(c.a, c.b, c.r, c.n, restitution(rng), mu(rng));
      const double e1 = kinetic(c.a) + (c.b.isStatic ? 0.0 : kinetic(c.b));
      CHECK(e1 <= e0 * (1.0 + 1e-12));
    }
  }
}

TEST_CASE("friction stays in Coulomb's cone |j_t| ≤ μγ and stops the sliding when the cone allows") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> restitution(0.0, 1.0), mu(0.05, 1.5);
  int inside = 0, onCone = 0;
  for (int k = 0; k < 1000; ++k) {
    RandomImpact c = randomImpact(rng);
    if (k % 2 == 0) c.b = obstacle();
    if (normalVelocity(c.a, c.b, c.r, c.n) >= 0.0) continue;
    const double cr = restitution(rng), friction = mu(rng);
    const sim::core::Vec2 t(-c.n.y(), c.n.x());
    // what the normal impulse alone leaves: the sliding that friction then acts on
    sim::core::Body a0 = c.a, b0 = c.b;
    const double gamma = sim::collision::resolveImpact(a0, b0, c.r, c.n, cr, 0.0).gamma;
    const double vt = t.dot(sim::collision::relativeVelocity(a0, b0, c.r));
    const double stopping = -vt / sim::collision::inverseEffectiveMass(a0, b0, c.r, t);

    const sim::collision::ImpulseResult j = sim::collision::resolveImpact(c.a, c.b, c.r, c.n, cr, friction);
    const double vtAfter = t.dot(sim::collision::relativeVelocity(c.a, c.b, c.r));
    CAPTURE(k);
    CHECK(j.gamma == gamma);
    CHECK(std::abs(j.tangent) <= friction * j.gamma * (1.0 + 1e-15));
    if (std::abs(stopping) < friction * gamma) {
      // inside the cone: sticking, the tangential relative velocity is gone
      ++inside;
      CHECK(std::abs(vtAfter) <= 1e-12 * (std::abs(vt) + 1.0));
      CHECK(j.tangent == doctest::Approx(stopping).epsilon(1e-12));
    } else {
      // on the cone: the full μγ against the sliding, which slows but keeps its direction
      ++onCone;
      CHECK(std::abs(j.tangent) == doctest::Approx(friction * gamma).epsilon(1e-15));
      CHECK(j.tangent * vt <= 0.0);
      CHECK(vtAfter * vt >= 0.0);
      CHECK(std::abs(vtAfter) <= std::abs(vt));
    }
  }
  // both regimes were exercised
  CHECK(inside > 50);
  CHECK(onCone > 50);
}

TEST_CASE("two points solved together: the block impulses give both points the normal velocity change asked for") {
  // random bodies and two points on a shared normal: K γ = d, applied as two impulses, changes
  // the normal velocity of each point by exactly d_i (both points feel both impulses)
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    RandomImpact c = randomImpact(rng);
    const sim::core::Vec2 t(-c.n.y(), c.n.x());
    const sim::core::Vec2 r1 = c.r + 0.4 * t, r2 = c.r - (0.1 + 0.3 * (u(rng) + 1.0)) * t;
    const double k11 = sim::collision::inverseEffectiveMass(c.a, c.b, r1, c.n);
    const double k22 = sim::collision::inverseEffectiveMass(c.a, c.b, r2, c.n);
    const sim::collision::NormalBlock K = sim::collision::normalBlock(c.a, c.b, r1, r2, c.n, k11, k22);
    // K is symmetric positive definite for two distinct points: det > 0
    CHECK(K.det > 0.0);
    const double v1 = normalVelocity(c.a, c.b, r1, c.n), v2 = normalVelocity(c.a, c.b, r2, c.n);
    const double d1 = 2.0 * u(rng), d2 = 2.0 * u(rng);
    const sim::core::Vec2 gamma = K.solve(d1, d2);
    sim::collision::applyImpulsePair(c.a, c.b, r1, gamma.x() * c.n);
    sim::collision::applyImpulsePair(c.a, c.b, r2, gamma.y() * c.n);
    CAPTURE(k);
    CHECK(normalVelocity(c.a, c.b, r1, c.n) - v1 == doctest::Approx(d1).epsilon(1e-9).scale(1.0));
    CHECK(normalVelocity(c.a, c.b, r2, c.n) - v2 == doctest::Approx(d2).epsilon(1e-9).scale(1.0));
  }
}

TEST_CASE("two points solved together: a box landing flat on a floor bounces without turning") {
  // a 1 × 1 box (m = 1, I = 1/6) falling flat at 2 m/s onto a static floor, contact at its two
  // bottom corners: the block gives equal impulses, c_r = 0.5 makes both corners leave at 1 m/s
  sim::core::Body box = body(1.0, 1.0 / 6.0, {0.0, 0.5}, {0.0, -2.0}, 0.0);
  sim::core::Body floor = obstacle();
  const sim::core::Vec2 n(0.0, 1.0), r1(-0.5, 0.0), r2(0.5, 0.0);
  const sim::collision::NormalBlock K =
      sim::collision::normalBlock(box, floor, r1, r2, n, sim::collision::inverseEffectiveMass(box, floor, r1, n),
                                  sim::collision::inverseEffectiveMass(box, floor, r2, n));
  // K = [[1 + 0.25·6, 1 − 0.25·6], [1 − 0.25·6, 1 + 0.25·6]] = [[2.5, −0.5], [−0.5, 2.5]]
  CHECK(K.k11 == 2.5);
  CHECK(K.k12 == -0.5);
  CHECK(K.k22 == 2.5);
  const sim::core::Vec2 gamma = K.solve(3.0, 3.0);  // −(1 + c_r) v_n⁻ at each corner
  CHECK(gamma.x() == doctest::Approx(1.5));
  CHECK(gamma.y() == doctest::Approx(1.5));
  sim::collision::applyImpulsePair(box, floor, r1, gamma.x() * n);
  sim::collision::applyImpulsePair(box, floor, r2, gamma.y() * n);
  CHECK(box.v.y() == doctest::Approx(1.0));
  CHECK(box.omega == doctest::Approx(0.0).scale(1.0));
}
