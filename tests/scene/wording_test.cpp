// "Did you mean …": which misspellings find their name, and which are left
// alone (too far off, or as near to two names).
#include "zeroset/scene/wording.hpp"

#include <gtest/gtest.h>

namespace zeroset {
namespace {

constexpr std::string_view keys[] = {"color", "ambient", "diffuse", "specular", "shininess", "reflection"};

TEST(ClosestName, FindsTypicalSlips) {
    EXPECT_EQ(closest_name("colour", keys), "color");      // an insertion
    EXPECT_EQ(closest_name("difuse", keys), "diffuse");    // a deletion
    EXPECT_EQ(closest_name("specualr", keys), "specular"); // a swap counts once
    EXPECT_EQ(closest_name("Ambient", keys), "ambient");   // case is ignored
    EXPECT_EQ(did_you_mean("shinyness", keys), "; did you mean 'shininess'?");
}

TEST(ClosestName, LeavesFarAndTiedWordsAlone) {
    EXPECT_FALSE(closest_name("metallic", keys));           // nothing near
    EXPECT_FALSE(closest_name("color", keys));              // the name itself needs no suggestion
    EXPECT_EQ(did_you_mean("xyz", keys), "");
    constexpr std::string_view two[] = {"cat", "car"};
    EXPECT_FALSE(closest_name("cab", two));                 // as near to both
    EXPECT_FALSE(closest_name(std::string(200, 'a'), keys)); // too long to be a slip
}

TEST(UnknownChoice, ListsTheFamilyAndSuggests) {
    constexpr std::string_view modes[] = {"analytic", "fd", "central"};
    EXPECT_EQ(unknown_choice("normal mode", "centrl", modes),
              "unknown normal mode 'centrl' (expected analytic, fd or central); did you mean 'central'?");
}

}  // namespace
}  // namespace zeroset
