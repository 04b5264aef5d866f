// A gzip database read from a file (shadowgen/scene/database_reader.h): the same scene as
// from its plain text, through every member, also where the members the header needs
// come after the faces (a second pass over the file, opened and inflated again); a
// truncated one names the file.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "shadowgen/compressed/gzip_members.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;

// Two faces, the format, lights and views after them.
const std::string kFacesFirst = R"({
  "faces": [
    {"id": "a", "source_file": "t.json",
     "parts": [{"outer": [[0.0,0.0,0.0],[4.0,0.0,0.0],[4.0,1.0,0.0],[0.0,1.0,0.0]], "holes": []}],
     "numbers": [0.0,1.0,2.0],
     "vertices": [0,0,0,2,0,0,2,1,0,0,1,0],
     "lit": {"sun": [[[0,1,2,3]]]}},
    {"id": "b", "source_file": "t.json",
     "parts": [{"outer": [[0.0,0.0,1.0],[1.0,0.0,1.0],[1.0,1.0,1.0],[0.0,1.0,1.0]], "holes": []}],
     "lit": {}}
  ],
  "format": "shadowgen-shadowed/2",
  "lights": [{"id": "sun", "type": "directional", "direction": [0.0, 0.0, -1.0],
              "intensity": [1.0, 1.0, 1.0]}],
  "views": []
}
)";

class DatabaseReaderGzip : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& bytes) const {
    return folder_.write(name, bytes);
  }

  test::TempFolder folder_{"shadowgen-db-gzip"};
};

TEST_F(DatabaseReaderGzip, ReadsAsThePlainTextInEveryMemberAndPass) {
  const std::string plain = database_json(read_database(write("db.json", kFacesFirst)));
  EXPECT_NE(plain.find("\"b\""), std::string::npos);
  // Members of 100 bytes: the faces span several, and the second pass reads them again.
  std::string gzip;
  compressed::GzipMembers members([&gzip](std::string_view bytes) { gzip.append(bytes); }, 1, 100);
  members.write(kFacesFirst);
  members.finish();
  EXPECT_EQ(database_json(read_database(write("db.gz.json", gzip))), plain);
}

TEST_F(DatabaseReaderGzip, TruncatedFileNamesIt) {
  const std::string gzip = compressed::gzip_member(kFacesFirst, 1);
  const fs::path file = write("db.json.gz", gzip.substr(0, gzip.size() / 2));
  try {
    read_database(file);
    FAIL() << "read";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        file.string() + ": the gzip data ends before its last member does (a truncated file)");
  }
}

}  // namespace
}  // namespace shadowgen
