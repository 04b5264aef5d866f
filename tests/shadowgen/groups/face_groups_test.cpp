// Groups of faces (shadowgen/groups/face_groups.h): a scene's groups and --group-by's rules
// resolved against the faces, each face once per group, in scene order; origin groups in
// the order their values first appear; every way a group can name nothing, an error.

#include "shadowgen/groups/face_groups.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"

namespace shadowgen::groups {
namespace {

using Faces = std::vector<std::size_t>;

Face face(std::string id, FaceOrigin origin = {}) {
  Face f;
  f.id = std::move(id);
  f.origin = std::move(origin);
  return f;
}

// A garden scene and a district of two buildings, one with a part (CityJSON origins).
Scene scene() {
  Scene s;
  s.file = "scene.json";
  s.faces = {face("garden"),
             face("garden-bed"),
             face("lawn/0"),
             face("lawn/1"),
             face("d/b1/0", {"cityjson", "b1", "b1", "RoofSurface"}),
             face("d/b2-part/0", {"cityjson", "b2-part", "b2", "WallSurface"}),
             face("d/b1/1", {"cityjson", "b1", "b1", "WallSurface"}),
             face("d/b2/0", {"cityjson", "b2", "b2", "RoofSurface"})};
  return s;
}

std::string input_error(const auto& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneGroups, EachGroupHoldsWhatAnyOfItsPatternsMatchesOnceInSceneOrder) {
  Scene s = scene();
  s.groups = {{"garden", {"lawn/*", "garden*", "garden"}}, {"district", {"d/**"}}};
  const std::vector<FaceGroup> groups = scene_groups(s);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].id, "garden");
  EXPECT_EQ(groups[0].faces, (Faces{0, 1, 2, 3}));
  EXPECT_EQ(groups[1].id, "district");
  EXPECT_EQ(groups[1].faces, (Faces{4, 5, 6, 7}));
}

TEST(SceneGroups, APatternMatchingNoFaceOrAnIdGivenTwiceIsAnError) {
  Scene s = scene();
  s.groups = {{"garden", {"garden", "gardn*"}}};
  EXPECT_EQ(input_error([&] { (void)scene_groups(s); }),
            "scene.json: group 'garden': the pattern 'gardn*' matches no face id");
  s.groups = {{"garden", {"garden"}}, {"garden", {"lawn/*"}}};
  EXPECT_EQ(input_error([&] { (void)scene_groups(s); }),
            "scene.json: group 'garden' is given twice in the scene's groups");
}

TEST(GroupsBy, AnOriginKeyGivesAGroupPerValueInTheOrderOfItsFirstFace) {
  const Scene s = scene();
  const std::vector<std::string> rules{"origin.group", "origin.semantic", "garden*"};
  const std::vector<FaceGroup> groups = groups_by(s, rules);
  ASSERT_EQ(groups.size(), 5u);
  EXPECT_EQ(groups[0].id, "b1");  // a building holding its parts, faces without one left out
  EXPECT_EQ(groups[0].faces, (Faces{4, 6}));
  EXPECT_EQ(groups[1].id, "b2");
  EXPECT_EQ(groups[1].faces, (Faces{5, 7}));
  EXPECT_EQ(groups[2].id, "RoofSurface");
  EXPECT_EQ(groups[2].faces, (Faces{4, 7}));
  EXPECT_EQ(groups[3].id, "WallSurface");
  EXPECT_EQ(groups[3].faces, (Faces{5, 6}));
  EXPECT_EQ(groups[4].id, "garden*");  // a pattern's group is named by the pattern
  EXPECT_EQ(groups[4].faces, (Faces{0, 1}));
  const std::vector<FaceGroup> objects = groups_by(s, std::vector<std::string>{"origin.object"});
  ASSERT_EQ(objects.size(), 3u);
  EXPECT_EQ(objects[1].id, "b2-part");
  EXPECT_EQ(objects[1].faces, (Faces{5}));
}

TEST(GroupsBy, SceneGroupsAreTheScenesOwnAmongTheOtherRules) {
  Scene s = scene();
  s.groups = {{"lawn", {"lawn/*"}}};
  const std::vector<FaceGroup> groups =
      groups_by(s, std::vector<std::string>{"garden", "scene.groups"});
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].id, "garden");
  EXPECT_EQ(groups[0].faces, (Faces{0}));
  EXPECT_EQ(groups[1].id, "lawn");
  EXPECT_EQ(groups[1].faces, (Faces{2, 3}));
  s.groups.clear();
  EXPECT_EQ(input_error([&] { (void)groups_by(s, std::vector<std::string>{"scene.groups"}); }),
            "scene.json: --group-by scene.groups: the input has no groups (a scene's \"groups\" "
            "key, kept in its database)");
}

TEST(GroupsBy, WhatNamesNoFaceIsAnError) {
  Scene s = scene();
  EXPECT_EQ(input_error([&] { (void)groups_by(s, std::vector<std::string>{"lawn/*/x"}); }),
            "scene.json: --group-by: the pattern 'lawn/*/x' matches no face id");
  s.faces.resize(4);  // no face with an origin
  EXPECT_EQ(input_error([&] { (void)groups_by(s, std::vector<std::string>{"origin.semantic"}); }),
            "scene.json: --group-by origin.semantic: no face has a semantic type (faces read from "
            "EnergyPlus, CityJSON and glTF models have origins)");
  EXPECT_THROW((void)groups_by(s, std::vector<std::string>{"lawn/*", "lawn/*"}),
               std::invalid_argument);
  EXPECT_THROW((void)groups_by(s, std::vector<std::string>{"origin.zone"}), std::invalid_argument);
}

TEST(GroupsBy, TwoRulesGivingOneGroupIdAreAnError) {
  Scene s = scene();
  s.faces.push_back(face("b1"));
  EXPECT_EQ(input_error([&] {
              (void)groups_by(s, std::vector<std::string>{"origin.group", "b1"});
            }),
            "scene.json: group 'b1' is given twice by --group-by's rules");
}

TEST(GroupRuleProblem, OriginKeysAreTheFourOfFaceOriginAndPatternsAsFacePatternSays) {
  EXPECT_EQ(group_rule_problem("origin.group"), std::nullopt);
  EXPECT_EQ(group_rule_problem("garden*"), std::nullopt);
  EXPECT_EQ(group_rule_problem("origin\\.zone"), std::nullopt);  // a pattern
  EXPECT_EQ(group_rule_problem("origin.zone"),
            "'origin.zone': the origin keys are origin.format, origin.object, origin.group and "
            "origin.semantic (a face pattern beginning with 'origin.' is written 'origin\\.')");
  EXPECT_EQ(group_rule_problem("scene.group"),
            "'scene.group': the scene's groups are scene.groups (a face pattern beginning with "
            "'scene.' is written 'scene\\.')");
  EXPECT_EQ(group_rule_problem(""), "'': a face pattern must not be empty");
}

}  // namespace
}  // namespace shadowgen::groups
