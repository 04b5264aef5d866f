#pragma once

// What places a file's surfaces (placement.h): its GlobalGeometryRules, its Building's
// north axis and its zones, read as EnergyPlus reads them (SurfaceGeometry.cc,
// GetGeometryParameters; HeatBalanceManager's Building and Zone). Names are matched as
// EnergyPlus matches them, ignoring case.

#include <map>
#include <string>
#include <vector>

#include "detail/input_object.h"
#include "detail/placement.h"

namespace shadowgen::energyplus::detail {

// A name as EnergyPlus compares names: upper case.
std::string name_key(std::string_view name);

struct ModelFrame {
  PlacementFrame placement;
  std::map<std::string, ZoneFrame> zones;  // by name_key
};

// InputError naming `file` when GlobalGeometryRules is missing or given twice, when one of
// its choices is none EnergyPlus knows, when Building is given twice, when two zones share
// a name, for a number that does not read, and for what this reader does not place as
// EnergyPlus would: Compliance:Building's Appendix G rotation, GeometryTransform.
ModelFrame read_frame(const std::vector<InputObject>& objects, const std::string& file);

}  // namespace shadowgen::energyplus::detail
