#include "result_arrays.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

namespace py = pybind11;
using namespace pybind11::literals;

namespace shadowgen::python {
namespace {

// A table class: rows as tuples (`row` makes the i-th), and each field a column.
template <class Table>
class TableClass {
 public:
  using Row = typename decltype(Table::rows)::value_type;

  TableClass(py::module_& module, const char* name, const char* doc, py::object (*row)(const Row&))
      : class_(module, name, doc) {
    class_.def("__len__", [](const Table& t) { return t.rows.size(); })
        .def("__getitem__",
             [row](const Table& t, py::ssize_t index) {
               const auto size = static_cast<py::ssize_t>(t.rows.size());
               if (index < 0) index += size;
               if (index < 0 || index >= size) throw py::index_error("row index out of range");
               return row(t.rows[static_cast<std::size_t>(index)]);
             })
        .def("__iter__",
             [row](const Table& t) {
               py::list rows;
               for (const Row& r : t.rows) rows.append(row(r));
               return py::iter(rows);
             })
        .def("__repr__", [name = std::string(name)](const Table& t) {
          return "<shadowgen." + name + " of " + std::to_string(t.rows.size()) + " rows>";
        });
  }

  // The column of `field` as a numpy array: int64 for indices, float64 for numbers, str
  // for ids (numpy's fixed-width unicode).
  template <class Field>
  TableClass& column(const char* name, Field Row::*field) {
    class_.def_property_readonly(name, [field](const Table& t) -> py::object {
      if constexpr (std::is_same_v<Field, std::string>) {
        py::list ids;
        for (const Row& r : t.rows) ids.append(r.*field);
        return py::module_::import("numpy").attr("array")(ids, "dtype"_a = "str");
      } else {
        using Number = std::conditional_t<std::is_integral_v<Field>, std::int64_t, double>;
        py::array_t<Number> out(static_cast<py::ssize_t>(t.rows.size()));
        auto at = out.template mutable_unchecked<1>();
        for (std::size_t i = 0; i < t.rows.size(); ++i) {
          at(static_cast<py::ssize_t>(i)) = static_cast<Number>(t.rows[i].*field);
        }
        return out;
      }
    });
    return *this;
  }

  py::class_<Table>& get() { return class_; }

 private:
  py::class_<Table> class_;
};

py::array_t<double> loop_array(const api::Loop& loop) {
  py::array_t<double> out({static_cast<py::ssize_t>(loop.size()), py::ssize_t{3}});
  auto at = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    for (py::ssize_t axis = 0; axis < 3; ++axis) {
      at(static_cast<py::ssize_t>(i), axis) = loop[i][static_cast<std::size_t>(axis)];
    }
  }
  return out;
}

}  // namespace

void register_results(py::module_& module) {
  TableClass<LitAreas>(module, "LitAreas",
                       "The lit area on each face from each light, one row per (face, light), "
                       "faces outer: the report CSV's rows and numbers.",
                       [](const api::LitArea& r) -> py::object {
                         return py::make_tuple(r.face_id, r.light_id, r.area, r.lit_area);
                       })
      .column("face", &api::LitArea::face)
      .column("light", &api::LitArea::light)
      .column("face_id", &api::LitArea::face_id)
      .column("light_id", &api::LitArea::light_id)
      .column("area", &api::LitArea::area)
      .column("lit_area", &api::LitArea::lit_area)
      .column("lit_fraction", &api::LitArea::lit_fraction);

  TableClass<SunHoursTable>(
      module, "SunHoursTable", "Sun hours per face and sun path: the sun-hours CSV's rows.",
      [](const api::SunHours& r) -> py::object {
        return py::make_tuple(r.face_id, r.path_id, r.area, r.mean_hours, r.min_hours, r.max_hours);
      })
      .column("face", &api::SunHours::face)
      .column("face_id", &api::SunHours::face_id)
      .column("path_id", &api::SunHours::path_id)
      .column("area", &api::SunHours::area)
      .column("mean_hours", &api::SunHours::mean_hours)
      .column("min_hours", &api::SunHours::min_hours)
      .column("max_hours", &api::SunHours::max_hours)
      .get()
      .def_property_readonly("thresholds",
                             [](const SunHoursTable& t) {
                               return py::array_t<double>(
                                   static_cast<py::ssize_t>(t.thresholds.size()),
                                   t.thresholds.data());
                             })
      .def_property_readonly("area_at_least", [](const SunHoursTable& t) {
        const auto width = static_cast<py::ssize_t>(t.thresholds.size());
        py::array_t<double> out({static_cast<py::ssize_t>(t.rows.size()), width});
        auto at = out.mutable_unchecked<2>();
        for (std::size_t i = 0; i < t.rows.size(); ++i) {
          for (py::ssize_t k = 0; k < width; ++k) {
            at(static_cast<py::ssize_t>(i), k) =
                t.rows[i].area_at_least[static_cast<std::size_t>(k)];
          }
        }
        return out;
      });
}

py::list polygons_object(const std::vector<api::PolygonData>& polygons) {
  py::list out;
  for (const api::PolygonData& polygon : polygons) {
    py::list holes;
    for (const api::Loop& hole : polygon.holes) holes.append(loop_array(hole));
    out.append(py::make_tuple(loop_array(polygon.outer), holes));
  }
  return out;
}

}  // namespace shadowgen::python
