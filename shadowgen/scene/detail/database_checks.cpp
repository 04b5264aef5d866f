#include "database_checks.h"

#include <optional>
#include <string>

#include "clipper/clip.h"
#include "hsr/parallel.h"
#include "lit_checks.h"
#include "sun_hours_checks.h"

namespace shadowgen::scene::detail {
namespace {

// A check whose clip did not settle its snapping (docs/clipper.md, Limit): not the
// input's fault, and not known to be right either. The clipper's error, naming the
// file, the face and where in it (the command line's exit code 3).
[[noreturn]] void not_checked(const JsonPlace& place, const std::string& what,
                              const std::string& why) {
  throw clipper::SnapRoundingError(place.message(what + " could not be checked: " + why));
}

}  // namespace

void check_lit_lists(const ShadowedScene& shadowed, const std::vector<std::size_t>& lists_of_face,
                     const std::vector<LitList>& lists) {
  const std::size_t faces = lists_of_face.size();
  std::vector<std::optional<LitProblem>> problems(lists.size());
  std::vector<std::optional<std::string>> unsettled(lists.size());
  hsr::for_each_in_parallel(faces, [&](std::size_t f) {
    const std::size_t end = f + 1 < faces ? lists_of_face[f + 1] : lists.size();
    if (lists_of_face[f] == end) return;
    const LitChecker checker(shadowed.scene().faces[f]);
    for (std::size_t k = lists_of_face[f]; k < end; ++k) {
      try {
        problems[k] = checker.check(shadowed.lit()[f][lists[k].light]);
      } catch (const clipper::SnapRoundingError& e) {
        unsettled[k] = e.what();
      }
    }
  });
  for (std::size_t k = 0; k < lists.size(); ++k) {
    if (unsettled[k]) not_checked(lists[k].place, "the lit polygons", *unsettled[k]);
    if (const std::optional<LitProblem>& problem = problems[k]) {
      const JsonPlace& place = lists[k].place;
      (problem->polygon ? place.element(*problem->polygon) : place).fail(problem->what);
    }
  }
}

void check_sun_hours_sums(const ShadowedScene& shadowed,
                          const std::vector<std::vector<JsonPlace>>& places) {
  const std::size_t faces = shadowed.scene().faces.size();
  for (std::size_t p = 0; p < shadowed.sun_paths.size(); ++p) {
    const SunPathHours& path = shadowed.sun_paths[p];
    std::vector<std::optional<std::string>> problems(faces), unsettled(faces);
    hsr::for_each_in_parallel(faces, [&](std::size_t f) {
      const Face& face = shadowed.scene().faces[f];
      try {
        if (!shadowed.shard) {
          problems[f] = sun_hours_problem(face, path, f);
          return;
        }
        if (path.regions_kept) problems[f] = nodes_problem(face, path, f);
        if (!problems[f]) problems[f] = lit_areas_problem(face, path, f);
      } catch (const clipper::SnapRoundingError& e) {
        unsettled[f] = e.what();
      }
    });
    for (std::size_t f = 0; f < faces; ++f) {
      if (unsettled[f]) not_checked(places[p][f], "the sun-hours regions", *unsettled[f]);
      if (problems[f]) places[p][f].fail(*problems[f]);
    }
  }
}

}  // namespace shadowgen::scene::detail
