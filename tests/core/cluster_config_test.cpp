// The [cluster] section and the walls' rank and host keys: placements of
// included walls apply after every file is read; bad values name file, line
// and key.
#include <gtest/gtest.h>

#include "core/config/app_config.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

const std::string kWalls = R"(
[[wall]]
name = "front"
lower_left = [-1.5, 1.5, 0.0]
lower_right = [1.5, 1.5, 0.0]
upper_left = [-1.5, 1.5, 3.0]

[[wall]]
name = "left"
rank = 2
host = "node-b"
lower_left = [-1.5, -1.5, 0.0]
lower_right = [-1.5, 1.5, 0.0]
upper_left = [-1.5, -1.5, 3.0]
)";

std::string errorOf(const std::string& text) {
  try {
    parseConfig(text, "test.toml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ClusterConfig, DefaultsAndWallKeys) {
  const AppConfig c = parseConfig(kWalls, "test.toml");
  EXPECT_FLOAT_EQ(c.cluster.timeoutSeconds, 10.0f);
  EXPECT_FALSE(c.cluster.readField);
  EXPECT_TRUE(c.cluster.readSteps);  // every rank reads a series' steps itself
  EXPECT_EQ(c.walls[0].rank, 0);
  EXPECT_EQ(c.walls[1].rank, 2);
  EXPECT_EQ(c.walls[1].host, "node-b");
}

TEST(ClusterConfig, PlacementsApplyToWallsFromAnyFile) {
  // [cluster] before the walls, as a file that includes its walls would have it.
  const AppConfig c = parseConfig(R"(
[cluster]
timeout_s = 2.5
startup_timeout_s = 30
field = "read"
steps = "broadcast"
chunk_kib = 64
field_cache = 8
walls = "round-robin"
ranks = { front = 3, left = 1 }
hosts = { front = "node-a" }
)" + kWalls,
                                  "test.toml");
  EXPECT_FLOAT_EQ(c.cluster.timeoutSeconds, 2.5f);
  EXPECT_FLOAT_EQ(c.cluster.startupTimeoutSeconds, 30.0f);
  EXPECT_TRUE(c.cluster.readField);
  EXPECT_FALSE(c.cluster.readSteps);
  EXPECT_EQ(c.cluster.chunkKiB, 64);
  EXPECT_EQ(c.cluster.fieldCache, 8);
  EXPECT_TRUE(c.cluster.roundRobin);
  EXPECT_EQ(c.walls[0].rank, 3);
  EXPECT_EQ(c.walls[0].host, "node-a");
  EXPECT_EQ(c.walls[1].rank, 1);
}

TEST(ClusterConfig, BadValuesNameTheirLineAndKey) {
  struct Case {
    std::string text, expected[2];
  };
  for (const Case& c :
       {Case{"[cluster]\ntimeout_s = 0\n",
             {"test.toml:2", "cluster.timeout_s: expected 0.1..3600"}},
        Case{"[cluster]\nfield = \"mail\"\n", {"test.toml:2", "broadcast, read"}},
        Case{"[cluster]\nsteps = \"copy\"\n", {"test.toml:2", "cluster.steps"}},
        Case{"[cluster]\nranks = { front = -1 }\n", {"test.toml:2", "cluster.ranks.front"}},
        Case{"[cluster]\nranks = { back = 1 }\n",
             {"test.toml:2", "no wall named 'back'; the walls are front, left"}},
        Case{"[cluster]\nhosts = { left = 7 }\n",
             {"test.toml:2", "cluster.hosts.left: expected a host name"}},
        Case{"[cluster]\nspeed = 7\n", {"test.toml:2", "cluster.speed: unknown key"}}}) {
    const std::string message = errorOf(c.text + kWalls);
    for (const std::string& part : c.expected)
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
  std::string badRank = kWalls;
  badRank.replace(badRank.find("rank = 2"), 8, "rank = 5000");
  EXPECT_NE(errorOf(badRank).find("wall[1].rank: expected an integer in 0..4095"),
            std::string::npos)
      << errorOf(badRank);
}

}  // namespace
}  // namespace sandstorm
