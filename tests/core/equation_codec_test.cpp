// Cluster mode's wire format carries what issue 6 added to the frame packet:
// an analytic field's equation (field.mode = equation) and the level of
// detail's scale, bit for bit.
#include <gtest/gtest.h>

#include "core/field/analytic_field_factory.h"
#include "core/field/field_equation.h"
#include "core/field/sum_field.h"
#include "core/sim/frame_packet_codec.h"

namespace sandstorm {
namespace {

TEST(EquationCodec, EquationTermsAndTheLodScaleSurviveARoundTrip) {
  SumField sum;
  sum.add(makeAnalyticField("tornado", {{"spin", -3.5}}))
      .add(makeAnalyticField("curl_noise", {{"seed", 11}}));
  FieldUpdate update;
  update.equation = std::make_shared<FieldEquation>(*fieldEquation(sum));
  FramePacket p;
  p.frame = 7;
  p.emission = {12, 3};
  p.lodScale = 0.375f;
  p.fieldUpdate = std::make_shared<const FieldUpdate>(update);
  const FramePacket q = decodePacket(encodePacket(p));
  EXPECT_EQ(q.lodScale, 0.375f);
  ASSERT_TRUE(q.fieldUpdate && q.fieldUpdate->equation);
  const auto& a = update.equation->terms;
  const auto& b = q.fieldUpdate->equation->terms;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].kind, b[i].kind);
    EXPECT_EQ(a[i].seed, b[i].seed);
    EXPECT_EQ(a[i].a, b[i].a);
    EXPECT_EQ(a[i].b, b[i].b);
    EXPECT_EQ(a[i].c, b[i].c);
  }
  // A field update without an equation stays without one.
  p.fieldUpdate = std::make_shared<const FieldUpdate>();
  EXPECT_EQ(decodePacket(encodePacket(p)).fieldUpdate->equation, nullptr);
}

}  // namespace
}  // namespace sandstorm
