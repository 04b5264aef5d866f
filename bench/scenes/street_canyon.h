#pragma once

// A street canyon whose floor's sky view factor is known in closed form: walls of height
// H along x at y = ±W/2, 200 W long, and a small horizontal face at the middle of the floor,
// which sees cos(atan(2H/W)) of the sky when the canyon is infinitely long (its ends,
// 100 W away, add under 1e-5 of that).

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

// The canyon of width 1 and height `height`: faces "floor" (0.01 × 0.01, facing up, first),
// "south" and "north" (the walls, facing into the street).
Scene street_canyon(double height);

// cos(atan(2H/W)) for W = 1.
double street_canyon_sky_view_factor(double height);

}  // namespace shadowgen::bench
