// The over-budget errors' advice: the value named is at least what the check
// needs, reads back as a configuration value, and, followed, opens the file.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <regex>

#include "core/config/byte_size.h"
#include "core/io/budget_advice.h"
#include "core/io/field_loader.h"
#include "tests/io/io_test_util.h"

namespace sandstorm {
namespace {

TEST(BudgetAdvice, NamesAValueAtLeastTheNeedThatAConfigurationReadsBack) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> exponent(0.0, 50.0);
  for (int i = 0; i < 2000; ++i) {
    const double need = std::floor(std::exp2(exponent(random)));
    const std::string text = budgetValueAtLeast(need);
    const std::optional<std::uint64_t> value = parseByteSize(text);
    ASSERT_TRUE(value) << text;
    EXPECT_GE(double(*value), need) << text;
    EXPECT_LE(double(*value), std::max(need, 1048576.0) * 1.01) << text;  // three digits, up
  }
  EXPECT_EQ(budgetValueAtLeast(1536.0 * 1024 * 1024), "1.50 GiB");
  EXPECT_EQ(raiseBudget(1000.0), "; raise field.memory_budget to at least 1.00 MiB");
}

// A grid too large for a small budget: each error's advice, taken, gets past
// that check, and within a few the file opens.
TEST(BudgetAdvice, FollowedTheAdviceOpensTheFile) {
  const auto dir = test::scratch();
  const int extent[6] = {0, 119, 0, 99, 0, 79};  // 11 MiB of vectors
  const auto image = test::asymmetricImage(extent, glm::dvec3(0.0), glm::dvec3(0.1));
  for (const char* name : {"grid.vti", "grid.vtk"}) {
    SCOPED_TRACE(name);
    const auto path = dir / name;
    if (std::string(name).ends_with(".vti"))
      test::writeRawVti(image, path);
    else
      ASSERT_TRUE(test::writeStructuredPoints(image, path, true));
    LoadOptions options;
    options.memoryBudget = 4096;
    bool opened = false;
    for (int attempt = 0; attempt < 6 && !opened; ++attempt) {
      try {
        loadField(path, options);
        opened = true;
      } catch (const Error& e) {
        const std::string what = e.what();
        std::smatch m;
        ASSERT_TRUE(
            std::regex_search(what, m, std::regex("field.memory_budget to at least ([^;,)]+)")))
            << what;
        const std::optional<std::uint64_t> advised = parseByteSize(m[1].str());
        ASSERT_TRUE(advised) << what;
        ASSERT_GT(*advised, options.memoryBudget) << what;
        options.memoryBudget = *advised;
        std::printf("[ measured ] %s\n", what.c_str());
      }
    }
    EXPECT_TRUE(opened);
  }
}

}  // namespace
}  // namespace sandstorm
