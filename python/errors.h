#pragma once

// The library's errors as Python exceptions (docs/library.md, "Python"):
//
//   shadowgen.Error(Exception)           .file, .problem; str() is the command's one line
//   ├── shadowgen.InputError             .face_id
//   └── shadowgen.GenerationError        .face_id, .light_id
//
// An attribute is "" where the C++ error's field is empty. Other C++ exceptions keep
// pybind11's mapping: std::invalid_argument is ValueError, std::out_of_range IndexError,
// std::runtime_error (an output that cannot be written) RuntimeError, std::bad_alloc
// MemoryError.

#include <pybind11/pybind11.h>

namespace shadowgen::python {

// Adds the exception classes to `module` and the translation from shadowgen::api's errors
// to them, tried before pybind11's own.
void register_errors(pybind11::module_& module);

}  // namespace shadowgen::python
