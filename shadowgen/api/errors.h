#pragma once

// The errors the library throws at its surface, each naming the input at fault. Every
// entry point of shadowgen/shadowgen.h throws these, or std::runtime_error (its what()
// naming the path) where an output cannot be written, or std::bad_alloc:
//
//   try {
//     shadowgen::api::Shadows shadows = shadowgen::api::load("scene.json");
//   } catch (const shadowgen::api::InputError& e) {
//     std::cerr << e.file() << ": " << e.face_id() << ": " << e.problem() << '\n';
//   }
//
// what() is the one line the command line prints ("scene.json: face 'wall': ...").

#include <stdexcept>
#include <string>

namespace shadowgen::api {

// What every error of the library is; file() names the input (a scene, a database, a file
// a scene names, or SceneData::name), empty where none is known.
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, std::string file, std::string problem)
      : std::runtime_error(message), file_(std::move(file)), problem_(std::move(problem)) {}

  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, problem_;
};

// Bad input: a file that cannot be read or does not follow its format, a face that is no
// polygon, a light, group or sun path the input does not have. face_id() is empty where no
// face is to blame.
class InputError : public Error {
 public:
  InputError(const std::string& message, std::string file, std::string face_id, std::string problem)
      : Error(message, std::move(file), std::move(problem)), face_id_(std::move(face_id)) {}

  const std::string& face_id() const { return face_id_; }

 private:
  std::string face_id_;
};

// Shadows that could not be computed exactly: the clipper's snap rounding did not settle
// (an internal limit, not the input's fault; no input is known to cause it). face_id() and
// light_id() are empty where no one face or light is known.
class GenerationError : public Error {
 public:
  GenerationError(const std::string& message, std::string file, std::string face_id,
                  std::string light_id, std::string problem)
      : Error(message, std::move(file), std::move(problem)),
        face_id_(std::move(face_id)),
        light_id_(std::move(light_id)) {}

  const std::string& face_id() const { return face_id_; }
  const std::string& light_id() const { return light_id_; }

 private:
  std::string face_id_, light_id_;
};

}  // namespace shadowgen::api
