#include "shadowgen/model/lit_table.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace shadowgen {

LitTable::LitTable(std::size_t faces, std::size_t lights, std::vector<bool> kept)
    : faces_(faces), slot_(lights, kNotKept) {
  if (!kept.empty() && kept.size() != lights) {
    throw std::invalid_argument("LitTable: " + std::to_string(kept.size()) + " kept flags for " +
                                std::to_string(lights) + " lights");
  }
  for (std::size_t l = 0; l < lights; ++l) {
    if (kept.empty() || kept[l]) slot_[l] = kept_count_++;
  }
  cells_.resize(faces_ * kept_count_);
}

LitTable::LitTable(std::vector<std::vector<Polygons>> rows)
    : LitTable(rows.size(), rows.empty() ? 0 : rows.front().size()) {
  for (std::size_t f = 0; f < rows.size(); ++f) {
    if (rows[f].size() != lights()) {
      throw std::invalid_argument("LitTable: face " + std::to_string(f) + " has lists for " +
                                  std::to_string(rows[f].size()) + " lights, face 0 for " +
                                  std::to_string(lights()));
    }
    for (std::size_t l = 0; l < lights(); ++l) at(f, l) = std::move(rows[f][l]);
  }
}

const LitTable::Polygons& LitTable::at(std::size_t face, std::size_t light) const {
  static const Polygons kNone;
  if (face >= faces_ || light >= slot_.size()) {
    throw std::out_of_range("LitTable: (face " + std::to_string(face) + ", light " +
                            std::to_string(light) + ") outside " + std::to_string(faces_) + " × " +
                            std::to_string(slot_.size()));
  }
  const std::size_t slot = slot_[light];
  return slot == kNotKept ? kNone : cells_[face * kept_count_ + slot];
}

LitTable::Polygons& LitTable::at(std::size_t face, std::size_t light) {
  const Polygons& cell = std::as_const(*this).at(face, light);
  if (slot_[light] == kNotKept) {
    throw std::logic_error("LitTable: light " + std::to_string(light) + " keeps no lit polygons");
  }
  return const_cast<Polygons&>(cell);
}

void LitTable::add_face() {
  cells_.resize(cells_.size() + kept_count_);
  ++faces_;
}

void LitTable::keep_lights(const std::vector<bool>& keep) {
  if (keep.size() != slot_.size()) {
    throw std::invalid_argument("LitTable::keep_lights: " + std::to_string(keep.size()) +
                                " flags for " + std::to_string(slot_.size()) + " lights");
  }
  std::vector<bool> kept;
  std::vector<std::size_t> from;  // [new light]: the old light
  for (std::size_t l = 0; l < slot_.size(); ++l) {
    if (!keep[l]) continue;
    kept.push_back(slot_[l] != kNotKept);
    from.push_back(l);
  }
  LitTable out(faces_, from.size(), std::move(kept));
  for (std::size_t f = 0; f < faces_; ++f) {
    for (std::size_t l = 0; l < from.size(); ++l) {
      if (out.kept(l)) out.at(f, l) = std::move(at(f, from[l]));
    }
  }
  *this = std::move(out);
}

}  // namespace shadowgen
