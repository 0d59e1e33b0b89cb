// How to draw a scene: the `render:` block and each body's `color` and `label`, as plain
// definitions (documented in scenes/README.md). The simulator never sees them; colors are
// "#rrggbb" strings.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/draw/roles.h"
#include "sim/core/enum_names.h"
#include "sim/core/force_defs.h"
#include "sim/core/math.h"

namespace render::scene {

// frame sides are even (H.264 in yuv420p halves the chroma planes) and at most this many pixels:
// a 8192 × 8192 RGBA frame is 256 MiB, and supersampled several times that
inline constexpr int kMaxFrameSide = 8192;
inline constexpr int kMinFrameSide = 16;
// frames per second, at most: beyond this a lecture video gains nothing
inline constexpr double kMaxFps = 1000.0;
// text size, pixels: whole pixels from 1 (FreeType draws nothing at 0) to a line an eighth of the
// largest frame high
inline constexpr double kMinFontSize = 1.0;
inline constexpr double kMaxFontSize = 1000.0;
// a title card, s, at most: a lecture's card is read in a few seconds, and a longer one is a typo
// (a card of 1e300 s overflowed the frame count)
inline constexpr double kMaxTitleCard = 60.0;
// frames of one video, at most: 10⁷ frames are 46 hours at 60 fps, and 3 hours at the largest
// frame rate; a video past this is a duration or slow motion typed wrong (a count past a long's
// range is undefined behavior)
inline constexpr double kMaxFrames = 1e7;

// the survey's run kept for the drawing (render/frame/kept_run.h), bytes, at most per render (shared
// by the variants it surveys): past it the drawing steps the rest of the run again, as it did before
// states were kept. A lecture scene's states are tens of kB; a 5,050-box pile's 12 MB each (30 of
// them took a 0.5 s render from 234 to 611 MB)
inline constexpr size_t kKeptRunBytes = size_t{64} << 20;
// a video's frames whose instants are offered to its survey to keep, at most: more states than
// kKeptRunBytes holds of the smallest scene's (a few kB each)
inline constexpr long kKeptMostInstants = 100000;
// the steps a kept state must save, at least, over the one kept before it: a state of a pile that
// steps once a frame costs more to copy and hold than the step it saves
inline constexpr long kKeptMinSteps = 4;
// and the kept history's paths (trails and body points keep every step's point until the camera is
// known), bytes: 10 bodies over 25,000 steps. Past it nothing more is kept: memory that grew with the
// steps would undo trails kept at the frame's spacing (10 bodies over 10⁷ steps: 1.6 GB)
inline constexpr size_t kKeptPathBytes = size_t{4} << 20;

// the largest view, m, a side and away from the origin: squared lengths of what it shows stay finite
// in double (a view past it is a bad scene: hatching, pixels and GL's clipping all need them)
inline constexpr double kMaxViewExtent = 1e150;

// what the view shows: everything the run covers (auto), or a fixed window
struct CameraDef {
  bool automatic = true;
  double margin = 0.08;                              // auto: free space on each side, as a fraction of the fitted size
  sim::core::Vec2 center = sim::core::Vec2::Zero();  // fixed: world point at the middle of the frame, m
  double height = 0.0;                               // fixed: world height the frame shows, m
  sim::core::SourceLoc loc;                          // where `camera:` is written; 0 when it is the default
};

// colors of what is not a body's own (the roles' keys, render/draw/roles.h); bodies without
// `color` take the palette in order
struct ColorsDef {
  std::vector<std::string> palette = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                      "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
  // by role, its table default unless the scene gives its key ("" for roles in their body's color)
  std::array<std::string, draw::kRoleCount> roles = defaults();

  const std::string& operator[](draw::Role role) const { return roles[static_cast<size_t>(role)]; }

 private:
  static std::array<std::string, draw::kRoleCount> defaults() {
    std::array<std::string, draw::kRoleCount> out;
    for (const draw::RoleInfo& r : draw::kRoles) out[static_cast<size_t>(r.role)] = r.color;
    return out;
  }
};

// a body's look: its own color ("#rrggbb"; empty for the palette's) and its label
struct BodyLook {
  std::string color;
  std::string label;
  bool named = false;  // the label is the scene's own `label:`, not the body's name
};

// a teaching vector drawn every frame: one entry of `arrows:`
struct ArrowDef {
  enum class Show { Velocity, Offset, Omega, Frame, Path, Force, Torque, Momentum, NormalForce, Friction, Center };
  Show show = Show::Velocity;
  int body = 0;                                  // index into SceneDef::bodies, resolved when read
  sim::core::Vec2 at = sim::core::Vec2::Zero();  // body coordinates as written (before the centroid shift)
  std::string label;                             // empty: the default of `show` ("v", "r′", "ω", …)
  bool value = false;                            // the magnitude with its unit after the label
  std::string color;                             // "#rrggbb"; empty: the color of `show`'s role
};

// the `show:` names
inline constexpr sim::core::EnumNames<ArrowDef::Show, 11> kShowNames{{{
    {ArrowDef::Show::Velocity, "velocity"},
    {ArrowDef::Show::Offset, "offset"},
    {ArrowDef::Show::Omega, "omega"},
    {ArrowDef::Show::Frame, "frame"},
    {ArrowDef::Show::Path, "path"},
    {ArrowDef::Show::Force, "force"},
    {ArrowDef::Show::Torque, "torque"},
    {ArrowDef::Show::Momentum, "momentum"},
    {ArrowDef::Show::NormalForce, "normal_force"},
    {ArrowDef::Show::Friction, "friction"},
    {ArrowDef::Show::Center, "center"},
}}};

// the lecture overlays of a frame (scenes/README.md, render:), all off by default
struct OverlaysDef {
  std::vector<ArrowDef> arrows;
  double forceScale = 0.0;     // m per N; 0: the largest point force of the run is 1/6 of the view
  double momentumScale = 0.0;  // m per kg·m/s; 0: the largest momentum of the run is 1/6 of the view
  bool impactValues = false;   // impact afterimages labeled n̂, j and v_n⁻ → v_n⁺
  bool energy = false;         // the energy bars panel, top right
  bool momentum = false;       // p and L as text in that panel
  bool satAxes = false;        // every candidate axis of the SAT overlay labeled with its separation
};

// a stretch of the video that runs `factor` times slower: `window` s around each impact of the run
// (when window > 0), else simulation times [from, to]
struct SlowMotionDef {
  double factor = 1.0;
  double window = 0.0;          // s
  double from = 0.0, to = 0.0;  // s
};

// the poll panels `rigidreel lecture` writes (every variant side by side): at these times, or at
// each impact; none when `times` is empty and `impacts` false. The scene reader fills the default
// (the duration, for a scene with two or more variants) and checks the times against the duration.
struct PanelsDef {
  std::vector<double> times;  // s
  bool impacts = false;
  int line = 0, column = 0;  // where `panels:` is written (1-based); 0 when it is the default
};

// another simulator's trajectory drawn over the run (`render`/`snapshot --overlay`): its name in the
// legend, and each body's pose at a time (false where it has none), read from its trace
struct TraceOverlayDef {
  struct Pose {
    sim::core::Vec2 x = sim::core::Vec2::Zero();
    double angle = 0.0;
  };
  std::string name;
  std::function<bool(size_t body, double t, Pose& pose)> poseAt;
};

// a poll's question apart from its answer (scenes/README.md): the title card shows the question, and
// the answer is shown only where the scene asks (a closing card, panels labelled from `reveal` on)
struct PollDef {
  std::string question;     // top-level (or a variant's) `question:`; empty: the card shows the description
  std::string answer;       // `answer:`; never drawn but on the answer card, never on the page but folded
  std::string title;        // a variant's `title:`: its panel's title on a poll sheet ("A: at the center")
  double answerCard = 0.0;  // s of a closing card with the answer (`render: {answer_card}`); 0: none
  double reveal = -1.0;     // s from which a panel is labelled "answer" (`render: {reveal}`); < 0: never
  // where the card's text is written (the question, else the description), for a card that cannot fit
  std::string file;
  int line = 0, column = 0;
  int answerLine = 0, answerColumn = 0;  // where `answer:` is written
  bool revealed(double t) const { return reveal >= 0.0 && t >= reveal; }
  // does a picture at time t tell the answer? In a poll (a scene with a question) everything after
  // t = 0 does, unless `reveal` marks it a question time (before it); elsewhere only from `reveal` on
  bool tellsAnswer(double t) const { return question.empty() || reveal >= 0.0 ? revealed(t) : t > 0.0; }
};

struct RenderDef {
  std::vector<BodyLook> bodies;  // by body index of the model
  int width = 1280;              // pixels
  int height = 720;
  double fps = 60.0;  // frames per second of a video
  std::string background = "#ffffff";
  double lineWidth = 0.0;  // pixels, of outlines, arrows and segments; 0: lineWidthFor's default
  double fontSize = 0.0;   // pixels; 0: the frame height / 36, at least 11
  ColorsDef colors;
  CameraDef camera;
  bool contacts = true;  // contact points, normals and impact impulses
  // `contacts: auto` (the default): a frame with many contacts on screen shows their dots alone,
  // without normals (render/frame/frame_painter.cpp); `contacts: true` always draws both
  bool contactsAuto = true;
  double contactHold = 0.5;    // s a contact stays on screen after an impact, fading
  bool impulses = true;        // arrows where events apply their impulses (held as contacts)
  double impulseScale = 0.0;   // m per N·s; 0: the largest event impulse is 1/6 of the view
  bool velocities = false;     // velocity arrows at the centers of mass
  double velocityScale = 0.0;  // m per m/s (s); 0: the fastest body's arrow is 1/6 of the view
  bool trails = false;         // the path of every center of mass so far
  bool centers = false;        // every moving body's center of mass marked with the quartered disc
  bool sat = false;            // the separating-axis overlay: reference edge, incident vertex
  int strobe = 0;              // snapshots and the poster: this many ghosted earlier poses
  bool springs = true;         // springs as zigzags, world anchors as dots
  bool labels = true;          // body labels
  // `labels: auto` (the default): only labels that fit inside their body, or all of a scene of at
  // most 20 bodies, and leader lines only for the scene's own `label:`s; `labels: true`: all, always
  bool labelsAuto = true;
  bool time = true;  // the time in a corner
  bool key = true;   // a key to the overlays not labelled where they are drawn (overlay_key.h)
  // video timing and text (section B of the lecture pack): the opening card, the caption, slow motion
  std::string title;                    // the title card's; empty: the scene's name with '_' as spaces
  double titleCard = 0.0;               // s the video opens with a title card; 0: none
  bool captionFromDescription = false;  // `caption: true`: the description's first sentence
  std::string caption;                  // `caption: "text"`; empty (and not from the description): none
  std::vector<SlowMotionDef> slowMotion;
  OverlaysDef overlays;                            // the lecture overlays
  PanelsDef panels;                                // `rigidreel lecture`'s poll panels
  std::shared_ptr<const TraceOverlayDef> overlay;  // set from the command line, never by the file
  PollDef poll;                                    // question, answer, answer card, reveal
};

}  // namespace render::scene
