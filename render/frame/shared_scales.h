// Side-by-side pictures of a scene's variants compare at one scale: each survey's scale fields
// (2D RunSurvey or 3D RunSurvey3d) set to their largest over all the surveys.
#pragma once

#include <algorithm>
#include <vector>

namespace render::frame {

// every `fields` (pointers to double members of Survey) of every survey set to its largest over them
template <class Survey, class... Field>
void shareLargest(const std::vector<Survey*>& surveys, Field... fields) {
  if (surveys.empty()) return;
  for (double Survey::*field : {fields...}) {
    double largest = surveys.front()->*field;
    for (const Survey* s : surveys) largest = std::max(largest, s->*field);
    for (Survey* s : surveys) s->*field = largest;
  }
}

}  // namespace render::frame
