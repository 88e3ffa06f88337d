#pragma once
// The table `triwalk bench` prints: the machine, then one row per figure
// with the data size it was measured on.

#include <string>
#include <vector>

namespace triwalk {

struct BenchRow {
  std::string benchmark;
  std::string dataSize;
  std::string figure;
  std::string notes;
};

class BenchTable {
public:
  void add(BenchRow row);
  // Markdown table preceded by the machine description.
  void print(const std::string& glDescription) const;

private:
  std::vector<BenchRow> rows_;
};

std::string machineDescription();
std::string formatNumber(double value, int decimals);
// "4.12x": to over from, or "-" when from is not positive.
std::string formatRatio(double to, double from);
// "median / p95 ms" of frame times: the values at ranks n/2 and n*95/100.
std::string formatMedianAndP95(std::vector<double> milliseconds);

}  // namespace triwalk
