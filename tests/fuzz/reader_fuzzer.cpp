// libFuzzer target for the readers: scene JSON (shadowgen/scene/scene_reader.h), the mesh
// files a scene references (OBJ, STL, OFF, PLY; glTF models as a scene's attached file)
// and the shadowed database (shadowgen/scene/database_reader.h; written by
// shadowgen/output/database.h).
//
// Input: byte 0 is a header: kind = header % 6; strict = (header / 6) % 2, the readers'
// ReadOptions::strict (--strict on the command line); generate = (header / 12) % 2, which
// asks for shadows of a tiny scene (the invariant `generate`, below: shadow generation
// costs far more than reading, so it is asked for, not done on every input). The other
// bytes are the content:
//   0 scene     the JSON text of a scene, read by parse_scene as <case>/scene.json. A NUL
//               byte may follow, then a file name, a NUL byte and the file's bytes (to the
//               end): that one file is written to <case>/<name> first, so that the scene
//               can reference a mesh. A name must be relative, of [A-Za-z0-9._/-] without
//               empty, "." or ".." parts, at most 64 characters; any other name leaves the
//               file out.
//   1 obj, 2 stl, 3 off, 4 ply
//               the bytes of a mesh file, written to <case>/mesh.<ext> and read through a
//               fixed scene that references it (kMeshScene: one sun, one lamp).
//   5 database  the JSON text of a shadowed database, read by parse_database.
// <case> is a folder inside a temporary folder made once per process (mkdtemp under
// $TMPDIR or /tmp, removed at exit); the files an input writes are removed after it. A
// scene whose text could name a file outside <case> (an absolute path, "..", an escaped
// '/' or '.') is left out, so that the fuzzer never reads the machine's files.
//
// Invariants, with the name a failure prints (SHADOWGEN_FUZZ_SKIP=name,... skips it; a
// name may carry a kind, as in off:reader-exception, and a kind alone skips its reader):
//   reader-exception    the reader returns or throws shadowgen::InputError; any other
//                       exception is a finding (crashes, aborts, sanitizer reports, hangs
//                       and running out of memory are libFuzzer's to catch);
//   finite              every number of what it read is finite;
//   database-json       database_json() writes what was read (for a scene, with no lit
//                       details yet) without throwing;
//   database-roundtrip  that text reads back (parse_database) and writes out the same;
//   report              report_rows() has finite numbers, report_json() is JSON whose
//                       numbers are all finite, report_csv() and report_table() hold no
//                       "inf" or "nan" token (not checked when an id holds one), and none
//                       throws anything but an InputError;
//   merge               a database that is shard 1 of 1 (generate --instants 1/1) merges
//                       alone (merge_shards) or throws InputError or GenerationError;
//                       what it makes goes through database-json, database-roundtrip
//                       and report (reports are not asked of a shard: they take whole
//                       databases);
//   generate            when the header asks for it, for a tiny scene (kTinyFaces faces,
//                       kTinyLights lights, kTinyVertices vertices at most),
//                       generate_shadows() throws nothing and its lit details are finite;
//                       the shadowed database it makes then goes through database-json,
//                       database-roundtrip and report.
// The output checks (database-json, database-roundtrip, report) run on what has at most
// kOutputRows (face, light) pairs: a sun path of thousands of instants, a few bytes of
// text, makes megabytes of output whose checks alone outlast -timeout under the
// sanitizers (a four-year path at 2-hour steps: 8,700 instants, 18 s).
// A broken invariant prints its name, the kind and the input, then traps.
// SHADOWGEN_FUZZ_VERBOSE=1 prints the outcome of every input.

#include <stdlib.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/database.h"
#include "shadowgen/output/report.h"
#include "shadowgen/pipeline/merge_shards.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/fuzz/reader_fuzz_case.h"

namespace shadowgen::fuzz {
namespace {

namespace fs = std::filesystem;

enum class Kind { kScene, kObj, kStl, kOff, kPly, kDatabase };
constexpr int kKinds = 6;

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::kScene:
      return "scene";
    case Kind::kObj:
      return "obj";
    case Kind::kStl:
      return "stl";
    case Kind::kOff:
      return "off";
    case Kind::kPly:
      return "ply";
    case Kind::kDatabase:
      return "database";
  }
  return "?";
}

// The scene through which mesh bytes are read; %s is the mesh file's extension.
constexpr const char* kMeshScene =
    R"({"format": "shadowgen-scene/1", "meshes": [{"id": "m", "file": "mesh.%s"}],
  "lights": [{"id": "sun", "type": "directional", "direction": [-0.3, 0.2, -1]},
             {"id": "lamp", "type": "point", "position": [0.5, 0.5, 3],
              "range": {"falloff_start": 2, "end": 10, "exponent": 2}}]})";

// Shadows are generated only for scenes this small, to keep every execution fast.
constexpr std::size_t kTinyFaces = 8;
constexpr std::size_t kTinyLights = 2;
constexpr std::size_t kTinyVertices = 64;
// The outputs are checked for at most this many (face, light) pairs.
constexpr std::size_t kOutputRows = 20'000;

// Checks and kinds named in SHADOWGEN_FUZZ_SKIP (comma separated) are not run, so that
// fuzzing can go on past a finding already recorded (tests/fuzz/findings/readers/).
bool enabled(std::string_view check, Kind kind) {
  static const std::string skip = [] {
    const char* value = std::getenv("SHADOWGEN_FUZZ_SKIP");
    std::string s(1, ',');
    s.append(value != nullptr ? value : "").push_back(',');
    return s;
  }();
  std::string key(1, ',');
  key.append(check).push_back(',');
  std::string kinded(1, ',');
  kinded.append(kind_name(kind)).push_back(':');
  kinded.append(check).push_back(',');
  return skip.find(key) == std::string::npos && skip.find(kinded) == std::string::npos;
}

bool verbose() {
  static const bool on = std::getenv("SHADOWGEN_FUZZ_VERBOSE") != nullptr;
  return on;
}

// The per-process folder, made on first use and removed at exit (by an atexit handler;
// the path itself is never destroyed, so that the handler can still use it).
const fs::path& process_dir() {
  static const fs::path* const dir = [] {
    std::error_code error;
    fs::path base = fs::temp_directory_path(error);
    if (error) base = "/tmp";
    std::string pattern = (base / "shadowgen-reader-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("reader_fuzzer: mkdtemp");
      std::abort();
    }
    return new fs::path(pattern);
  }();
  static const bool removed_at_exit = [] {
    return std::atexit([] {
             std::error_code ignored;
             fs::remove_all(process_dir(), ignored);
           }) == 0;
  }();
  (void)removed_at_exit;
  return *dir;
}

// <case>: where an input's files are written, and its scene is said to lie.
const fs::path& case_dir() {
  static const fs::path dir = [] {
    fs::path path = process_dir() / "case";
    fs::create_directories(path);
    return path;
  }();
  return dir;
}

void write_file(const fs::path& path, std::string_view bytes) {
  if (path.parent_path() != case_dir()) fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "reader_fuzzer: cannot write %s\n", path.c_str());
    std::abort();
  }
}

bool safe_name(std::string_view name) {
  if (name.empty() || name.size() > 64 || name.front() == '/') return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-' &&
        c != '/') {
      return false;
    }
  }
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string_view part = name.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") return false;
    start = end + 1;
  }
  return true;
}

std::string lowered(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Whether a mesh file name in this scene text could lead outside <case>: an absolute path,
// a "..", or a '/' or '.' written as an escape.
bool may_reach_outside(std::string_view text) {
  if (text.find("..") != std::string_view::npos || text.find("\"/") != std::string_view::npos ||
      text.find("\\/") != std::string_view::npos) {
    return true;
  }
  const std::string lower = lowered(text);
  return lower.find("\\u002f") != std::string::npos || lower.find("\\u002e") != std::string::npos;
}

// Whether `text` holds "inf" or "nan" as a token of its own (as printf and to_chars write
// them: "inf", "-inf", "nan", "-nan(...)"), case-insensitively.
bool has_non_finite_token(std::string_view text) {
  const std::string lower = lowered(text);
  for (const std::string_view token : {std::string_view("inf"), std::string_view("nan")}) {
    for (std::size_t at = lower.find(token); at != std::string::npos;
         at = lower.find(token, at + 1)) {
      const bool starts = at == 0 || (!std::isalnum(static_cast<unsigned char>(lower[at - 1])) &&
                                      lower[at - 1] != '_');
      const std::size_t after = at + token.size();
      const bool ends =
          after == lower.size() || !std::isalpha(static_cast<unsigned char>(lower[after]));
      if (starts && ends) return true;
    }
  }
  return false;
}

// A lit detail polygon, whatever ShadowedScene stores per polygon (the polygon itself, or a
// record holding it as `polygon`).
template <class Lit>
const hsr::Polygon3& polygon_of(const Lit& lit) {
  if constexpr (requires { lit.polygon; }) {
    return lit.polygon;
  } else {
    return lit;
  }
}

bool finite(double x) { return std::isfinite(x); }

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}
bool finite(const glm::dvec3& v) { return finite(v.x) && finite(v.y) && finite(v.z); }
bool finite(const hsr::Polygon3& polygon) {
  for (const glm::dvec3& p : polygon.outer) {
    if (!finite(p)) return false;
  }
  for (const hsr::Loop3& hole : polygon.holes) {
    for (const glm::dvec3& p : hole) {
      if (!finite(p)) return false;
    }
  }
  return true;
}

// The first non-finite number of `scene`, described; empty when there is none.
std::string non_finite_in(const Scene& scene) {
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      if (!finite(part)) return "face '" + face.id + "': a vertex coordinate";
    }
  }
  for (const Light& light : scene.lights) {
    if (!finite(light.direction) || !finite(light.position) || !finite(light.intensity)) {
      return "light '" + light.id + "': direction, position or intensity";
    }
    if (light.range && (!finite(light.range->falloff_start) || !finite(light.range->end) ||
                        !finite(light.range->exponent))) {
      return "light '" + light.id + "': range";
    }
  }
  for (const ViewSpec& view : scene.views) {
    if (!finite(view.eye) || !finite(view.target) || !finite(view.up) || !finite(view.fov_deg)) {
      return "view '" + view.id + "'";
    }
  }
  return "";
}

std::string non_finite_in(const ShadowedScene& shadowed) {
  std::string found = non_finite_in(shadowed.scene());
  if (!found.empty()) return found;
  for (std::size_t f = 0; f < shadowed.lit().size(); ++f) {
    for (const auto& per_light : shadowed.lit()[f]) {
      for (const auto& lit : per_light) {
        if (!finite(polygon_of(lit))) {
          return "face '" + shadowed.scene().faces[f].id + "': a lit detail's vertex coordinate";
        }
      }
    }
  }
  return "";
}

std::size_t vertex_count(const Scene& scene) {
  std::size_t count = 0;
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      count += part.outer.size();
      for (const hsr::Loop3& hole : part.holes) count += hole.size();
    }
  }
  return count;
}

// A number of `value` (a parsed JSON document) that is not finite, described; empty when
// there is none.
std::string non_finite_in(const nlohmann::json& value, const std::string& where) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) return where;
  if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      std::string found = non_finite_in(value[i], where + "[" + std::to_string(i) + "]");
      if (!found.empty()) return found;
    }
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      std::string found = non_finite_in(member, where + "." + key);
      if (!found.empty()) return found;
    }
  }
  return "";
}

class ReaderCase {
 public:
  ReaderCase(Kind kind, bool strict, bool generate, std::string_view content)
      : kind_(kind), strict_(strict), generate_(generate), content_(content) {}

  bool run() {
    if (!enabled(kind_name(kind_), kind_)) return false;
    // The files an input brings are removed after it, so no input sees another's files.
    const fs::path& dir = case_dir();
    std::error_code error;
    if (kind_ == Kind::kDatabase) {
      read_database(dir / "db.json");
      return true;
    }
    std::string text;
    fs::path written;  // the file or folder to remove afterwards
    bool tested = true;
    if (kind_ == Kind::kScene) {
      const std::size_t nul = content_.find('\0');
      text = std::string(content_.substr(0, nul));
      if (nul != std::string_view::npos) {
        const std::string_view rest = content_.substr(nul + 1);
        const std::size_t name_end = rest.find('\0');
        if (name_end != std::string_view::npos && safe_name(rest.substr(0, name_end))) {
          attachment_ = std::string(rest.substr(0, name_end));
          written = dir / *fs::path(attachment_).begin();
          write_file(dir / attachment_, rest.substr(name_end + 1));
        }
      }
      tested = !may_reach_outside(text);
    } else {
      const std::string ext = kind_name(kind_);
      written = dir / ("mesh." + ext);
      write_file(written, content_);
      std::vector<char> buffer(std::string_view(kMeshScene).size() + ext.size());
      std::snprintf(buffer.data(), buffer.size(), kMeshScene, ext.c_str());
      text = buffer.data();
    }
    if (tested) read_scene_text(text, dir / "scene.json");
    if (!written.empty()) fs::remove_all(written, error);
    return tested;
  }

 private:
  void read_scene_text(const std::string& text, const fs::path& path) {
    ReadResult read;
    try {
      ReadOptions options;
      options.strict = strict_;
      read = parse_scene(text, path, options);
    } catch (const InputError& e) {
      if (verbose()) {
        std::fprintf(stderr, "reader_fuzzer: %s: InputError: %s\n", kind_name(kind_), e.what());
      }
      return;
    } catch (const std::exception& e) {
      if (enabled("reader-exception", kind_)) {
        violation("reader-exception",
                  std::string("parse_scene threw a non-InputError: ") + e.what());
      }
      return;
    } catch (...) {
      if (enabled("reader-exception", kind_)) {
        violation("reader-exception", "parse_scene threw something that is no std::exception");
      }
      return;
    }
    const Scene& scene = read.scene;
    if (verbose()) {
      std::fprintf(
          stderr,
          "reader_fuzzer: %s: read %zu face(s), %zu light(s), %zu view(s), %zu warning(s)\n",
          kind_name(kind_), scene.faces.size(), scene.lights.size(), scene.views.size(),
          read.warnings.size());
      for (const std::string& warning : read.warnings) {
        std::fprintf(stderr, "  warning: %s\n", warning.c_str());
      }
    }
    if (enabled("finite", kind_)) {
      const std::string found = non_finite_in(scene);
      if (!found.empty()) violation("finite", "parse_scene returned a non-finite number: " + found);
    }

    // The scene as a database without lit details: what `report` and `generate` start from.
    const ShadowedScene unlit(scene, LitTable(scene.faces.size(), scene.lights.size()));
    check_outputs(unlit, "the scene read");

    if (generate_ && scene.faces.size() <= kTinyFaces && scene.lights.size() <= kTinyLights &&
        vertex_count(scene) <= kTinyVertices && enabled("generate", kind_)) {
      GenerateResult generated;
      try {
        GenerateOptions options;
        options.threads = 1;  // on this thread
        generated = generate_shadows(scene, options);
      } catch (const std::exception& e) {
        violation("generate", std::string("generate_shadows threw: ") + e.what());
      }
      if (verbose()) {
        std::size_t lit = 0;
        for (std::size_t f = 0; f < generated.shadowed.lit().size(); ++f) {
          for (const auto& per_light : std::as_const(generated.shadowed.lit())[f])
            lit += per_light.size();
        }
        std::fprintf(stderr, "reader_fuzzer: %s: generated %zu lit polygon(s)\n", kind_name(kind_),
                     lit);
      }
      const std::string found = non_finite_in(generated.shadowed);
      if (!found.empty()) {
        violation("generate", "generate_shadows made a non-finite number: " + found);
      }
      check_outputs(generated.shadowed, "the generated database");
    }
  }

  void read_database(const fs::path& path) {
    ShadowedScene shadowed;
    try {
      ReadOptions options;
      options.strict = strict_;
      std::vector<std::string> warnings;
      shadowed = parse_database(std::string(content_), path, options, warnings);
    } catch (const InputError& e) {
      if (verbose()) {
        std::fprintf(stderr, "reader_fuzzer: database: InputError: %s\n", e.what());
      }
      return;
    } catch (const std::exception& e) {
      if (enabled("reader-exception", kind_)) {
        violation("reader-exception",
                  std::string("parse_database threw a non-InputError: ") + e.what());
      }
      return;
    } catch (...) {
      if (enabled("reader-exception", kind_)) {
        violation("reader-exception", "parse_database threw something that is no std::exception");
      }
      return;
    }
    if (verbose()) {
      std::fprintf(stderr, "reader_fuzzer: database: read %zu face(s), %zu light(s)\n",
                   shadowed.scene().faces.size(), shadowed.scene().lights.size());
    }
    if (enabled("finite", kind_)) {
      const std::string found = non_finite_in(shadowed);
      if (!found.empty()) {
        violation("finite", "parse_database returned a non-finite number: " + found);
      }
    }
    check_outputs(shadowed, "the database read");
  }

  // database-json, database-roundtrip and report on `shadowed`.
  void check_outputs(const ShadowedScene& shadowed, const std::string& what) {
    if (shadowed.scene().faces.size() * shadowed.scene().lights.size() > kOutputRows) return;
    if (enabled("database-json", kind_)) {
      std::string text;
      try {
        text = database_json(shadowed);
      } catch (const std::exception& e) {
        violation("database-json", "database_json(" + what + ") threw: " + e.what());
      }
      if (enabled("database-roundtrip", kind_)) {
        std::string again;
        try {
          again = database_json(parse_database(text, case_dir() / "written.json"));
        } catch (const InputError& e) {
          violation("database-roundtrip",
                    "database_json(" + what + ") does not read back: " + e.what() + "\n" + text);
        } catch (const std::exception& e) {
          violation("database-roundtrip", "database_json(" + what +
                                              ") does not read back, and not with an InputError: " +
                                              e.what() + "\n" + text);
        }
        if (again != text) {
          violation("database-roundtrip", "database_json(" + what +
                                              ") reads back to another database:\n" + text +
                                              "\nthen\n" + again);
        }
      }
    }
    // Reports take a whole database: load_shadowed refuses a shard before any report.
    if (shadowed.shard) {
      if (enabled("merge", kind_)) check_merge(shadowed, what);
      return;
    }
    if (enabled("report", kind_)) check_report(shadowed, what);
  }

  // A shard 1 of 1 is a whole run's shards: merge_shards joins it or refuses it with an
  // InputError (or, where joining does not settle, a GenerationError), and what it makes
  // goes through the other invariants.
  void check_merge(const ShadowedScene& shadowed, const std::string& what) {
    if (shadowed.shard->count != 1) return;
    ShadowedScene merged;
    try {
      merged = merge_shards({{"shard.json", shadowed}});
    } catch (const InputError&) {
      return;
    } catch (const GenerationError&) {
      return;
    } catch (const std::exception& e) {
      violation("merge", "merge_shards(" + what + ") threw a non-InputError: " + e.what());
    }
    check_outputs(merged, "the merge of " + what);
  }

  void check_report(const ShadowedScene& shadowed, const std::string& what) {
    try {
      for (const ReportRow& row : report_rows(shadowed)) {
        if (!finite(row.area) || !finite(row.lit_area) || !finite(row.lit_fraction)) {
          violation("report",
                    "report_rows(" + what + "): face '" + shadowed.scene().faces[row.face].id +
                        "', light '" + shadowed.scene().lights[row.light].id + "': area " +
                        number_text(row.area) + ", lit area " + number_text(row.lit_area) +
                        ", lit fraction " + number_text(row.lit_fraction));
        }
      }
      const std::string json_text = report_json(shadowed);
      const nlohmann::json parsed = nlohmann::json::parse(json_text, nullptr, false);
      if (parsed.is_discarded()) {
        violation("report", "report_json(" + what + ") is not JSON:\n" + json_text);
      }
      const std::string found = non_finite_in(parsed, "report");
      if (!found.empty()) {
        violation("report", "report_json(" + what + "): " + found + " not finite");
      }
      if (!ids_hold_non_finite_token(shadowed.scene())) {
        const std::string csv = report_csv(shadowed);
        if (has_non_finite_token(csv)) {
          violation("report", "report_csv(" + what + ") holds inf or nan:\n" + csv);
        }
        const std::string table = report_table(shadowed);
        if (has_non_finite_token(table)) {
          violation("report", "report_table(" + what + ") holds inf or nan:\n" + table);
        }
      }
    } catch (const InputError& e) {
      // What the command line reports as bad input (exit status 1): an exit path allowed.
      if (verbose()) {
        std::fprintf(stderr, "reader_fuzzer: %s: a report of %s: InputError: %s\n",
                     kind_name(kind_), what.c_str(), e.what());
      }
    } catch (const std::exception& e) {
      violation("report", "a report of " + what + " threw a non-InputError: " + e.what());
    }
  }

  static bool ids_hold_non_finite_token(const Scene& scene) {
    for (const Face& face : scene.faces) {
      if (has_non_finite_token(face.id)) return true;
    }
    for (const Light& light : scene.lights) {
      if (has_non_finite_token(light.id)) return true;
    }
    return false;
  }

  [[noreturn]] void violation(const char* check, const std::string& what) const {
    std::fprintf(stderr, "reader_fuzzer [%s]: %s: %s\n", check, kind_name(kind_), what.c_str());
    std::fprintf(stderr, "  strict %s", strict_ ? "yes" : "no");
    if (!attachment_.empty()) std::fprintf(stderr, ", file '%s' attached", attachment_.c_str());
    std::fprintf(stderr, ", content of %zu byte(s)%s:\n", content_.size(),
                 content_.size() > 4096 ? " (the first 4096)" : "");
    std::string shown;
    for (const char c : content_.substr(0, 4096)) {
      const auto byte = static_cast<unsigned char>(c);
      if (byte == '\n' || (byte >= 0x20 && byte < 0x7f)) {
        shown += c;
      } else {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
        shown += escaped;
      }
    }
    std::fprintf(stderr, "%s\n", shown.c_str());
    __builtin_trap();
  }

  const Kind kind_;
  const bool strict_;
  const bool generate_;
  const std::string_view content_;
  std::string attachment_;
};

}  // namespace

bool run_reader_case(std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return false;
  const Kind kind = static_cast<Kind>(bytes[0] % kKinds);
  const bool strict = (bytes[0] / kKinds) % 2 == 1;
  const bool generate = (bytes[0] / (2 * kKinds)) % 2 == 1;
  const std::string_view content(reinterpret_cast<const char*>(bytes.data() + 1), bytes.size() - 1);
  return ReaderCase(kind, strict, generate, content).run();
}

}  // namespace shadowgen::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  shadowgen::fuzz::run_reader_case(std::span<const std::uint8_t>(data, size));
  return 0;
}
