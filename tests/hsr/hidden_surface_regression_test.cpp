// Minimal scenes that broke hidden-surface removal, each named after what broke it; the
// full oracle check (visibility_check.h) runs on every one of them.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hsr/hidden_surface.h"
#include "tests/hsr/scenes.h"
#include "tests/hsr/visibility_check.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::test {
namespace {

using hsr::Polygon3;

Scene scene(const char* name, std::vector<Polygon3> polygons, const glm::dvec3& direction) {
  ViewSpec view;
  view.direction = direction;
  return {name, std::move(polygons), {view}};
}

// A nearly edge-on quad crosses a large one; the clipper's difference of the large image
// and the thin front part came back empty, so the large quad vanished.
TEST(HiddenSurfaceRegression, ThinFrontPartOfANearlyEdgeOnQuad) {
  ExpectVisibilityMatchesOracles(
      scene("thin_front_part_of_a_nearly_edge_on_quad",
            {{{{0.41638709953102637, 0.93506240338187774, -0.2241380221996907},
               {0.25340062646773109, -0.10691101593558855, -1.0014722977096944},
               {0.32219855276887555, -0.67376289909318898, -0.25606394272854166},
               {0.48518502583217082, 0.3682105202242773, 0.52127033278146195}},
              {}},
             {{{-0.51965777346626063, -0.16650679020470049, -0.02377654186532055},
               {0.08340983274217445, -0.85426758277925208, -0.33135660984880311},
               {0.99664753505612813, 0.045256382279069474, -0.55215518291561916},
               {0.39357992884769299, 0.73301717485362106, -0.24457511493213654}},
              {}}},
            {0.28472611726788055, -0.93307959739322277, -0.21975782824295126}));
}

// Four stacked sticks at scale 1e5, no interpenetration: a vertex of one image lies
// 2.6e-13 from an edge of another, and the clipper's outside piece crossed itself, so
// the lowest stick's fragments covered more than its own image.
TEST(HiddenSurfaceRegression, StackedSticksWithAVertexWithinRoundingOfAnEdge) {
  ExpectVisibilityMatchesOracles(scene("stacked_sticks_with_a_vertex_within_rounding_of_an_edge",
                                       {{{{10571.796769724506, 114310.88913245536, 50000},
                                          {-93710.235533030631, -66310.889132455326, 0},
                                          {-79853.82907247961, -74310.889132455326, 0},
                                          {24428.203230275518, 106310.88913245534, 50000}},
                                         {}},
                                        {{{-121656.77804702109, -4227.340338340101, 130000},
                                          {50469.997186972163, -122004.00310443234, 80000},
                                          {59505.238266598149, -108799.29111843889, 80000},
                                          {-112621.53696739509, 8977.3716476533409, 130000}},
                                         {}},
                                        {{{-86569.805021501888, 16680.71844816102, 210000},
                                          {109048.74207119941, -55654.287448790637, 160000},
                                          {114597.924748188, -40647.403307923494, 160000},
                                          {-81020.622344513307, 31687.602589028156, 210000}},
                                         {}},
                                        {{{77448.374996379105, 129082.95778172834, 210000},
                                          {-83004.851239628813, -4160.1705034777187, 160000},
                                          {-72783.099680482352, -16469.345742423942, 160000},
                                          {87670.126555525567, 116773.78254278211, 210000}},
                                         {}}},
                                       {0.15, -0.1, -1.0}));
}

// Seven quads crossing each other: a piece and a template share a vertex where their
// edges are almost collinear, and the clipper's inside piece crossed itself.
TEST(HiddenSurfaceRegression, InterpenetratingQuadsWithAlmostCollinearEdgesAtASharedVertex) {
  ExpectVisibilityMatchesOracles(
      scene("interpenetrating_quads_with_almost_collinear_edges_at_a_shared_vertex",
            {{{{0.47791433637921932, 1.0603245556554279, 0.1795726382015006},
               {-0.30629544864504815, 0.98757641097573723, -0.26002975122157368},
               {-0.24553484690104935, -0.34615646839170572, -0.1477065809460919},
               {0.53867493812321809, -0.27340832371201512, 0.29189580847698238}},
              {}},
             {{{0.57440566692322825, 0.7852419950706987, 0.14386140341521125},
               {-0.34955326944870363, 0.93350407934048374, -0.39462161560199249},
               {-0.79383060256281368, -0.31912620334388475, 0.022803684156356807},
               {0.13012833380911831, -0.4673882876136698, 0.56128670317356055}},
              {}},
             {{{0.91211412397213953, -0.13470170736307208, 0.41983329139730768},
               {0.25890497563435538, -0.47058536191673261, -0.095880777796627403},
               {-0.51234316589980189, 0.57082953307727302, 0.20271898910931174},
               {0.14086598243798232, 0.90671318763093356, 0.71843305830324677}},
              {}},
             {{{0.35077500658019573, 0.084646563781937439, 0.4234923611019929},
               {-0.2891078909114454, 1.1520908161904548, -0.19065376784959456},
               {-1.0552343681065053, 0.70559574171758077, -0.16847235457404183},
               {-0.41535147061486427, -0.36184851069093671, 0.44567377437754568}},
              {}},
             {{{0.54660759838989581, -0.14076368523039184, 0.085868683421242625},
               {-0.18536270927692133, 0.071271444283125263, 0.06366281257466494},
               {-0.015603491075053655, 0.59073910604291824, -0.57190398571430867},
               {0.71636681659176349, 0.37870397652940113, -0.54969811486773101}},
              {}},
             {{{0.41638709953102637, 0.93506240338187774, -0.2241380221996907},
               {0.25340062646773109, -0.10691101593558855, -1.0014722977096944},
               {0.32219855276887555, -0.67376289909318898, -0.25606394272854166},
               {0.48518502583217082, 0.3682105202242773, 0.52127033278146195}},
              {}},
             {{{0.53191964229154842, -0.27845632149654864, -0.24579554443857196},
               {-0.7505876792893591, -0.62785549688826181, 0.14750307295902146},
               {-1.0052341339773361, 0.3603799901407595, 0.19505656255064616},
               {0.27727318760357145, 0.70977916553247267, -0.19824205484694726}},
              {}}},
            {0.28472611726788055, -0.93307959739322277, -0.21975782824295126}));
}

// Seven sticks of stacked cyclic triples seen from straight above: processed in another
// input order, a clip with a vertex of one piece within rounding of the other's edge
// crossed itself and stick 0 lost 2.5% of its visible area.
TEST(HiddenSurfaceRegression, SticksGiveTheSameAreasInAnotherInputOrder) {
  const std::vector<Polygon3> sticks{
      {{{-1.0428203230275512, -0.47999999999999965, 0.5},
        {1.0428203230275508, -0.48000000000000054, 0},
        {1.0428203230275508, -0.32000000000000051, 0},
        {-1.0428203230275512, -0.31999999999999962, 0.5}},
       {}},
      {{{-1.2606226707447818, -0.7235129362775099, 1.3},
        {0.80803296288479687, -0.45788015605310178, 0.80000000000000004},
        {0.78765493423624, -0.29918316191522093, 0.80000000000000004},
        {-1.2810006993933387, -0.56481594213962905, 1.3}},
       {}},
      {{{-0.9488154870839417, 0.21453904276698849, 2.1000000000000001},
        {0.91620492898919836, -0.71905388357056466, 1.6000000000000001},
        {0.98782554517566579, -0.57597877274736553, 1.6000000000000001},
        {-0.87719487089747428, 0.35761415359018761, 2.1000000000000001}},
       {}},
      {{{0.73970504417562266, -0.83547100188628876, 2.1000000000000001},
        {0.6157100271408269, 1.2464805201784501, 1.6000000000000001},
        {0.45599303842542888, 1.2369682378190263, 1.6000000000000001},
        {0.57998805546022469, -0.84498328424571256, 2.1000000000000001}},
       {}},
      {{{0.97243500400722716, 0.89917541996434414, 2.9000000000000004},
        {-0.96533590588450235, 0.12785136014608589, 2.4000000000000004},
        {-0.90616375184907461, -0.02080480752551668, 2.4000000000000004},
        {1.0316071580426549, 0.75051925229274163, 2.9000000000000004}},
       {}},
      {{{-0.93483165332706575, 0.33707527214482252, 2.9000000000000004},
        {0.70204003197155784, -0.95542153262677354, 2.4000000000000004},
        {0.80119397258669101, -0.82984886019964599, 2.4000000000000004},
        {-0.83567771271193259, 0.46264794457194997, 2.9000000000000004}},
       {}},
      {{{0.5055946828227742, -1.0336160309879452, 2.9000000000000004},
        {0.80649390741588012, 1.030204833601909, 2.4000000000000004},
        {0.64816781276531943, 1.0532883288463839, 2.4000000000000004},
        {0.34726858817221357, -1.0105325357434702, 2.9000000000000004}},
       {}}};
  const std::vector<std::size_t> order{5, 2, 1, 4, 6, 0, 3};
  std::vector<Polygon3> reordered;
  for (std::size_t i : order) reordered.push_back(sticks[i]);
  ExpectVisibilityMatchesOracles(scene("sticks_as_given", sticks, {0.0, 0.0, -1.0}));
  ExpectVisibilityMatchesOracles(scene("sticks_reordered", reordered, {0.0, 0.0, -1.0}));

  const hsr::View view = hsr::View::orthographic({0.0, 0.0, -1.0}, {0.0, 0.0, 0.0});
  const std::vector<double> as_given =
      visible_area_by_parent(hsr::remove_hidden_surfaces(sticks, view), sticks.size());
  const std::vector<double> shuffled =
      visible_area_by_parent(hsr::remove_hidden_surfaces(reordered, view), sticks.size());
  for (std::size_t j = 0; j < order.size(); ++j) {
    const double image = exact_area_of_pieces(hsr::project_polygon(sticks[order[j]], view));
    EXPECT_NEAR(shuffled[j], as_given[order[j]], 1e-9 * image) << "stick " << order[j];
  }
}

// A wall standing on the ground, seen from a lamp above it, 1e8 from the origin. The
// faces' nearness came from plane offsets of 1e8 less the eye's, which cancel and keep
// only a few digits: the ground was judged in front of the wall along its foot and took a
// strip 3e-6 high of it (the lamp's shadow generation lost 3.6e-6 of the wall's light).
// Nothing hides any of the wall from the lamp, in any of the six frusta around it.
TEST(HiddenSurfaceRegression, WallOnTheGroundSeenFromALampFarFromTheOrigin) {
  const glm::dvec3 shift(1e8, -1e8, 1e8);
  const glm::dvec3 a{1.1006911162676865, -0.0088780376854659115, 0.0};
  const glm::dvec3 b{1.758878037685466, 0.35069111626768634, 0.0};
  const glm::dvec3 up{0.0, 0.0, 2.0};
  std::vector<Polygon3> polygons{{{{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}}, {}},
                                 {{a, b, b + up, a + up}, {}}};
  for (Polygon3& p : polygons) {
    for (glm::dvec3& v : p.outer) v += shift;
  }
  const glm::dvec3 lamp = shift + glm::dvec3(0.25, -0.5, 3.0);
  const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::dvec3& axis : axes) {
    const glm::dvec3 roll = axis.z != 0.0 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    const hsr::View view = hsr::View::perspective(lamp, axis, roll, 90.0, 0.25);
    const double image = exact_area_of_pieces(hsr::project_polygon(polygons[1], view));
    const double seen = visible_area_by_parent(hsr::remove_hidden_surfaces(polygons, view), 2)[1];
    EXPECT_NEAR(seen, image, 1e-12 * image)
        << "frustum along " << axis.x << ' ' << axis.y << ' ' << axis.z;
  }
}

}  // namespace
}  // namespace shadowgen::test

namespace shadowgen::test {
namespace {

// Thakur, Cheng and Miura's cube grid, 5 x 5 x 5 cubes of side 0.1 spaced 0.2 apart,
// seen along (1, 2, -3): the fragments overlapped (their areas summed to 1.18308 where
// the images' union is 1.17773; 283 of 100,000 samples covered twice) until the clipper
// located stretches at exact midpoints and ordered crossings along an edge exactly.
std::vector<Polygon3> cube_grid(int k) {
  std::vector<Polygon3> faces;
  const double s = 1.0 / k;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      for (int l = 0; l < k; ++l) {
        const double x0 = (i + 0.25) * s, y0 = (j + 0.25) * s, z0 = (l + 0.25) * s;
        const double x1 = x0 + 0.5 * s, y1 = y0 + 0.5 * s, z1 = z0 + 0.5 * s;
        // The faces and their vertices in bench/scenes/box.h's order: the order of the
        // input decides which clips are made, and so whether the defect shows.
        faces.push_back({{{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, {}});
        faces.push_back({{{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, {}});
        faces.push_back({{{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, {}});
        faces.push_back({{{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}}, {}});
        faces.push_back({{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, {}});
        faces.push_back({{{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}}, {}});
      }
    }
  }
  return faces;
}

TEST(HiddenSurfaceRegression, CubeGridFragmentsDoNotOverlap) {
  ViewSpec view;  // bench/hsr_bench.cpp's oblique view
  view.point = {0.5, 0.5, 0.5};
  view.direction = {1.0, 2.0, -3.0};
  ExpectVisibilityMatchesOracles({"cube_grid_5", cube_grid(5), {view}});
}

}  // namespace
}  // namespace shadowgen::test
