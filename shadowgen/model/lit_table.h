#pragma once

// The lit detail polygons of a shadowed database, table[face][light]. Only the lights whose
// polygons a run keeps take room: the instants of a sun path summed into lit areas
// (SunPathHours) hold none, and a year of hourly instants over 1e4 faces would otherwise be
// 45 million empty lists, a gigabyte of nothing.

#include <cstddef>
#include <iterator>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen {

// One lit detail polygon, lying in the plane of part `part` of its face (Face::parts):
// the part is known where the polygon is made, so no reader of it has to guess.
struct LitPolygon {
  std::size_t part = 0;
  hsr::Polygon3 polygon;
};

class LitTable {
 public:
  using Polygons = std::vector<LitPolygon>;

  class ConstRow;
  class Row;

  LitTable() = default;
  // `faces` rows of `lights` empty lists; kept[l] false: light l holds no polygons and
  // takes no room (kept empty: every light is kept).
  LitTable(std::size_t faces, std::size_t lights, std::vector<bool> kept = {});
  // rows[face][light], every light kept. Throws std::invalid_argument where rows differ
  // in length.
  explicit LitTable(std::vector<std::vector<Polygons>> rows);

  std::size_t size() const { return faces_; }  // faces
  bool empty() const { return faces_ == 0; }
  std::size_t lights() const { return slot_.size(); }
  bool kept(std::size_t light) const { return slot_.at(light) != kNotKept; }

  // The polygons of (face, light): empty for a light not kept. Throws std::out_of_range.
  const Polygons& at(std::size_t face, std::size_t light) const;
  // The same, to fill; throws std::logic_error for a light not kept.
  Polygons& at(std::size_t face, std::size_t light);

  ConstRow operator[](std::size_t face) const { return ConstRow(*this, face); }
  Row operator[](std::size_t face) { return Row(*this, face); }

  // Appends a face whose lists are all empty (a reader adds faces as it meets them).
  void add_face();
  // Keeps the lights marked in `keep` (one flag per light), in order, renumbered.
  void keep_lights(const std::vector<bool>& keep);

  // The lists of one face, light by light (a light not kept gives an empty list).
  class ConstRow {
   public:
    ConstRow(const LitTable& table, std::size_t face) : table_(&table), face_(face) {}
    std::size_t size() const { return table_->lights(); }
    const Polygons& operator[](std::size_t light) const { return table_->at(face_, light); }

    class iterator {
     public:
      using iterator_category = std::forward_iterator_tag;
      using value_type = Polygons;
      using difference_type = std::ptrdiff_t;
      using pointer = const Polygons*;
      using reference = const Polygons&;
      iterator() = default;
      iterator(const ConstRow* row, std::size_t light) : row_(row), light_(light) {}
      reference operator*() const { return (*row_)[light_]; }
      iterator& operator++() {
        ++light_;
        return *this;
      }
      iterator operator++(int) {
        iterator before = *this;
        ++light_;
        return before;
      }
      bool operator==(const iterator& other) const { return light_ == other.light_; }

     private:
      const ConstRow* row_ = nullptr;
      std::size_t light_ = 0;
    };
    iterator begin() const { return iterator(this, 0); }
    iterator end() const { return iterator(this, size()); }

   private:
    const LitTable* table_;
    std::size_t face_;
  };

  class Row {
   public:
    Row(LitTable& table, std::size_t face) : table_(&table), face_(face) {}
    std::size_t size() const { return table_->lights(); }
    // Throws std::logic_error for a light not kept.
    Polygons& operator[](std::size_t light) const { return table_->at(face_, light); }
    operator ConstRow() const { return ConstRow(*table_, face_); }

   private:
    LitTable* table_;
    std::size_t face_;
  };

 private:
  static constexpr std::size_t kNotKept = static_cast<std::size_t>(-1);

  std::size_t faces_ = 0;
  std::size_t kept_count_ = 0;
  std::vector<std::size_t> slot_;  // [light]: its column among the kept, or kNotKept
  std::vector<Polygons> cells_;    // [face * kept_count_ + column]
};

}  // namespace shadowgen
