// The built-in schemes match DESIGN.md (table 3.1 of the thesis) and bad scheme files are rejected
// with messages that name the file and the field.
#include "core/scheme/scheme.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// Runs fromJson and returns the InputError message ("" if it did not throw).
std::string schemeError(const std::string& json) {
  try {
    Scheme::fromJson(json, "lab.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kMinimal = R"({"name": "tiny", "landmarks": [{"id": "a"}, {"id": "b"}, {"id": "c"}],
  "mirror_pairs": [["a", "c"]], "regions": [{"name": "r", "colour": "#ff0080",
  "landmarks": ["a", 1]}], "normalisation": ["a", "c"]})";

TEST(Scheme, Thesis25MatchesTheDesign) {
  const auto& s = Scheme::thesis25();
  EXPECT_EQ(s.name(), "thesis25");
  ASSERT_EQ(s.size(), 25);
  EXPECT_EQ(s.id(0), "mid_eyes");
  EXPECT_EQ(s.id(7), "left_eye_centre");
  EXPECT_EQ(s.label(1), "Outer corner of the left eye");
  EXPECT_EQ(s.id(24), "right_earlobe");
  EXPECT_EQ(s.normalisationPair(), std::make_pair(7, 10));  // points 8 and 11
  // Mirror pairs of DESIGN.md, 1-based.
  const std::vector<std::pair<int, int>> pairs = {{2, 3},   {4, 7},   {5, 6},   {8, 11},  {9, 10},
                                                  {13, 14}, {15, 16}, {19, 25}, {20, 24}, {21, 23}};
  for (const auto& [a, b] : pairs) {
    EXPECT_EQ(s.mirrorOf(a - 1), b - 1);
    EXPECT_EQ(s.mirrorOf(b - 1), a - 1);
  }
  for (const int mid : {1, 12, 17, 18, 22}) EXPECT_EQ(s.mirrorOf(mid - 1), mid - 1);
  // Regions of DESIGN.md, 1-based.
  const std::vector<std::pair<std::string, std::vector<int>>> regions = {
      {"left_eye", {2, 4, 5, 8, 9}},
      {"right_eye", {3, 6, 7, 10, 11}},
      {"nose", {1, 12, 13, 14}},
      {"mouth", {15, 16, 17, 18}},
      {"jaw", {19, 20, 21, 22, 23, 24, 25}}};
  ASSERT_EQ(s.regions().size(), regions.size());
  for (std::size_t r = 0; r < regions.size(); ++r) {
    EXPECT_EQ(s.regions()[r].name, regions[r].first);
    std::vector<int> oneBased;
    for (const int i : s.regions()[r].indices) oneBased.push_back(i + 1);
    EXPECT_EQ(oneBased, regions[r].second);
    for (const int i : s.regions()[r].indices) EXPECT_EQ(s.regionOf(i), static_cast<int>(r));
  }
}

TEST(Scheme, MirrorPairsAreSymmetricAndCrossTheMidline) {
  for (const auto* s : {&Scheme::thesis25(), &Scheme::ibug68()}) {
    for (int i = 0; i < s->size(); ++i) {
      EXPECT_EQ(s->mirrorOf(s->mirrorOf(i)), i) << s->name() << " " << s->id(i);
      const auto& id = s->id(i);
      const auto& mirror = s->id(s->mirrorOf(i));
      // A left point mirrors to a right point (ids say which side).
      if (id.find("left") != std::string::npos) {
        EXPECT_NE(mirror.find("right"), std::string::npos) << id << " -> " << mirror;
      }
    }
  }
}

TEST(Scheme, Ibug68FollowsTheIbugOrder) {
  const auto& s = Scheme::ibug68();
  ASSERT_EQ(s.size(), 68);
  EXPECT_EQ(s.mirrorOf(0), 16);
  EXPECT_EQ(s.mirrorOf(8), 8);
  EXPECT_EQ(s.mirrorOf(36), 45);
  EXPECT_EQ(s.mirrorOf(39), 42);
  EXPECT_EQ(s.mirrorOf(48), 54);
  EXPECT_EQ(s.mirrorOf(51), 51);
  EXPECT_EQ(s.mirrorOf(30), 30);
  EXPECT_EQ(s.indexOf("left_eye_3"), 45);
  EXPECT_EQ(s.indexOf("nose_bridge_3"), 30);
  EXPECT_EQ(s.normalisationPair(), std::make_pair(36, 45));
  for (int i = 0; i < s.size(); ++i) EXPECT_GE(s.regionOf(i), 0) << i;
  ASSERT_EQ(s.ljsonLayouts().size(), 1u);
}

TEST(Scheme, LookupsAndRanges) {
  const auto s = Scheme::fromJson(kMinimal, "lab.json");
  EXPECT_EQ(s.indexOf("b"), 1);
  EXPECT_EQ(s.indexOf("nope"), -1);
  EXPECT_EQ(s.label(1), "b");  // label defaults to the id
  EXPECT_EQ(s.mirrorOf(1), 1);
  EXPECT_EQ(s.regionOf(2), -1);
  EXPECT_EQ(s.regions()[0].colour, (RgbColour{255, 0, 128}));
  EXPECT_THROW(s.id(3), std::out_of_range);
  EXPECT_THROW(s.mirrorOf(-1), std::out_of_range);
}

TEST(Scheme, ValidationErrorsNameTheFileAndField) {
  struct Case {
    std::string json;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"not json", "not valid JSON"},
      {"[]", "must be a JSON object"},
      {R"({"landmarks": [{"id": "a"}], "normalisation": ["a", "a"]})", "field name: missing"},
      {R"({"name": "x", "normalisation": [0, 1]})", "field landmarks: missing"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "a"}], "normalisation": [0, 1]})",
       "landmarks[1].id: duplicate landmark id \"a\""},
      {R"({"name": "x", "landmarks": [{"label": "A"}], "normalisation": [0, 1]})",
       "landmarks[0].id: missing"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}]})", "normalisation: missing"},
      // Unknown keys are refused, naming the key.
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "mirrorpairs": []})",
       "field mirrorpairs: unknown field"},
      {R"({"name": "x", "landmarks": [{"id": "a", "colour": "#ff0000"}, {"id": "b"}],
          "normalisation": [0, 1]})",
       "field landmarks[0].colour: unknown field"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "regions": [{"name": "r", "landmarks": ["a"], "color": "#ff0000"}]})",
       "field regions[0].color: unknown field"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 2]})",
       "normalisation[1]: landmark index 2 out of range 0..1"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "mirror_pairs": [["a", 7]]})",
       "mirror_pairs[0][1]: landmark index 7 out of range"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "mirror_pairs": [["a", "zz"]]})",
       "unknown landmark id \"zz\""},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "mirror_pairs": [["a", "a"]]})",
       "with itself"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}, {"id": "c"}],
          "normalisation": [0, 1], "mirror_pairs": [["a", "b"], ["b", "c"]]})",
       "mirror_pairs[1]: landmark \"b\" is already in another pair"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "regions": [{"name": "r", "landmarks": [5]}]})",
       "regions[0].landmarks[0]: landmark index 5 out of range"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "regions": [{"name": "r", "landmarks": [0]}, {"name": "s", "landmarks": [0]}]})",
       "already in region \"r\""},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "regions": [{"name": "r", "colour": "red", "landmarks": [0]}]})",
       "regions[0].colour: must be \"#rrggbb\""},
      {R"({"name": "x", "version": 2, "landmarks": [{"id": "a"}], "normalisation": [0, 0]})",
       "unsupported scheme version"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "ljson_layouts": [{"name": "l", "labels": [{"label": "g", "landmarks": ["b"]}]}]})",
       "ljson_layouts[0]: does not place landmark \"a\""},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "ljson_layouts": [{"name": "l", "labels": [{"label": "g", "landmarks": ["b", 1]}]}]})",
       "ljson_layouts[0].labels[0].landmarks[1]: landmark \"b\" appears twice"},
      {R"({"name": "x", "landmarks": [{"id": "a b"}], "normalisation": [0, 0]})",
       "landmarks[0].id: \"a b\" is not a word"},
      {R"({"name": "x", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": ["a", "a"]})",
       "normalisation: must name two different landmarks"},
  };
  for (const auto& c : cases) {
    const auto message = schemeError(c.json);
    EXPECT_NE(message.find("lab.json: "), std::string::npos) << c.json << "\n-> " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.json << "\n-> " << message;
  }
}

TEST(Scheme, LoadNamesTheFile) {
  test::TempDir dir;
  test::writeFile(dir / "mine.json", kMinimal);
  EXPECT_EQ(Scheme::load(dir / "mine.json").size(), 3);
  EXPECT_EQ(Scheme::byNameOrPath((dir / "mine.json").string()).name(), "tiny");
  EXPECT_EQ(Scheme::byNameOrPath("ibug68").size(), 68);
  test::writeFile(dir / "broken.json", R"({"name": "x"})");
  try {
    Scheme::load(dir / "broken.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: field landmarks: missing"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(Scheme::byNameOrPath("thesis26"), InputError);
  EXPECT_THROW(Scheme::load(dir / "absent.json"), InputError);
}

}  // namespace
}  // namespace clm3d
