#include "app/bench/bench_table.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <thread>

namespace triwalk {

void BenchTable::add(BenchRow row) {
  std::printf("  %s: %s (%s)\n", row.benchmark.c_str(), row.figure.c_str(), row.dataSize.c_str());
  std::fflush(stdout);
  rows_.push_back(std::move(row));
}

void BenchTable::print(const std::string& glDescription) const {
  std::printf("\nmachine: %s\n", machineDescription().c_str());
  if (!glDescription.empty()) std::printf("OpenGL: %s\n", glDescription.c_str());
  std::printf("\n| benchmark | data size | figure | notes |\n|---|---|---|---|\n");
  for (const BenchRow& row : rows_) {
    std::printf("| %s | %s | %s | %s |\n", row.benchmark.c_str(), row.dataSize.c_str(), row.figure.c_str(),
                row.notes.c_str());
  }
}

std::string machineDescription() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  std::ifstream meminfo("/proc/meminfo");
  std::string memory;
  while (std::getline(meminfo, line)) {
    if (line.rfind("MemTotal", 0) == 0) {
      long kilobytes = std::stol(line.substr(line.find(':') + 1));
      memory = formatNumber(double(kilobytes) / (1024.0 * 1024.0), 1) + " GiB";
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads, " + memory;
}

std::string formatRatio(double to, double from) {
  return from > 0.0 ? formatNumber(to / from, 2) + "x" : "-";
}

std::string formatNumber(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string formatMedianAndP95(std::vector<double> milliseconds) {
  if (milliseconds.empty()) return "none timed";
  std::sort(milliseconds.begin(), milliseconds.end());
  const size_t n = milliseconds.size();
  return formatNumber(milliseconds[n / 2], 1) + " / " + formatNumber(milliseconds[std::min(n - 1, n * 95 / 100)], 1) + " ms";
}

}  // namespace triwalk
