// The scheme's skeleton (the lines that draw a set as a figure, COCO keypoints' "skeleton"): read
// from the scheme JSON by id, derived from the regions when absent, and the errors for a line that
// is not a pair, joins a point to itself, repeats, or names an unknown landmark.
#include <gtest/gtest.h>

#include <string>

#include "core/common/error.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {
namespace {

std::string skeletonScheme(const std::string& skeleton) {
  return R"({"name": "three", "landmarks": [{"id": "a"}, {"id": "b"}, {"id": "c"}],
             "regions": [{"name": "r", "landmarks": ["c", "a", "b"]}],
             "normalisation": ["a", "b"])" +
         (skeleton.empty() ? std::string() : ", \"skeleton\": " + skeleton) + "}";
}

std::string skeletonError(const std::string& skeleton) {
  try {
    Scheme::fromJson(skeletonScheme(skeleton), "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SchemeSkeleton, ReadsLinesById) {
  const Scheme scheme = Scheme::fromJson(skeletonScheme(R"([["a", "b"], [2, "a"]])"), "s.json");
  ASSERT_EQ(scheme.skeleton().size(), 2u);
  EXPECT_EQ(scheme.skeleton()[0], (std::pair<int, int>{0, 1}));
  EXPECT_EQ(scheme.skeleton()[1], (std::pair<int, int>{2, 0}));
}

TEST(SchemeSkeleton, WithoutOneTheRegionsAreJoinedInOrder) {
  const Scheme scheme = Scheme::fromJson(skeletonScheme(""), "s.json");
  ASSERT_EQ(scheme.skeleton().size(), 2u);
  EXPECT_EQ(scheme.skeleton()[0], (std::pair<int, int>{2, 0}));
  EXPECT_EQ(scheme.skeleton()[1], (std::pair<int, int>{0, 1}));
}

TEST(SchemeSkeleton, BuiltInSchemesHaveOneOverEveryPoint) {
  for (const Scheme* scheme : {&Scheme::thesis25(), &Scheme::ibug68()}) {
    std::vector<bool> joined(static_cast<std::size_t>(scheme->size()), false);
    for (const auto& [a, b] : scheme->skeleton()) {
      joined[static_cast<std::size_t>(a)] = true;
      joined[static_cast<std::size_t>(b)] = true;
    }
    for (int i = 0; i < scheme->size(); ++i) {
      EXPECT_TRUE(joined[static_cast<std::size_t>(i)]) << scheme->name() << " " << scheme->id(i);
    }
  }
  EXPECT_EQ(Scheme::thesis25().skeleton().size(), 21u);
  EXPECT_EQ(Scheme::ibug68().skeleton().size(), 64u);
}

TEST(SchemeSkeleton, ErrorsNameTheLine) {
  EXPECT_NE(skeletonError(R"([["a"]])").find("s.json: field skeleton[0]: must be a pair"),
            std::string::npos);
  EXPECT_NE(
      skeletonError(R"([["a", "a"]])").find("field skeleton[0]: joins landmark \"a\" to itself"),
      std::string::npos);
  EXPECT_NE(
      skeletonError(R"([["a", "b"], ["b", "a"]])").find("field skeleton[1]: repeats the line"),
      std::string::npos);
  EXPECT_NE(skeletonError(R"([["a", "z"]])").find("skeleton[0][1]"), std::string::npos);
  EXPECT_NE(skeletonError(R"({"a": "b"})").find("field skeleton: must be an array"),
            std::string::npos);
}

}  // namespace
}  // namespace clm3d
