// The colour maps that ParaView defines by control points interpolated in a
// colour space, against VTK's own vtkColorTransferFunction (what ParaView
// colours with): "Fast" in CIELAB, "Cool to Warm" in Moreland's diverging space.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include <vtkColorTransferFunction.h>
#include <vtkNew.h>

#include "core/color/color_map.h"

namespace sandstorm {
namespace {

// The largest difference of any channel over [0, 1], sampled finely.
float worstAgainst(const ColorMap& map, vtkColorTransferFunction& vtk) {
  float worst = 0.0f;
  for (int i = 0; i <= 1000; ++i) {
    const double t = double(i) / 1000.0;
    std::array<double, 3> rgb{};
    vtk.GetColor(t, rgb.data());
    const glm::vec3 ours = map.at(float(t));
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, float(std::abs(double(ours[c]) - rgb[std::size_t(c)])));
  }
  return worst;
}

TEST(ColorMapVtk, FastIsParaViewsFastInterpolatedInLab) {
  // ParaView's preset (Remoting/Views/ColorMaps.json), as ParaView loads it.
  vtkNew<vtkColorTransferFunction> fast;
  fast->SetColorSpaceToLab();
  const double points[][4] = {
      {0.0, 0.05639999999999999, 0.05639999999999999, 0.47},
      {0.17159223942480895, 0.24300000000000013, 0.4603500000000004, 0.81},
      {0.2984914818394138, 0.3568143826543521, 0.7450246485363142, 0.954367702893722},
      {0.4321287371255907, 0.6882, 0.93, 0.9179099999999999},
      {0.5, 0.8994959551205902, 0.944646394975174, 0.7686567142818399},
      {0.5882260353170073, 0.957107977357604, 0.8338185108985666, 0.5089156299842102},
      {0.7061412605695164, 0.9275207599610714, 0.6214389091739178, 0.31535705838676426},
      {0.8476395308725272, 0.8, 0.3520000000000001, 0.15999999999999998},
      {1.0, 0.59, 0.07670000000000013, 0.11947499999999994}};
  for (const auto& p : points)
    fast->AddRGBPoint(p[0], p[1], p[2], p[3]);
  EXPECT_LT(worstAgainst(ColorMap(ColorMapName::Fast), *fast), 0.1f / 255.0f);

  // The comparison can fail: the same points interpolated in sRGB differ.
  fast->SetColorSpaceToRGB();
  EXPECT_GT(worstAgainst(ColorMap(ColorMapName::Fast), *fast), 2.0f / 255.0f);
}

TEST(ColorMapVtk, CoolWarmIsParaViewsCoolToWarm) {
  vtkNew<vtkColorTransferFunction> coolWarm;
  coolWarm->SetColorSpaceToDiverging();
  coolWarm->AddRGBPoint(0.0, 0.23137254902, 0.298039215686, 0.752941176471);
  coolWarm->AddRGBPoint(1.0, 0.705882352941, 0.0156862745098, 0.149019607843);
  EXPECT_LT(worstAgainst(ColorMap(ColorMapName::CoolWarm), *coolWarm), 0.25f / 255.0f);
}

}  // namespace
}  // namespace sandstorm
