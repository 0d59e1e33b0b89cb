// Every drawing role of a frame in one table: what it is, its name in draw lists, its key in the
// scene's `render: {colors: ...}`, its default color and its stroke width. The canvas, the draw
// list, the style and the YAML reader all read this table, so a new overlay is one row here.
// The simulator's roles (sim::debug_draw::DrawRole) are rows of it too, under the same names.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "sim/debug_draw/debug_draw.h"

namespace render::draw {

enum class Role {
  // the physics the simulator describes (sim::debug_draw::DrawRole)
  Body,            // a dynamic body's shape: filled and outlined
  StaticBody,      // a static body or a half-plane obstacle: drawn visibly different
  BodyAxis,        // a radius marking a body's rotation (circles)
  ContactPoint,    // a contact point: a dot
  ContactNormal,   // a contact normal: an arrow from the point
  Impulse,         // an impulse applied by an event or an impact: an arrow
  Spring,          // a spring's coils, as segments; a world anchor as a dot
  ReferenceEdge,   // the separating-axis reference edge
  IncidentVertex,  // the separating-axis incident vertex
  Label,           // text, centered on its point
  // the renderer's
  Velocity,         // a body's velocity: an arrow
  Trail,            // the path of a center of mass
  Caption,          // text fixed to the frame (the time, the caption): its point is the top-left corner
  Offset,           // r′ = R r_b, from the center of mass to a body point
  AngularVelocity,  // ω as a curved arrow around the center of mass
  BodyFrame,        // the body's axes R x̂, R ŷ
  Path,             // the path of a body point
  Force,            // a point force at its point
  Torque,           // τ as a curved arrow around the center of mass
  Momentum,         // m v from the center of mass
  KineticBar,       // an energy bar of ½ m v², filled
  RotationalBar,    // an energy bar of ½ I ω², filled
  PotentialBar,     // the potential energy's bar, filled
  TotalBar,         // the total energy's bar, filled
  Panel,            // the background of a panel fixed to the frame, filled
  // the 3D frames' (render/draw3d)
  AxisX,            // a body's or the world's x axis: an arrow
  AxisY,            // y
  AxisZ,            // z
  AngularMomentum,  // L = I ω from the center of mass: an arrow
  // another simulator's trajectory over ours (--overlay)
  Overlay,  // its bodies' outlines, dashed
  // a text's backing where it stands over hatching or a body: the background, nearly opaque, filled
  Backing,
  // a contact's forces on a body (arrows: show: normal_force, friction)
  NormalForce,  // N n̂ at the pair's contact: an arrow
  Friction,     // the friction force along the surface: an arrow
  // a body made of parts (sim::debug_draw::DrawRole): its parts filled, its outline in pieces
  BodyPart,
  BodyEdge,
  // a body's center of mass: the quartered disc (render: {centers: true})
  CenterOfMass,
};
inline constexpr size_t kRoleCount = static_cast<size_t>(Role::CenterOfMass) + 1;

struct RoleInfo {
  Role role;
  std::string_view name;      // in draw lists, e.g. "ContactPoint"
  std::string_view colorKey;  // the key under render.colors; "" when drawn in its body's color
  std::string_view color;     // the default "#rrggbb" of colorKey
  double width;               // stroke width, in line widths
  bool area;                  // a filled area without an outline (bars, panels)
};

// one row per role, in the order of Role
inline constexpr std::array<RoleInfo, kRoleCount> kRoles{{
    {Role::Body, "Body", "", "", 1.0, false},
    {Role::StaticBody, "StaticBody", "static", "#8c8c8c", 1.0, false},
    {Role::BodyAxis, "BodyAxis", "", "", 1.0, false},
    // the overlays in Okabe and Ito's colour-blind-safe palette (jfly.uni-koeln.de/color): normals
    // vermilion, impulses blue, velocities bluish green, forces orange, told apart by every viewer
    {Role::ContactPoint, "ContactPoint", "contact", "#d55e00", 1.0, false},
    {Role::ContactNormal, "ContactNormal", "normal", "#d55e00", 1.0, false},
    {Role::Impulse, "Impulse", "impulse", "#0072b2", 1.5, false},
    {Role::Spring, "Spring", "spring", "#4d4d4d", 1.0, false},
    {Role::ReferenceEdge, "ReferenceEdge", "reference_edge", "#ff7f0e", 3.0, false},
    {Role::IncidentVertex, "IncidentVertex", "incident_vertex", "#9467bd", 1.0, false},
    {Role::Label, "Label", "text", "#1f1f1f", 1.0, false},
    {Role::Velocity, "Velocity", "velocity", "#009e73", 1.0, false},
    // a trail is its body's color; the key's is for a trail of no body
    {Role::Trail, "Trail", "trail", "#9a9a9a", 0.75, false},
    {Role::Caption, "Caption", "text", "#1f1f1f", 1.0, false},
    {Role::Offset, "Offset", "offset", "#7f7f7f", 1.0, false},
    {Role::AngularVelocity, "AngularVelocity", "omega", "#17becf", 1.0, false},
    {Role::BodyFrame, "BodyFrame", "frame", "#8c564b", 1.0, false},
    {Role::Path, "Path", "path", "#e377c2", 0.75, false},
    {Role::Force, "Force", "force", "#e69f00", 1.5, false},
    {Role::Torque, "Torque", "torque", "#a55194", 1.0, false},
    {Role::Momentum, "Momentum", "momentum", "#3182bd", 1.0, false},
    {Role::KineticBar, "KineticBar", "", "", 1.0, true},
    {Role::RotationalBar, "RotationalBar", "", "", 1.0, true},
    {Role::PotentialBar, "PotentialBar", "potential", "#31a354", 1.0, true},
    {Role::TotalBar, "TotalBar", "total", "#636363", 1.0, true},
    {Role::Panel, "Panel", "panel", "#f2f2f2", 1.0, true},
    // the usual red, green and blue of x, y and z
    {Role::AxisX, "AxisX", "axis_x", "#d62728", 1.0, false},
    {Role::AxisY, "AxisY", "axis_y", "#2ca02c", 1.0, false},
    {Role::AxisZ, "AxisZ", "axis_z", "#1f77b4", 1.0, false},
    {Role::AngularMomentum, "AngularMomentum", "angular_momentum", "#6a3d9a", 1.5, false},
    // a magenta that no default role or palette colour is near
    {Role::Overlay, "Overlay", "overlay", "#e7298a", 1.25, false},
    {Role::Backing, "Backing", "backing", "#ffffff", 1.0, true},
    // Okabe and Ito's sky blue and reddish purple, apart from the impulse's blue and the force's orange
    {Role::NormalForce, "NormalForce", "normal_force", "#56b4e9", 1.5, false},
    {Role::Friction, "Friction", "friction", "#cc79a7", 1.5, false},
    {Role::BodyPart, "BodyPart", "", "", 1.0, true},
    {Role::BodyEdge, "BodyEdge", "", "", 1.0, false},
    {Role::CenterOfMass, "CenterOfMass", "center", "#1f1f1f", 1.0, false},
}};

constexpr const RoleInfo& info(Role role) { return kRoles[static_cast<size_t>(role)]; }

// the simulator's role as a row of the table (the same name)
Role fromPhysics(sim::debug_draw::DrawRole role);

// how one call is drawn: its role, the body whose color it takes (-1: none), its opacity (fading
// contacts, strobe ghosts) and, for a teaching arrow, the index of its own color (-1: the role's)
struct Pen {
  Role role = Role::Body;
  int body = -1;
  double opacity = 1.0;
  int color = -1;
};

}  // namespace render::draw
