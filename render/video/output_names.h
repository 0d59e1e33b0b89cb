// Where outputs go and what they are called: out/<scene>/<scene>[-<variant>]…, one scheme for the
// videos, posters, frames, snapshots and poll panels of the render plan.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene_def.h"

namespace render::video {

// "<scene>" or "<scene>-<variant>": the start of every output name of a run
std::string outputBase(const sim::scene::SceneDef& def);
// the same from the scene's name and its variant's ("" for the base scene), for 3D scenes too
std::string outputBase(const std::string& scene, const std::string& variant);
// the poll slide's file name: "<scene>-panels<when>[-strobe<N>].png", `when` "-t1.5" or "-impact2"
std::string panelsFileName(const std::string& scene, const std::string& when, int strobe);
// "-strobe<N>" for a still with N ghosts, "" without
std::string strobeSuffix(int strobe);
// a time for a file name: shortest form, at most 6 significant digits ("0.5", "1.23457"); -0 is "0"
std::string timeForName(double t);
// the names of several times: 6 significant digits, or as many more as tell every two different
// times apart (100.0001 and 100.0004 are "100.0001" and "100.0004", not both "100")
std::vector<std::string> timesForNames(const std::vector<double>& times);

}  // namespace render::video
