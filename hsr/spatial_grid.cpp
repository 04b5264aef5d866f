#include "hsr/spatial_grid.h"

#include <algorithm>
#include <cmath>

namespace shadowgen::hsr {

SpatialGrid::SpatialGrid(const clipper::Box2& extent, std::size_t expected_items)
    : extent_(extent) {
  const double w = extent.xmax - extent.xmin, h = extent.ymax - extent.ymin;
  const double cells = static_cast<double>(std::max<std::size_t>(expected_items, 1));
  if (w > 0.0 && h > 0.0) {
    const double side = std::sqrt(w * h / cells);
    nx_ = static_cast<int>(std::clamp(std::ceil(w / side), 1.0, 2048.0));
    ny_ = static_cast<int>(std::clamp(std::ceil(h / side), 1.0, 2048.0));
  }
  sx_ = w > 0.0 ? nx_ / w : 0.0;
  sy_ = h > 0.0 ? ny_ / h : 0.0;
  cells_.resize(static_cast<std::size_t>(nx_) * ny_);
}

bool SpatialGrid::cell_range(const clipper::Box2& box, int& x0, int& y0, int& x1, int& y1) const {
  auto clamp_cell = [](double v, int n) {
    return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(n - 1)));
  };
  x0 = clamp_cell((box.xmin - extent_.xmin) * sx_, nx_);
  x1 = clamp_cell((box.xmax - extent_.xmin) * sx_, nx_);
  y0 = clamp_cell((box.ymin - extent_.ymin) * sy_, ny_);
  y1 = clamp_cell((box.ymax - extent_.ymin) * sy_, ny_);
  return !box.empty();
}

void SpatialGrid::insert(std::size_t item, const clipper::Box2& box) {
  if (item >= seen_.size()) {
    seen_.resize(item + 1, 0);
    is_wide_.resize(item + 1, false);
    erased_.resize(item + 1, 0);
  }
  int x0, y0, x1, y1;
  if (!cell_range(box, x0, y0, x1, y1)) return;
  const std::size_t count = static_cast<std::size_t>(x1 - x0 + 1) * (y1 - y0 + 1);
  if (count > kMaxCells) {
    wide_.push_back(item);
    is_wide_[item] = true;
    return;
  }
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) cells_[static_cast<std::size_t>(y) * nx_ + x].push_back(item);
  }
}

bool SpatialGrid::is_wide(const clipper::Box2& box) const {
  int x0, y0, x1, y1;
  if (!cell_range(box, x0, y0, x1, y1)) return false;
  return static_cast<std::size_t>(x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCells;
}

std::vector<clipper::Box2> SpatialGrid::tiles(const clipper::Box2& box, int block) const {
  std::vector<clipper::Box2> out;
  int x0, y0, x1, y1;
  if (!cell_range(box, x0, y0, x1, y1)) return out;
  // Grid lines computed one way only, so neighbouring tiles share their sides exactly.
  auto line_x = [this](int i) {
    return i >= nx_ ? extent_.xmax : extent_.xmin + (extent_.xmax - extent_.xmin) * i / nx_;
  };
  auto line_y = [this](int j) {
    return j >= ny_ ? extent_.ymax : extent_.ymin + (extent_.ymax - extent_.ymin) * j / ny_;
  };
  for (int j = y0 - y0 % block; j <= y1; j += block) {
    for (int i = x0 - x0 % block; i <= x1; i += block) {
      clipper::Box2 t;
      t.xmin = i == 0 ? std::min(box.xmin, extent_.xmin) : line_x(i);
      t.ymin = j == 0 ? std::min(box.ymin, extent_.ymin) : line_y(j);
      t.xmax = i + block >= nx_ ? std::max(box.xmax, extent_.xmax) : line_x(i + block);
      t.ymax = j + block >= ny_ ? std::max(box.ymax, extent_.ymax) : line_y(j + block);
      out.push_back(t);
    }
  }
  return out;
}

void SpatialGrid::erase(std::size_t item) {
  if (item >= erased_.size()) return;  // never inserted
  erased_[item] = 1;
  if (!is_wide_[item]) return;
  is_wide_[item] = false;
  const auto it = std::find(wide_.begin(), wide_.end(), item);
  if (it != wide_.end()) {
    *it = wide_.back();
    wide_.pop_back();
  }
}

void SpatialGrid::query(const clipper::Box2& box, std::vector<std::size_t>& out) {
  if (++stamp_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0);
    stamp_ = 1;
  }
  auto take = [&](std::size_t item) {
    if (seen_[item] == stamp_) return;
    seen_[item] = stamp_;
    out.push_back(item);
  };
  for (std::size_t item : wide_) take(item);
  int x0, y0, x1, y1;
  if (!cell_range(box, x0, y0, x1, y1)) return;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      // The erased entries are dropped on the way, the others keep their order.
      std::vector<std::size_t>& cell = cells_[static_cast<std::size_t>(y) * nx_ + x];
      std::size_t kept = 0;
      for (const std::size_t item : cell) {
        if (erased_[item]) continue;
        cell[kept++] = item;
        take(item);
      }
      cell.resize(kept);
    }
  }
}

void SpatialGrid::query_shared(const clipper::Box2& box, std::vector<std::size_t>& out) const {
  out.insert(out.end(), wide_.begin(), wide_.end());
  int x0, y0, x1, y1;
  if (!cell_range(box, x0, y0, x1, y1)) return;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      for (const std::size_t item : cells_[static_cast<std::size_t>(y) * nx_ + x]) {
        if (!erased_[item]) out.push_back(item);
      }
    }
  }
}

}  // namespace shadowgen::hsr
