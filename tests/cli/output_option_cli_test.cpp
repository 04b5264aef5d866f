// End-to-end tests of -o/--output on every subcommand (cli/output_by_extension.h): render
// and export take their file by -o, its format told by the extension, beside the older
// --svg, --png and --obj; -o and an older option for one format is a usage error naming
// both, and the checks of cli/run_files.h hold for -o as for the older options.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

// A ground under a square lit straight down, with a view.
constexpr const char* kScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "roof", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}
  ],
  "lights": [{"id": "sun", "type": "directional", "direction": [0.2,0.1,-1]}],
  "views": [{"id": "main", "eye": [20,-15,12], "target": [5,5,0]}]
})";

const std::string kHint = "\nRun with --help for more information.\n";

class OutputOptionCli : public CliFolderTest<> {
 protected:
  OutputOptionCli() : CliFolderTest("shadowgen-output") {}

  void SetUp() override {
    CliFolderTest::SetUp();
    scene_ = write("scene.json", kScene).string();
    db_ = (dir_ / "db.json").string();
    const Outcome generated = run({"generate", scene_, "-o", db_});
    ASSERT_EQ(generated.code, 0) << generated.err;
  }

  // The files left but the scene and the database.
  std::vector<std::string> made() const {
    std::vector<std::string> names = files();
    std::erase(names, "scene.json");
    std::erase(names, "db.json");
    return names;
  }

  std::string scene_, db_;
};

TEST_F(OutputOptionCli, RenderTellsSvgFromPngByTheExtension) {
  const std::vector<std::string> look = {"render",  db_,  "--view",   "main",
                                         "--width", "64", "--height", "48"};
  auto with = [&look](std::vector<std::string> more) {
    more.insert(more.begin(), look.begin(), look.end());
    return more;
  };
  ASSERT_EQ(
      run(with({"--svg", (dir_ / "old.svg").string(), "--png", (dir_ / "old.png").string()})).code,
      0);
  const Outcome both =
      run(with({"-o", (dir_ / "new.svg").string(), "--output", (dir_ / "new.PNG").string()}));
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_EQ(both.err, "");
  EXPECT_EQ(contents(dir_ / "new.svg"), contents(dir_ / "old.svg"));
  EXPECT_EQ(contents(dir_ / "new.PNG"), contents(dir_ / "old.png"));
  // One -o, the other picture by its older option.
  ASSERT_EQ(run(with({"-o", (dir_ / "one.png").string(), "--svg", (dir_ / "one.svg").string(),
                      "--shadows", "exact"}))
                .code,
            0);
  EXPECT_EQ(contents(dir_ / "one.png"), contents(dir_ / "old.png"));
  EXPECT_EQ(contents(dir_ / "one.svg"), contents(dir_ / "old.svg"));
  // --by-light with the SVG named by -o.
  EXPECT_EQ(run(with({"-o", (dir_ / "layers.svg").string(), "--by-light"})).code, 0);
}

TEST_F(OutputOptionCli, RenderRefusesAnOutputItCannotTellOrOneNamedTwice) {
  const std::string svg = (dir_ / "x.svg").string(), png = (dir_ / "x.png").string();
  struct Case {
    std::vector<std::string> outputs;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"-o", (dir_ / "x.jpg").string()},
       "-o " + (dir_ / "x.jpg").string() +
           ": the extension tells what to write: .svg (SVG picture) or .png (PNG picture)"},
      {{"--svg", svg, "-o", (dir_ / "y.svg").string()},
       "--svg " + svg + " and -o " + (dir_ / "y.svg").string() +
           " both name the SVG picture; give one"},
      {{"-o", png, "-o", (dir_ / "y.png").string()},
       "-o " + png + " and -o " + (dir_ / "y.png").string() +
           " both name the PNG picture; give one"},
      {{}, "-o FILE.svg or -o FILE.png is required (or both; --svg and --png name them too)"},
      {{"-o", svg, "--shadows", "volumes"},
       "--shadows applies only to the PNG picture (-o FILE.png or --png)"},
      {{"-o", png, "--by-light"},
       "--by-light draws the SVG picture in layers: it needs -o FILE.svg (or --svg)"},
      // Two outputs that are one file, and an output that is the input (run_files.h).
      {{"-o", svg, "--png", svg},
       "-o " + svg + " and --png " + svg + " name the same file; one would be lost"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"render", db_, "--view", "main"};
    args.insert(args.end(), c.outputs.begin(), c.outputs.end());
    const Outcome out = run(args);
    EXPECT_EQ(out.code, 2) << c.message << "\n" << out.err;
    EXPECT_EQ(out.err, "shadowgen: " + c.message + kHint);
  }
  const std::string input = (dir_ / "db.svg").string();  // a database by content
  fs::copy_file(db_, input);
  const Outcome replaced = run({"render", input, "--view", "main", "-o", input});
  EXPECT_EQ(replaced.code, 2);
  EXPECT_EQ(replaced.err, "shadowgen: -o " + input + ": is the input " + input +
                              "; it would be replaced" + kHint);
  fs::remove(input);
  EXPECT_EQ(made(), std::vector<std::string>{});
}

TEST_F(OutputOptionCli, ExportWritesTheObjThatMinusONames) {
  ASSERT_EQ(run({"export", db_, "--obj", (dir_ / "old.obj").string()}).code, 0);
  const Outcome exported = run({"export", db_, "-o", (dir_ / "new.obj").string()});
  ASSERT_EQ(exported.code, 0) << exported.err;
  EXPECT_EQ(exported.err, "");
  EXPECT_EQ(contents(dir_ / "new.mtl"), contents(dir_ / "old.mtl"));
  std::string obj = contents(dir_ / "old.obj");
  obj.replace(obj.find("mtllib old.mtl"), 14, "mtllib new.mtl");
  EXPECT_EQ(contents(dir_ / "new.obj"), obj);
}

TEST_F(OutputOptionCli, ExportRefusesAnOutputItCannotTellOrOneNamedTwice) {
  const std::string obj = (dir_ / "x.obj").string();
  struct Case {
    std::vector<std::string> outputs;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"-o", (dir_ / "x.stl").string()},
       "-o " + (dir_ / "x.stl").string() +
           ": the extension tells what to write: .obj (OBJ file) or .glb (binary glTF file) or "
           ".gltf (glTF file)"},
      {{"-o", obj, "--obj", (dir_ / "y.obj").string()},
       "--obj " + (dir_ / "y.obj").string() + " and -o " + obj +
           " both name the OBJ file; give one"},
      {{},
       "-o FILE.obj, FILE.glb or FILE.gltf is required (--obj FILE and --gltf FILE name them "
       "too)"},
      {{"-o", "-"}, "-o -: an OBJ and its MTL are two files, not one stream"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"export", db_};
    args.insert(args.end(), c.outputs.begin(), c.outputs.end());
    const Outcome out = run(args);
    EXPECT_EQ(out.code, 2) << c.message << "\n" << out.err;
    EXPECT_EQ(out.err, "shadowgen: " + c.message + kHint);
  }
  // The MTL of -o is an output too: a link named like it to the OBJ is one file.
  write("z.obj", "# an older export\n");
  fs::create_symlink(dir_ / "z.obj", dir_ / "z.mtl");
  const Outcome linked = run({"export", db_, "-o", (dir_ / "z.obj").string()});
  EXPECT_EQ(linked.code, 2);
  EXPECT_EQ(linked.err, "shadowgen: -o " + (dir_ / "z.obj").string() + " and -o's MTL " +
                            (dir_ / "z.mtl").string() + " name the same file; one would be lost" +
                            kHint);
  EXPECT_EQ(contents(dir_ / "z.obj"), "# an older export\n");
  fs::remove(dir_ / "z.mtl");
  fs::remove(dir_ / "z.obj");
  EXPECT_EQ(made(), std::vector<std::string>{});
}

// The subcommands that always wrote to -o keep it: report, sun, compare, merge, generate.
TEST_F(OutputOptionCli, EverySubcommandNamesItsFileWithMinusO) {
  const std::vector<std::vector<std::string>> runs = {
      {"report", db_, "-o", (dir_ / "report.csv").string()},
      {"compare", scene_, "--methods", "rays:4", "-o", (dir_ / "compare.txt").string()},
      {"generate", scene_, "--output", (dir_ / "again.json").string()},
      {"export", db_, "--output", (dir_ / "model.obj").string()},
      {"render", db_, "--view", "main", "--output", (dir_ / "picture.svg").string()},
  };
  for (const std::vector<std::string>& args : runs) {
    const Outcome out = run(args);
    EXPECT_EQ(out.code, 0) << args[0] << ": " << out.err;
  }
  EXPECT_EQ(made(), (std::vector<std::string>{"again.json", "compare.txt", "model.mtl", "model.obj",
                                              "picture.svg", "report.csv"}));
}

}  // namespace
}  // namespace shadowgen::test
