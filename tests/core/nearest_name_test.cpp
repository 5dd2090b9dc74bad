// nearestName: the name a typo meant, by Damerau-Levenshtein distance worked
// out by hand; and the errors that offer it (an attribute's key or choice,
// a configuration's key).
#include "core/util/nearest_name.h"

#include <gtest/gtest.h>

#include "core/sim/attribute_table.h"
#include "core/util/error.h"

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

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(NearestName, AnAttributesKeyOrChoiceMistypedIsNamed) {
  const AttributeTable& table = AttributeTable::instance();
  EXPECT_NE(errorOf([&] {
              table.lookup("render.sise");
            }).find("unknown attribute 'render.sise' (did you mean 'render.size'?)"),
            std::string::npos);
  // An emitter's key keeps the emitter typed.
  EXPECT_NE(
      errorOf([&] { table.lookup("emitter.3.rat"); }).find("(did you mean 'emitter.3.rate'?)"),
      std::string::npos)
      << errorOf([&] { table.lookup("emitter.3.rat"); });
  EXPECT_NE(errorOf([&] {
              table.parse("render.color_by", "spead");
            }).find("cannot read 'spead' (did you mean 'speed'?) as one of the listed choices"),
            std::string::npos)
      << errorOf([&] { table.parse("render.color_by", "spead"); });
  EXPECT_EQ(errorOf([&] { table.parse("render.color_by", "temperature"); }).find("did you mean"),
            std::string::npos);
}

}  // namespace
}  // namespace sandstorm
