#include "errors.h"

#include <shadowgen/shadowgen.h>

#include <exception>
#include <initializer_list>
#include <string>
#include <utility>

namespace py = pybind11;

namespace shadowgen::python {
namespace {

// The classes, made once per process when the module is imported and kept for its life
// (a module's exception types are never freed, so a bare PyObject* outlives every raise).
PyObject* error_type = nullptr;
PyObject* input_error_type = nullptr;
PyObject* generation_error_type = nullptr;

// A class `name` deriving from `base`, its attributes `fields` "" until an error sets them.
PyObject* new_error_type(py::module_& module, const char* name, const char* doc, PyObject* base,
                         std::initializer_list<const char*> fields) {
  py::dict attributes;
  for (const char* field : fields) attributes[field] = "";
  const std::string qualified = std::string("shadowgen.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, attributes.ptr());
  if (type == nullptr) throw py::error_already_set();
  module.add_object(name, py::handle(type));  // the module holds a reference of its own
  return type;
}

// Raises an instance of `type` whose message is `error`'s what() and whose attributes are
// `fields`.
void raise(PyObject* type, const api::Error& error,
           std::initializer_list<std::pair<const char*, const std::string*>> fields) {
  py::object instance = py::reinterpret_borrow<py::object>(type)(error.what());
  instance.attr("file") = error.file();
  instance.attr("problem") = error.problem();
  for (const auto& [name, value] : fields) instance.attr(name) = *value;
  PyErr_SetObject(type, instance.ptr());
}

}  // namespace

void register_errors(py::module_& module) {
  error_type = new_error_type(module, "Error",
                              "An error of shadowgen, naming the input at fault: .file, .problem.",
                              PyExc_Exception, {"file", "problem"});
  input_error_type = new_error_type(
      module, "InputError",
      "Bad input (a file, a face, a light, group or sun path the input lacks): .face_id.",
      error_type, {"face_id"});
  generation_error_type = new_error_type(
      module, "GenerationError", "Shadows that could not be computed exactly: .face_id, .light_id.",
      error_type, {"face_id", "light_id"});

  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const api::InputError& e) {
      raise(input_error_type, e, {{"face_id", &e.face_id()}});
    } catch (const api::GenerationError& e) {
      raise(generation_error_type, e, {{"face_id", &e.face_id()}, {"light_id", &e.light_id()}});
    } catch (const api::Error& e) {
      raise(error_type, e, {});
    }
  });
}

}  // namespace shadowgen::python
