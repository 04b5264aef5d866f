#pragma once

// A kind of warning that many faces of one group draw (the faces of one mesh, a scene's
// polygons) is one line, as ReadOptions::verbose says: how many, the group, the kind, the
// first kWarningsListed faces' ids ("56 faces of mesh 'spider': zero area: spider/924,
// spider/927, spider/931, ... (--verbose lists all)"). A kind that kWarningsListed faces or
// fewer draw keeps its lines, and so does every kind under verbose.

#include <string>
#include <vector>

namespace shadowgen::scene::detail {

class WarningSummary {
 public:
  // `file` is the file the faces' warnings name; `group` says whose faces they are, after
  // the count: "faces of mesh 'spider'", "polygons".
  WarningSummary(std::string file, std::string group);

  // One warning `line` of face `face_id`, as face_message(file, face_id, what) wrote it.
  // Its kind is `what` up to its first " (" or ":" ("zero area", "not planar"); kinds keep
  // the order they first appear in.
  void add(const std::string& face_id, std::string line);

  // The lines of every kind, each kind summarised unless `verbose` or a few.
  void append_to(std::vector<std::string>& warnings, bool verbose) const;

 private:
  struct Kind {
    std::string name;
    std::vector<std::string> face_ids;
    std::vector<std::string> lines;
  };
  std::string file_;
  std::string group_;
  std::vector<Kind> kinds_;
};

}  // namespace shadowgen::scene::detail
