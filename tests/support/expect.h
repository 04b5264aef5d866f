#pragma once

// Shared test vocabulary of shadowgen's suites: area and validity expectations backed
// by the exact oracle, and pictures of failing cases written to the build folder.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <string_view>

#include "clipper/clip.h"
#include "tests/support/clip_check.h"

namespace shadowgen::test {

// A file in the build folder's test-artifacts directory (created on first use).
std::string artifact_path(std::string_view file_name);

// Writes artifact <name>.svg showing subject, clip and (if given) our inside and outside
// pieces; returns its path.
std::string write_case_svg(std::string_view name, const clipper::PolygonSet2& subject,
                           const clipper::PolygonSet2& clip,
                           const clipper::ClipResult* result = nullptr);

::testing::AssertionResult AreaNear(double actual, double expected, double tolerance);

// The exact area enclosed by `result` is within `tolerance` (absolute) of `exact_area`.
void ExpectAreaNear(const clipper::PolygonSet2& result, double exact_area, double tolerance);

// Valid per the oracle (validity_problem): the message names the polygon and the reason.
::testing::AssertionResult IsValid(const clipper::PolygonSet2& polygons);
void ExpectValid(const clipper::PolygonSet2& polygons);

// The whole oracle check of one case (check_clip, both orders): areas within
// relative_tolerance × the subject's area (the clip's, for the swapped run), every piece
// valid. On failure, reports the case and writes <name>.svg.
void ExpectClipMatchesOracle(std::string_view name, const clipper::PolygonSet2& subject,
                             const clipper::PolygonSet2& clip, double relative_tolerance);

// Failure accounting for suites of thousands of cases: every failure is counted, the
// first few are reported in full (with an SVG), so one bug does not flood the log.
class CaseFailures {
 public:
  explicit CaseFailures(std::string suite, int reported = 5);
  // Records a failing case (`why` non-empty); does nothing when `why` is empty.
  void record(std::string_view case_name, const std::string& why, const ClipCheck& check,
              const clipper::PolygonSet2& subject, const clipper::PolygonSet2& clip);
  int count() const { return count_; }
  // Failures by kind, e.g. "clip threw 1, invalid output (overlap) 3"; "" when none.
  std::string summary() const;

 private:
  std::string suite_;
  int reported_;
  int count_ = 0;
  std::map<std::string, int> kinds_;
};

}  // namespace shadowgen::test
