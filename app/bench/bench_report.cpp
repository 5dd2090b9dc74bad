#include "app/bench/bench_report.h"

#include <cstdio>
#include <fstream>

#include "core/util/error.h"

namespace sandstorm::bench {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string count(std::size_t n) {
  char buf[32];
  if (n >= 1000000 && n % 1000000 == 0)
    std::snprintf(buf, sizeof buf, "%zuM", n / 1000000);
  else if (n >= 1000 && n % 1000 == 0)
    std::snprintf(buf, sizeof buf, "%zuk", n / 1000);
  else
    std::snprintf(buf, sizeof buf, "%zu", n);
  return buf;
}

}  // namespace

void printTable(const Report& r) {
  std::printf("\n%s\n", r.device.c_str());
  std::printf("%-8s %-11s %-8s %-8s %-10s %-8s %6s %5s %10s %10s %9s  %s\n", "section", "stage",
              "backend", "field", "renderer", "sim", "N", "walls", "GPU ms", "Mpart/s", "GB/s",
              "ratio to ceiling");
  for (const Row& row : r.rows) {
    char ratio[200] = "";
    if (row.ratio > 0)
      std::snprintf(ratio, sizeof ratio, "%.2f of %s", row.ratio, row.ceiling.c_str());
    if (!row.note.empty()) std::snprintf(ratio, sizeof ratio, "%s", row.note.c_str());
    char rate[32] = "-", bytes[32] = "-";
    if (row.particlesPerS > 0) std::snprintf(rate, sizeof rate, "%.1f", row.particlesPerS * 1e-6);
    if (row.bytesPerS > 0) std::snprintf(bytes, sizeof bytes, "%.1f", row.bytesPerS * 1e-9);
    const std::string field =
        row.field.empty() ? "-"
                          : row.field + (row.obstacles > 0 ? concat("+obst", row.obstacles) : "") +
                                (row.molecules > 0 ? concat("+mol", row.molecules) : "");
    std::printf(
        "%-8s %-11s %-8s %-8s %-10s %-8s %6s %5d %10.3f %10s %9s  %s\n", row.section.c_str(),
        row.stage.c_str(), row.backend.empty() ? "-" : row.backend.c_str(), field.c_str(),
        row.renderer.empty() ? "-" : row.renderer.c_str(), row.sim.empty() ? "-" : row.sim.c_str(),
        count(row.particles).c_str(), row.walls, row.ms, rate, bytes, ratio);
  }
  std::fflush(stdout);
}

void writeJson(const Report& r, const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw Error(concat("sandstorm-bench: cannot write ", path.string()));
  out << "{\n  \"device\": " << quoted(r.device) << ",\n  \"command\": " << quoted(r.command)
      << ",\n  \"copy_bytes_per_s\": " << r.copyBytesPerS
      << ",\n  \"shader_copy_bytes_per_s\": " << r.shaderCopyBytesPerS << ",\n  \"rows\": [\n";
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const Row& row = r.rows[i];
    out << "    {\"section\": " << quoted(row.section) << ", \"stage\": " << quoted(row.stage)
        << ", \"backend\": " << quoted(row.backend) << ", \"field\": " << quoted(row.field)
        << ", \"renderer\": " << quoted(row.renderer) << ", \"sim\": " << quoted(row.sim)
        << ", \"particles\": " << row.particles << ", \"walls\": " << row.walls
        << ", \"trails\": " << row.trails << ", \"shadows\": " << (row.shadows ? "true" : "false")
        << ", \"obstacles\": " << row.obstacles << ", \"molecules\": " << row.molecules
        << ", \"width\": " << row.width << ", \"height\": " << row.height
        << ", \"gpu_ms\": " << row.ms << ", \"particles_per_s\": " << row.particlesPerS
        << ", \"bytes_per_s\": " << row.bytesPerS << ", \"ceiling\": " << quoted(row.ceiling)
        << ", \"ratio\": " << row.ratio << ", \"wall_clock_ms\": " << row.wallMs
        << ", \"note\": " << quoted(row.note) << "}" << (i + 1 < r.rows.size() ? "," : "") << "\n";
  }
  out << "  ]\n}\n";
  if (!out) throw Error(concat("sandstorm-bench: writing ", path.string(), " failed"));
}

}  // namespace sandstorm::bench
