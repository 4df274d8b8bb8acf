// A number field's rule: text read whole and checked against the key's range, refused in the
// field's own words (issue 45: "0-5" was read as 0 and reverted without a word).
#include "number_rules.h"

#include <gtest/gtest.h>

namespace paver::studio {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(NumberRules, TextIsReadWholeSoAnExpressionIsNoNumber) {
  const NumberRule spacing = NumberRule::of(Key::pattern_spacing, "mm");
  const TypedNumber typed = read_typed_number("D (spacing)", "0-5", spacing);
  EXPECT_FALSE(typed.value) << "'0-5' is not 0";
  EXPECT_TRUE(has(typed.problem, "D (spacing) '0-5': is not a number")) << typed.problem;
  EXPECT_TRUE(has(typed.problem, "give a value of at least 0 mm")) << typed.problem;
  EXPECT_TRUE(has(typed.problem, "0 = derive from the surface")) << "the key table's note: " << typed.problem;
  EXPECT_EQ(read_typed_number("D (spacing)", " 2.5 ", spacing).value, 2.5) << "blanks around are a person's";
  EXPECT_FALSE(read_typed_number("D (spacing)", "", spacing).value);
  EXPECT_FALSE(read_typed_number("D (spacing)", "inf", spacing).value);
  EXPECT_FALSE(read_typed_number("D (spacing)", "nan", spacing).value);
}

TEST(NumberRules, AValueOutOfRangeSaysTheRangeAndWhy) {
  NumberRule stone{ValueRange::above(0), "mm"};
  const TypedNumber zero = read_typed_number("stone diameter", "0", stone);
  EXPECT_FALSE(zero.value);
  EXPECT_EQ(zero.problem, "stone diameter '0': too small; give a value above 0 mm");
  stone.below(39.8, "D = stone + gap would be larger than the surface: the surface is about 40 mm across");
  const TypedNumber huge = read_typed_number("stone diameter", "99", stone);
  EXPECT_FALSE(huge.value);
  EXPECT_TRUE(has(huge.problem, "too large; give a value above 0 mm and below 39.8 mm (D = stone + gap")) << huge.problem;
  EXPECT_FALSE(read_typed_number("stone diameter", "39.8", stone).value) << "the open bound itself is refused";
  EXPECT_EQ(read_typed_number("stone diameter", "1.5", stone).value, 1.5);
  // A looser bound does not widen the rule.
  stone.below(100, "never said");
  EXPECT_FALSE(read_typed_number("stone diameter", "50", stone).value);
}

TEST(NumberRules, RangesAreSaidAsAPersonReadsThem) {
  EXPECT_EQ(range_text(NumberRule{ValueRange::closed(0, 1)}), "a value from 0 to 1");
  EXPECT_EQ(range_text(NumberRule{ValueRange::open_closed(0, 1), "x D"}), "a value above 0 x D and at most 1 x D");
  EXPECT_EQ(range_text(NumberRule{ValueRange::at_least(0.5), "mm"}), "a value of at least 0.5 mm");
  EXPECT_EQ(range_text(NumberRule{}), "a number");
}

TEST(NumberRules, RefusalsAreTakenOnce) {
  take_refusals();
  post_refusal("a");
  post_refusal("b");
  EXPECT_EQ(take_refusals(), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(take_refusals().empty());
}

}  // namespace
}  // namespace paver::studio
