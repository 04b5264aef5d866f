#include "detail/placement.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <utility>

namespace shadowgen::energyplus::detail {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// GetVertices drops a vertex closer than this to the one before it (metres).
constexpr double kCoincidentVertices = 0.01;
// GetVertices' test of a roof facing down or a floor facing up: the z of the unit normal.
constexpr double kUpsideDown = 0.000001;

// A rotation by -angle (clockwise seen from above), as EnergyPlus's CosBldgRelNorth and
// CosZoneRelNorth hold it: cos(-angle), sin(-angle).
struct Rotation {
  double cos, sin;
  explicit Rotation(double angle_deg)
      : cos(std::cos(-angle_deg * kDegToRad)), sin(std::sin(-angle_deg * kDegToRad)) {}
  glm::dvec2 apply(double x, double y) const { return {x * cos - y * sin, x * sin + y * cos}; }
};

// CreateNewellSurfaceNormalVector: Newell's sums, normalised (zero stays zero).
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& v) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3& a = v[i];
    const glm::dvec3& b = v[(i + 1) % v.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  const double length = glm::length(n);
  return length != 0.0 ? n / length : n;
}

// DetermineAzimuthAndTilt (Vectors.cc): the azimuth of the normal's horizontal part,
// clockwise from +y; for a horizontal surface, of its edge from vertex 2 to vertex 3.
void set_orientation(PlacedSurface& s) {
  const glm::dvec3 n = newell_normal(s.vertices);
  const glm::dvec3 edge = s.vertices[2] - s.vertices[1];
  const double edge_length = glm::length(edge);
  const glm::dvec3 lcsx = edge_length != 0.0 ? edge / edge_length : glm::dvec3(0.0);
  constexpr double kEpsilon = 1.12e-16;
  double rotation = 0.0;
  if (std::abs(n.z) < 1.0 - kEpsilon) {
    const glm::dvec3 x2 = glm::cross(glm::dvec3(0.0, 0.0, 1.0), n);
    rotation = std::atan2(x2.y, x2.x);
  } else {
    rotation = std::atan2(lcsx.y, lcsx.x);
  }
  double tilt = std::acos(n.z) / kDegToRad;
  double azimuth = rotation / kDegToRad;
  azimuth = std::fmod(450.0 - azimuth, 360.0);
  azimuth += 90.0;
  if (azimuth < 0.0) azimuth += 360.0;
  azimuth = std::fmod(azimuth, 360.0);
  if (std::abs(azimuth - 360.0) < 0.001) {
    azimuth = 0.0;
  } else if (std::abs(azimuth - 180.0) < 0.000001) {
    azimuth = 180.0;
  }
  if (std::abs(tilt - 180.0) < 0.000001) tilt = 180.0;
  s.azimuth_deg = azimuth;
  s.tilt_deg = tilt;
}

void set_sines(PlacedSurface& s, double azimuth_deg, double tilt_deg) {
  s.sin_azimuth = std::sin(azimuth_deg * kDegToRad);
  s.cos_azimuth = std::cos(azimuth_deg * kDegToRad);
  s.sin_tilt = std::sin(tilt_deg * kDegToRad);
  s.cos_tilt = std::cos(tilt_deg * kDegToRad);
}

// GetVertices' swaps that turn clockwise input counter-clockwise, vertex 1 kept.
void make_counterclockwise(std::vector<glm::dvec3>& v) {
  std::size_t source = v.size() - 1;
  std::size_t target = 1;
  for (std::size_t n = 1; n <= (v.size() - 1) / 2; ++n) std::swap(v[source--], v[target++]);
}

// GetVertices' loop that brings the upper left corner first: each pass moves every vertex
// one place back, from the entered corner to UpperLeftCorner (1), wrapping past the last
// vertex; a triangle entered from UpperRightCorner is taken as it is.
void start_upper_left(std::vector<glm::dvec3>& v, int corner) {
  const int sides = static_cast<int>(v.size());
  while (corner != 1) {
    if (sides < 4 && corner == 4) break;
    std::rotate(v.begin(), v.begin() + 1, v.end());
    ++corner;
    if (corner > sides) corner = 1;
  }
}

// GetVertices' dropping of a vertex within kCoincidentVertices of the one before, from the
// first such pair again after each drop, while more than 3 vertices remain.
std::size_t drop_coincident(std::vector<glm::dvec3>& v) {
  std::size_t dropped = 0;
  bool popped = true;
  while (popped) {
    popped = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::size_t next = (i + 1) % v.size();
      if (glm::distance(v[i], v[next]) < kCoincidentVertices && v.size() > 3) {
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(next));
        ++dropped;
        popped = true;
        break;
      }
    }
  }
  return dropped;
}

// The rectangle both MakeRectangularVertices and MakeRelativeRectangularVertices make, from
// its lower left `corner` along the azimuth and up the tilt held in `s`: upper left,
// lower left, lower right, upper right.
void make_rectangle(PlacedSurface& s, const glm::dvec3& corner, double length, double height) {
  const double xx[4] = {0.0, 0.0, length, length};
  const double yy[4] = {height, 0.0, 0.0, height};
  for (int n = 0; n < 4; ++n) {
    s.vertices.push_back({corner.x - xx[n] * s.cos_azimuth - yy[n] * s.cos_tilt * s.sin_azimuth,
                          corner.y + xx[n] * s.sin_azimuth - yy[n] * s.cos_tilt * s.cos_azimuth,
                          corner.z + yy[n] * s.sin_tilt});
  }
  set_orientation(s);
  s.width = length;
  s.height = height;
}

}  // namespace

PlacedSurface place_vertices(std::vector<glm::dvec3> v, const PlacementFrame& frame,
                             const ZoneFrame* zone, SurfaceClass surface_class) {
  if (frame.rules.clockwise) make_counterclockwise(v);
  start_upper_left(v, frame.rules.starting_corner);
  if (!frame.rules.world) {
    const Rotation building(frame.building_north_deg);
    if (zone != nullptr) {
      const Rotation relative(zone->relative_north_deg);
      for (glm::dvec3& p : v) {
        const glm::dvec2 b = relative.apply(p.x, p.y) + glm::dvec2(zone->origin);
        const glm::dvec2 w = building.apply(b.x, b.y);
        p = {w.x, w.y, p.z + zone->origin.z};
      }
    } else if (surface_class == SurfaceClass::kBuildingShading) {
      for (glm::dvec3& p : v) {
        const glm::dvec2 w = building.apply(p.x, p.y);
        p = {w.x, w.y, p.z};
      }
    }
  }
  PlacedSurface s;
  s.dropped_vertices = drop_coincident(v);
  s.vertices = std::move(v);
  const double up = newell_normal(s.vertices).z;
  if ((surface_class == SurfaceClass::kRoof && up < -kUpsideDown) ||
      (surface_class == SurfaceClass::kFloor && up > kUpsideDown)) {
    std::reverse(s.vertices.begin(), s.vertices.end());
  }
  set_orientation(s);
  set_sines(s, s.azimuth_deg, s.tilt_deg);
  s.width = glm::distance(s.vertices[2], s.vertices[1]);
  s.height = glm::distance(s.vertices[1], s.vertices[0]);
  return s;
}

PlacedSurface place_rectangle(const PlacementFrame& frame, const ZoneFrame* zone,
                              SurfaceClass surface_class, double azimuth_deg, double tilt_deg,
                              const glm::dvec3& start, double length, double height) {
  // GetRectSurfaces and GetRectDetShdSurfaceData: the azimuth entered turns with the
  // zone's and the building's north axes, unless coordinates are World.
  if (!frame.rules.world) {
    if (zone != nullptr) {
      azimuth_deg += frame.building_north_deg + zone->relative_north_deg;
    } else if (surface_class == SurfaceClass::kBuildingShading) {
      azimuth_deg += frame.building_north_deg;
    }
  }
  glm::dvec3 corner = start;
  if (!frame.rules.rectangles_world) {
    const Rotation building(frame.building_north_deg);
    if (zone != nullptr) {
      const glm::dvec2 b =
          Rotation(zone->relative_north_deg).apply(start.x, start.y) + glm::dvec2(zone->origin);
      const glm::dvec2 w = building.apply(b.x, b.y);
      corner = {w.x, w.y, start.z + zone->origin.z};
    } else if (surface_class == SurfaceClass::kBuildingShading) {
      const glm::dvec2 w = building.apply(start.x, start.y);
      corner = {w.x, w.y, start.z};
    }
  }
  PlacedSurface s;
  set_sines(s, azimuth_deg, tilt_deg);
  make_rectangle(s, corner, length, height);
  return s;
}

PlacedSurface place_on_base(const PlacedSurface& base, double azimuth_deg, double tilt_deg,
                            double x, double z, double length, double height) {
  const glm::dvec3& origin = base.vertices[1];
  const glm::dvec3 corner(origin.x - x * base.cos_azimuth - z * base.cos_tilt * base.sin_azimuth,
                          origin.y + x * base.sin_azimuth - z * base.cos_tilt * base.cos_azimuth,
                          origin.z + z * base.sin_tilt);
  PlacedSurface s;
  set_sines(s, azimuth_deg, tilt_deg);
  make_rectangle(s, corner, length, height);
  return s;
}

}  // namespace shadowgen::energyplus::detail
