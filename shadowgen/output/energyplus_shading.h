#pragma once

// The shading schedule of a sun path in the layout EnergyPlus writes for its external
// shading results and reads back through Schedule:File:Shading (docs/scene-format.md,
// "Shading schedule for EnergyPlus", which cites the EnergyPlus sources it follows):
//
//   Surface Name,ROOF,WALL-SOUTH,
//    01/01 01:00,0.00000000,0.00000000,
//    ...
//    06/21 12:00,1.00000000,0.43750000,
//
// One column per face, headed by its id in upper case (EnergyPlus keeps surface names in
// upper case), every cell followed by a comma; one row per time step of every day from the
// path's `from` to its `to`, stamped " MM/DD HH:MM" with the end of the step (the day's last
// is 24:00), holding each face's sunlit fraction (lit area / area, 8 decimals) at the
// instant that starts the step; 0 where the sun is down or the step lies outside the path.
// EnergyPlus reads such a file only when it covers a whole year at its own time step.

#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

struct EnergyPlusShading {
  std::string csv;
  // Why EnergyPlus would not read the file as it stands (a path of less than a year).
  std::vector<std::string> warnings;
};

// Of the one sun path of `shadowed`. Throws InputError naming the input (Scene::file) for one
// without a sun path or with several, a step that does not divide an hour, a path not
// starting at a step's start, and a face id that cannot be an EnergyPlus surface name
// (empty, a comma or a control character in it, spaces around it, or the same as another
// face's in upper case).
EnergyPlusShading energyplus_shading(const ShadowedScene& shadowed);

}  // namespace shadowgen
