#include "shadowgen/model/input_error.h"

#include "shadowgen/model/one_line.h"

namespace shadowgen {

std::string InputError::format(const std::string& file, const std::string& face_id,
                               const std::string& problem) {
  std::string s = file;
  if (!face_id.empty()) s += ": face '" + face_id + "'";
  return one_line(s + ": " + problem);
}

}  // namespace shadowgen
