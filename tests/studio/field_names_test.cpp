#include "field_names.h"

#include "design/design.h"
#include "core/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace paver::studio {
namespace {

TEST(FieldNames, KeysNameThePanelAndTheFieldADesignerSees) {
  EXPECT_EQ(studio_field("pattern.spacing"), "Pattern > D (spacing)");
  EXPECT_EQ(studio_field("elements.vertex.scale"), "Elements > V-elements > size (x D)");
  EXPECT_EQ(studio_field("elements.edge[3].t"), "Elements > E-element 3 > along the edge");
  EXPECT_EQ(studio_field("elements.gap"), "Elements > Stones (jewellery) > gap");
  EXPECT_EQ(studio_field("placement.offset[1]"), "Pattern > Placement > offset");
  EXPECT_EQ(studio_field("solver.lambda_r"), "Optimize > keep the spacing (lambda_r)");
  EXPECT_EQ(studio_field("guidance[2].radius"), "Pattern > Guidance brush > dab 2");
  EXPECT_EQ(studio_field("edits.moved[0].uv[1]"), "Elements > Single stones > edits (moved)");
  EXPECT_EQ(studio_field("solver.no_such"), "");
  EXPECT_EQ(studio_field("version"), "");
}

// Every refusal of the design's own validation that names a key a panel shows is rewritten.
TEST(FieldNames, ARefusedDesignNamesTheFieldThenTheKey) {
  const auto message_for = [](Design d) {
    try {
      validate_design(d, "this change");
    } catch (const InputError& e) {
      return in_studio_words(e.what());
    }
    return std::string("accepted");
  };
  Design gap;
  gap.elements.gap = -0.1;
  EXPECT_EQ(message_for(gap).rfind("this change: Elements > Stones (jewellery) > gap (elements.gap) must be", 0), 0u)
      << message_for(gap);
  Design scale;
  scale.placement.scale = 0;
  EXPECT_NE(message_for(scale).find("Pattern > Placement > scale (placement.scale) must be"), std::string::npos)
      << message_for(scale);
  Design edge;
  edge.elements.edge.push_back({});
  edge.elements.edge[0].t = 2;
  EXPECT_NE(message_for(edge).find("Elements > E-element 0 > along the edge (elements.edge[0].t)"), std::string::npos)
      << message_for(edge);
  EXPECT_EQ(in_studio_words("a 'quoted word' and 'elements.gap'"),
            "a 'quoted word' and Elements > Stones (jewellery) > gap (elements.gap)")
      << "only keys with a field are rewritten";
  EXPECT_EQ(in_studio_words("it's one unpaired quote"), "it's one unpaired quote");
}

}  // namespace
}  // namespace paver::studio
