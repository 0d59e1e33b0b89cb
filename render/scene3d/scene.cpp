#include "render/scene3d/scene.h"

#include <sstream>

#include "render/scene/render_yaml.h"
#include "render/scene/output_name_rules.h"
#include "render/scene/scene_style.h"
#include "sim/yaml3d/reader3d.h"

namespace render::scene3d {
using sim::world3d::Vec3;
using sim::yaml::Reader;
using sim::yaml3d::Reader3d;

namespace {

// what 3D frames show instead of the 2D block's keys
const char* const kOnly2d =
    "' draws 2D scenes only; a 3D scene's render: has camera, arrows (axes, omega, angular_momentum, velocity, path, "
    "omega_path, state), trails, springs, energy, momentum and world_axes";

void camera(const YAML::Node& n, const Reader3d& r, Camera3dDef& out) {
  if (n.IsScalar()) {
    if (n.Scalar() != "auto")
      r.fail(n,
             "'camera' is 'auto', {direction: [x, y, z], margin: m, fov: f, up: [x, y, z]} or {eye: [x, y, z], "
             "target: [x, y, z], up: [x, y, z], fov: f}, got '" +
                 n.Scalar() + "'");
    return;
  }
  r.checkKeys(n, {"eye", "target", "up", "fov", "direction", "margin"}, "camera");
  if (n["eye"] || n["target"]) {
    if (!n["eye"] || !n["target"]) r.fail(n, "a fixed camera needs both 'eye' and 'target'");
    for (const char* key : {"direction", "margin"})
      if (n[key])
        r.fail(n[key], std::string("'") + key + "' is for the automatic camera; a fixed one looks from 'eye' at 'target'");
    out.automatic = false;
    out.eye = r.vec3(n["eye"], "eye");
    out.target = r.vec3(n["target"], "target");
    if ((out.eye - out.target).norm() == 0.0) r.fail(n["target"], "the camera's 'target' must differ from its 'eye'");
  }
  if (n["direction"]) {
    out.direction = r.vec3(n["direction"], "direction");
    if (out.direction.norm() == 0.0)
      r.fail(n["direction"], "'direction' must be a non-zero vector, from the scene toward the eye");
  }
  if (n["margin"]) {
    out.margin = r.nonNegative(n["margin"], "margin");
    if (out.margin >= 0.5) r.fail(n["margin"], "'margin' is a fraction of the view on each side, below 0.5");
  }
  if (n["up"]) {
    out.up = r.vec3(n["up"], "up");
    if (out.up.norm() == 0.0) r.fail(n["up"], "'up' must be a non-zero vector");
  }
  if (n["fov"]) {
    out.fov = r.positive(n["fov"], "fov");
    if (out.fov >= 170.0) r.fail(n["fov"], "'fov' is the vertical field of view in degrees, below 170");
  }
  const Vec3 view = out.automatic ? out.direction : Vec3(out.eye - out.target);
  if (view.normalized().cross(out.up.normalized()).norm() < 1e-6)
    r.fail(n, "the camera looks along 'up'; give an 'up' that is not along the view");
}

Arrow3dDef arrow(const YAML::Node& n, const Reader3d& r, const sim::scene3d::SceneDef& scene) {
  r.checkKeys(n, {"body", "show", "at", "label", "value", "color"}, "an arrow");
  Arrow3dDef a;
  a.body = scene.bodyIndex(r.bodyRef(n, "body", scene, "an arrow"));
  a.show = r.named(
      r.required(n, "show", "an arrow"), "show", [](const std::string& s) { return kShow3dNames.parse(s); }, kShow3dNames.list());
  r.optional(n, "at", a.at, &Reader3d::vec3);
  r.optional(n, "label", a.label, &Reader::text);
  r.optional(n, "value", a.value, &Reader::boolean);
  if (n["color"]) a.color = render::scene::readColor(n["color"], r, "color");
  return a;
}

void readBlock(const YAML::Node& node, const Reader3d& r, const sim::scene3d::SceneDef& model, Scene& out) {
  for (const char* key : {"contacts", "contact_hold", "impulses", "impulse_scale", "velocities", "sat", "sat_axes", "strobe",
                          "force_scale", "momentum_scale", "impact_values"})
    if (node[key]) r.fail(node[key], std::string("'") + key + kOnly2d);
  r.checkKeys(node,
              {"size",
               "fps",
               "background",
               "line_width",
               "font_size",
               "colors",
               "camera",
               "trails",
               "springs",
               "labels",
               "time",
               "panels",
               "title",
               "title_card",
               "caption",
               "slow_motion",
               "answer_card",
               "reveal",
               "arrows",
               "energy",
               "momentum",
               "omega_scale",
               "angular_momentum_scale",
               "velocity_scale",
               "world_axes"},
              "render");
  render::scene::RenderDef& shared = out.render;
  render::scene::readFrame(node, r, shared);
  render::scene::readTiming(node, r, shared);
  r.optional(node, "trails", shared.trails, &Reader::boolean);
  r.optional(node, "springs", shared.springs, &Reader::boolean);
  r.optional(node, "labels", shared.labels, &Reader::boolean);
  r.optional(node, "time", shared.time, &Reader::boolean);
  r.optional(node, "energy", shared.overlays.energy, &Reader::boolean);
  r.optional(node, "momentum", shared.overlays.momentum, &Reader::boolean);
  Render3dDef& space = out.space;
  if (node["camera"]) camera(node["camera"], r, space.camera);
  if (const YAML::Node arrows = node["arrows"]) {
    if (!arrows.IsSequence()) r.fail(arrows, "'arrows' must be a list of {body, show}, got " + sim::yaml::describe(arrows));
    for (const YAML::Node& a : arrows) space.arrows.push_back(arrow(a, r, model));
  }
  r.optional(node, "omega_scale", space.omegaScale, &Reader::positive);
  r.optional(node, "angular_momentum_scale", space.angularMomentumScale, &Reader::positive);
  r.optional(node, "velocity_scale", space.velocityScale, &Reader::positive);
  r.optional(node, "world_axes", space.worldAxes, &Reader::boolean);
}

}  // namespace

Scene readScene(const sim::yaml::SceneSource& source, const sim::yaml::OtherKeys& others) {
  // the model reads its keys and leaves ours alone
  sim::yaml::OtherKeys keys = others;
  keys.scene.emplace_back(render::scene::kRenderKey);
  keys.scene.insert(keys.scene.end(), render::scene::kPollKeys.begin(), render::scene::kPollKeys.end());
  keys.body.insert(keys.body.end(), render::scene::kBodyKeys.begin(), render::scene::kBodyKeys.end());
  Scene s;
  s.model = sim::yaml3d::readModel(source, keys);
  sim::yaml::readGuarded(source.file, [&] {
    Reader3d r(source.file);
    r.placeUnmarked(source.variantMark);
    render::scene::checkOutputNames(source, s.model.name, r);
    // the looks of the bodies that move: a plane's entry is an obstacle, apart from them
    YAML::Node moving(YAML::NodeType::Sequence);
    for (const YAML::Node& b : source.root["bodies"])
      if (!(b.IsMap() && b["shape"] && b["shape"].IsMap() && b["shape"]["plane"])) moving.push_back(b);
    s.render.bodies = render::scene::readLooks(moving, r);
    const YAML::Node block = source.root[render::scene::kRenderKey];
    if (block) readBlock(block, r, s.model, s);
    render::scene::readPanels(block ? block["panels"] : block, r, s.model.duration, s.model.variantNames.size(), s.render.panels);
    render::scene::readPoll(source.root, block, r, source.file, s.model.duration, s.render.poll);
  });
  return s;
}

draw::Style makeStyle(const Scene& scene, int frameHeight) {
  std::vector<std::string> arrowColors;
  for (const Arrow3dDef& a : scene.space.arrows) arrowColors.push_back(a.color);
  return render::scene::makeStyle(scene.render, std::vector<bool>(scene.model.bodies.size(), false), arrowColors, frameHeight);
}

}  // namespace render::scene3d
