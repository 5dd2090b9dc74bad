// FluidDriver: the live solver in the main context (solver.device = cpu) hands each step's flow to
// every wall as the field, gives the field it started from back when turned
// off, and starts afresh from a field loaded while it runs.
#include "app/fluid_driver.h"

#include <gtest/gtest.h>

#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

std::shared_ptr<const VectorField> wind(glm::vec3 v) {
  return std::make_shared<const VectorField>(Box{{-2, -2, 0}, {2, 2, 2}}, glm::ivec3(9, 9, 5),
                                             std::vector<glm::vec3>(9 * 9 * 5, v));
}

TEST(FluidDriver, StepsTheFlowIntoTheFieldAndGivesTheOldOneBack) {
  MainContext::Options options;
  options.fixedDt = 0.05f;
  ParticleState state;
  state.solver.every = 2;
  const auto start = wind({1.0f, 0.0f, 0.0f});
  MainContext main(state, FieldUpdate{.field = start}, options);
  FluidDriver driver(nullptr);
  driver.update(main, main.next());
  EXPECT_EQ(driver.solver(), nullptr);  // off
  main.set("solver.device", std::string("cpu"));
  main.set("solver.enabled", true);
  // An obstacle in the wind: the flow goes around it.
  std::vector<std::shared_ptr<const VectorField>> seen;
  for (int f = 0; f < 6; ++f) {
    const FramePacket p = main.next();
    if (p.fieldUpdate) seen.push_back(p.fieldUpdate->field);
    driver.update(main, p);
  }
  ASSERT_NE(driver.solver(), nullptr);
  // A step every second frame: the new grid travels in the next packet, on every wall alike.
  EXPECT_EQ(seen.size(), 2u);
  EXPECT_NE(main.field()->field, start);
  EXPECT_LT(driver.solver()->maxDivergence(), 1e-3);
  // Off: the field it started from, at the next packet.
  main.set("solver.enabled", false);
  driver.update(main, main.next());
  EXPECT_EQ(main.field()->field, start);
  EXPECT_EQ(driver.solver(), nullptr);
  // On again, then a field loaded meanwhile: it starts afresh from that one.
  main.set("solver.enabled", true);
  for (int f = 0; f < 3; ++f)
    driver.update(main, main.next());
  const auto loaded = wind({0.0f, 2.0f, 0.0f});
  main.setField(FieldUpdate{.field = loaded});
  driver.update(main, main.next());
  main.set("solver.enabled", false);
  driver.update(main, main.next());
  EXPECT_EQ(main.field()->field, loaded);  // the base is the loaded field now
}

// solver.device = gpu: each wall's GPU solves it; the driver leaves the field alone.
TEST(FluidDriver, LeavesTheFieldToTheGpusWhenTheySolve) {
  MainContext::Options options;
  options.fixedDt = 0.05f;
  const auto start = wind({1.0f, 0.0f, 0.0f});
  MainContext main(ParticleState{}, FieldUpdate{.field = start}, options);
  FluidDriver driver(nullptr);
  main.set("solver.enabled", true);
  main.set("solver.device", std::string("gpu"));
  for (int f = 0; f < 4; ++f)
    driver.update(main, main.next());
  EXPECT_EQ(driver.solver(), nullptr);
  EXPECT_EQ(main.field()->field, start);
}

// solver.device = auto (the default): the application picks the CPU where the
// walls' OpenGL runs in software (llvmpipe), else the GPU, before the first
// frame, as a recorded change.
TEST(FluidDriver, AutoPicksTheCpuUnderSoftwareOpenGlAndTheGpuElse) {
  const auto dir = test::scratchDir("solver-auto");
  const auto r = test::runSandstorm(
      "--config tests/data/identity.toml --walls front --frames 3 --set solver.enabled=true "
      "--record " +
      (dir / "s.session").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const bool software = r.output.find("llvmpipe") != std::string::npos;
  const std::string expected = software ? "0 set solver.device cpu" : "0 set solver.device gpu";
  bool found = false;
  for (const std::string& line : test::readLines(dir / "s.session"))
    found = found || line == expected;
  EXPECT_TRUE(found) << "expected '" << expected << "' in the session\n" << r.output;
}

// The transform-feedback backend cannot read the GPU solver's grid; with the
// solver off it has nothing to refuse, so a run says nothing of it (it said
// "solver.device = gpu: ..." every frame).
TEST(FluidDriver, ATransformFeedbackRunWithTheSolverOffSaysNothingOfIt) {
  const auto r = test::runSandstorm(
      "--config config/desktop.toml --headless --frames 4 --set run.backend=tf-gs "
      "--set sim.maximum=1000");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("solver.device = gpu"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sandstorm
