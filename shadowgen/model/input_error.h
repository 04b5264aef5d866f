#pragma once

// Errors in user input: what is wrong, in which file, on which face (when one is to blame).
// The library throws them; the command line turns them into one message and exit code 1.
// what() is one line whatever the file name, id or problem hold (shadowgen/model/one_line.h);
// file(), face_id() and problem() are as given.

#include <stdexcept>
#include <string>
#include <string_view>

namespace shadowgen {

// The problem of an input that needs more memory than the process may use (`ulimit -v`):
// the command line says it of the input it read when nothing nearer named the file, a
// reader of a file the input names (a weather file) says it of that file.
inline constexpr std::string_view kOutOfMemoryProblem =
    "out of memory: this input needs more memory than the process may use";

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string face_id, const std::string& problem)
      : std::runtime_error(format(file, face_id, problem)),
        file_(std::move(file)),
        face_id_(std::move(face_id)),
        problem_(problem) {}

  const std::string& file() const { return file_; }
  const std::string& face_id() const { return face_id_; }  // empty when no face is to blame
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, const std::string& face_id,
                            const std::string& problem);
  std::string file_, face_id_, problem_;
};

}  // namespace shadowgen
