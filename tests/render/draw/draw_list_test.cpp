// The recording canvas: every call becomes one line of text (the draw-list level of the regression
// tests), replays into another canvas with its opacity scaled, and filters by role.
#include <doctest/doctest.h>

#include "render/draw/draw_list.h"

using render::draw::DrawList;
using render::draw::Role;

TEST_CASE("every kind of call is one line, numbers to 6 significant digits") {
  DrawList d;
  d.polygon({{0, 0}, {1, 0}, {0, 1.0 / 3.0}}, {Role::Body, 0, 1.0});
  d.circle({1, 2}, 0.5, {Role::StaticBody, 1, 1.0});
  d.halfPlane({0, -1}, {0, 1}, {Role::StaticBody, 2, 1.0});
  d.segment({0, 0}, {1e-17, 2}, {Role::BodyAxis, 0, 1.0});
  d.point({3, 4}, {Role::ContactPoint, -1, 1.0});
  d.arrow({0, 0}, {1, 1}, {Role::Impulse, 0, 0.5});
  d.text({0, 0}, "ω", {Role::Label, 0, 1.0});
  CHECK(d.toText() ==
        "polygon Body#0 (0,0) (1,0) (0,0.333333)\n"
        "circle StaticBody#1 (1,2) r=0.5\n"
        "halfplane StaticBody#2 (0,-1) n=(0,1)\n"
        "segment BodyAxis#0 (0,0) (0,2)\n"
        "point ContactPoint (3,4)\n"
        "arrow Impulse#0@0.5 (0,0) -> (1,1)\n"
        "text Label#0 (0,0) \"ω\"\n");
}

TEST_CASE("a replay repeats the calls with their opacity scaled") {
  DrawList a, b;
  a.point({1, 1}, {Role::ContactPoint, -1, 0.5});
  a.arrow({0, 0}, {0, 1}, {Role::ContactNormal, -1, 1.0});
  a.replay(b, 0.5);
  CHECK(b.toText() == "point ContactPoint@0.25 (1,1)\narrow ContactNormal@0.5 (0,0) -> (0,1)\n");
}

TEST_CASE("a faded canvas draws what a replay at that opacity draws, every kind of call") {
  const auto draw = [](render::draw::Canvas& c) {
    c.polygon({{0, 0}, {1, 0}, {0, 1}}, {Role::Body, 0, 1.0});
    c.circle({1, 2}, 0.5, {Role::Body, 1, 0.5});
    c.halfPlane({0, -1}, {0, 1}, {Role::StaticBody, 2, 1.0});
    c.segment({0, 0}, {1, 2}, {Role::Trail, 0, 1.0});
    c.point({3, 4}, {Role::ContactPoint, -1, 1.0});
    c.arrow({0, 0}, {1, 1}, {Role::Impulse, 0, 0.5});
    c.text({0, 0}, "t", {Role::Caption, -1, 1.0});
    c.label({1, 1}, {0, 1}, "j", {Role::Label, -1, 1.0});
  };
  DrawList recorded, replayed, faded;
  draw(recorded);
  recorded.replay(replayed, 0.3);
  render::draw::Faded fade(faded, 0.3);
  draw(fade);
  REQUIRE(replayed.calls().size() == 8);
  CHECK(faded.toText() == replayed.toText());
  for (size_t i = 0; i < 8; ++i) CHECK(faded.calls()[i].style.opacity == replayed.calls()[i].style.opacity);
}

TEST_CASE("a role filter passes only the roles it keeps") {
  DrawList all, kept;
  all.polygon({{0, 0}, {1, 0}, {1, 1}}, {Role::StaticBody, 0, 1.0});
  all.polygon({{0, 0}, {1, 0}, {1, 1}}, {Role::Body, 1, 1.0});
  all.point({0, 0}, {Role::ContactPoint, -1, 1.0});
  render::draw::RoleFilter filter(kept, [](render::draw::Role r) { return r == Role::StaticBody; });
  all.replay(filter);
  REQUIRE(kept.calls().size() == 1);
  CHECK(kept.calls()[0].style.role == Role::StaticBody);
}

TEST_CASE("a copied list, and one cleared and refilled, replays its own calls; a polygon of any size stays a polygon") {
  DrawList a;
  a.polygon({{0, 0}, {1, 0}}, {Role::Body, 0, 1.0});
  a.polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {Role::Body, 1, 1.0});
  a.arrow({0, 0}, {1, 1}, {Role::ContactNormal, -1, 1.0});
  a.point({5, 6}, {Role::ContactPoint, -1, 1.0});
  const DrawList copy = a;
  a.clear();
  a.point({7, 8}, {Role::ContactPoint, -1, 1.0});
  DrawList replayed;
  copy.replay(replayed);
  CHECK(replayed.toText() ==
        "polygon Body#0 (0,0) (1,0)\n"
        "polygon Body#1 (0,0) (2,0) (2,2) (0,2)\n"
        "arrow ContactNormal (0,0) -> (1,1)\n"
        "point ContactPoint (5,6)\n");
  CHECK(a.toText() == "point ContactPoint (7,8)\n");
  CHECK(copy.calls()[2].points.size() == 2);
  CHECK(copy.calls()[2].points.at(1) == sim::core::Vec2(1, 1));
  CHECK_THROWS_AS((void)copy.calls()[3].points.at(1), std::out_of_range);
}
