#include "tests/support/expect.h"

#include <filesystem>
#include <utility>

#include "tests/support/cgal_oracle.h"
#include "tests/support/svg.h"

namespace shadowgen::test {

using clipper::PolygonSet2;

std::string artifact_path(std::string_view file_name) {
  const std::filesystem::path directory(SHADOWGEN_TEST_ARTIFACT_DIR);
  std::error_code ignored;
  std::filesystem::create_directories(directory, ignored);
  std::string safe(file_name);
  for (char& c : safe) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '-' || c == '_' || c == '.';
    if (!plain) c = '_';
  }
  return (directory / safe).string();
}

std::string write_case_svg(std::string_view name, const PolygonSet2& subject,
                           const PolygonSet2& clip, const clipper::ClipResult* result) {
  const std::string path = artifact_path(std::string(name) + ".svg");
  std::vector<SvgLayer> layers{{&subject, "#4c72b0", "#4c72b0", "subject"},
                               {&clip, "#dd8452", "#dd8452", "clip"}};
  if (result != nullptr) {
    layers.push_back({&result->inside, "#55a868", "#1b5e20", "inside pieces"});
    layers.push_back({&result->outside, "none", "#c44e52", "outside pieces (outline)"});
  }
  write_svg(path, layers);
  return path;
}

::testing::AssertionResult AreaNear(double actual, double expected, double tolerance) {
  const double error = std::abs(actual - expected);
  if (error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "area " << actual << " differs from " << expected
                                       << " by " << error << " > " << tolerance;
}

void ExpectAreaNear(const PolygonSet2& result, double exact_area, double tolerance) {
  EXPECT_TRUE(AreaNear(exact_area_of_pieces(result), exact_area, tolerance));
}

::testing::AssertionResult IsValid(const PolygonSet2& polygons) {
  const std::string problem = validity_problem(polygons);
  if (problem.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << problem;
}

void ExpectValid(const PolygonSet2& polygons) { EXPECT_TRUE(IsValid(polygons)); }

void ExpectClipMatchesOracle(std::string_view name, const PolygonSet2& subject,
                             const PolygonSet2& clip, double relative_tolerance) {
  const ClipCheck check =
      check_clip(subject, clip, {.swapped = true, .symmetric_difference = true});
  const std::string why = check.failure(relative_tolerance * check.exact.subject,
                                        relative_tolerance * check.exact.clip);
  if (why.empty()) return;
  const std::string svg = write_case_svg(name, subject, clip, &check.forward);
  ADD_FAILURE() << name << ": " << why << '\n'
                << describe(check, subject, clip) << "picture: " << svg;
}

CaseFailures::CaseFailures(std::string suite, int reported)
    : suite_(std::move(suite)), reported_(reported) {}

namespace {

// A short name for the kind of a failure reason given by ClipCheck::failure.
std::string failure_kind(const std::string& why) {
  static const char* const kInvalidKinds[] = {
      "non-finite",     "vertices (at least", "zero-length", "visits vertex", "doubles back",
      "crosses itself", "touches itself",     "overlap",     "cross",         "inside an edge",
      "clockwise",      "not inside",         "lies inside"};
  if (why.rfind("invalid output", 0) == 0) {
    for (const char* kind : kInvalidKinds) {
      if (why.find(kind) != std::string::npos) return std::string("invalid output (") + kind + ")";
    }
    return "invalid output";
  }
  if (const std::size_t error = why.find(" error "); error != std::string::npos) {
    return why.substr(0, error) + " error";
  }
  return why.substr(0, why.find(':'));
}

}  // namespace

std::string CaseFailures::summary() const {
  std::string text;
  for (const auto& [kind, count] : kinds_) {
    text += (text.empty() ? "" : ", ") + kind + " " + std::to_string(count);
  }
  return text;
}

void CaseFailures::record(std::string_view case_name, const std::string& why,
                          const ClipCheck& check, const PolygonSet2& subject,
                          const PolygonSet2& clip) {
  if (why.empty()) return;
  ++count_;
  ++kinds_[failure_kind(why)];
  if (count_ > reported_) return;
  const std::string svg =
      write_case_svg(suite_ + "-" + std::string(case_name), subject, clip, &check.forward);
  ADD_FAILURE() << suite_ << " " << case_name << ": " << why << '\n'
                << describe(check, subject, clip) << "picture: " << svg
                << (count_ == reported_ ? "\n(further failures are only counted)" : "");
}

}  // namespace shadowgen::test
