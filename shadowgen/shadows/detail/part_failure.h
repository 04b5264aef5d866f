#pragma once

// A clip that failed while one face part was being worked on (clipper::SnapRoundingError,
// clipper/clip.h): the stages of a light's shadows pass it on naming the part, and
// generate.cpp turns it into a GenerationError naming the face and the light. Without
// the name, all the user would learn is that some clip somewhere gave up.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "clipper/clip.h"

namespace shadowgen::shadows::detail {

class PartFailure : public std::runtime_error {
 public:
  PartFailure(std::size_t part, const std::string& problem)
      : std::runtime_error(problem), part_(part) {}

  std::size_t part() const { return part_; }  // index in the FaceParts

 private:
  std::size_t part_;
};

// Runs `work` for face part `part` (an index in the FaceParts) and returns its result; a
// clip that fails in it comes out as PartFailure.
template <class Work>
auto on_part(std::size_t part, Work&& work) {
  return clipper::failing_as<PartFailure>(part, std::forward<Work>(work));
}

}  // namespace shadowgen::shadows::detail
