#pragma once

// The outlines of a picture (render.h's Outline): what of each face, or of each object of
// a model file, the picture shows, drawn thin and dark over the fills (svg_writer.h).
//
// Faces that carry an origin object (FaceOrigin::object: an EnergyPlus surface, a CityJSON
// city object, a glTF node) are outlined by object, the union of all their visible pieces,
// so that a building reads as one block; every other face by itself. The union is the
// pieces of the base layer (layers by light overlap it) joined along shared edges
// (clipper::merge_adjacent), in order of each outline's first piece.

#include <span>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

std::vector<Outline> picture_outlines(const Scene& scene, std::span<const Piece> pieces);

}  // namespace shadowgen
