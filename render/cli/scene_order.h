// A folder's order.txt: the order in which a lecture shows the folder's scenes, one file name a line
// (".yaml" may be left out; blank lines and text after '#' are ignored). Without it, by name.
#pragma once

#include <string>
#include <vector>

namespace render::cli {

inline constexpr const char* kOrderName = "order.txt";

// the folder's scene files (`found`, each a path in `folder`) in order.txt's order when the folder
// has one: those it lists first, as listed, then the others by name; else by name. Throws
// sim::yaml::SceneError at order.txt's line for a name that is no scene file of the folder, or
// that it lists twice
std::vector<std::string> orderedSceneFiles(const std::string& folder, std::vector<std::string> found);

// the file's place (1, 2, ...) in its folder's order.txt; 0 when the folder has none or it is not
// listed (a bad order.txt is reported when the pack's files are listed, before anything renders)
int orderInFolder(const std::string& file);

}  // namespace render::cli
