// nearestName: the name a typo meant, by Damerau-Levenshtein distance worked
// out by hand. The errors that offer it: attribute_table_test.cpp (a key or
// choice), config_test.cpp (a configuration's key).
#include "core/util/nearest_name.h"

#include <gtest/gtest.h>

namespace sandstorm {
namespace {

TEST(NearestName, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(editDistance("size", "size"), 0u);
  EXPECT_EQ(editDistance("sise", "size"), 1u);   // a substitution
  EXPECT_EQ(editDistance("szie", "size"), 1u);   // neighbours swapped
  EXPECT_EQ(editDistance("siz", "size"), 1u);    // a deletion
  EXPECT_EQ(editDistance("sizes", "size"), 1u);  // an insertion
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("SPEED", "speed"), 0u);  // without case
}

TEST(NearestName, OffersTheOneNearestWithinAThirdOfTheWord) {
  const std::vector<std::string> names = {"age", "speed", "velocity_x", "velocity_y", "array"};
  EXPECT_EQ(nearestName("spead", names), "speed");
  EXPECT_EQ(nearestName("Speed", names), "speed");  // only the case differs
  EXPECT_EQ(nearestName("velocity_xx", names), "velocity_x");
  EXPECT_EQ(nearestName("velocity_z", names), std::nullopt);  // as near x as y: no guess
  EXPECT_EQ(nearestName("temperature", names), std::nullopt);
  EXPECT_EQ(nearestName("speed", names), std::nullopt);  // not a typo
  EXPECT_EQ(didYouMean("arary", names), " (did you mean 'array'?)");
  EXPECT_EQ(didYouMean("zzz", names), "");
  EXPECT_EQ(nearestName(std::string(65, 'a'), {std::string(64, 'a')}), std::nullopt);  // too long
  EXPECT_EQ(nearestName(std::string(63, 'a'), {std::string(64, 'a')}), std::string(64, 'a'));
}

}  // namespace
}  // namespace sandstorm
