// What a frame shows besides the present state, gathered while the world steps: where each body has
// been (its trail), and what happened a moment ago and stays on screen a while, fading (an impact's
// contact point, normal and impulses; the arrow of an event's impulse; contacts after they part),
// so that a video shows them for more than the one frame in which they happen. It keeps what
// happened, not how it looks: the arrows' scales come with the frame that draws them (Look), so a
// history gathered before the camera is known draws the same frames as one gathered after.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "render/draw/draw_list.h"
#include "render/frame/impact_labels.h"
#include "sim/describe/describe.h"
#include "sim/world/world.h"

namespace render::frame {

class History : public sim::world::StepObserver {
 public:
  // the contacts of the world now, as marks (empty: none)
  using ContactSource = std::function<void(const sim::world::World&, std::vector<sim::describe::ContactMark>&)>;

  struct Options {
    bool trails = false;
    double hold = 0.5;                                         // s an afterimage stays, fading
    bool eventImpulses = true;                                 // an arrow where each event applies its impulse
    bool impacts = true;                                       // each impact the collision response logs: point, normal, impulses
    ContactSource contacts;                                    // the contacts touching now (empty: none)
    std::vector<std::pair<int, sim::core::Vec2>> points = {};  // body points (body coordinates) whose paths to keep
    // m: a trail keeps a point only this far from the one it kept before (and always the latest),
    // as drawTrails draws them: the same trail, in memory that grows with the path drawn, not with
    // the steps (10 bodies over 10⁷ steps kept every point: 3.7 GB); 0 keeps every step's
    double trailSpacing = 0.0;
  };
  // how a frame draws the afterimages: its scales
  struct Look {
    double impulseScale = 1.0;                          // m of arrow per N·s
    double normalLength = 1.0;                          // m, the arrow of a contact normal
    std::optional<ImpactLabels> labels = std::nullopt;  // impact_values: text on impact and event afterimages
  };

  // starts with the world's present state (its contacts and positions at the start)
  History(const sim::world::World& world, Options options);

  void afterStep(const sim::world::World& world) override;
  void afterEvent(const sim::world::World& world, const sim::world::ImpulseEvent& event) override;

  const Options& options() const { return options_; }
  // the same record as a history with `spacing` between trail points would hold after the same
  // steps: exact from a history that kept every step's point (trailSpacing 0), as the survey's does
  void respace(double spacing);
  // about how much memory it holds, bytes: in all, and in its paths (trails and body points)
  size_t bytes() const;
  size_t pathBytes() const;

  // every dynamic body's path up to now as Trail segments, points closer than `spacing` merged
  void drawTrails(render::draw::Canvas& draw, double spacing) const;
  // the path so far of Options::points[k]
  const std::vector<sim::core::Vec2>& pointPath(size_t k) const { return points_[k]; }
  // a path as segments in `style`, points closer than `spacing` merged (the last one always kept)
  static void drawPath(const std::vector<sim::core::Vec2>& path, double spacing, const render::draw::Pen& style,
                       render::draw::Canvas& draw);
  // what happened at most `hold` before `world`'s time, its opacity falling linearly from 1 to 0 with
  // age, drawn as `look` says (the world names which bodies are static)
  void drawAfterimages(const sim::world::World& world, const Look& look, render::draw::Canvas& draw) const;

 private:
  // what happened, as it happened: drawn only when a frame shows it
  struct Moment {
    enum class Kind { Contact, Impact, Event };
    double time;
    Kind kind;
    std::pair<int, int> pair;                               // the bodies of an impact
    std::vector<sim::describe::ContactMark> contacts = {};  // Kind::Contact: the points touching
    std::vector<sim::world::ImpactRecord> impacts = {};     // Kind::Impact: its records at `time`
    sim::world::ImpulseEvent event = {};                    // Kind::Event: its point in world coordinates
  };
  // a moment as `look` draws it
  static void describe(const sim::world::World& world, const Moment& moment, const Look& look, render::draw::Canvas& draw);
  // drawPath's rule, applied as the points come: the latest point replaces one not kept
  void keepTrailPoint(size_t body, const sim::core::Vec2& x);
  void observeContacts(const sim::world::World& world);
  void observeImpacts(const sim::world::World& world);
  // a new moment, held from now on; its number
  long begin(Moment moment);
  // the moment numbered `id` happened again at `time`
  void retime(long id, double time);
  void forgetOld(double now);

  Options options_;
  std::vector<std::vector<sim::core::Vec2>> trails_;  // by body; empty for static bodies or without trails
  std::vector<bool> tentative_;                       // by body: the trail's last point is the latest, not one kept
  std::vector<std::vector<sim::core::Vec2>> points_;  // by Options::points
  // The moments held, by a number each gets when it begins: the order they are drawn in. A step
  // touches only the moments it adds, changes or forgets (each found by time or by pair), never
  // the others: a vector copied whenever one was forgotten made each step cost every held moment
  // (100,000 events took over a minute to draw where the run took 2 s)
  std::map<long, Moment> moments_;
  std::set<std::pair<double, long>> byTime_;          // (time, number) of each held moment, oldest first
  std::map<std::pair<int, int>, long> impactOfPair_;  // the number of each pair's impact moment
  long next_ = 0;                                     // the number the next moment gets
  std::vector<sim::describe::ContactMark> spare_;     // the touching contacts' previous marks, their storage reused
  long touching_ = -1;                                // the number of the contacts still touching, -1 when none
  size_t impactsSeen_ = 0;                            // records of world.impacts already turned into moments
};

}  // namespace render::frame
